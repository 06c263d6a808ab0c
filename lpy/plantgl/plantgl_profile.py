# openalea.plantgl.scenegraph.interpolated_profile as Sprout provides it: a profile made of
# cross sections given at parameters, a section at any parameter between them (PlantGL's
# interpolated_profile: the editor's "InterpolatedProfile" panel). Sections are interpolated
# linearly between their neighbours, point by point, with NurbsMethod (PlantGL makes a NURBS
# patch through them); with CSplineMethod, as PlantGL does: a cardinal spline through each
# control point's positions over the sections (PlantGL's cspline.py).
from openalea.plantgl.all import Vector2, Vector3, NurbsCurve, NurbsCurve2D


def _cspline(points, distances=None):
    """PlantGL's cspline(points, distances=...): the cubic NURBS curve through `points` (Vector3),
    the derivative at each inner point half the vector from its neighbour before to the one
    after, at the ends half the first and last segments, as Bezier arcs; its knots are the
    cumulated distances between the points (or the given ones), each three times."""
    n = len(points)
    dist = list(distances) if distances is not None else [abs(points[i + 1] - points[i]) for i in range(n - 1)]
    der = [(points[1] - points[0]) / 2.0]
    der += [(points[i + 1] - points[i - 1]) / 2.0 for i in range(1, n - 1)]
    der.append((points[-1] - points[-2]) / 2.0)
    ctrl = [None] * (3 * n - 2)
    for i in range(n - 1):
        ctrl[3 * i] = points[i]
        ctrl[3 * i + 1] = points[i] + der[i] * (1.0 / 3)
        ctrl[3 * i + 2] = points[i + 1] - der[i + 1] * (1.0 / 3)
    ctrl[-1] = points[-1]
    param = [0.0]
    for d in dist:
        param.append(param[-1] + d)
    knots = [param[0]] + [p for p in param for _ in range(3)] + [param[-1]]
    return NurbsCurve([(c[0], c[1], c[2], 1.0) for c in ctrl], 3, knots, stride=(n - 1) * 10)


class NurbsMethod:
    """PlantGL's NURBS interpolation between sections (here: linear, point by point)."""


class CSplineMethod:
    """PlantGL's cubic spline interpolation between sections (as PlantGL computes it)."""


class CrossSection(list):
    """A cross section: its control points (x, y) or (x, y, weight)."""

    def __init__(self, *points):
        list.__init__(self, [tuple(p) for p in points])


class InterpolatedProfile(dict):
    """Cross sections by parameter; get_interpolated_section(t) between them."""

    def __init__(self, interpolator=NurbsMethod):
        dict.__init__(self)
        self.interpolator = interpolator
        self.name = ''
        self._param_range = (0.0, 1.0)
        self._abscissa_range = (-0.5, 0.5)

    @staticmethod
    def make_default():
        p = InterpolatedProfile()
        p.add_cross_section(0.0, CrossSection((-0.5, 0.0), (0.5, 0.0)))
        p.add_cross_section(1.0, CrossSection((-0.5, 0.0), (0.5, 0.0)))
        return p

    def set_param_range(self, low, high):
        self._param_range = (float(low), float(high))

    def get_param_range(self):
        return self._param_range

    def set_abscissa_range(self, low, high):
        self._abscissa_range = (float(low), float(high))

    def get_abscissa_range(self):
        return self._abscissa_range

    def check_control_point_count(self, section):
        return not self or len(section) == len(next(iter(self.values())))

    def add_cross_section(self, parameter, section, autoUpdate=True, normalised=False):
        if not self.check_control_point_count(section):
            raise ValueError("a cross section has as many control points as the others")
        self[float(parameter)] = CrossSection(*section)

    def add_cross_sections(self, *parameters_and_sections, **kwargs):
        for parameter, section in zip(parameters_and_sections[::2], parameters_and_sections[1::2]):
            self.add_cross_section(parameter, section)

    def as_sorted_tuples(self):
        return sorted(self.items())

    def get_interpolated_section(self, parameter, curve=True):
        """The section at `parameter`: a curve (NurbsCurve2D) or its points."""
        items = self.as_sorted_tuples()
        if not items:
            raise ValueError("the profile has no cross section")
        t = float(parameter)
        if self.interpolator is CSplineMethod and len(items) >= 2:
            # A spline through each control point's (x, y, parameter) over the sections, knots
            # at the parameters; the section is the points of those splines at t.
            # The splines depend on the sections only: made once for them (as PlantGL makes
            # its interpolator when sections are added), and again when one changes.
            key = tuple((par, tuple(tuple(p) for p in sec)) for par, sec in items)
            if self.__dict__.get('_splines_of') != key:
                vdist = [items[k + 1][0] - items[k][0] for k in range(len(items) - 1)]
                self._splines = [_cspline([Vector3(sec[j][0], sec[j][1], par) for par, sec in items], vdist)
                                 for j in range(len(items[0][1]))]
                self._splines_of = key
            section = [c.getPointAt(t) for c in self._splines]
            if not curve:
                return section
            spline = _cspline(section)
            return NurbsCurve2D([(c[0], c[1], 1.0) for c in spline.ctrlPointList], 3, spline.knotList)
        if t <= items[0][0] or len(items) == 1:
            points = items[0][1]
        elif t >= items[-1][0]:
            points = items[-1][1]
        else:
            k = next(i for i in range(1, len(items)) if t <= items[i][0])
            (t0, a), (t1, b) = items[k - 1], items[k]
            f = (t - t0) / (t1 - t0)
            points = [tuple((1 - f) * x + f * y for x, y in zip(p, q)) for p, q in zip(a, b)]
        if not curve:  # the points, as PlantGL gives them (x, y; and the weight when given)
            return [Vector3(*p[:3]) if len(p) > 2 else Vector2(p[0], p[1]) for p in points]
        pts = [(p[0], p[1], p[2] if len(p) > 2 else 1.0) for p in points]
        return NurbsCurve2D(pts, min(3, len(pts) - 1))
