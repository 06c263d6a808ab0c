"""`import sprout`: every kind of file, the derivation as a read-only sequence, the turtle's
geometry as numpy arrays, headless pictures, exports, and the notebook's picture and slider.
Run by ctest (Python.Pytest) with PYTHONPATH=build/python."""
import os
import struct

import numpy as np
import pytest

import sprout

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")


def test_preset_derives_the_fractal_plant():
    p = sprout.open("fractal_plant")
    assert (p.n, p.angle, p.dialect) == (5, 22.5, ".lsys")
    s = p.derive(1)
    assert str(s) == "F-[[X]+X]+F[+FX]-X"
    assert len(s) == 18
    assert s[0] == ("F", ()) and s[-1] == ("X", ())
    assert [m[0] for m in s][:4] == ["F", "-", "[", "["]
    with pytest.raises(IndexError):
        s[18]
    assert s.count("F") == 3


def test_steps_one_after_another():
    p = sprout.parse("n: 4\naxiom: A\nA -> AB\nB -> A\n")
    lengths = [len(s) for s in p.steps()]
    assert lengths == [1, 2, 3, 5, 8]  # Fibonacci, as ABOP's algae


def test_parameters_and_names_come_back():
    p = sprout.parse("n: 2\naxiom: A(1)\nA(x) -> F(x) SetContour('leaf') A(x * 2)\n")
    s = p.derive()
    assert s[0] == ("F", (1.0,))
    assert s[1] == ("SetContour", ("leaf",))
    assert s[-1] == ("A", (4.0,))
    assert list(s.params) == [1.0, 0.0, 2.0, 0.0, 4.0]


def test_the_string_is_a_view_not_a_copy():
    p = sprout.parse("n: 20\naxiom: A\nA -> AB\nB -> A\n")
    s = p.derive()
    assert len(s) == 17711
    a, b = s.symbols, s.symbols
    assert a.ctypes.data == b.ctypes.data  # the same memory each time: the derivation's own
    assert not a.flags.writeable
    names = [n for n, _ in s.alphabet]
    assert int((a == names.index("A")).sum()) == s.count("A") == 10946


def test_every_kind_of_file(tmp_path):
    cpfg = sprout.open(os.path.join(ROOT, "tests", "cpfg", sorted(f for f in os.listdir(os.path.join(ROOT, "tests", "cpfg")) if f.endswith(".l"))[0]))
    assert cpfg.dialect == "cpfg"
    notation = sprout.open(os.path.join(ROOT, "tests", "notation", "abop_1_24a.txt"))
    assert notation.dialect == "ABOP notation" and str(notation.derive(1)) == "F[+F]F[-F]F"
    lparser = sprout.parse("recursion 2\nangle 30\naxiom F\nF=F+F\n", kind="lparser")
    assert lparser.dialect == "Lparser" and lparser.n == 2
    fractint = tmp_path / "two.l"
    fractint.write_text("Koch {\n  Angle 6\n  Axiom F--F--F\n  F=F+F--F+F\n}\nOther {\n  Angle 4\n  Axiom F\n  F=FF\n}\n")
    k = sprout.open(str(fractint) + ":Koch")
    assert k.dialect == "Fractint" and str(k.derive(1)).startswith("F+F--F+F")
    lpy = sprout.open(os.path.join(ROOT, "tests", "lpy", "models", "native_branches.lpy"))
    assert lpy.dialect == "L-Py" and lpy.lpy_string == "F(2)[+F(1)[+X(2)][-X(2)]][-F(1)[+X(2)][-X(2)]]"
    with pytest.raises(ValueError, match="refuses"):
        sprout.open(os.path.join(ROOT, "tests", "lpy", "models", "native_branches.lpy"), python=False)
    png = tmp_path / "plant.png"
    sprout.open("fractal_plant").render(n=2, width=80, height=60, path=str(png))
    again = sprout.open(str(png))  # a picture Sprout wrote carries its grammar
    assert str(again.derive(2)) == str(sprout.open("fractal_plant").derive(2))


