# openalea.plantgl._arrays, a part of Sprout's PlantGL (openalea.plantgl.all gathers the parts:
# plantgl.py): PlantGL's arrays (Point2Array, Point3Array, Point4Array: lists of vectors;
# RealArray; Point4Matrix), their text and the members models call on them. Its own file: what
# the curves (plantgl_curves.py) and patches are made of.
import math as _math

from openalea.plantgl._vectors import _Vec, Vector2, Vector3, Vector4


def _point_text(p, n):
    """A point as PlantGL writes it: Vector3(0.5,1,1) (C++'s default 6 significant digits)."""
    return "Vector%d(%s)" % (n, ",".join("%g" % c for c in tuple(p)[:n]))


class _Points(list):
    """PlantGL's arrays of points: lists of vectors of their size. Point3Array(points),
    Point3Array(points, z) (2D points, z added: Point4Array(points, w) alike), Point3Array(n)
    (n origins)."""
    _n = 3

    def __init__(self, *args):
        vec = (Vector2, Vector3, Vector4)[self._n - 2]
        if len(args) == 1 and isinstance(args[0], int):
            list.__init__(self, [vec() for _ in range(args[0])])
        elif len(args) == 1:
            list.__init__(self, [p if type(p) is vec else vec(p) for p in args[0]])
        elif len(args) == 2 and not isinstance(args[0], (int, float, _Vec)):
            last = float(args[1])
            list.__init__(self, [vec(*(tuple(p)[:self._n - 1] + (last,))) for p in args[0]])
        else:
            list.__init__(self, [p if type(p) is vec else vec(p) for p in args])

    def __repr__(self):  # Point3Array([Vector3(1,2,3),Vector3(4,5,6)])
        return "%s([%s])" % (type(self).__name__, ",".join(_point_text(p, self._n) for p in self))

    __str__ = __repr__

    def normalize(self):
        """Each point normalised in place (PlantGL's)."""
        for p in self:
            p.normalize()

    def getBounds(self):
        """The lowest and highest coordinates, each a vector."""
        vec = type(self[0]) if self else Vector3
        return (vec(*[min(p[k] for p in self) for k in range(self._n)]),
                vec(*[max(p[k] for p in self) for k in range(self._n)]))

    def getCenter(self):
        vec = (Vector2, Vector3, Vector4)[self._n - 2]
        return vec(*[sum(p[k] for p in self) / len(self) for k in range(self._n)]) if self else vec()

    def getLength(self):
        """The length of the polyline through the points."""
        return sum(abs(self[i + 1] - self[i]) for i in range(len(self) - 1))

    def getExtent(self):
        lo, hi = self.getBounds()
        return hi - lo

    def _index(self, k, better):
        best = 0
        for i in range(1, len(self)):
            if better(self[i][k], self[best][k]):
                best = i
        return best

    def translate(self, v):
        for i, p in enumerate(self):
            self[i] = p + type(p)(v)

    def scale(self, v):
        for i, p in enumerate(self):
            self[i] = p.cwiseProduct(v) if hasattr(v, '__len__') else p * v

    def transform(self, matrix):
        for i, p in enumerate(self):
            self[i] = matrix * p

    def prepend(self, p):
        self.insert(0, type(self)([p])[0])

    def subset(self, indices):
        return type(self)([self[i] for i in indices])

    def opposite_subset(self, indices):
        left = set(indices)
        return type(self)([p for i, p in enumerate(self) if i not in left])

    def findClosest(self, point):
        """(the nearest point, its index, its distance) (PlantGL's)."""
        point = (Vector2, Vector3, Vector4)[self._n - 2](point)
        dist = [abs(p - point) for p in self]
        i = min(range(len(dist)), key=dist.__getitem__)
        return self[i], i, dist[i]

    def empty(self):
        return len(self) == 0

    def isValid(self):
        return all(p.isValid() for p in self)

    def getPglId(self):
        return id(self)

    getId = getPglId


def _extremes(name, k):
    setattr(_Points, 'get%sMinIndex' % name, lambda self: self._index(k, lambda a, b: a < b))
    setattr(_Points, 'get%sMaxIndex' % name, lambda self: self._index(k, lambda a, b: a > b))
    setattr(_Points, 'get%sMinAndMaxIndex' % name,
            lambda self: (self._index(k, lambda a, b: a < b), self._index(k, lambda a, b: a > b)))

    def sort(self):  # in place, as PlantGL's sortX
        self[:] = sorted(self, key=lambda p: p[k])
    setattr(_Points, 'sort' + name, sort)


