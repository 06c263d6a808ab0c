# openalea.plantgl._vectors, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): PlantGL's vectors, Matrix3 and the functions on vectors. Its own file
# because every other part builds on it.
#
# Index of this file:
#   [SECTION] Vectors
#   [SECTION] PlantGL's members of each size of vector
#   [SECTION] Matrix3 and the functions on vectors
import math as _math

# Every change of a vector in place counts here: a curve's evaluator in C++ is kept while the
# count and the curve's lists are the same (plantgl_curves.py's _native).
_changes = [0]


# [SECTION] Vectors
def _coordinate(i, n):
    """The property of coordinate i of a vector of n: read (0 past its size) and set in place."""
    return property((lambda s: s._v[i]) if i < n else (lambda s: 0.0), lambda s, value: s.__setitem__(i, value))


class _Vec:
    """PlantGL's vectors: mutable (v.z *= -1), indexable, with +, -, * (by a number, or a dot
    product), / and ^ (cross)."""
    _n = 3
    __slots__ = ('_v',)

    def __init__(self, *args):
        if len(args) == 1 and hasattr(args[0], '__len__'):
            args = tuple(args[0])
        elif len(args) == 2 and hasattr(args[0], '__len__'):  # Vector4(Vector3(...), w), Vector3(Vector2(...), z)
            args = tuple(args[0]) + (args[1],)
        v = [float(a) for a in args[:self._n]]
        self._v = v + [0.0] * (self._n - len(v))

    # The arithmetic below is written out for each size: models make vectors by the hundred
    # thousand a step (the same sums, in the same order, as a loop would make).

    def __len__(self):
        return self._n

    def __getitem__(self, i):
        return self._v[i]

    def __setitem__(self, i, value):
        self._v[i] = float(value)
        _changes[0] += 1

    @classmethod
    def _of(cls, values):
        """A vector of `values`, a list of cls._n floats taken as it is (the C++ curves' points)."""
        v = object.__new__(cls)
        v._v = values
        return v

    def __iter__(self):
        return iter(self._v)

    def __eq__(self, o):
        try:
            return len(o) == self._n and all(a == b for a, b in zip(self._v, o))
        except TypeError:
            return False

    def __hash__(self):
        return hash(tuple(self._v))

    x, y, z, w = (_coordinate(i, 4) for i in range(4))

    def __add__(self, o):
        v, w = self._v, (o._v if isinstance(o, _Vec) else o)
        if len(v) == 3 and len(w) == 3:
            return self._of([v[0] + w[0], v[1] + w[1], v[2] + w[2]])
        if len(v) == 2 and len(w) == 2:
            return self._of([v[0] + w[0], v[1] + w[1]])
        return type(self)(*[a + b for a, b in zip(v, w)])

    __radd__ = __add__

    def __sub__(self, o):
        v, w = self._v, (o._v if isinstance(o, _Vec) else o)
        if len(v) == 3 and len(w) == 3:
            return self._of([v[0] - w[0], v[1] - w[1], v[2] - w[2]])
        if len(v) == 2 and len(w) == 2:
            return self._of([v[0] - w[0], v[1] - w[1]])
        return type(self)(*[a - b for a, b in zip(v, w)])

    def __rsub__(self, o):
        return type(self)(*[b - a for a, b in zip(self._v, o)])

    def __neg__(self):
        return self._of([-a for a in self._v])

    def __mul__(self, k):
        v = self._v
        if isinstance(k, (int, float)):
            if len(v) == 3:
                return self._of([v[0] * k, v[1] * k, v[2] * k])
            if len(v) == 2:
                return self._of([v[0] * k, v[1] * k])
            return type(self)(*[a * k for a in v])
        w = k._v if isinstance(k, _Vec) else k
        if len(v) == 3 and len(w) == 3:  # dot product, as PlantGL's Vector * Vector
            return 0.0 + v[0] * w[0] + v[1] * w[1] + v[2] * w[2]  # from 0 as sum(): -0.0 terms give 0.0
        if len(v) == 2 and len(w) == 2:
            return 0.0 + v[0] * w[0] + v[1] * w[1]
        return sum(a * b for a, b in zip(v, w))

    __rmul__ = __mul__

    def __truediv__(self, k):
        v = self._v
        if len(v) == 3:
            return self._of([v[0] / k, v[1] / k, v[2] / k])
        if len(v) == 2:
            return self._of([v[0] / k, v[1] / k])
        return type(self)(*[a / k for a in v])

    def __xor__(self, o):  # cross product
        return cross(self, o)

    def __abs__(self):
        v = self._v
        if len(v) == 3:
            return _math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
        return _math.sqrt(sum(a * a for a in v))

    def norm(self):
        return abs(self)

    def normSquared(self):
        return sum(a * a for a in self._v)

    def normed(self):
        n = abs(self)
        return self / n if n > 0 else self._of(list(self._v))

    def anOrthogonalVector(self):
        """PlantGL's: an axis where a coordinate is 0 (x first), else (-y, x, 0) / |v|."""
        x, y, z = (list(self._v) + [0.0, 0.0])[:3]
        if abs(x) < 1e-5:
            return Vector3(1, 0, 0)
        if abs(y) < 1e-5:
            return Vector3(0, 1, 0)
        if abs(z) < 1e-5:
            return Vector3(0, 0, 1)
        n = _math.sqrt(x * x + y * y + z * z)
        return Vector3(0, 0, 0) if n < 1e-10 else Vector3(-y / n, x / n, 0)

    def normalize(self):
        n = abs(self)
        if n > 0:
            self._v = [a / n for a in self._v]
            _changes[0] += 1
        return n

    def cwiseProduct(self, o):
        return type(self)(*[a * b for a, b in zip(self._v, o)])

    def _abs_coord(self, better):
        """PlantGL's getMaxAbsCoord / getMinAbsCoord: the index kept along x, y, z, w."""
        v = [abs(a) for a in self._v]
        k = 0 if better(v[0], v[1]) else 1
        for j in range(2, len(v)):
            k = k if better(v[k], v[j]) else j
        return k

    def getMaxAbsCoord(self):
        return self._abs_coord(lambda a, b: a > b)

    def getMinAbsCoord(self):
        return self._abs_coord(lambda a, b: a < b)

    def isNormalized(self):
        return abs(self.normSquared() - 1) < 1e-5

    def isOrthogonalTo(self, o):
        return abs(sum(a * b for a, b in zip(self._v, o))) < 1e-5

    def isValid(self):
        return all(_math.isfinite(a) for a in self._v)

    def __repr__(self):  # as PlantGL writes it: Vector3(0.123457,2,1e-07)
        return "%s(%s)" % (type(self).__name__, ",".join("%g" % a for a in self._v))

    def __reduce__(self):
        return (type(self), tuple(self._v))


