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


_U64 = (1 << 64) - 1


def _size_t(x):
    """C++'s size_t(x) of a double (truncated; a negative one wraps, as on x86-64)."""
    return int(x) & _U64


class Point3Grid:
    """PlantGL's Point3Grid (its regularpointgrid.h, in double precision): a regular grid of
    voxels over the points' bounds, each voxel keeping the indices of its points in the order
    they were added; queries walk the voxels near the query (the last coordinate fastest) and
    each voxel's points in order, so they give PlantGL's indices in PlantGL's order. Disabling a
    point takes it out of its voxel; enabling puts it back at the voxel's end."""

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
        self._size = [v if v > 1e-5 else 1e-5 for v in size]
        self._lo = lo
        self._dims = [_size_t((hi[k] - lo[k]) / self._size[k]) + 1 for k in range(3)]
        self._voxels = {}
        for i, p in enumerate(self.points):
            self._voxels.setdefault(self._cell_id(self._index(p)), []).append(i)

    def _index(self, p):
        return [_size_t((p[k] - self._lo[k]) / self._size[k]) for k in range(3)]

    def _cell_id(self, index):
        nx, ny, nz = self._dims
        return (index[2] + nz * (index[1] + ny * index[0])) & _U64

    def _centre(self, index):
        return [self._lo[k] + (index[k] + 0.5) * self._size[k] for k in range(3)]

    def _around(self, centre, radius):
        """The voxels of the box around `centre` reaching `radius`, as PlantGL walks them:
        (cell id, index), the last coordinate fastest."""
        c = self._index(centre)
        lo, hi = [], []
        for k in range(3):
            r = _size_t(1 + radius / self._size[k])
            lo.append(0 if c[k] < r else c[k] - r)
            hi.append(min(self._dims[k] - 1, (c[k] + r) & _U64))
        if any(lo[k] > hi[k] for k in range(3)):
            return
        for i in range(lo[0], hi[0] + 1):
            for j in range(lo[1], hi[1] + 1):
                for k in range(lo[2], hi[2] + 1):
                    yield self._cell_id((i, j, k)), (i, j, k)

    @staticmethod
    def _norm(v):
        return _math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])

    def query_ball_point(self, centre, radius):
        c = [float(v) for v in tuple(centre)[:3]]
        r = radius + self._norm(self._size)
        out = []
        for cid, index in self._around(c, radius):
            pts = self._voxels.get(cid)
            if not pts:
                continue
            vc = self._centre(index)
            if not self._norm([vc[k] - c[k] for k in range(3)]) < r:
                continue
            for i in pts:
                p = self.points[i]
                if not self._norm([p[k] - c[k] for k in range(3)]) > radius:
                    out.append(i)
        return out

    def _corners(self, index):
        lo = [self._lo[k] + index[k] * self._size[k] for k in range(3)]
        hi = [self._lo[k] + (index[k] + 1) * self._size[k] for k in range(3)]
        corners = [lo]
        for k in range(3):
            for q in list(corners):
                q = list(q)
                q[k] = hi[k]
                corners.append(q)
        return corners

    def query_points_in_cone(self, centre, direction, radius, angle=_math.pi / 2):
        c = [float(v) for v in tuple(centre)[:3]]
        dv = [float(v) for v in tuple(direction)[:3]]
        n = self._norm(dv)
        d = [v / n for v in dv] if n > 0 else dv
        r = radius + self._norm(self._size)
        cos_half = _math.cos(angle / 2)
        cos_large = _math.cos(min(angle / 2 + _math.pi / 4, _math.pi))

        def unit(v):
            m = self._norm(v)
            return ([x / m for x in v] if m > 0 else v), m

        out = []
        for cid, index in self._around(c, radius):
            pts = self._voxels.get(cid)
            if not pts:
                continue
            vc = self._centre(index)
            u, dist = unit([vc[k] - c[k] for k in range(3)])
            if not dist < r:
                continue
            a = sum(u[k] * d[k] for k in range(3))
            inside = a > cos_half
            if not inside and a > cos_large:
                for q in self._corners(index):
                    w, _ = unit([q[k] - c[k] for k in range(3)])
                    if sum(w[k] * d[k] for k in range(3)) > cos_half:
                        inside = True
                        break
            if not inside:
                continue
            for i in pts:
                p = self.points[i]
                w, dist = unit([p[k] - c[k] for k in range(3)])
                if dist <= radius + 1e-5 and sum(w[k] * d[k] for k in range(3)) > cos_half - 1e-5:
                    out.append(i)
        return out

    def disable_point(self, i):
        pts = self._voxels.get(self._cell_id(self._index(self.points[i])), [])
        if i in pts:
            pts.remove(i)
            return True
        return False

    def enable_point(self, i):
        pts = self._voxels.setdefault(self._cell_id(self._index(self.points[i])), [])
        if i not in pts:
            pts.append(i)
            return True
        return False

    def disable_points(self, indices):
        for i in indices:
            self.disable_point(i)

    def enable_points(self, indices):
        for i in indices:
            self.enable_point(i)

    def is_point_enabled(self, i):
        return i in self._voxels.get(self._cell_id(self._index(self.points[i])), ())

    @property
    def enabled(self):
        return [self.is_point_enabled(i) for i in range(len(self.points))]

    def get_enabled_point_indices(self):
        return [i for i in range(len(self.points)) if self.is_point_enabled(i)]

    def get_enabled_points(self):  # the points themselves, as PlantGL's grid gives them
        return [self.points[i] for i in self.get_enabled_point_indices()]

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