LAZY_MODEL = """Axiom: A(1)
derivation length: 2
production:
A(x) --> A(x + 1) B
interpretation:
B :
    if broken:
        raise ValueError("drawn")
    produce F(1)
endlsystem
"""


def test_an_lpy_model_is_derived_by_open_and_drawn_when_asked():
    # open() and derive() derive: the interpretation rule, which fails here, has not run.
    plant = sprout.parse("broken = True\n" + LAZY_MODEL, kind="lpy")
    assert str(plant.derive()) == "A(3)BB" and plant.lpy_string == "A(3)BB"
    assert [str(s) for s in plant.steps(2)] == ["A(1)", "A(2)B", "A(3)BB"]
    assert plant.derive(1)[1] == ("B", ())
    with pytest.raises(RuntimeError, match=r"^<model>:9:9: ValueError: drawn"):
        plant.geometry()
    # Drawn when asked, each step on its own, and kept.
    plant = sprout.parse("broken = False\n" + LAZY_MODEL, kind="lpy")
    assert [len(plant.geometry(n)["segments"]) for n in (2, 1, 0, 2)] == [2, 1, 0, 2]
    assert plant.render(n=1, width=40, height=30).shape == (30, 40, 4)


def test_an_lpy_crown_is_drawn_as_plantgl_meshes_it():
    # An AsymmetricHull is meshed in C++ (lpy/plantgl/meshes.cpp): 4 * slices meridians of
    # 2 * stacks - 1 points, 2 * (2 * stacks - 1) triangles each; the same mesh in a group as
    # alone.
    model = ("from openalea.plantgl.all import *\nAxiom: F(1) @g(AsymmetricHull(1, 2, 1, 2, 0.5, 0, 0, 0.5, "
             "(0, 0, -1), (0, 0, 2), 2, 3, %d, %d))\nderivation length: 0\nproduction:\nendlsystem\n")
    for slices, stacks in ((4, 4), (2, 3), (1, 1)):
        g = sprout.parse(model % (slices, stacks), kind="lpy").geometry()
        assert len(g["triangles"]) == 4 * slices * 2 * (2 * stacks - 1)
    import openalea.plantgl.all as pgl
    from _sprout_lpy import _shape_mesh
    hull = pgl.AsymmetricHull(1, 2, 1, 2, 0.5, 0, 0, 0.5, (0, 0, -1), (0, 0, 2), 2, 3, 4, 4)
    points, triangles, segments = _shape_mesh(hull)
    g = sprout.parse(model % (4, 4), kind="lpy").geometry()
    assert len(triangles) == len(g["triangles"])
    # The crown's top, 2 above its base along the turtle's heading (up), at the stem's end.
    assert abs(g["triangles"][..., 1].max() - (1 + 2)) < 1e-5


def test_errors_carry_line_and_column():
    with pytest.raises(sprout.GrammarError) as e:
        sprout.parse("n: 2\naxiom: F\nF -> F[+F\n")
    assert (e.value.line, e.value.col) == (3, 7)
    assert "never closed" in str(e.value)
    assert e.value.diagnostics[0][:3] == (3, 7, "error")
    with pytest.raises(ValueError):
        sprout.open("no_such_plant_anywhere")
    with pytest.raises(sprout.GrammarError) as e:
        sprout.parse("def f(:\n    pass\nAxiom: A\nproduction:\nA --> B\nendlsystem\n", kind="lpy")
    assert e.value.line == 1 and "SyntaxError" in str(e.value)


