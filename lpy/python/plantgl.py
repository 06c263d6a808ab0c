# The part of PlantGL (openalea.plantgl.all) that L-Py model files use, as Sprout provides
# it: vectors and colours, materials, the 2D curves and the functions made from them
# (evaluated as PlantGL evaluates them), and a Viewer whose calls do nothing.
import math as _math

try:
    from openalea.lpy import _warn
except ImportError:  # imported on its own
    def _warn(message):
        pass


class _Vec:
    """PlantGL's vectors: mutable (v.z *= -1), indexable, with +, -, * (by a number, or a dot
    product), / and ^ (cross)."""
    _n = 3
    __slots__ = ('_v',)

    def __init__(self, *args):
        if len(args) == 1 and hasattr(args[0], '__len__'):
            args = tuple(args[0])
        v = [float(a) for a in args[:self._n]]
        self._v = v + [0.0] * (self._n - len(v))

    def __len__(self):
        return self._n

    def __getitem__(self, i):
        return self._v[i]

    def __setitem__(self, i, value):
        self._v[i] = float(value)

    def __iter__(self):
        return iter(self._v)

    def __eq__(self, o):
        try:
            return len(o) == self._n and all(a == b for a, b in zip(self._v, o))
        except TypeError:
            return False

    def __hash__(self):
        return hash(tuple(self._v))

    def _get(i):
        return property(lambda s: s._v[i] if i < s._n else 0.0, lambda s, value: s.__setitem__(i, value))

    x, y, z, w = _get(0), _get(1), _get(2), _get(3)

    def __add__(self, o):
        return type(self)(*[a + b for a, b in zip(self._v, o)])

    __radd__ = __add__

    def __sub__(self, o):
        return type(self)(*[a - b for a, b in zip(self._v, o)])

    def __rsub__(self, o):
        return type(self)(*[b - a for a, b in zip(self._v, o)])

    def __neg__(self):
        return type(self)(*[-a for a in self._v])

    def __mul__(self, k):
        if isinstance(k, (int, float)):
            return type(self)(*[a * k for a in self._v])
        return sum(a * b for a, b in zip(self._v, k))  # dot product, as PlantGL's Vector * Vector

    __rmul__ = __mul__

    def __truediv__(self, k):
        return type(self)(*[a / k for a in self._v])

    def __xor__(self, o):  # cross product
        return cross(self, o)

    def __abs__(self):
        return _math.sqrt(sum(a * a for a in self._v))

    def norm(self):
        return abs(self)

    def normSquared(self):
        return sum(a * a for a in self._v)

    def normed(self):
        n = abs(self)
        return self / n if n > 0 else type(self)(*self._v)

    def anOrthogonalVector(self):
        x, y, z = (list(self._v) + [0.0, 0.0])[:3]
        v = Vector3(-y, x, 0) if abs(x) > 1e-9 or abs(y) > 1e-9 else Vector3(0, -z, y)
        return v.normed()

    def normalize(self):
        n = abs(self)
        if n > 0:
            self._v = [a / n for a in self._v]
        return n

    def __repr__(self):
        return "%s(%s)" % (type(self).__name__, ", ".join("%g" % a for a in self._v))

    def __reduce__(self):
        return (type(self), tuple(self._v))


class Vector2(_Vec):
    _n = 2


class Vector3(_Vec):
    _n = 3

    class Cylindrical:
        def __init__(self, radius, theta, z):
            self.radius, self.theta, self.z = radius, theta, z

    class Spherical:
        def __init__(self, radius, theta, phi):
            self.radius, self.theta, self.phi = radius, theta, phi

    def __init__(self, *args):
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


Vector2.OX, Vector2.OY, Vector2.ORIGIN = Vector2(1, 0), Vector2(0, 1), Vector2(0, 0)
Vector3.OX, Vector3.OY, Vector3.OZ, Vector3.ORIGIN = Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1), Vector3(0, 0, 0)
Vector4.OX, Vector4.OY, Vector4.OZ, Vector4.OW = Vector4(1, 0, 0, 0), Vector4(0, 1, 0, 0), Vector4(0, 0, 1, 0), Vector4(0, 0, 0, 1)