for _k, _name in enumerate('XYZW'):
    _extremes(_name, _k)
del _k, _name


class Point2Array(_Points):
    _n = 2


class Point3Array(_Points):
    _n = 3


class Point4Array(_Points):
    _n = 4


class RealArray(list):
    """PlantGL's array of reals (a curve's knots): RealArray([0, 0, 1, 1]), or RealArray(n) of n
    zeros."""

    def __init__(self, values=()):
        if isinstance(values, int):
            list.__init__(self, [0.0] * values)
        else:
            list.__init__(self, [float(v) for v in values])

    def __repr__(self):  # RealArray([0.0,1.5])
        return "RealArray([%s])" % ",".join(repr(float(v)) for v in self)

    __str__ = __repr__

    def getMin(self):
        return min(self)

    def getMax(self):
        return max(self)

    def getSum(self):
        return float(sum(self))

    def getMean(self):
        return sum(self) / len(self)

    def getMinIndex(self):
        return min(range(len(self)), key=self.__getitem__)

    def getMaxIndex(self):
        return max(range(len(self)), key=self.__getitem__)

    def getMinAndMax(self):
        return (min(self), max(self))

    def getMinAndMaxIndex(self):
        return (self.getMinIndex(), self.getMaxIndex())

    def sqrt(self):
        return RealArray([_math.sqrt(v) for v in self])

    def log(self):
        return RealArray([_math.log(v) for v in self])

    def exp(self):
        return RealArray([_math.exp(v) for v in self])

    def pow(self, e):
        return RealArray([v ** e for v in self])

    def prepend(self, v):
        self.insert(0, float(v))

    def subset(self, indices):
        return RealArray([self[i] for i in indices])

    def opposite_subset(self, indices):
        left = set(indices)
        return RealArray([v for i, v in enumerate(self) if i not in left])

    def empty(self):
        return len(self) == 0

    def isValid(self):
        return all(_math.isfinite(v) for v in self)


class Point4Matrix(list):
    """PlantGL's matrix of 4D points (a patch's control points): rows of points (kept as
    given), m[i, j], sizes(), getRow, getColumn, pushRow, insertRow... Point4Matrix(rows,
    columns) holds origins."""

    def __init__(self, rows=(), columns=None):
        if isinstance(rows, int):
            rows = [[(0.0, 0.0, 0.0, 0.0)] * int(columns or 0) for _ in range(rows)]
        list.__init__(self, [[tuple(p) for p in row] for row in rows])

    def __getitem__(self, key):
        if isinstance(key, tuple):
            i, j = key
            return Vector4(*list.__getitem__(self, i)[j])
        return list.__getitem__(self, key)

    def sizes(self):
        return (len(self), len(self[0]) if len(self) else 0)

    def size(self):
        rows, columns = self.sizes()
        return rows * columns

    def getRowNb(self):
        return self.sizes()[0]

    def getColumnNb(self):
        return self.sizes()[1]

    def getRowSize(self):
        return self.sizes()[1]

    def getColumnSize(self):
        return self.sizes()[0]

    def getRow(self, i):
        return [Vector4(*p) for p in list.__getitem__(self, i)]

    def getColumn(self, j):
        return [Vector4(*row[j]) for row in self]

    def getDiagonal(self):
        return [Vector4(*self[i][i]) for i in range(min(self.sizes()))]

    def transpose(self):
        rows, columns = self.sizes()
        return Point4Matrix([[self[i][j] for i in range(rows)] for j in range(columns)])

    def empty(self):
        return self.size() == 0

    def isUnique(self):
        """Whether no point is there twice (PlantGL's)."""
        points = [tuple(p) for row in self for p in row]
        return len(set(points)) == len(points)

    def _fits(self, points, count):
        points = [tuple(p) for p in points]
        if len(self) and len(points) != count:
            raise ValueError("Point4Matrix: %d points where %d are needed" % (len(points), count))
        return points

    def pushRow(self, points):
        self.append(self._fits(points, self.getColumnNb()))

    def insertRow(self, i, points):
        self.insert(i, self._fits(points, self.getColumnNb()))

    def pushColumn(self, points):
        for row, p in zip(self, self._fits(points, self.getRowNb())):
            row.append(p)

    def insertColumn(self, j, points):
        for row, p in zip(self, self._fits(points, self.getRowNb())):
            row.insert(j, p)

    def __repr__(self):  # Point4Matrix([[Vector4(0,0,0,1),...],[...]])
        return "Point4Matrix([%s])" % ",".join("[%s]" % ",".join(_point_text(p, 4) for p in row) for row in self)

    __str__ = __repr__
