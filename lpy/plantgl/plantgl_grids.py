# openalea.plantgl._grids, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): the voxel grid (Grid3Indexing) and the point grid (Point3Grid) that space
# colonisation models query, and pointset_mean_direction. Its own file: spatial queries,
# apart from the geometry.
import math as _math

from _sprout_lpy import _PointGrid
from openalea.plantgl._vectors import Vector3, dot


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
        Grid3Indexing.__init__(self, size, lo, hi)  # its cells' ids and indices, as PlantGL's grid has them

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