def test_geometry_as_numpy_arrays():
    p = sprout.open("fractal_plant")
    g = p.geometry(3)
    n = p.derive(3).count("F")
    assert g["segments"].shape == (n, 2, 3) and g["segments"].dtype == np.float32
    assert g["radii"].shape == (n, 2) and g["colors"].shape == (n, 4)
    # The first segment starts at the origin and goes up (+Y) one step.
    assert np.allclose(g["segments"][0], [[0, 0, 0], [0, 1, 0]], atol=1e-5)
    lo, hi = np.array(g["bounds"][0]), np.array(g["bounds"][1])
    assert np.all(g["segments"].reshape(-1, 3) >= lo - 1e-4) and np.all(g["segments"].reshape(-1, 3) <= hi + 1e-4)
    leafy = sprout.open("abop_1_26_flower_plant").geometry(3)
    assert leafy["triangles"].shape[1:] == (3, 3) and len(leafy["triangles"]) > 0


def test_render_to_numpy_and_png(tmp_path):
    p = sprout.open("fractal_plant")
    img = p.render(width=160, height=120, ground=False, shadows=False)
    assert img.shape == (120, 160, 4) and img.dtype == np.uint8
    empty = sprout.parse("axiom: X\n").render(width=160, height=120, ground=False, shadows=False)
    plant_pixels = int((np.abs(img.astype(int) - empty.astype(int)).max(axis=2) > 30).sum())
    assert plant_pixels > 200  # the plant is drawn over the sky
    green = img[..., 1].astype(int) - img[..., 2].astype(int)
    assert (green > 20).sum() > 50  # and it is green
    out = tmp_path / "p.png"
    p.render(width=64, height=48, path=str(out))
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", data[16:24]) == (64, 48)


def test_exports(tmp_path):
    p = sprout.open("fractal_plant")
    for ext in ("glb", "obj", "ply", "svg"):
        path = tmp_path / ("plant." + ext)
        stats = p.export(str(path), n=3)
        assert path.stat().st_size > 100 and stats["bytes"] > 0
    assert (tmp_path / "plant.glb").read_bytes()[:4] == b"glTF"
    assert (tmp_path / "plant.svg").read_text().lstrip().startswith("<?xml")
    with pytest.raises(ValueError, match="extension"):
        p.export(str(tmp_path / "plant.xyz"))


def test_notebook_picture_and_slider():
    p = sprout.open("koch")
    png = p._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    widgets = pytest.importorskip("ipywidgets")
    box = sprout.slider(p, width=120, height=90)
    before = box.image.value
    box.step.value = 1
    assert box.image.value != before and box.image.value[:4] == b"\x89PNG"
    assert box.step.max == p.n


def test_the_example_notebook_runs(tmp_path, monkeypatch):
    """examples/sprout.ipynb's code cells, in order, as a kernel would run them."""
    import json

    nb = json.load(open(os.path.join(ROOT, "examples", "sprout.ipynb"), encoding="utf-8"))
    monkeypatch.chdir(tmp_path)
    scope = {}
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            code = "".join(cell["source"])
            if "slider" in code:
                pytest.importorskip("ipywidgets")
            exec(compile(code, "sprout.ipynb", "exec"), scope)
    assert (tmp_path / "fractal_plant.glb").read_bytes()[:4] == b"glTF"
    assert scope["bush"].dialect == "ABOP notation"


def test_the_dask_sweep_writes_pictures_and_a_csv(tmp_path):
    """examples/sweep.py on a local cluster of one worker: a PNG and a CSV row per specimen."""
    pytest.importorskip("dask.distributed")
    import csv
    import subprocess
    import sys

    out = tmp_path / "sweep"
    r = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "sweep.py"), "--count", "6", "--workers", "1",
                        "--size", "48", "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr[-2000:]
    assert "6 specimens of stochastic_flower_plant" in r.stdout
    rows = list(csv.DictReader(open(out / "specimens.csv")))
    assert [int(x["seed"]) for x in rows] == [1, 2, 3, 4, 5, 6]
    assert len({x["modules"] for x in rows}) > 1  # seeds give other specimens
    for x in rows:
        assert (out / x["file"]).read_bytes()[:4] == b"\x89PNG" and int(x["segments"]) > 0


