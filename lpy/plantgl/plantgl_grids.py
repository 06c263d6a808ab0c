# openalea.plantgl._grids, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): the voxel grid (Grid3Indexing) and the point grid (Point3Grid) that space
# colonisation models query, and pointset_mean_direction. Its own file: spatial queries,
# apart from the geometry.
import math as _math

from _sprout_lpy import _PointGrid
from openalea.plantgl._vectors import Vector3, dot


class Grid3Indexing:
    """PlantGL's regular 3D grid of voxels (its SpatialArrayN, tool/util_spatialarray.h):
    `int(extent / voxel size) + 1` voxels along each axis from the origin; cell ids with the last
    coordinate fastest (id = k + nz (j + ny i)); the voxels near a point or in a cone, in that
    order."""

    def __init__(self, voxelsize=(1, 1, 1), origin=(0, 0, 0), upper=(10, 10, 10)):
        size = tuple(voxelsize) if hasattr(voxelsize, '__len__') else (voxelsize,) * 3
        self._size = [float(v) for v in size[:3]]
        self._lo = [float(v) for v in tuple(origin)[:3]]
        hi = [float(v) for v in tuple(upper)[:3]]
        for k in range(3):
            if self._size[k] < 1e-5:
                raise ValueError("Bad voxelSize value for dimension %i : %f" % (k, self._size[k]))
            if self._lo[k] > hi[k]:
                raise ValueError("Bad min and max point value for dimension %i : %f - %f" % (k, self._lo[k], hi[k]))
        self._dims = [int((hi[k] - self._lo[k]) / self._size[k]) + 1 for k in range(3)]

    def size(self):
        return self._dims[0] * self._dims[1] * self._dims[2]

    def valuesize(self):
        """The values the grid holds: none for a Grid3Indexing (PlantGL's NoneContainer), one a
        voxel for a Point3Grid."""
        return 0

    def nbDimensions(self):
        return 3

    def dimensions(self):
        return tuple(self._dims)

    def getVoxelSize(self):
        return Vector3(*self._size)

    def getOrigin(self):
        return Vector3(*self._lo)

    getLowerCorner = getOrigin

    def getGridSize(self):
        return Vector3(*[self._size[k] * self._dims[k] for k in range(3)])

    def getUpperCorner(self):
        return self.getOrigin() + self.getGridSize()

    def cellId(self, index):
        _, ny, nz = self._dims  # (the last index fastest)
        return (int(index[0]) * ny + int(index[1])) * nz + int(index[2])

    def index(self, cid):
        cid = int(cid)
        nx, ny, nz = self._dims
        out = []
        for offset in (ny * nz, nz, 1):
            out.append(cid // offset)
            cid -= out[-1] * offset
        return tuple(out)

    def isValidId(self, cid):
        return 0 <= cid < self.valuesize()  # (PlantGL's: so never for a Grid3Indexing)

    def isValidIndex(self, index):
        return all(0 <= int(index[k]) < self._dims[k] for k in range(3))

    def indexFromCoord(self, coord, dimension):
        if hasattr(coord, '__len__'):
            coord = tuple(coord)[dimension]
        return int((float(coord) - self._lo[dimension]) / self._size[dimension])

    def indexFromPoint(self, p):
        p, lo, size = tuple(p), self._lo, self._size
        return (int((float(p[0]) - lo[0]) / size[0]), int((float(p[1]) - lo[1]) / size[1]),
                int((float(p[2]) - lo[2]) / size[2]))

    def cellIdFromPoint(self, p):  # (models ask it for every cell they read)
        p, lo, size = tuple(p), self._lo, self._size
        _, ny, nz = self._dims
        return ((int((float(p[0]) - lo[0]) / size[0]) * ny + int((float(p[1]) - lo[1]) / size[1])) * nz
                + int((float(p[2]) - lo[2]) / size[2]))

    def getVoxelCenter(self, index):
        return Vector3(*[self._lo[k] + (int(index[k]) + 0.5) * self._size[k] for k in range(3)])

    def getVoxelCenterFromId(self, cid):
        return self.getVoxelCenter(self.index(cid))

    def getVoxelLowerPoint(self, index):
        return Vector3(*[self._lo[k] + int(index[k]) * self._size[k] for k in range(3)])

    def getVoxelLowerPointFromId(self, cid):
        return self.getVoxelLowerPoint(self.index(cid))

    def getVoxelUpperPoint(self, index):
        return Vector3(*[self._lo[k] + (int(index[k]) + 1) * self._size[k] for k in range(3)])

    def getVoxelUpperPointFromId(self, cid):
        return self.getVoxelUpperPoint(self.index(cid))

    @staticmethod
    def _corners(low, high):
        """PlantGL's order: the low corner, then each axis in turn doubling the list."""
        out = [low]
        for k in range(3):
            for p in list(out):
                q = Vector3(p)
                q[k] = high[k]
                out.append(q)
        return out

    def getCorners(self):
        return self._corners(self.getLowerCorner(), self.getUpperCorner())

    def getVoxelCorners(self, index):
        return self._corners(self.getVoxelLowerPoint(index), self.getVoxelUpperPoint(index))

    def getVoxelCornersFromId(self, cid):
        return self.getVoxelCorners(self.index(cid))

    def getMaxIndexDistanceToBorder(self, index):
        return tuple(max(int(index[k]), self._dims[k] - int(index[k])) for k in range(3))

    def getMaxDistanceToBorder(self, v):
        lo, hi = self.getLowerCorner(), self.getUpperCorner()
        return Vector3(*[max(abs(v[k] - lo[k]), abs(v[k] - hi[k])) for k in range(3)]).norm()

    def _around(self, centre, radius):
        """The voxels' indices in the box around `centre` reaching `radius`, the last fastest."""
        c = self.indexFromPoint(centre)
        reach = [1 + int(radius / self._size[k]) for k in range(3)]
        lo = [0 if c[k] < reach[k] else c[k] - reach[k] for k in range(3)]
        hi = [min(self._dims[k] - 1, c[k] + reach[k]) for k in range(3)]
        for i in range(lo[0], hi[0] + 1):
            for j in range(lo[1], hi[1] + 1):
                for k in range(lo[2], hi[2] + 1):
                    yield (i, j, k)

    def query_voxels_around_point(self, center, radius, minradius=0):
        """The voxels whose centre is nearer than radius + a voxel's diagonal (PlantGL's)."""
        p = Vector3(*tuple(center)[:3])
        diagonal = self.getVoxelSize().norm()
        r, minr = radius + diagonal, max(0.0, minradius - diagonal)
        out = []
        for index in self._around(p, radius):
            d = (self.getVoxelCenter(index) - p).norm()
            if minr <= d < r:
                out.append(self.cellId(index))
        return out

    query_voxels_in_ball = query_voxels_around_point

    def query_voxels_in_cone(self, origin, direction, radius, angle=_math.pi / 2):
        """The voxels near `origin` (as query_voxels_around_point) in the cone of full opening
        `angle`: by their centre, or, a little wider, by one of their corners (PlantGL's).
        Written out on floats (the vectors' arithmetic in their order: the same numbers),
        models ask it for every apex of a step."""
        ox, oy, oz = Vector3(*tuple(origin)[:3])._v
        dx, dy, dz = Vector3(*tuple(direction)[:3]).normed()._v
        r = radius + self.getVoxelSize().norm()
        half = angle / 2
        cos_cone, cos_large = _math.cos(half), _math.cos(min(half + _math.pi / 4, _math.pi))
        (lx, ly, lz), (sx, sy, sz) = self._lo, self._size
        _, ny, nz = self._dims
        sqrt = _math.sqrt
        out = []
        for i, j, k in self._around(Vector3(ox, oy, oz), radius):
            # v = getVoxelCenter(index) - o; dist = v.normalize()
            vx, vy, vz = lx + (i + 0.5) * sx - ox, ly + (j + 0.5) * sy - oy, lz + (k + 0.5) * sz - oz
            dist = sqrt(vx * vx + vy * vy + vz * vz)
            if dist > 0:
                vx, vy, vz = vx / dist, vy / dist, vz / dist
            if not dist < r:
                continue
            a = 0.0 + vx * dx + vy * dy + vz * dz
            if a > cos_cone:
                out.append((i * ny + j) * nz + k)
            elif a > cos_large:
                low = (lx + i * sx, ly + j * sy, lz + k * sz)
                high = (lx + (i + 1) * sx, ly + (j + 1) * sy, lz + (k + 1) * sz)
                for cx, cy, cz in self._corner_points(low, high):
                    wx, wy, wz = cx - ox, cy - oy, cz - oz  # (corner - o).normed() * d
                    n = sqrt(wx * wx + wy * wy + wz * wz)
                    if n > 0:
                        wx, wy, wz = wx / n, wy / n, wz / n
                    if 0.0 + wx * dx + wy * dy + wz * dz > cos_cone:
                        out.append((i * ny + j) * nz + k)
                        break
        return out

    @staticmethod
    def _corner_points(low, high):
        """_corners' order on tuples: the low corner, then each axis in turn doubling the list."""
        out = [low]
        for axis in range(3):
            out += [p[:axis] + (high[axis],) + p[axis + 1:] for p in out]
        return out

    def query_voxels_in_box(self, center, maxradius, minradius=None):
        c, maxr = [int(v) for v in center], [int(v) for v in maxradius]
        minr = [0, 0, 0] if minradius is None else [int(v) for v in minradius]
        bmin = [0 if c[k] < minr[k] else c[k] - minr[k] for k in range(3)]
        emin = [min(self._dims[k] - 1, c[k] + minr[k]) for k in range(3)]
        lo = [0 if c[k] < maxr[k] else c[k] - maxr[k] for k in range(3)]
        hi = [min(self._dims[k] - 1, c[k] + maxr[k]) for k in range(3)]
        out = []
        for i in range(lo[0], hi[0] + 1):
            for j in range(lo[1], hi[1] + 1):
                for k in range(lo[2], hi[2] + 1):
                    index = (i, j, k)
                    if any(index[a] <= bmin[a] or index[a] >= emin[a] for a in range(3)):
                        out.append(self.cellId(index))
        return out


class Point3Grid(Grid3Indexing):
    """PlantGL's Point3Grid: its arguments read here, its voxels and queries in C++
    (lpy/plantgl/point_grid.hpp says how it follows PlantGL's order)."""

    def __init__(self, a, b=None, c=None, d=None):
        if d is not None:  # (voxel size, min point, max point, points)
            pts = d
            lo, hi = [float(v) for v in tuple(b)[:3]], [float(v) for v in tuple(c)[:3]]
            size = [float(v) for v in tuple(a)[:3]]
        elif b is not None and not isinstance(b, (int, float)):  # (voxel size: a number or a vector, points)
            pts = b
        else:  # (points, voxel size ratio from the global extent)
            pts = a
        self.points = [tuple(float(v) for v in tuple(p)[:3]) for p in pts]
        if d is None:
            lo = [min(p[k] for p in self.points) for k in range(3)] if self.points else [0.0] * 3
            hi = [max(p[k] for p in self.points) for k in range(3)] if self.points else [0.0] * 3
            if pts is b:
                size = [float(a)] * 3 if isinstance(a, (int, float)) else [float(v) for v in tuple(a)[:3]]
            else:
                size = [(hi[k] - lo[k]) / float(b if b is not None else 10) for k in range(3)]
        self._grid = _PointGrid(self.points, size, lo, hi)  # the voxels and the queries, in C++
        # Its cells' ids and indices, as PlantGL's grid has them (a voxel of 1e-5 at least, as the C++'s).
        Grid3Indexing.__init__(self, [max(float(v), 1e-5) for v in size], lo, [max(a, b) for a, b in zip(lo, hi)])

    def valuesize(self):
        return self.size()

    def query_ball_point(self, centre, radius):
        return self._grid.ball(tuple(centre), float(radius))

    def query_points_in_cone(self, centre, direction, radius, angle=_math.pi / 2):
        return self._grid.cone(tuple(centre), tuple(direction), float(radius), float(angle))

    def disable_point(self, i):
        return self._grid.disable(i)

    def enable_point(self, i):
        return self._grid.enable(i)

    def disable_points(self, indices):
        self._grid.disable_all(indices)

    def enable_points(self, indices):
        self._grid.enable_all(indices)

    def is_point_enabled(self, i):
        return self._grid.enabled(i)

    @property
    def enabled(self):
        return [self._grid.enabled(i) for i in range(len(self.points))]

    def get_enabled_point_indices(self):
        return self._grid.enabled_indices()

    def get_enabled_points(self):  # the points themselves, as PlantGL's grid gives them
        return [self.points[i] for i in self._grid.enabled_indices()]

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
