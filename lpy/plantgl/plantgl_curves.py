# openalea.plantgl._curves, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): the 2D and 3D curves (NURBS, Bezier, polylines; point arrays:
# plantgl_arrays.py), the
# functions made from them (QuantisedFunction, the arc-length mappings), the Discretizer (NURBS
# patches and volumes: plantgl_patches.py): PlantGL's interface, evaluated in C++
# (lpy/plantgl/curves.cpp, through bind_curves.cpp: de Boor, the knots, arc lengths are there
# alone). Its own file: the curves.
#
# Index of this file:
#   [SECTION] NURBS and Bezier curves
#   [SECTION] Polylines and the Discretizer
#   [SECTION] QuantisedFunction
import math as _math

from _sprout_lpy import (_PglNurbs, _pgl_quantised_polyline, _pgl_uniform_knots,
                         _QuantisedBase)
from openalea.plantgl import _vectors
from openalea.plantgl._scene import Polyline as _ScenePolyline
from openalea.plantgl._vectors import _Vec, Vector2, Vector3, Vector4, cross
from openalea.plantgl._object import _SceneObject
from openalea.plantgl._arrays import (Point2Array, Point3Array, Point4Array, RealArray, Point4Matrix, _point_text,  # noqa: F401
                                      _Points)

_of2, _of3 = Vector2._of, Vector3._of


def _default_knots(knots, n, degree):
    """PlantGL's NurbsCurve::defaultKnotListTest: whether `knots` are the uniform clamped ones
    (then a curve's text leaves them out)."""
    if knots is None:
        return True
    size = len(knots)
    if size != n + degree + 1:
        return False
    if any(not abs(knots[i] - knots[0]) < 1e-10 for i in range(1, degree + 1)):
        return False
    step = 1.0 / (size - 2 * degree - 1) if size - 2 * degree - 1 else float("inf")
    if any(not abs(abs(knots[j + 1] - knots[j]) - step) < 1e-5 for j in range(degree + 1, size - degree - 1)):
        return False
    return all(abs(knots[k] - knots[-1]) < 1e-10 for k in range(size - degree - 1, size))


# [SECTION] NURBS and Bezier curves
def _closest_on_segment(p, a, b):
    """PlantGL's __closestPointToSegment: (the nearest point of [a, b], its squared distance,
    where along the segment)."""
    diff, m = p - a, b - a
    t = m * diff
    if t > 0:
        mm = m * m
        if t < mm:
            t = t / mm
            diff = diff - m * t
            q = a + m * t
        else:
            t, diff, q = 1, diff - m, b
    else:
        t, q = 0, a
    return q, diff * diff, t


def _find_closest(curve, point):
    """PlantGL's findClosest (LineicModel's, Curve2D's): the nearest point of the polyline
    through the curve's stride points, and its parameter. PlantGL leaves the parameter unset
    where the first point is the nearest; here it is the first knot then."""
    vec = (Vector2, Vector3)[curve._dim - 2]
    p = vec(*tuple(point)[:curve._dim])
    u0, u1 = curve.firstKnot, curve.lastKnot
    du = (u1 - u0) / curve.stride
    p1 = curve.getPointAt(u0)
    res, dist, found = p1, (p - p1) * (p - p1), u0
    u = u0 + du
    while u <= u1:
        p2 = curve.getPointAt(u)
        q, d, lu = _closest_on_segment(p, p1, p2)
        if curve._dim == 2:  # Curve2D's compares the distance itself with the squared one
            d = _math.sqrt(d)
        if d < dist:
            dist, res, found = d, q, u + du * (lu - 1)
        p1 = p2
        u += du
    return res, found


class Curve2D(_SceneObject):
    """PlantGL's base of the 2D curves (NurbsCurve2D, BezierCurve2D, Polyline2D)."""
    _kind = 'curve'