def test_a_quantised_function_is_called_in_c_with_the_pythons_numbers():
    # QuantisedFunction's call is C (lpy/plantgl/bind_quantised.cpp); its Python (_call_python) is the
    # reference: the same bits for every x, errors where it errs, and it pickles with its samples.
    import copy
    import pickle
    import random
    import struct

    sprout.parse("Axiom: A\nderivation length: 0\nproduction:\nendlsystem\n", kind="lpy")
    import openalea.plantgl.all as pgl
    curve = pgl.NurbsCurve2D([(0, 0.5, 1), (0.3, 1.5, 1), (0.7, 0.2, 1), (1, 1, 1)])
    rng = random.Random(5)
    # Its call is the C base's: the class defines none of its own.
    assert "__call__" not in vars(pgl.QuantisedFunction) and pgl.QuantisedFunction.__mro__[1].__name__ == "_QuantisedBase"
    for f in (pgl.QuantisedFunction(curve), pgl.QuantisedFunction([(0, 3), (0.5, -1), (2, 4)], 37)):
        xs = [0, 1, -1, 2, 10 ** 20, -0.0, float("inf"), True] + [rng.uniform(-1, 3) for _ in range(2000)]
        for x in xs:
            got, want = f(x), f._call_python(x)
            assert struct.pack("d", got) == struct.pack("d", want), x
        with pytest.raises(ValueError):
            f(float("nan"))  # math.floor(nan), as the Python raises it
        assert f(0.25) != f(0.75)  # not one value everywhere
        for g in (pickle.loads(pickle.dumps(f)), copy.deepcopy(f)):
            assert (g(0.3), g.getValue(0.7), g.sampling, g.clamped) == (f(0.3), f(0.7), f.sampling, f.clamped)


def test_the_shapes_given_to_at_g_are_meshed_in_c_as_the_python_meshes_them():
    # lpy/plantgl/meshes.cpp makes @g's shapes, all of them now, as the drawing made them when
    # part of them were the Python's (plantgl_drawing.py's _sprout_triangles, gone since):
    # 3,000 random shapes of every kind give what data/at_g_meshes.txt recorded then (the same
    # points to the bit, the same triangles and segments, or the same refusal).
    import sys

    sprout.parse("Axiom: A\nderivation length: 0\nproduction:\nendlsystem\n", kind="lpy")
    import openalea.plantgl.all as pgl
    from _sprout_lpy import _shape_mesh

    sys.path.insert(0, os.path.dirname(__file__))
    import at_g_shapes

    with open(os.path.join(os.path.dirname(__file__), "data", "at_g_meshes.txt")) as f:
        expected = [line.strip() for line in f if not line.startswith("#")]
    shapes = at_g_shapes.shapes(pgl, 3000)
    assert len(expected) == len(shapes) == 3000
    got = [at_g_shapes.drawn(_shape_mesh(s)) for s in shapes]
    wrong = [i for i, (g, e) in enumerate(zip(got, expected)) if g != e]
    assert not wrong, (len(wrong), wrong[:10])
    assert sum(1 for e in expected if e not in ("none", "empty")) > 2200  # most are drawn
    assert len(set(got)) > 2000  # and differ
    # What the Python meshed before: a curve in a group (its polyline after the box), no shape.
    curve = pgl.NurbsCurve([(0, 0, 0, 1), (1, 0, 0, 1), (1, 1, 0, 1)], 2)
    points, triangles, segments = _shape_mesh(pgl.Group([pgl.Box(1), curve]))
    assert (len(points), len(triangles), segments[0]) == (24 + 30, 12, (24, 25))
    assert _shape_mesh(pgl.Shape(None)) is None
    assert _shape_mesh(pgl.Box(0.5))[1][:2] == [(0, 1, 2), (0, 2, 3)]
