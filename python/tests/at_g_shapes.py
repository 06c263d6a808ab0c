"""Random PlantGL shapes as models give them to @g, and what the drawing keeps of a mesh: for
test_sprout.py's check of lpy/plantgl/meshes.cpp against at_g_meshes.txt (the meshes the
Python meshing, plantgl_drawing.py's _sprout_triangles, made of the same shapes before the C++
replaced it; see that file's head)."""
import hashlib
import random
import struct


def shapes(pgl, count, seed=11):
    """`count` shapes from `seed`, the same every run: every kind @g meshes (solids, sets,
    transformations, groups, curves, patches, crowns), now and then with values a model should
    not give (NaN, a string, a vector of two numbers, a negative index)."""
    rng = random.Random(seed)
    num = lambda: rng.choice([rng.uniform(-3, 3), 0.0, -0.0, 1, rng.randint(1, 70)])
    odd = lambda: rng.choice([float("nan"), float("inf"), "2", None, True, 1e308, -7, "x"])
    val = lambda: odd() if rng.random() < 0.04 else num()
    vec = lambda: rng.choice([(num(), num(), num()), pgl.Vector3(num(), num(), num())])
    short = lambda: rng.choice([(), (num(),), (num(), num()), [num(), "x", num()], (val(), val(), val(), val())])
    any_vec = lambda: short() if rng.random() < 0.05 else vec()
    ctrl = lambda n, d: [tuple(num() for _ in range(d)) + (rng.choice([1, 1, 0.5, 2]),) for _ in range(n)]

    def curve():
        k = rng.randrange(5)
        n = rng.randint(2, 6)
        if k == 0:
            return pgl.NurbsCurve(ctrl(n, 3), rng.randint(1, 4), stride=rng.randint(2, 40))
        if k == 1:
            return pgl.NurbsCurve2D(ctrl(n, 2), rng.randint(1, 4), stride=rng.randint(2, 40))
        if k == 2:
            return pgl.BezierCurve2D(ctrl(n, 2), stride=rng.randint(2, 40))
        if k == 3:
            return pgl.Polyline2D([(num(), num()) for _ in range(n)])
        return pgl.Polyline([any_vec() for _ in range(rng.randint(0, 5))])

    def patch():
        rows, cols = rng.randint(2, 4), rng.randint(2, 4)
        m = [[(num(), num(), num(), rng.choice([1, 1, 0.5])) for _ in range(cols)] for _ in range(rows)]
        if rng.random() < 0.5:
            return pgl.BezierPatch(m)
        return pgl.NurbsPatch(m, rng.randint(1, 3), rng.randint(1, 3))

    def hull():
        return pgl.AsymmetricHull(*(val() for _ in range(8)), any_vec(), any_vec(), val(), val(),
                                  rng.choice([rng.randint(-1, 6), val()]), rng.choice([rng.randint(-1, 6), val()]))

    def faces():
        index = lambda: rng.choice([rng.randint(0, 5), rng.randint(0, 5), -1, 2.0, True])
        return [[index() for _ in range(rng.choice([3, 3, 4, 0, 1, 5]))] for _ in range(rng.randint(0, 4))]

    def shape(depth=0):
        k = rng.randrange(24 if depth < 3 else 15)
        made = [lambda: pgl.Box(any_vec()), lambda: pgl.Sphere(val(), rng.randint(-2, 70), rng.randint(-2, 70)),
                lambda: pgl.Cylinder(val(), val(), True, rng.randint(1, 80)), lambda: pgl.Frustum(val(), val(), val()),
                lambda: pgl.Paraboloid(val(), val(), val(), True, 9, 5), lambda: pgl.Disc(val()),
                lambda: pgl.TriangleSet([any_vec() for _ in range(4)], faces()),
                lambda: pgl.PointSet([any_vec() for _ in range(rng.randint(0, 4))]),
                lambda: pgl.Cone(val(), val(), True, rng.randint(1, 20)), curve, curve, patch, hull,
                lambda: pgl.QuadSet([vec() for _ in range(5)], faces()), lambda: rng.choice([None, pgl.Text("t"), pgl.Shape(None)]),
                lambda: pgl.Scaled(rng.choice([vec(), short(), val()]), shape(depth + 1)),
                lambda: pgl.Translated(rng.choice([vec(), vec(), short()]), shape(depth + 1)),
                lambda: pgl.AxisRotated(any_vec(), val(), shape(depth + 1)),
                lambda: pgl.EulerRotated(val(), val(), val(), shape(depth + 1)),
                lambda: pgl.Oriented(any_vec(), any_vec(), shape(depth + 1)),
                lambda: pgl.Group([pgl.Shape(shape(depth + 1)) for _ in range(rng.randint(0, 3))]),
                lambda: pgl.Group([shape(depth + 1) for _ in range(rng.randint(0, 3))]),
                lambda: [shape(depth + 1) for _ in range(rng.randint(0, 3))],
                lambda: pgl.Shape(shape(depth + 1))]
        return made[k]()

    return [shape() for _ in range(count)]


def drawn(r):
    """What lpy/draw/shapes.cpp keeps of a mesh (points, triangles[, segments]), as a short
    text: 'none' (not drawn), 'empty' (a shape with nothing to draw), else a hash of the points'
    bits, the triangles and the segments; the drawing refuses a point that is not three numbers
    and an index outside the points."""
    if r is None:
        return "none"
    points, triangles = list(r[0]), list(r[1])
    segments = list(r[2]) if len(r) > 2 else []
    if not points and not triangles and not segments:
        return "empty"
    number = lambda v: isinstance(v, (int, float))
    index = lambda v: number(v) and 0 <= v < len(points)
    if not all(len(p) == 3 and all(number(c) for c in p) for p in points):
        return "none"
    if not all(len(t) == 3 and all(index(v) for v in t) for t in triangles):
        return "none"
    if not all(len(s) == 2 and all(index(v) for v in s) for s in segments):
        return "none"
    if not triangles and not segments:
        return "none"
    form = ([struct.pack("d", float(c)).hex() for p in points for c in p], [int(v) for t in triangles for v in t],
            [int(v) for s in segments for v in s])
    return hashlib.sha256(repr(form).encode()).hexdigest()[:20]


def python_drawn(meshing, shape):
    """drawn() of the Python meshing's answer, an exception as not drawn."""
    try:
        return drawn(meshing(shape))
    except Exception:
        return "none"