class NurbsCurve2D(Curve2D):
    """A 2D NURBS curve; control points are (x, y, weight)."""
    _dim = 2

    def __init__(self, ctrlPointList, degree=3, knotList=None, stride=30, width=1, **kwargs):
        if isinstance(degree, (list, tuple)):  # the form (points, knots, degree, ...)
            knotList, degree = degree, knotList if isinstance(knotList, int) else 3
        pts = [tuple(p) for p in ctrlPointList]
        d = self._dim
        self.ctrlPointList = [[Vector3, Vector4][d - 2](*(tuple(p[:d]) + ((p[d] if len(p) > d else 1.0),))) for p in pts]
        self.degree = max(1, min(int(degree), len(pts) - 1))
        self.knotList = list(knotList) if knotList else _pgl_uniform_knots(len(pts), self.degree)
        self.stride = int(kwargs.get('stride', stride))
        self.width = width
        self.name = ''

    DEFAULT_NURBS_DEGREE, DEFAULT_STRIDE, DEFAULT_WIDTH = 3, 30, 1

    def isDegreeToDefault(self):
        return self.degree == 3

    def isStrideToDefault(self):
        return self.stride == 30

    def isWidthToDefault(self):
        return self.width == 1

    def isKnotListToDefault(self):
        return _default_knots(self.knotList, len(self.ctrlPointList), self.degree)

    def setKnotListToDefault(self):
        self.knotList = _pgl_uniform_knots(len(self.ctrlPointList), self.degree)
        return True

    @staticmethod
    def defaultKnotList(nbCtrlPoints, degree):
        return RealArray(_pgl_uniform_knots(nbCtrlPoints, degree))

    @staticmethod
    def defaultKnotListTest(knots, nbCtrlPoints, degree):
        return _default_knots(knots, nbCtrlPoints, degree)

    def findClosest(self, point):
        """(the nearest point, its parameter), along the curve's stride points."""
        return _find_closest(self, point)

    def getDerivativeAt(self, u, d=1):
        """The d-th derivative at u (d up to 2)."""
        return self._derivative(u, d)

    @property
    def firstKnot(self):
        return self.knotList[self.degree]

    @property
    def lastKnot(self):
        return self.knotList[len(self.ctrlPointList)]

    # The arithmetic is C++'s (lpy/plantgl/curves.cpp, the same numbers as PlantGL's): an
    # evaluator built from the curve's lists, kept on the curve while they hold the same
    # objects and no vector has changed in place (the count of _vectors._changes).
    def _native(self):
        pts, knots = self.ctrlPointList, self.knotList
        key = (_vectors._changes[0], self.degree, tuple(pts), tuple(knots))
        cache = self.__dict__.get('_sprout_native_cache')
        if cache is not None and cache[0] == key:
            return cache[1]
        native = _PglNurbs(self._dim, self.degree, knots, pts)
        if all(isinstance(q, (_Vec, tuple)) for q in pts):  # a point that is a list may change unseen
            self.__dict__['_sprout_native_cache'] = (key, native)
        return native

    _NATIVE = ('getPointAt', '_derivative', 'getTangentAt', 'getLength', 'getArcLengthToUMapping', 'firstKnot', 'lastKnot')

    def _sprout_native(self):
        """The C++ evaluator, for Sprout's drawing (a guide along the curve); None where a
        subclass evaluates the curve its own way."""
        cls = type(self)
        if any(getattr(cls, m) is not getattr(NurbsCurve2D, m) for m in self._NATIVE):
            return None
        return self._native()

    def __getstate__(self):  # pickled and copied without its evaluator
        state = dict(self.__dict__)
        state.pop('_sprout_native_cache', None)
        return state

    def getPointAt(self, u):
        """de Boor on the homogeneous points, u clamped to the knots."""
        return (_of2, _of3)[self._dim - 2](self._native().point(u))

    def _derivative(self, u, d=1):
        """The curve's d-th derivative at u (d up to 2; PlantGL's deriveAt, the NURBS Book's
        A4.2): the weighted control points' B-spline and its derivatives, then the rational
        curve's."""
        return (_of2, _of3)[self._dim - 2](self._native().derivative(u, d))

    def getTangentAt(self, u):
        """The first derivative, not normalised (PlantGL's getTangentAt)."""
        return self._derivative(u, 1)

    def getNormalAt(self, u):
        """PlantGL's normal: (T x C'') x T / |T|^4, T the first derivative."""
        return (_of2, _of3)[self._dim - 2](self._native().normal(u))

    def getLength(self, begin=None, end=None):
        """The length of the polyline through `stride` evenly spaced parameters (PlantGL's
        LineicModel::getLength, its corrections at both ends included)."""
        return self._native().length(self.firstKnot if begin is None else begin, self.lastKnot if end is None else end,
                                     self.stride)

    def getArcLengthToUMapping(self):
        """A function from the fraction of the curve's length to the parameter u (PlantGL's:
        the polyline through `stride` steps of u, sampled 5 * stride times)."""
        return QuantisedFunction._of(self._native().arc_to_u(self.stride))

    def getUToArcLengthMapping(self):
        """A function from u to the fraction of the curve's length (PlantGL's)."""
        return QuantisedFunction._of(self._native().u_to_arc(self.stride))

    def deepcopy(self):
        import copy
        return copy.deepcopy(self)

    def points(self, samples=None):
        """`samples` (the stride) points at evenly spaced parameters."""
        of = (_of2, _of3)[self._dim - 2]
        return [of(p) for p in self._native().points(samples or max(2, self.stride))]


    def apply(self, action):
        """PlantGL's actions on a curve: a Discretizer gets its polyline (the curve's stride)."""
        return action.process(self)

    def __repr__(self):
        """As PlantGL writes a curve (its nc2_repr): the control points, then what is not the
        default (degree 3, the uniform knots, stride 30, width 1)."""
        n = self._dim + 1
        text = "%s(%s([%s])" % (type(self).__name__, "Point%dArray" % n, ",".join(_point_text(p, n) for p in self.ctrlPointList))
        if self.degree != 3:
            text += ", degree = %d" % self.degree
        if not _default_knots(self.knotList, len(self.ctrlPointList), self.degree):
            text += ", knotList = " + repr(RealArray(self.knotList))
        return text + self._stride_width_text() + ")"

    def _stride_width_text(self):
        """The end of a curve's text: its stride and width where not PlantGL's defaults (30, 1)."""
        return (", stride = %d" % self.stride if self.stride != 30 else "") + (", width = %d" % int(self.width) if self.width != 1 else "")

    __str__ = __repr__


