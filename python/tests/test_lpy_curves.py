"""sprout.lpy_curves and sprout.set_lpy_curve (issue 52): an L-Py model's 2D curves as the
viewer's curve editor reads and writes them, from Python. tests/reference/lpy_curves_roundtrip.py
checks, where the reference L-Py is built, that L-Py reads the written curves back."""
import pytest

import sprout

MODEL = ("Axiom: A\nderivation length: 1\nproduction:\nA --> B\nendlsystem\n"
         "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\n"
         "def __initialiseContext__(context):\n"
         "\timport openalea.plantgl.all as pgl\n"
         "\tpath = pgl.NurbsCurve2D(\t\n"
         "\t    ctrlPointList = pgl.Point3Array([(-0.5, 0, 1),(0, 0.25, 1),(0.5, 0, 1)]) , \n\t    )\n"
         "\tpanel_0 = ({'name': 'Panel 1', 'active': False, 'visible': True},[('Curve2D',path)])\n"
         "\tpath = pgl.NurbsCurve2D(\t\n"
         "\t    ctrlPointList = pgl.Point3Array([(-0.5, 0, 1),(0, 0.5, 1),(0.5, 0, 1)]) , \n\t    )\n"
         "\tshape = pgl.Polyline2D([(0, 0),(1, 1)])\n"
         "\tpanel_1 = ({'name': 'Panel 2', 'active': True, 'visible': True},[('Curve2D',path),('Function',shape)])\n")


def test_curves_are_listed_with_their_numbers():
    curves = sprout.lpy_curves(MODEL)
    assert [(c['name'], c['kind'], c['function'], c['degree']) for c in curves] == [
        ('path', 'NURBS', False, 2), ('path', 'NURBS', False, 2), ('shape', 'Polyline', True, 3)]
    assert curves[1]['points'][1] == [0, 0.5, 1] and curves[1]['line'] == 16


def test_a_curve_set_is_written_in_place_the_last_of_its_name():
    text = sprout.set_lpy_curve(MODEL, 'path', [(-0.5, 0, 1), (0.125, 2 / 3, 1), (0.5, 0, 1)])
    assert "Point3Array([(-0.5, 0, 1),(0.125, 0.666667, 1),(0.5, 0, 1)])" in text
    assert text.count("(0, 0.25, 1)") == 1  # the first panel's curve of that name is as it was
    assert sprout.lpy_curves(text)[1]['points'][1] == [0.125, 0.666667, 1]
    assert sprout.set_lpy_curve(text, 'path', sprout.lpy_curves(MODEL)[1]['points']) == MODEL
    with pytest.raises(KeyError):
        sprout.set_lpy_curve(MODEL, 'nothing', [(0, 0, 1), (1, 1, 1)])
    with pytest.raises(ValueError):
        sprout.set_lpy_curve(MODEL, 'path', [(0, 0, 1)])
    with pytest.raises(ValueError):
        sprout.set_lpy_curve(MODEL, 'path', [(0, 0, 1), (float('nan'), 1, 1)])


MATERIALS = (
    "def __initialiseContext__(context):\n"
    "\tColor_1 = pgl.Material(\"Color_1\" , ambient = (10,60,10) , diffuse = 3 , )\n"
    "\tcontext.turtle.setMaterial(1,Color_1)\n"
    "\tcontext.turtle.setMaterial(2,Material('Red',Color3(39,0,0),4.5,Color3(40,40,40),Color3(0,0,0),1,0))\n"
)


def test_materials_are_read_and_set_in_place():
    m = sprout.lpy_materials(MATERIALS)
    assert [x["index"] for x in m] == [1, 2]
    assert m[0]["ambient"] == [10, 60, 10] and m[0]["diffuse"] == 3 and m[0]["specular"] == [0, 0, 0]
    assert m[1]["name"] == "Red" and m[1]["shininess"] == 1
    text = sprout.set_lpy_material(MATERIALS, 1, "ambient", (80, 10, 10))
    assert text == MATERIALS.replace("(10,60,10)", "(80,10,10)")
    text = sprout.set_lpy_material(text, 2, "transparency", 0.5)
    assert "Color3(0,0,0),1,0.5))" in text
    assert sprout.lpy_materials(text)[1]["transparency"] == 0.5


def test_a_material_refuses_what_plantgl_would_not_keep():
    with pytest.raises(ValueError):
        sprout.set_lpy_material(MATERIALS, 1, "diffuse", 5)  # 60 x 5 > 255
    with pytest.raises(ValueError):
        sprout.set_lpy_material(MATERIALS, 1, "ambient", (300, 0, 0))
    with pytest.raises(KeyError):
        sprout.set_lpy_material(MATERIALS, 7, "diffuse", 1)
    with pytest.raises(KeyError):
        sprout.set_lpy_material(MATERIALS, 1, "glow", 1)


PATCH = ("Axiom: @g(sheet)\nderivation length: 0\n###### INITIALISATION ######\n\ndef __initialiseContext__(context):\n"
         "\timport openalea.plantgl.all as pgl\n"
         "\tsheet = pgl.NurbsPatch(pgl.Point4Matrix([[(0, 0, 0, 1), (0, 1, 0, 1)], [(1, 0, 0, 1), (1, 1, 0, 1)]]), udegree = 1, vdegree = 1)\n"
         "\tcontext[\"sheet\"] = sheet\n")


def test_a_patch_takes_rows_and_weights_as_long_as_its_degree_allows():
    [sheet] = sprout.lpy_patches(PATCH)
    assert len(sheet["points"]) == 2 and sheet["udegree"] == 1
    rows = [list(r) for r in sheet["points"]]
    rows.insert(1, [(0.5, 0, 0.2, 1), (0.5, 1, 0.2, 3)])  # a row between, one point heavier
    text = sprout.set_lpy_patch(PATCH, "sheet", rows)
    [grown] = sprout.lpy_patches(text)
    assert len(grown["points"]) == 3
    assert tuple(grown["points"][1][1]) == (0.5, 1, 0.2, 3)
    with pytest.raises(ValueError):
        sprout.set_lpy_patch(PATCH, "sheet", rows[:1])  # fewer rows than its degree + 1
    with pytest.raises(ValueError):
        sprout.set_lpy_patch(PATCH, "sheet", [rows[0], rows[1][:1], rows[2]])  # not a matrix
