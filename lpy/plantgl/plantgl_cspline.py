# openalea.plantgl.scenegraph.cspline as Sprout provides it: PlantGL's cardinal spline
# (its scenegraph/cspline.py, read line by line): a cubic NURBS curve through given points, made
# of one Bezier arc between each two of them, the derivative at each inner point half the
# vector from the point before to the one after. The same control points, knots and stride as
# PlantGL's; the curve is Sprout's NurbsCurve / NurbsCurve2D (plantgl_curves.py).
# Installed by lpy/interpreter/interpreter.cpp before openalea.plantgl.all, which keeps it as
# `cspline` and as NurbsCurve.CSpline, as PlantGL's scenegraph package does.
from openalea.plantgl._curves import Point2Array, Point3Array, Point4Array, RealArray, NurbsCurve, NurbsCurve2D
from openalea.plantgl._vectors import norm

epsilon = 0.001


class CSpline:
    """
    A CSpline interpolate a set of points.
    """

    def __init__(self, points, is_closed=False):
        """
        Create a CSpline from a set of 2d or 3d points.
        """
        if len(points) != 0:
            self.dim = len(points[0])
            if self.dim == 2:
                self.points = Point2Array(points)
            elif self.dim == 3:
                self.points = Point3Array(points)
            elif self.dim == 4:
                self.points = Point4Array(points)
        else:
            self.dim = 3
            self.points = points
        self.is_closed = is_closed
        if is_closed:
            if norm(points[-1] - points[0]) > epsilon:
                self.points.append(points[0])

        self.nurbs = None
        self.dist = None
        self.der = None

    def __len__(self):
        return len(self.points)

    def distances(self):
        """
        Compute the distance between the input points.
        """
        n = len(self)
        self.dist = []
        for i in range(n - 1):
            p, q = self.points[i], self.points[i + 1]
            self.dist.append(norm(q - p))

    def derivatives(self):
        """
        Compute the derivatives based on the knots and the distance.
        At Pi, the derivative is:
            D_i = P_(i-1)P_i / 4||.|| + P_iP_(i+1) / 4||.||
        """
        deriv = self._derivative1

        n = len(self.points)
        d0 = (self.points[1] - self.points[0]) / (2.)
        dn = (self.points[-1] - self.points[-2]) / (2.)
        if self.is_closed:
            d0 = dn = deriv(self.points[-1], self.points[0], self.points[1], self.dist[-1], self.dist[0])

        self.der = [d0]

        for i in range(1, n - 1):
            p, q, r = self.points[i - 1], self.points[i], self.points[i + 1]
            dx1, dx2 = self.dist[i - 1], self.dist[i]
            der = self._derivative1(p, q, r, dx1, dx2)
            self.der.append(der)

        self.der.append(dn)

    def _derivative1(self, p, q, r, d0, d1):
        return (r - p) / 2.

    def _derivative2(self, p, q, r, d0, d1):
        d = d0 + d1
        d0 /= d
        d1 /= d
        der = (q - p) / (2 * d0) + (r - q) / (2 * d1)
        return der

    def bezier_cp(self, degree=3):
        """
        Compute bezier control points from the input points.
        """
        if degree == 1:
            self.ctrl_pts = self.points
        elif degree in (2, 3):  # PlantGL's two branches differ only in a: 1/2 and 1/3
            a = 1. / degree
            n = len(self)
            self.ctrl_pts = [0] * (3 * n - 2)
            for i in range(0, n - 1):
                p, q = self.points[i:i + 2]
                dp, dq = self.der[i:i + 2]
                self.ctrl_pts[i * 3] = p
                self.ctrl_pts[i * 3 + 1] = p + dp * a
                self.ctrl_pts[i * 3 + 2] = q - dq * a
            # last point
            self.ctrl_pts[-1] = self.points[-1]
            if self.is_closed:
                self.ctrl_pts[1] = self.ctrl_pts[2]
                self.ctrl_pts[-2] = self.ctrl_pts[-3]

    def bezier_kv(self, is_linear=False, degree=3):
        """
        Compute a nurbs knot vector from Bezier control points.
        bezier_kv(linear=False) -> knot_vector

        :param: is_linear indicate if the parametrization is linear or
        pseudo curvilinear abscisse.
        """
        nb_pts = len(self.ctrl_pts)
        nb_arc = len(self) - 1
        assert nb_arc == (nb_pts - 1) / degree

        p = 0.
        param = [p]

        if is_linear:
            param = list(map(float, list(range(nb_arc + 1))))
            self.kv = [param[0]] * (degree + 1)
            step = (param[-1] - param[0]) / float(nb_arc)
            for i in range(1, nb_arc):
                self.kv.extend([param[0] + i * step] * degree)
            self.kv.extend([param[-1]] * (degree + 1))
        else:
            dist = self.dist
            assert len(dist) == nb_arc
            # PlantGL rebuilds the knots after each distance; the last build is what stays.
            for d in dist:
                p += d
                param.append(p)
            self.kv = [param[0]]
            for p in param:
                for j in range(degree):
                    self.kv.append(p)
            self.kv.append(param[-1])

    def add_point(self, pt):
        if self.is_closed:
            raise Exception("Unable to add a point to a closed curve")

        self.points.append(pt)
        self.nurbs = None

    def move_point(self, i, pt):
        if i >= len(self):
            raise Exception("Index %d out of range [0,%d[" % (i, len(self)))

        self.points[i] = pt
        self.nurbs = None

    def curve(self, is_linear=False, degree=3, stride_factor=10, distances=None):
        """
        Return the equivalent PlantGL nurbs curve which interpol the points.
        :param: stride_factor is the number of points to draw an arc of the curve.
        """
        if not self.nurbs:
            if distances is None:
                self.distances()
            else:
                self.dist = distances
            self.derivatives()
            self.bezier_cp()
            self.bezier_kv(is_linear, degree)

        pts = self.points
        kv = RealArray(self.kv)

        stride = (len(pts) - 1) * stride_factor
        if self.dim == 3:
            ctrl_pts = Point4Array(self.ctrl_pts, 1)
            self.nurbs = NurbsCurve(ctrl_pts, kv, 3, stride)
        elif self.dim == 2:
            ctrl_pts = Point3Array(self.ctrl_pts, 1)
            self.nurbs = NurbsCurve2D(ctrl_pts, kv, 3, stride)
        else:
            raise Exception("Unable to build a spline curve from points of dimension %d" % (self.dim,))

        return self.nurbs


def cspline(pts, is_closed=False, is_linear=False, distances=None, degree=3):
    """
    Build a nurbs curve by interpolate (C1) the points pts.
    The resulting curve can be closed.
    """
    spline = CSpline(pts, is_closed)
    return spline.curve(is_linear, degree=degree, distances=distances)


class NurbsSwung:
    """PlantGL's NurbsSwung, as its cspline.py defines it: its interpolator uses Vector3 and
    Vector4, which that module never imports, so making one raises NameError there; the same
    here."""

    def __init__(self, profileList, angleList, degree=3, ccw=True, slices=30, stride=30):
        assert degree in [1, 3]
        self.profileList = profileList
        self.angleList = angleList
        self.degree = degree
        self.ccw = ccw
        self.slices = slices
        self.stride = stride
        self.build_interpolator()

    def build_interpolator(self):
        raise NameError("name '%s' is not defined" % ('Vector3' if self.degree > 1 else 'Vector4'))