class NurbsCurve(NurbsCurve2D):
    """A 3D NURBS curve; control points are (x, y, z, weight)."""
    _dim = 3


class BezierCurve(NurbsCurve):
    """A 3D Bezier curve: a NURBS whose degree is its number of points less one."""

    def __init__(self, ctrlPointList, stride=30, width=1, **kwargs):
        n = len(list(ctrlPointList))
        NurbsCurve.__init__(self, ctrlPointList, n - 1, [0.0] * n + [1.0] * n, stride, width)

    def __repr__(self):
        points = ",".join(_point_text(p, 4) for p in self.ctrlPointList)
        return "BezierCurve(Point4Array([%s])%s)" % (points, self._stride_width_text())

    __str__ = __repr__


class BezierCurve2D(NurbsCurve2D):
    def __init__(self, ctrlPointList, stride=30, width=1, **kwargs):
        n = len(list(ctrlPointList))
        NurbsCurve2D.__init__(self, ctrlPointList, n - 1, [0.0] * n + [1.0] * n, stride, width)

    def __repr__(self):  # its control points, its stride and width where not the default
        points = ",".join(_point_text(p, 3) for p in self.ctrlPointList)
        return "BezierCurve2D(Point3Array([%s])%s)" % (points, self._stride_width_text())

    __str__ = __repr__


# [SECTION] Polylines and the Discretizer
class _PolylineCurve:
    """What PlantGL's Polyline and Polyline2D share (polyline.cpp): point i at u = i, linear
    between; their stride is their number of segments."""
    _kind, _explicit = 'curve', True
    DEFAULT_WIDTH = 1

    firstKnot = property(lambda self: 0.0)
    lastKnot = property(lambda self: float(len(self.pointList) - 1))
    stride = property(lambda self: len(self.pointList) - 1)

    def _vec(self, p):
        return (Vector2, Vector3)[self._dim - 2](*tuple(p)[:self._dim])

    def getPointAt(self, u):
        pts = self.pointList
        if len(pts) == 1:
            return self._vec(pts[0])
        last = len(pts) - 1
        u = max(0.0, min(float(last), u))
        if abs(u) < 1e-5:
            u = 0.0
        elif abs(u - last) < 1e-5:
            u = float(last)
        i = int(u)
        if i == u:
            return self._vec(pts[i])
        a, b = self._vec(pts[i]), self._vec(pts[i + 1])
        return a * ((i + 1) - u) + b * (u - i)

    def getTangentAt(self, u):
        pts = [self._vec(p) for p in self.pointList]
        i = int(u)
        if u <= 0:
            return pts[1] - pts[0]
        if u >= len(pts) - 1:
            return pts[-1] - pts[-2]
        if i == u:
            a, b = pts[i] - pts[i - 1], pts[i + 1] - pts[i]
            la, lb = a.normalize(), b.normalize()
            return (a + b) * (la + lb) / 2
        return pts[i + 1] - pts[i]

    def getNormalAt(self, u):
        t = self.getTangentAt(u)
        if self._dim == 2:
            return Vector2(-t.y, t.x)
        if abs(t.x) < 1e-5 and abs(t.y) < 1e-5:
            return cross(t, Vector3(1, 0, 0))
        return cross(t, Vector3(0, 0, 1))

    def _native(self):  # a polyline is the NURBS of degree 1 through its points
        pts = [tuple(p)[:self._dim] + (1.0,) for p in self.pointList]
        n = len(pts)
        return _PglNurbs(self._dim, 1, [0.0] + [float(i) for i in range(n)] + [float(n - 1)], pts)

    def getLength(self, begin=None, end=None):
        """PlantGL's LineicModel::getLength, at the polyline's points."""
        return self._native().length(self.firstKnot if begin is None else begin, self.lastKnot if end is None else end,
                                     max(1, self.stride))

    def getArcLengthToUMapping(self):
        return QuantisedFunction._of(self._native().arc_to_u(max(1, self.stride)))

    def getUToArcLengthMapping(self):
        return QuantisedFunction._of(self._native().u_to_arc(max(1, self.stride)))

    def points(self, samples=None):
        return [self._vec(p) for p in self.pointList]

    def findClosest(self, point):
        return _find_closest(self, point)

    def split(self, u):
        """The polyline cut at u: the two polylines before and after."""
        i = int(u)
        p = self.getPointAt(u)
        head = [self._vec(q) for q in self.pointList[:i + 1]] + ([p] if i != u else [])
        tail = [p] + [self._vec(q) for q in self.pointList[i + 1:]]
        return type(self)(head), type(self)(tail)

    def deepcopy(self):
        import copy
        return copy.deepcopy(self)

    def apply(self, action):
        return action.process(self)