class Vector2(_Vec):
    _n = 2
    x, y, z, w = (_coordinate(i, 2) for i in range(4))

    def __init__(self, *args):
        if len(args) == 2:
            self._v = [float(args[0]), float(args[1])]
            return
        _Vec.__init__(self, *args)


class Vector3(_Vec):
    _n = 3
    x, y, z, w = (_coordinate(i, 3) for i in range(4))

    class Cylindrical:
        def __init__(self, radius, theta, z):
            self.radius, self.theta, self.z = radius, theta, z

    class Spherical:
        def __init__(self, radius, theta, phi):
            self.radius, self.theta, self.phi = radius, theta, phi

    def __init__(self, *args):
        if len(args) == 3:
            self._v = [float(args[0]), float(args[1]), float(args[2])]
            return
        if len(args) == 1 and isinstance(args[0], Vector3.Cylindrical):
            c = args[0]
            args = (c.radius * _math.cos(c.theta), c.radius * _math.sin(c.theta), c.z)
        elif len(args) == 1 and isinstance(args[0], Vector3.Spherical):
            s = args[0]
            args = (s.radius * _math.cos(s.theta) * _math.sin(s.phi), s.radius * _math.sin(s.theta) * _math.sin(s.phi),
                    s.radius * _math.cos(s.phi))
        _Vec.__init__(self, *args)


class Vector4(_Vec):
    _n = 4

    def project(self):
        x, y, z, w = self._v
        return Vector3(x / w, y / w, z / w)

    def wtoxyz(self):
        x, y, z, w = self._v
        return Vector4(x * w, y * w, z * w, w)


Vector2.OX, Vector2.OY, Vector2.ORIGIN = Vector2(1, 0), Vector2(0, 1), Vector2(0, 0)
Vector3.OX, Vector3.OY, Vector3.OZ, Vector3.ORIGIN = Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1), Vector3(0, 0, 0)
Vector4.OX, Vector4.OY, Vector4.OZ, Vector4.OW = Vector4(1, 0, 0, 0), Vector4(0, 1, 0, 0), Vector4(0, 0, 1, 0), Vector4(0, 0, 0, 1)
Vector4.ORIGIN = Vector4(0, 0, 0, 0)


# [SECTION] PlantGL's members of each size of vector


def _v3_project(self):
    x, y, z = self._v
    return Vector2(x / z, y / z)


def _v3_reflect(self, v):
    """PlantGL's Vector3::reflect as it is written: v - 2 (self.normed() . v) v."""
    v = Vector3(v)
    return v - v * (2. * (self.normed() * v))


def _v3_refract(self, v, eta):
    n, v = self.normed(), Vector3(v)
    d = n * v
    k = 1.0 - eta * eta * (1.0 - d * d)
    return Vector3(0.0, 0.0, 0.0) if k < 0.0 else v * eta - n * (eta * d + _math.sqrt(k))


