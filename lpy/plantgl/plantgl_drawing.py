# openalea.plantgl._drawing, a part of Sprout's PlantGL (openalea.plantgl.all gathers the
# parts: plantgl.py): Sprout's drawing of `@g(shape)`, the PlantGL shapes and curves a model
# builds made into triangles and segments (lpy/draw/draw.cpp calls _sprout_triangles). Its own
# file: Sprout's code, not PlantGL's interface.
import math as _math

from _sprout_lpy import _hull_mesh
from openalea.plantgl._curves import NurbsPatch
from openalea.plantgl._vectors import Matrix3, Vector3


def _asymmetric_hull(obj, num):
    """PlantGL's AsymmetricHull (a tree crown) as `(points, triangles)`, as PlantGL's discretizer
    makes it (lpy/plantgl/asymmetric_hull.hpp says how): its fields read here, its mesh made in
    C++."""
    g = lambda field, default: num(getattr(obj, field, default), default)
    point = lambda v, d: tuple(num(x, 0) for x in (tuple(v) + (0.0, 0.0, 0.0))[:3]) if v is not None else d
    return _hull_mesh(tuple(g(k + 'Radius', 0.5) for k in ('negX', 'posX', 'negY', 'posY')),
                      tuple(g(k + 'Height', 0.0) for k in ('negX', 'posX', 'negY', 'posY')),
                      point(getattr(obj, 'bottom', None), (0.0, 0.0, -0.5)), point(getattr(obj, 'top', None), (0.0, 0.0, 0.5)),
                      g('bottomShape', 2.0), g('topShape', 2.0), int(max(-1e9, min(1e9, g('slices', 4)))),
                      int(max(-1e9, min(1e9, g('stacks', 4)))))


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
        pts.extend(patch._grid(n))  # patch.getPointAt(i / n, j / n), i outer, in one call
        tris.extend(t for i in range(n) for j in range(n) for t in (
            (i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1),
            (i * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1)))
        return pts, tris
    return None