class Polyline2D(_PolylineCurve, Curve2D):
    _dim = 2

    def __init__(self, pointList, width=1, **kwargs):
        self.pointList = Point2Array(pointList)
        self.width = width
        self.name = ''

    @staticmethod
    def Circle(radius=0.5, slices=8):
        return Polyline2D([(radius * _math.cos(2 * _math.pi * i / slices), radius * _math.sin(2 * _math.pi * i / slices))
                           for i in range(slices + 1)])

    def __repr__(self):  # Polyline2D(Point2Array([Vector2(0,0),Vector2(1,1)]))
        return "Polyline2D(Point2Array([%s]))" % ",".join(_point_text(p, 2) for p in self.pointList)

    __str__ = __repr__


class Polyline(_PolylineCurve, _ScenePolyline):
    """PlantGL's 3D Polyline: a curve through its points (drawn by meshes.cpp)."""
    _dim = 3

    def __init__(self, pointList=(), *args, **kwargs):  # its points kept as given (read as vectors when used)
        _ScenePolyline.__init__(self, pointList, *args, **kwargs)


class Discretizer:
    """PlantGL's Discretizer: `curve.apply(d)` leaves the curve's points in `d.result` (a
    Polyline2D for a 2D curve, a Polyline for a 3D one), sampled at the curve's stride."""

    def __init__(self):
        self.result = None

    def process(self, obj):
        pts = obj.points()
        if pts and len(tuple(pts[0])) >= 3:
            self.result = Polyline([Vector3(*tuple(p)[:3]) for p in pts])
        else:
            self.result = Polyline2D(pts)
        return True

    def clear(self):
        self.result = None


