# openalea.plantgl._grids, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): the voxel grid (Grid3Indexing) and the point grid (Point3Grid) that space
# colonisation models query, and pointset_mean_direction. Its own file: spatial queries,
# apart from the geometry.
import math as _math

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