def _v3_anisotropic_norm(self, factors):
    x, y, z = self._v
    f = tuple(factors)
    return _math.sqrt(f[0] * x * x + f[1] * y * y + f[2] * z * z)


def _v3_radial_anisotropic_norm(self, t, alpha, beta):
    t = Vector3(t)
    a = self * t
    b = self - t * a
    return _math.sqrt(a * a * alpha + beta * b.normSquared())


Vector3.project, Vector3.reflect, Vector3.refract = _v3_project, _v3_reflect, _v3_refract
Vector3.anisotropicNorm, Vector3.radialAnisotropicNorm = _v3_anisotropic_norm, _v3_radial_anisotropic_norm


class _Polar:
    """Vector2.Polar(radius, theta): Vector2(Vector2.Polar(r, a)) is (r cos a, r sin a)."""

    def __init__(self, radius, theta):
        self.radius, self.theta = float(radius), float(theta)


Vector2.Polar = _Polar
_vector2_init = Vector2.__init__


def _vector2_init_polar(self, *args):
    if len(args) == 1 and isinstance(args[0], _Polar):
        p = args[0]
        args = (p.radius * _math.cos(p.theta), p.radius * _math.sin(p.theta))
    _vector2_init(self, *args)


Vector2.__init__ = _vector2_init_polar