# [SECTION] QuantisedFunction
class QuantisedFunction(_QuantisedBase):
    """y = f(x) from a 2D curve, as PlantGL's QuantisedFunction makes it: `sampling` values at
    evenly spaced x over the curve's x range, each the y of the curve's point found by bisecting
    its parameter until x is within 1e-5 (PlantGL's _computeValue), read back by linear
    interpolation between the two samples around x. Called in C (_QuantisedBase, which keeps
    _first, _last and _values): _call_python below where C would not read x as Python does."""

    def __init__(self, curve, sampling=100, clamped=True):
        if isinstance(curve, (list, tuple)):
            curve = Polyline2D(curve)
        n = max(3, int(sampling))
        # Sprout's curves are sampled in C++ (lpy/plantgl/curves.cpp), the same numbers; any
        # other object with a point at each parameter, here.
        native = curve._sprout_native() if isinstance(curve, NurbsCurve2D) else None
        if native is not None:
            self._first, self._last, self._values = native.quantised(n)
        elif type(curve) is Polyline2D and curve.firstKnot == 0 and curve.lastKnot == len(curve.pointList) - 1:
            self._first, self._last, self._values = _pgl_quantised_polyline(curve.pointList, n)
        else:
            a, b = curve.firstKnot, curve.lastKnot
            first, last = curve.getPointAt(a), curve.getPointAt(b)
            self._first, self._last = first[0], last[0]
            extent = self._last - self._first
            self._values = [self._value(curve, extent * i / (n - 1) + self._first, a, b, first, last) for i in range(n)]
        self.clamped = clamped

    @classmethod
    def _of(cls, state, clamped=True):
        """The function of `state` (first x, last x, values), as the C++ curves give it."""
        f = cls.__new__(cls)
        f._first, f._last, f._values = state
        f.clamped = clamped
        return f

    @staticmethod
    def _value(curve, x, low, high, first, last):
        if x == first[0]:
            return first[1]
        if x == last[0]:
            return last[1]
        for _ in range(200):  # PlantGL loops until it is within 1e-5 (a curve not monotonous in x never ends there)
            check = (low + high) / 2.0
            p = curve.getPointAt(check)
            if p[0] > x:
                high = check
            else:
                low = check
            if not abs(p[0] - x) > 1e-5:
                break
        return p[1]

    @property
    def firstx(self):
        return self._first

    @property
    def lastx(self):
        return self._last

    @property
    def sampling(self):
        return len(self._values)

    def __reduce__(self):  # its samples live in the C base, not in __dict__
        return (type(self)._of, ((self._first, self._last, self._values), self.clamped), dict(self.__dict__))

    def getValue(self, x):
        return self(x)

    DEFAULT_CLAMPED, DEFAULT_SAMPLING = True, 100

    def isClampedToDefault(self):
        return self.clamped is True

    def isValid(self):
        return len(self._values) > 2

    def build(self, curve, sampling=None):
        """Sampled again from `curve` (at `sampling` values, or as many as now)."""
        QuantisedFunction.__init__(self, curve, len(self._values) if sampling is None else sampling, self.clamped)
        return True

    @staticmethod
    def checkQuantisableFunction(curve):
        """Whether x grows along the curve's stride points (PlantGL's check)."""
        start, size = curve.firstKnot, curve.stride
        step = (curve.lastKnot - start) / size
        x0 = curve.getPointAt(start)[0]
        for i in range(1, size):
            start += step
            if curve.getPointAt(start)[0] <= x0:
                return False
        return True

    def isIncreasing(self, strictly=False):
        v = self._values
        return not any(v[i - 1] > v[i] or (strictly and v[i - 1] == v[i]) for i in range(1, len(v)))

    def isDecreasing(self, strictly=False):
        v = self._values
        return not any(v[i - 1] < v[i] or (strictly and v[i - 1] == v[i]) for i in range(1, len(v)))

    def isMonotonous(self, strictly=False):
        return self.isIncreasing(strictly) or self.isDecreasing(strictly)

    def findX(self, y, startingX=None):
        """The first x from `startingX` on where the function meets y, by linear interpolation
        between its samples (None where it does not)."""
        v, n, first, last = self._values, len(self._values), self._first, self._last
        start = first if startingX is None else startingX
        i0 = int((n - 1) * (start - first) / (last - first) + 1)
        for i in range(max(i0, 1), n):
            if v[i - 1] <= y < v[i] or v[i - 1] >= y > v[i]:
                return first + (i - 1 + (y - v[i - 1]) / (v[i] - v[i - 1])) * (last - first) / (n - 1)
        return None

    def inverse(self):
        """x = f^-1(y) sampled as PlantGL samples it; None where f is not strictly monotonous."""
        if not self.isMonotonous(True):
            return None
        n = len(self._values)
        firsty, lasty = self._values[0], self._values[-1]
        if firsty > lasty:
            firsty, lasty = lasty, firsty
        x, y, delta, values = self._first, firsty, (lasty - firsty) / (n - 1), []
        for _ in range(n):
            found = self.findX(y, x)
            x = -1.0 if found is None else found
            values.append(x)
            y += delta
        return QuantisedFunction._of((firsty, lasty, values))

    def _call_python(self, x):
        values, n = self._values, len(self._values)
        first, last = self._first, self._last
        x = min(max(x, first), last)  # (PlantGL clamps when not `clamped`, and errs when it is)
        index = (n - 1) * (x - first) / (last - first) if last != first else 0.0
        floor = int(_math.floor(index))
        diff = index - floor
        if floor >= n - 1 or abs(diff) < 1e-5:
            return values[min(floor, n - 1)]
        return (1 - diff) * values[floor] + diff * values[floor + 1]