class Matrix3:
    """A 3x3 matrix (rows), with PlantGL's rotations."""

    def __init__(self, *rows):
        if len(rows) == 9:
            rows = (rows[0:3], rows[3:6], rows[6:9])
        self.rows = [list(map(float, r)) for r in rows] if rows else [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]

    @staticmethod
    def axisRotation(axis, angle):
        x, y, z = Vector3(axis).normed()
        c, s, t = _math.cos(angle), _math.sin(angle), 1 - _math.cos(angle)
        return Matrix3([t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                       [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                       [t * x * z - s * y, t * y * z + s * x, t * z * z + c])

    @staticmethod
    def IDENTITY():
        return Matrix3()

    def __mul__(self, o):
        if isinstance(o, Matrix3):
            return Matrix3(*[[sum(self.rows[i][k] * o.rows[k][j] for k in range(3)) for j in range(3)] for i in range(3)])
        return Vector3(*[sum(self.rows[i][k] * o[k] for k in range(3)) for i in range(3)])

    def transpose(self):
        return Matrix3(*[[self.rows[j][i] for j in range(3)] for i in range(3)])

    def getColumn(self, j):
        return Vector3(*[self.rows[i][j] for i in range(3)])

    def getRow(self, i):
        return Vector3(*self.rows[i])


def cross(a, b):
    if len(a) == 2 and len(b) == 2:  # PlantGL: the z of the 3D cross product
        return a[0] * b[1] - a[1] * b[0]
    return Vector3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(v):
    return _math.sqrt(sum(a * a for a in v))


def angle(a, b, axis=None):
    """The angle from a to b; signed about `axis` when one is given (PlantGL)."""
    c = dot(a, b) / (norm(a) * norm(b) or 1.0)
    result = _math.acos(max(-1.0, min(1.0, c)))
    if axis is not None and dot(cross(a, b), axis) < 0:
        result = -result
    return result


def direction(v):
    n = norm(v)
    return type(v)(*[a / n for a in v]) if n > 0 else v


class Color3(tuple):
    def __new__(cls, r=0, g=0, b=0):
        if isinstance(r, (tuple, list)):
            r, g, b = r[:3]
        return tuple.__new__(cls, (int(r), int(g), int(b)))

    red = property(lambda s: s[0])
    green = property(lambda s: s[1])
    blue = property(lambda s: s[2])


class Color4(tuple):
    def __new__(cls, r=0, g=0, b=0, a=0):
        if isinstance(r, (tuple, list)):
            r, g, b, a = (list(r) + [0])[:4]
        return tuple.__new__(cls, (int(r), int(g), int(b), int(a)))


class Material:
    """PlantGL's Material: the colour a surface shows is ambient x diffuse."""

    def __init__(self, *args, **kwargs):
        names = ['ambient', 'diffuse', 'specular', 'emission', 'shininess', 'transparency']
        args = list(args)
        self.name = args.pop(0) if args and isinstance(args[0], str) else kwargs.pop('name', '')
        values = dict(ambient=Color3(80, 80, 80), diffuse=2.0, specular=Color3(0, 0, 0), emission=Color3(0, 0, 0),
                      shininess=0.2, transparency=0.0)
        for n, v in zip(names, args):
            values[n] = v
        values.update(kwargs)
        self.ambient = Color3(values['ambient'])
        self.diffuse = float(values['diffuse'])
        self.specular = Color3(values['specular'])
        self.emission = Color3(values['emission'])
        self.shininess = float(values['shininess'])
        self.transparency = float(values['transparency'])

    def diffuseColor(self):
        return Color3(*[min(255, int(c * self.diffuse)) for c in self.ambient])


class _Points(list):
    def __init__(self, *args):
        if len(args) == 1 and not isinstance(args[0], (int, float)):
            list.__init__(self, [tuple(p) for p in args[0]])
        else:
            list.__init__(self, args)


class Point2Array(_Points):
    pass


class Point3Array(_Points):
    pass


class Point4Array(_Points):
    pass


class Point4Matrix(list):
    def __init__(self, rows=()):
        list.__init__(self, [[tuple(p) for p in row] for row in rows])


def _uniform_clamped_knots(n, degree):
    # n control points: degree+1 zeros, the inner knots evenly spaced, degree+1 ones.
    inner = n - degree - 1
    return [0.0] * (degree + 1) + [(i + 1) / (inner + 1) for i in range(inner)] + [1.0] * (degree + 1)


class NurbsCurve2D:
    """A 2D NURBS curve; control points are (x, y, weight)."""
    _dim = 2

    def __init__(self, ctrlPointList, degree=3, knotList=None, stride=30, width=1, **kwargs):
        if isinstance(degree, (list, tuple)):  # the form (points, knots, degree, ...)
            knotList, degree = degree, knotList if isinstance(knotList, int) else 3
        pts = [tuple(p) for p in ctrlPointList]
        d = self._dim
        self.ctrlPointList = [[Vector3, Vector4][d - 2](*(tuple(p[:d]) + ((p[d] if len(p) > d else 1.0),))) for p in pts]
        self.degree = max(1, min(int(degree), len(pts) - 1))
        self.knotList = list(knotList) if knotList else _uniform_clamped_knots(len(pts), self.degree)
        self.stride = int(kwargs.get('stride', stride))
        self.width = width
        self.name = ''

    @property
    def firstKnot(self):
        return self.knotList[self.degree]

    @property
    def lastKnot(self):
        return self.knotList[len(self.ctrlPointList)]

    def getPointAt(self, u):
        k, p, pts, dim = self.knotList, self.degree, self.ctrlPointList, self._dim
        n = len(pts) - 1
        u = max(self.firstKnot, min(self.lastKnot, u))
        span = p
        while span < n and u >= k[span + 1]:
            span += 1
        d = [[pts[j][c] * pts[j][dim] for c in range(dim)] + [pts[j][dim]] for j in range(span - p, span + 1)]
        for r in range(1, p + 1):  # de Boor, on homogeneous points
            for j in range(p, r - 1, -1):
                i = j + span - p
                den = k[i + p - r + 1] - k[i]
                a = (u - k[i]) / den if den else 0.0
                d[j] = [(1 - a) * d[j - 1][c] + a * d[j][c] for c in range(dim + 1)]
        w = d[p][dim] or 1.0
        return [Vector2, Vector3][dim - 2](*[d[p][c] / w for c in range(dim)])

    def getTangentAt(self, u):
        a, b = self.firstKnot, self.lastKnot
        h = (b - a) * 1e-4
        p0, p1 = self.getPointAt(max(a, u - h)), self.getPointAt(min(b, u + h))
        return (p1 - p0).normed()

    def getNormalAt(self, u):
        t = self.getTangentAt(u)
        return Vector2(-t[1], t[0]) if self._dim == 2 else t

    def getLength(self, begin=None, end=None):
        pts = self.points(200)
        return sum(abs(pts[i + 1] - pts[i]) for i in range(len(pts) - 1))

    def _arc_lengths(self):
        """200 parameters u along the curve and the fraction of its length at each."""
        a, b = self.firstKnot, self.lastKnot
        us = [a + (b - a) * i / 199 for i in range(200)]
        pts = [self.getPointAt(u) for u in us]
        lengths = [0.0]
        for i in range(199):
            lengths.append(lengths[-1] + abs(pts[i + 1] - pts[i]))
        total = lengths[-1] or 1.0
        return us, [l / total for l in lengths]

    def getArcLengthToUMapping(self):
        """A function from the fraction of the curve's length to the parameter u."""
        us, fractions = self._arc_lengths()
        return QuantisedFunction(Polyline2D(list(zip(fractions, us))), 200)

    def getUToArcLengthMapping(self):
        us, fractions = self._arc_lengths()
        return QuantisedFunction(Polyline2D(list(zip(us, fractions))), 200)

    def deepcopy(self):
        import copy
        return copy.deepcopy(self)

    def points(self, samples=None):
        n = samples or max(2, self.stride)
        a, b = self.firstKnot, self.lastKnot
        return [self.getPointAt(a + (b - a) * i / (n - 1)) for i in range(n)]


    def apply(self, action):
        """PlantGL's actions on a curve: a Discretizer gets its polyline (the curve's stride)."""
        return action.process(self)


class NurbsCurve(NurbsCurve2D):
    """A 3D NURBS curve; control points are (x, y, z, weight)."""
    _dim = 3


class BezierCurve2D(NurbsCurve2D):
    def __init__(self, ctrlPointList, stride=30, width=1, **kwargs):
        n = len(list(ctrlPointList))
        NurbsCurve2D.__init__(self, ctrlPointList, n - 1, [0.0] * n + [1.0] * n, stride, width)


class Polyline2D:
    def __init__(self, pointList, width=1, **kwargs):
        self.pointList = [Vector2(p[0], p[1]) for p in pointList]
        self.width = width
        self.name = ''
        self.firstKnot, self.lastKnot, self.stride = 0.0, 1.0, len(self.pointList)

    @staticmethod
    def Circle(radius=0.5, slices=8):
        return Polyline2D([(radius * _math.cos(2 * _math.pi * i / slices), radius * _math.sin(2 * _math.pi * i / slices))
                           for i in range(slices + 1)])

    def getPointAt(self, u):
        pts = self.pointList
        if len(pts) == 1:
            return pts[0]
        t = max(0.0, min(1.0, u)) * (len(pts) - 1)
        i = min(int(t), len(pts) - 2)
        f = t - i
        return Vector2(pts[i][0] + (pts[i + 1][0] - pts[i][0]) * f, pts[i][1] + (pts[i + 1][1] - pts[i][1]) * f)

    def points(self, samples=None):
        return list(self.pointList)

    def apply(self, action):
        return action.process(self)


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


class QuantisedFunction:
    """y = f(x) sampled from a 2D curve over its x range (PlantGL's QuantisedFunction)."""

    def __init__(self, curve, sampling=100, clamped=True):
        if isinstance(curve, (list, tuple)):
            curve = Polyline2D(curve)
        n = max(2, int(sampling))
        a, b = curve.firstKnot, curve.lastKnot
        pts = sorted((tuple(curve.getPointAt(a + (b - a) * i / (n - 1))) for i in range(n)))
        self._x = [p[0] for p in pts]
        self._y = [p[1] for p in pts]
        self.clamped = clamped

    @property
    def firstx(self):
        return self._x[0]

    @property
    def lastx(self):
        return self._x[-1]

    def __call__(self, x):
        xs, ys = self._x, self._y
        if x <= xs[0]:
            return ys[0]
        if x >= xs[-1]:
            return ys[-1]
        lo, hi = 0, len(xs) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if xs[mid] <= x:
                lo = mid
            else:
                hi = mid
        dx = xs[hi] - xs[lo]
        f = (x - xs[lo]) / dx if dx else 0.0
        return ys[lo] + (ys[hi] - ys[lo]) * f

    getValue = __call__


class NurbsPatch:
    """A NURBS surface; control points (x, y, z, w) in rows along u."""

    def __init__(self, ctrlPointMatrix, udegree=3, vdegree=3, *args, **kwargs):
        if isinstance(udegree, (list, tuple)):  # the form (ctrl, uknots, vknots, udegree, vdegree)
            self.uknotList, self.vknotList = list(udegree), list(vdegree)
            udegree, vdegree = (list(args) + [3, 3])[:2]
        else:
            self.uknotList = kwargs.get('uknotList')
            self.vknotList = kwargs.get('vknotList')
        self.ctrlPointMatrix = [[tuple(p) for p in row] for row in ctrlPointMatrix]
        self.udegree, self.vdegree = int(udegree), int(vdegree)
        self.ustride, self.vstride = kwargs.get('ustride', 30), kwargs.get('vstride', 30)
        self.name = ''

    def getPointAt(self, u, v):
        rows = [NurbsCurve([p for p in row], self.vdegree, self.vknotList) for row in self.ctrlPointMatrix]
        column = []
        for c in rows:
            q = c.getPointAt(c.firstKnot + (c.lastKnot - c.firstKnot) * v)
            column.append((q[0], q[1], q[2], 1.0))
        cu = NurbsCurve(column, self.udegree, self.uknotList)
        return cu.getPointAt(cu.firstKnot + (cu.lastKnot - cu.firstKnot) * u)

    def getUTangentAt(self, u, v):
        h = 1e-4
        return (self.getPointAt(min(1.0, u + h), v) - self.getPointAt(max(0.0, u - h), v)).normed()

    def getVTangentAt(self, u, v):
        h = 1e-4
        return (self.getPointAt(u, min(1.0, v + h)) - self.getPointAt(u, max(0.0, v - h))).normed()

    def getNormalAt(self, u, v):
        return cross(self.getUTangentAt(u, v), self.getVTangentAt(u, v)).normed()

    def getIsoUSectionAt(self, u):
        return NurbsCurve([tuple(self.getPointAt(u, i / 20.0)) + (1.0,) for i in range(21)], 1)

    def getIsoVSectionAt(self, v):
        return NurbsCurve([tuple(self.getPointAt(i / 20.0, v)) + (1.0,) for i in range(21)], 1)


class _Geometry:
    """PlantGL scene objects a model may build for @g: kept (with PlantGL's field names), not
    drawn by Sprout (a warning names the module that carries them)."""
    _fields = ()

    def __init__(self, *args, **kwargs):
        self.args, self.kwargs = args, kwargs
        self.name = ''
        for field, value in zip(self._fields, args):
            setattr(self, field, value)
        for field, value in kwargs.items():
            setattr(self, field, value)


_geometry_fields = {
    'Sphere': ('radius', 'slices', 'stacks'), 'Box': ('size',), 'Cylinder': ('radius', 'height', 'solid', 'slices'),
    'Cone': ('radius', 'height', 'solid', 'slices'), 'Frustum': ('radius', 'height', 'taper', 'solid', 'slices'),
    'Disc': ('radius', 'slices'), 'Paraboloid': ('radius', 'height', 'shape', 'solid', 'slices', 'stacks'),
    'Scaled': ('scale', 'geometry'), 'Translated': ('translation', 'geometry'),
    'AxisRotated': ('axis', 'angle', 'geometry'), 'EulerRotated': ('azimuth', 'elevation', 'roll', 'geometry'),
    'Oriented': ('primary', 'secondary', 'geometry'), 'Shape': ('geometry', 'appearance', 'id'),
    'QuadSet': ('pointList', 'indexList'), 'TriangleSet': ('pointList', 'indexList'), 'Polyline': ('pointList',),
    'BezierPatch': ('ctrlPointMatrix',), 'Extrusion': ('axis', 'crossSection', 'scale'), 'Revolution': ('profile',),
    'Swung': ('profileList', 'angleList'), 'Group': ('geometryList',), 'Text': ('string', 'position'), 'Font': (),
    'ImageTexture': ('name', 'filename'), 'Texture2D': ('image', 'transformation'), 'Texture2DTransformation': (),
    'PointSet': ('pointList', 'colorList'),
    'AsymmetricHull': ('negXRadius', 'posXRadius', 'negYRadius', 'posYRadius', 'negXHeight', 'posXHeight', 'negYHeight',
                       'posYHeight', 'bottom', 'top', 'bottomShape', 'topShape', 'slices', 'stacks'),
}
for _name, _f in _geometry_fields.items():
    globals()[_name] = type(_name, (_Geometry,), {'_fields': _f})


class Scene(list):
    """PlantGL's Scene: a list of shapes (`sc += Shape(...)`), kept, not drawn by Sprout."""

    def __init__(self, shapes=()):
        list.__init__(self, shapes if isinstance(shapes, (list, tuple)) else [])

    def __iadd__(self, o):
        if isinstance(o, (list, tuple)):
            self.extend(o)
        else:
            self.append(o)
        return self

    def add(self, shape):
        self.append(shape)


class BoundingBox:
    def __init__(self, lower=(0, 0, 0), upper=(0, 0, 0)):
        self.lowerLeftCorner, self.upperRightCorner = Vector3(*tuple(lower)[:3]), Vector3(*tuple(upper)[:3])

    def getXMin(self):
        return self.lowerLeftCorner.x

    def getCenter(self):
        return (self.lowerLeftCorner + self.upperRightCorner) / 2

    def getSize(self):
        return (self.upperRightCorner - self.lowerLeftCorner) / 2

    def contains(self, p):
        p = tuple(p)
        return all(self.lowerLeftCorner[k] <= p[k] <= self.upperRightCorner[k] for k in range(3))


class Grid3Indexing:
    """PlantGL's regular 3D grid of voxels (voxel size, lower and upper corners): cell ids,
    indices (i, j, k), centres, and the voxels in a ball or a cone. Id = i + nx * (j + ny * k)."""

    def __init__(self, voxelsize=(1, 1, 1), origin=(0, 0, 0), upper=(10, 10, 10)):
        self._size = [max(float(v), 1e-9) for v in (tuple(voxelsize) if hasattr(voxelsize, '__len__') else (voxelsize,) * 3)[:3]]
        self._lo = [float(v) for v in tuple(origin)[:3]]
        hi = [float(v) for v in tuple(upper)[:3]]
        self._dims = [max(1, int(_math.ceil((hi[k] - self._lo[k]) / self._size[k] - 1e-9))) for k in range(3)]

    def size(self):
        return self._dims[0] * self._dims[1] * self._dims[2]

    def dimensions(self):
        return Vector3(*self._dims)

    getGridSize = dimensions

    def getVoxelSize(self):
        return Vector3(*self._size)

    def getLowerCorner(self):
        return Vector3(*self._lo)

    def getUpperCorner(self):
        return Vector3(*[self._lo[k] + self._dims[k] * self._size[k] for k in range(3)])

    def cellId(self, index):
        i, j, k = (int(v) for v in tuple(index)[:3])
        return i + self._dims[0] * (j + self._dims[1] * k)

    def index(self, cid):
        cid = int(cid)
        nx, ny = self._dims[0], self._dims[1]
        return (cid % nx, (cid // nx) % ny, cid // (nx * ny))

    def indexFromPoint(self, p):
        p = tuple(p)
        return tuple(min(self._dims[k] - 1, max(0, int(_math.floor((float(p[k]) - self._lo[k]) / self._size[k])))) for k in range(3))

    def cellIdFromPoint(self, p):
        return self.cellId(self.indexFromPoint(p))

    def getVoxelCenter(self, index):
        return Vector3(*[self._lo[k] + (int(index[k]) + 0.5) * self._size[k] for k in range(3)])

    def getVoxelCenterFromId(self, cid):
        return self.getVoxelCenter(self.index(cid))

    def query_voxels_in_ball(self, centre, radius):
        c = [float(v) for v in tuple(centre)[:3]]
        lo = self.indexFromPoint([c[k] - radius for k in range(3)])
        hi = self.indexFromPoint([c[k] + radius for k in range(3)])
        out = []
        for k in range(lo[2], hi[2] + 1):
            for j in range(lo[1], hi[1] + 1):
                for i in range(lo[0], hi[0] + 1):
                    v = self.getVoxelCenter((i, j, k))
                    if sum((v[a] - c[a]) ** 2 for a in range(3)) <= radius * radius:
                        out.append(self.cellId((i, j, k)))
        return out

    def query_voxels_in_cone(self, centre, direction, radius, angle):
        c = Vector3(*tuple(centre)[:3])
        d = Vector3(*tuple(direction)[:3]).normed()
        cosmax = _math.cos(angle)
        out = []
        for cid in self.query_voxels_in_ball(centre, radius):
            v = self.getVoxelCenterFromId(cid) - c
            n = v.norm()
            if n > 1e-12 and (v * d) / n >= cosmax:
                out.append(cid)
        return out


class Point3Grid:
    """Points with the queries of PlantGL's Point3Grid (space colonisation): indices of the
    enabled points in a ball or a cone, found through a grid of cells; points can be disabled."""

    def __init__(self, a, b=None, *args):
        if b is not None and not isinstance(b, (int, float)):  # (voxel size, points)
            pts, size = b, a
        else:  # (points, points per voxel)
            pts, size = a, None
        self.points = [tuple(float(c) for c in tuple(p)[:3]) for p in pts]
        self.enabled = [True] * len(self.points)
        if size is None:
            lo = [min(p[k] for p in self.points) for k in range(3)] if self.points else [0, 0, 0]
            hi = [max(p[k] for p in self.points) for k in range(3)] if self.points else [1, 1, 1]
            per = max(1, int(b or 10))
            cells = max(1.0, len(self.points) / per)
            extent = max(hi[k] - lo[k] for k in range(3)) or 1.0
            self._size = max(extent / max(1.0, cells ** (1 / 3.0)), 1e-9)
        else:
            self._size = max(float(tuple(size)[0]) if hasattr(size, '__len__') else float(size), 1e-9)
        self._cells = {}
        for i, p in enumerate(self.points):
            self._cells.setdefault(self._cell(p), []).append(i)

    def _cell(self, p):
        s = self._size
        return (int(_math.floor(p[0] / s)), int(_math.floor(p[1] / s)), int(_math.floor(p[2] / s)))

    def _near(self, centre, radius):
        c = tuple(float(v) for v in tuple(centre)[:3])
        r2 = radius * radius
        lo, hi = self._cell([v - radius for v in c]), self._cell([v + radius for v in c])
        out = []
        pts, enabled = self.points, self.enabled
        for x in range(lo[0], hi[0] + 1):
            for y in range(lo[1], hi[1] + 1):
                for z in range(lo[2], hi[2] + 1):
                    for i in self._cells.get((x, y, z), ()):
                        p = pts[i]
                        if enabled[i] and (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 + (p[2] - c[2]) ** 2 <= r2:
                            out.append(i)
        out.sort()
        return out

    def query_ball_point(self, centre, radius):
        return self._near(centre, radius)

    def query_points_in_cone(self, centre, direction, radius, angle):
        c, d = Vector3(centre), Vector3(direction).normed()
        cos_a = _math.cos(angle)
        out = []
        for i in self._near(centre, radius):
            v = Vector3(self.points[i]) - c
            n = abs(v)
            if n == 0 or dot(v, d) / n >= cos_a:
                out.append(i)
        return out

    def disable_points(self, indices):
        for i in indices:
            self.enabled[i] = False

    def disable_point(self, i):
        self.enabled[i] = False

    def enable_points(self, indices):
        for i in indices:
            self.enabled[i] = True

    def is_point_enabled(self, i):
        return self.enabled[i]

    def get_enabled_points(self):  # the points themselves, as PlantGL's grid gives them
        return [self.points[i] for i, e in enumerate(self.enabled) if e]

    def nbPoints(self):
        return len(self.points)


def pointset_mean_direction(origin, points, indices=None):
    """The unit mean of the directions from origin to the points (those of `indices`)."""
    o = Vector3(origin)
    chosen = [points[i] for i in indices] if indices is not None else list(points)
    total = Vector3(0, 0, 0)
    for p in chosen:
        total = total + (Vector3(p) - o).normed()
    return total.normed()


eStatic, eAnimatedPrimitives, eAnimatedScene = 0, 1, 2


class _Viewer:
    class _Any:
        def __getattr__(self, name):
            return _Viewer._Any()

        def __call__(self, *args, **kwargs):
            _warn("Viewer: Sprout has no PlantGL viewer; the call does nothing")
            return None

    def __getattr__(self, name):
        return _Viewer._Any()


Viewer = _Viewer()


def diffuseInterception(scene, *args, **kwargs):
    """PlantGL's light model is not in Sprout: no shape receives light (a warning)."""
    _warn("diffuseInterception (openalea.plantgl.light) is not provided by Sprout: every shape gets no light")
    return {}


def _asymmetric_hull(obj, num):
    """PlantGL's AsymmetricHull (a tree crown) as `(points, triangles)`, as PlantGL's discretizer
    makes it: around the z axis, 4 * slices meridians through the points at the four radii (an
    ellipse in each quadrant: x from the x radius on its side, y from the y radius, the height
    from the two quadrant heights as cos^2 and sin^2); each meridian goes from the bottom to its
    point and on to the top in `stacks` steps, evenly in distance from the axis through the
    bottom (or top) point, its height following that distance's power bottomShape (topShape)."""
    g = lambda field, default: num(getattr(obj, field, default), default)
    rad = {k: g(k + 'Radius', 0.5) for k in ('negX', 'posX', 'negY', 'posY')}
    hgt = {k: g(k + 'Height', 0.0) for k in ('negX', 'posX', 'negY', 'posY')}
    point = lambda v, d: tuple(num(x, 0) for x in (tuple(v) + (0.0, 0.0, 0.0))[:3]) if v is not None else d
    bottom = point(getattr(obj, 'bottom', None), (0.0, 0.0, -0.5))
    top = point(getattr(obj, 'top', None), (0.0, 0.0, 0.5))
    shape_bottom, shape_top = max(1e-6, g('bottomShape', 2.0)), max(1e-6, g('topShape', 2.0))
    slices = max(1, min(64, int(g('slices', 4))))
    stacks = max(1, min(64, int(g('stacks', 4))))
    quadrants = (('posX', 'posY'), ('negX', 'posY'), ('negX', 'negY'), ('posX', 'negY'))
    around = 4 * slices
    ring = 2 * stacks - 1  # points on a meridian, between the bottom and the top
    pts, tris = [], []

    def towards(end, p, t, shape):  # from end (the bottom or top) towards p: t of the horizontal way
        dx, dy, dz = p[0] - end[0], p[1] - end[1], p[2] - end[2]
        return end[0] + dx * t, end[1] + dy * t, end[2] + dz * t ** shape

    for q, (kx, ky) in enumerate(quadrants):
        for i in range(slices):
            a = 2 * _math.pi * (q * slices + i) / around
            c, s = _math.cos(a), _math.sin(a)
            p = (c * rad[kx], s * rad[ky], hgt[kx] * c * c + hgt[ky] * s * s)
            pts.extend(towards(bottom, p, j / stacks, shape_bottom) for j in range(1, stacks))
            pts.append(p)
            pts.extend(towards(top, p, 1 - j / stacks, shape_top) for j in range(1, stacks))
    b, t = len(pts), len(pts) + 1
    pts.extend((bottom, top))
    for k in range(around):
        cur, nxt = k * ring, (k + 1) % around * ring
        tris.append((cur, b, nxt))
        for j in range(ring - 1):
            tris.extend(((cur + j, nxt + j, nxt + j + 1), (cur + j, nxt + j + 1, cur + j + 1)))
        tris.append((cur + ring - 1, nxt + ring - 1, t))
    return pts, tris


def _sprout_triangles(obj, depth=0):
    """Sprout's drawing of `@g(shape)`: the shape in its own frame (PlantGL's: x the turtle's
    up, y its right, z its heading) as `(points, triangles, segments)`, triangles and segments indexing the points
    (segments: a curve's polyline); None for what draws nothing (text, an empty group).
    Transformations and groups are applied; appearances are not (the turtle's colour is used).
    A point set's points are small octahedra."""
    if depth > 32:
        return None
    pts, tris, segs = [], [], []

    def add(mesh, transform=None):
        if not mesh:
            return
        base = len(pts)
        pts.extend(transform(p) if transform else p for p in mesh[0])
        tris.extend((a + base, b + base, c + base) for a, b, c in mesh[1])
        segs.extend((a + base, b + base) for a, b in (mesh[2] if len(mesh) > 2 else ()))

    def result():
        return (pts, tris, segs) if tris or segs else None

    def num(v, default):
        try:
            return float(v)
        except (TypeError, ValueError):
            return default

    name = type(obj).__name__
    get = lambda field, default=None: getattr(obj, field, default)
    if isinstance(obj, (list, tuple)) or name in ('Scene', 'Group'):
        for o in (get('geometryList', obj) if name == 'Group' else obj):
            add(_sprout_triangles(o, depth + 1))
        return result() or ([], [], [])  # an empty group is a shape with nothing to draw
    if name == 'Shape':
        return _sprout_triangles(get('geometry'), depth + 1)
    if name in ('Polyline', 'Polyline2D', 'NurbsCurve', 'NurbsCurve2D', 'BezierCurve2D', 'BezierCurve'):
        curve = get('pointList') if name == 'Polyline' else obj.points()
        pts.extend(tuple(num(x, 0) for x in (tuple(q) + (0.0, 0.0))[:3]) for q in curve)
        segs.extend((k, k + 1) for k in range(len(pts) - 1))
        return result()
    if name == 'PointSet':
        points = [tuple(num(x, 0) for x in (tuple(q) + (0.0, 0.0))[:3]) for q in get('pointList', ())]
        if not points:
            return [], [], []  # a shape, with nothing to draw
        extent = max(max(q[k] for q in points) - min(q[k] for q in points) for k in range(3))
        r = 0.005 * extent if extent > 0 else 0.01
        for q in points:
            base = len(pts)
            pts.extend((q[0] + dx * r, q[1] + dy * r, q[2] + dz * r)
                       for dx, dy, dz in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)))
            tris.extend((base + a, base + b, base + c) for a, b, c in (
                (0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)))
        return result()
    if name in ('Scaled', 'Translated', 'AxisRotated', 'EulerRotated', 'Oriented'):
        inner = _sprout_triangles(get('geometry'), depth + 1)
        if inner is None:
            return None
        if name == 'Scaled':
            s = get('scale', 1)
            s = (num(s, 1),) * 3 if not hasattr(s, '__len__') else tuple(num(x, 1) for x in tuple(s)[:3])
            f = lambda p: (p[0] * s[0], p[1] * s[1], p[2] * s[2])
        elif name == 'Translated':
            t = tuple(num(x, 0) for x in tuple(get('translation', (0, 0, 0)))[:3])
            f = lambda p: (p[0] + t[0], p[1] + t[1], p[2] + t[2])
        elif name == 'AxisRotated':
            m = Matrix3.axisRotation(Vector3(*tuple(get('axis', (0, 0, 1)))[:3]).normed(), num(get('angle', 0), 0))
            f = lambda p: tuple(m * Vector3(*p))
        elif name == 'EulerRotated':  # z (azimuth), then y (elevation), then x (roll)
            a, e, r = (num(get(k, 0), 0) for k in ('azimuth', 'elevation', 'roll'))
            m = (Matrix3.axisRotation(Vector3(0, 0, 1), a) * Matrix3.axisRotation(Vector3(0, 1, 0), e) *
                 Matrix3.axisRotation(Vector3(1, 0, 0), r))
            f = lambda p: tuple(m * Vector3(*p))
        else:
            x = Vector3(*tuple(get('primary', (1, 0, 0)))[:3]).normed()
            y = Vector3(*tuple(get('secondary', (0, 1, 0)))[:3]).normed()
            z = (x ^ y).normed()
            f = lambda p: tuple(x * p[0] + y * p[1] + z * p[2])
        add(inner, f)
        return result()
    ring = lambda r, z, n: [(r * _math.cos(2 * _math.pi * i / n), r * _math.sin(2 * _math.pi * i / n), z) for i in range(n)]

    def tube(profile, n, caps):  # profile: (radius, z) from bottom to top, swept about z
        for j, (r, z) in enumerate(profile):
            pts.extend(ring(r, z, n))
            if j:
                a, b = (j - 1) * n, j * n
                tris.extend(t for i in range(n) for t in ((a + i, a + (i + 1) % n, b + (i + 1) % n),
                                                             (a + i, b + (i + 1) % n, b + i)))
        for j in (caps if caps else ()):
            r, z = profile[j]
            if r > 0:
                c = len(pts)
                pts.append((0.0, 0.0, z))
                first = j * n if j >= 0 else (len(profile) - 1) * n
                tris.extend((c, first + (i + 1) % n, first + i) for i in range(n))
        return pts, tris

    if name == 'Box':
        s = get('size', (0.5, 0.5, 0.5))
        if len(obj.args) >= 3:
            s = obj.args[:3]
        s = (num(s, 0.5),) * 3 if not hasattr(s, '__len__') else tuple(num(v, 0.5) for v in tuple(s)[:3])
        for axis in range(3):
            for sign in (-1, 1):
                u, v = [k for k in range(3) if k != axis]
                base = len(pts)
                for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                    p = [0.0, 0.0, 0.0]
                    p[axis], p[u], p[v] = sign * s[axis], du * s[u], dv * s[v]
                    pts.append(tuple(p))
                tris.extend([(base, base + 1, base + 2), (base, base + 2, base + 3)])
        return pts, tris
    slices = max(3, min(64, int(num(get('slices', 8), 8))))
    if name == 'Sphere':
        r, stacks = num(get('radius', 0.5), 0.5), max(2, min(64, int(num(get('stacks', 8), 8))))
        prof = [(r * _math.sin(_math.pi * i / stacks), -r * _math.cos(_math.pi * i / stacks)) for i in range(stacks + 1)]
        return tube(prof, slices, None)
    if name in ('Cylinder', 'Cone', 'Frustum'):
        r, h = num(get('radius', 0.5), 0.5), num(get('height', 1), 1)
        top = r if name == 'Cylinder' else 0.0 if name == 'Cone' else r * num(get('taper', 0.5), 0.5)
        return tube([(r, 0.0), (top, h)], slices, (0, -1))
    if name == 'Paraboloid':
        r, h, shape = num(get('radius', 0.5), 0.5), num(get('height', 1), 1), max(1e-3, num(get('shape', 2), 2))
        stacks = max(2, min(64, int(num(get('stacks', 8), 8))))
        prof = [(r * max(0.0, 1 - i / stacks) ** (1 / shape), h * i / stacks) for i in range(stacks + 1)]
        return tube(prof, slices, (0,))
    if name == 'Disc':
        r = num(get('radius', 0.5), 0.5)
        pts.append((0.0, 0.0, 0.0))
        pts.extend(ring(r, 0.0, slices))
        tris.extend((0, 1 + i, 1 + (i + 1) % slices) for i in range(slices))
        return pts, tris
    if name == 'AsymmetricHull':
        return _asymmetric_hull(obj, num)
    if name in ('TriangleSet', 'QuadSet', 'FaceSet'):
        pts.extend(tuple(num(x, 0) for x in tuple(p)[:3]) for p in get('pointList', ()))
        for face in get('indexList', ()):
            f = [int(i) for i in face]
            tris.extend((f[0], f[k], f[k + 1]) for k in range(1, len(f) - 1) if max(f[0], f[k], f[k + 1]) < len(pts))
        return (pts, tris) if tris else None
    if name in ('NurbsPatch', 'BezierPatch'):
        patch = obj if name == 'NurbsPatch' else NurbsPatch(
            get('ctrlPointMatrix'), len(get('ctrlPointMatrix')) - 1, len(get('ctrlPointMatrix')[0]) - 1)
        n = 10
        for i in range(n + 1):
            for j in range(n + 1):
                pts.append(tuple(patch.getPointAt(i / n, j / n))[:3])
        tris.extend(t for i in range(n) for j in range(n) for t in (
            (i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1),
            (i * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1)))
        return pts, tris
    return None