# [SECTION] Matrix3 and the functions on vectors
class Matrix3:
    """A 3x3 matrix (kept as rows), with PlantGL's rotations. Matrix3(9 values row by row) or
    Matrix3(v0, v1, v2): three vectors as its columns, as PlantGL's constructor takes them."""

    def __init__(self, *args):
        if len(args) == 9:
            rows = (args[0:3], args[3:6], args[6:9])
        elif len(args) == 3:
            rows = [[float(tuple(v)[i]) for v in args] for i in range(3)]
        elif not args:
            rows = [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]
        else:
            raise TypeError("Matrix3(): 9 values or 3 column vectors")
        self.rows = [list(map(float, r)) for r in rows]

    @classmethod
    def _of_rows(cls, rows):
        m = cls.__new__(cls)
        m.rows = [list(map(float, r)) for r in rows]
        return m

    @staticmethod
    def axisRotation(axis, angle):
        # Vector3(axis).normed(), written out for a vector (the same operations).
        v = axis._v if isinstance(axis, _Vec) and len(axis._v) == 3 else Vector3(axis)._v
        n = _math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
        x, y, z = (v[0] / n, v[1] / n, v[2] / n) if n > 0 else v
        c, s, t = _math.cos(angle), _math.sin(angle), 1 - _math.cos(angle)
        m = Matrix3.__new__(Matrix3)  # its rows are floats already
        m.rows = [[float(t * x * x + c), float(t * x * y - s * z), float(t * x * z + s * y)],
                  [float(t * x * y + s * z), float(t * y * y + c), float(t * y * z - s * x)],
                  [float(t * x * z - s * y), float(t * y * z + s * x), float(t * z * z + c)]]
        return m

    @staticmethod
    def IDENTITY():
        return Matrix3()

    def __mul__(self, o):
        if isinstance(o, Matrix3):
            return Matrix3._of_rows([[sum(self.rows[i][k] * o.rows[k][j] for k in range(3)) for j in range(3)] for i in range(3)])
        if isinstance(o, _Vec) and len(o._v) == 3:  # sum() of each row's products, written out
            (a, b, c), (d, e, f), (g, h, i) = self.rows
            x, y, z = o._v
            return Vector3(0 + a * x + b * y + c * z, 0 + d * x + e * y + f * z, 0 + g * x + h * y + i * z)
        return Vector3(*[sum(self.rows[i][k] * o[k] for k in range(3)) for i in range(3)])

    def transpose(self):
        return Matrix3._of_rows([[self.rows[j][i] for j in range(3)] for i in range(3)])

    def det(self):
        (a, b, c), (d, e, f), (g, h, i) = self.rows
        return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)

    def inverse(self):
        """The inverse (the adjugate over the determinant, as PlantGL's Matrix3::inverse)."""
        (a, b, c), (d, e, f), (g, h, i) = self.rows
        adj = [[e * i - f * h, c * h - b * i, b * f - c * e],
               [f * g - d * i, a * i - c * g, c * d - a * f],
               [d * h - e * g, b * g - a * h, a * e - b * d]]
        det = a * adj[0][0] + b * adj[1][0] + c * adj[2][0]
        if det == 0:
            raise ValueError("Matrix3.inverse: the matrix is singular")
        return Matrix3._of_rows([[x / det for x in r] for r in adj])

    def __repr__(self):  # as PlantGL writes it, a row a line
        return "Matrix3( %s )" % " ,\n         ".join(", ".join("%g" % x for x in r) for r in self.rows)

    __str__ = __repr__

    def data(self):
        return [x for r in self.rows for x in r]

    def trace(self):
        return self.rows[0][0] + self.rows[1][1] + self.rows[2][2]

    def getDiagonal(self):
        return Vector3(self.rows[0][0], self.rows[1][1], self.rows[2][2])

    def adjoint(self):
        (a, b, c), (d, e, f), (g, h, i) = self.rows
        return Matrix3._of_rows([[e * i - f * h, c * h - b * i, b * f - c * e],
                                 [f * g - d * i, a * i - c * g, c * d - a * f],
                                 [d * h - e * g, b * g - a * h, a * e - b * d]])

    def isOrthogonal(self):
        c = [self.getColumn(j) for j in range(3)]
        return c[0].isOrthogonalTo(c[1]) and c[0].isOrthogonalTo(c[2]) and c[1].isOrthogonalTo(c[2])

    def isSingular(self):
        return abs(self.det()) < 1e-10

    def isValid(self):
        return all(_math.isfinite(x) for r in self.rows for x in r)

    @staticmethod
    def scaling(s):
        x, y, z = (s, s, s) if isinstance(s, (int, float)) else tuple(s)[:3]
        return Matrix3(x, 0, 0, 0, y, 0, 0, 0, z)

    @staticmethod
    def eulerRotationZYX(angle):
        ax, ay, az = tuple(angle)[:3]
        cz, sz, cy, sy, cx, sx = _math.cos(az), _math.sin(az), _math.cos(ay), _math.sin(ay), _math.cos(ax), _math.sin(ax)
        cxsy, sxsy = cx * sy, sx * sy
        return Matrix3(cx * cy, cxsy * sz - sx * cz, cxsy * cz + sx * sz, sx * cy, cx * cz + sxsy * sz, sxsy * cz - cx * sz,
                       -sy, cy * sz, cy * cz)

    @staticmethod
    def eulerRotationXYZ(angle):
        ax, ay, az = tuple(angle)[:3]
        cx, sx, cy, sy, cz, sz = _math.cos(ax), _math.sin(ax), _math.cos(ay), _math.sin(ay), _math.cos(az), _math.sin(az)
        cxsz, sxsy = cx * sz, sx * sy
        return Matrix3(cy * cz, -cxsz * cy + sxsy, sx * cy * sz + cx * sy, sz, cz * cx, -cz * sx,
                       -sy * cz, cxsz * sy + sx * cy, -sxsy * sz + cx * cy)

    def eulerAnglesZYX(self):
        m = self.data()
        b = _math.asin(-m[6])
        if b < _math.pi / 2:
            if b > -_math.pi / 2:
                a, c = _math.atan2(m[3], m[0]), _math.atan2(m[7], m[8])
            else:
                a, c = _math.atan2(-m[1], m[2]), 0.0
        else:
            a, c = -_math.atan2(-m[1], m[2]), 0.0
        return Vector3(a, b, c)

    def eulerAnglesXYZ(self):
        m = self.data()
        c = _math.asin(m[3])
        if c < _math.pi / 2:
            if c > -_math.pi / 2:
                b, a = _math.atan2(-m[6], m[0]), _math.atan2(-m[5], m[4])
            else:
                b, a = _math.atan2(m[2], m[1]), 0.0
        else:
            b, a = _math.atan2(m[2], -m[1]), 0.0
        return Vector3(a, b, c)

    def getColumn(self, j):
        return Vector3(*[self.rows[i][j] for i in range(3)])

    def getRow(self, i):
        return Vector3(*self.rows[i])


def cross(a, b):
    if len(a) == 2 and len(b) == 2:  # PlantGL: the z of the 3D cross product
        return a[0] * b[1] - a[1] * b[0]
    return Vector3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    if isinstance(a, _Vec) and isinstance(b, _Vec):
        return a * b
    return sum(x * y for x, y in zip(a, b))


def norm(v):
    if isinstance(v, _Vec):
        return abs(v)
    return _math.sqrt(sum(a * a for a in v))


def angle(a, b, axis=None):
    """The angle from a to b, as PlantGL's angle() gives it: atan2 of the cross and dot
    products; signed in 2D (the cross product's z), and in 3D about `axis` when one is given."""
    if len(a) == 2 and len(b) == 2:
        return _math.atan2(cross(a, b), dot(a, b))
    c = cross(a, b)
    sinus = norm(c)
    if axis is not None and dot(c, axis) < 0:
        sinus = -sinus
    return _math.atan2(sinus, dot(a, b))


def direction(v):
    n = norm(v)
    return type(v)(*[a / n for a in v]) if n > 0 else v
