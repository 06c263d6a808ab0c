"""plant.parameters (issue 52): a model's objects from Python, read from its text and written
back as the viewer's editors write them; the plant made again from the new text."""
import pytest
import sprout

GUIDED = (
    "Axiom: _(0.15) SetGuide(path, 8) nF(8, 0.1)\nderivation length: 0\nproduction:\nendlsystem\n"
    "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\ndef __initialiseContext__(context):\n"
    "\timport openalea.plantgl.all as pgl\n\tpath = pgl.NurbsCurve2D(\t\n"
    "\t    ctrlPointList = pgl.Point3Array([(-0.5, 0, 1),(-0.1, 0.05, 1),(0.2, -0.05, 1),(0.5, 0, 1)]) , \n\t    )\n"
    "\tpath.name = \"path\"\n"
    "\tColor_1 = pgl.Material(\"Color_1\" , ambient = (10,60,10) , diffuse = 3 , )\n"
    "\tcontext.turtle.setMaterial(1,Color_1)\n"
    "\tscalars = [('H', 'Float', 0.5, 0.0, 1.0, 2)]\n\tcontext[\"__scalars__\"] = scalars\n"
    "\tfor s in scalars:\n\t\tif not s[1] == \"Category\" : context[s[0]] = s[2]\n"
    "\tcontext[\"path\"] = path\n"
)


def test_an_lpy_models_objects_are_listed_and_set():
    plant = sprout.parse(GUIDED, kind="lpy")
    assert sorted(plant.parameters) == ["H", "material 1", "path"]
    path = plant.parameters["path"]
    assert path.kind == "curve"
    assert path.points[2] == (0.2, -0.05, 1.0)
    before = plant.render(width=160, height=120)
    path.points = [(x, y + (0.6 if k == 2 else 0), w) for k, (x, y, w) in enumerate(path.points)]
    assert "(0.2, 0.55, 1)" in plant.text, "written in the text as L-Py Studio writes it"
    assert plant.parameters["path"].points[2] == (0.2, 0.55, 1.0)
    after = plant.render(width=160, height=120)
    assert (abs(before.astype(int) - after.astype(int)).sum(axis=2) > 40).sum() > 100, "the plant was made again"
    material = plant.parameters["material 1"]
    assert material.ambient == [10, 60, 10]
    material.ambient = (200, 20, 20)
    assert "ambient = (200,20,20)" in plant.text
    plant.parameters["H"].value = 0.75
    assert plant.parameters["H"].value == 0.75
    with pytest.raises(AttributeError):
        plant.parameters["H"].points = []
    with pytest.raises(KeyError):
        plant.parameters["nothing"]


def test_an_lsys_grammars_functions_and_contours():
    text = ("n: 6\nangle: 20\nfunction: len 0,0.2 0.5,1 1,0.2\ncontour: 1 closed 1,0.3 1,-0.3 -1,-0.3 -1,0.3\n"
            "axiom: #(1.5) @#(1) @Gs A(0) @Ge\nA(t) : t < 6 -> F(0.3 + 2*func(len, t/6)) +(12) A(t+1)\n")
    plant = sprout.parse(text)
    assert sorted(plant.parameters) == ["1", "len"]
    assert plant.parameters["1"].kind == "contour"
    def middle_length():
        return [m for m in plant.derive(6) if m[0] == "F"][3][1][0]  # the segment at t = 3/6

    length = middle_length()
    plant.parameters["len"].points = [(0, 0.2), (0.5, 0.1), (1, 0.2)]
    assert "function: len 0,0.2 0.5,0.1 1,0.2" in plant.text
    assert middle_length() < length - 0.5, "the function's middle lowered: a shorter segment"


def test_a_bad_value_leaves_the_plant_as_it_was():
    plant = sprout.parse(GUIDED, kind="lpy")
    with pytest.raises(ValueError):
        plant.parameters["material 1"].diffuse = 50  # 60 x 50 > 255: PlantGL would not keep it
    with pytest.raises(ValueError):
        plant.parameters["path"].points = [(0, float("nan"), 1), (1, 0, 1)]
    assert plant.text == GUIDED


def test_the_notebook_editor_moves_a_point_and_redraws():
    pytest.importorskip("ipywidgets")
    pytest.importorskip("matplotlib")
    plant = sprout.parse(GUIDED, kind="lpy")
    box = sprout.editor(plant, "path", width=160, height=120)
    assert len(box.rows) == 4, "a row of sliders a control point"
    picture, curve = box.picture.value, box.curve.value
    assert picture[:4] == b"\x89PNG" and curve[:4] == b"\x89PNG"
    box.rows[2].children[1].value = 0.5  # point 2's y
    assert plant.parameters["path"].points[2] == (0.2, 0.5, 1.0)
    assert box.picture.value != picture and box.curve.value != curve, "both pictures redrawn"


def test_a_category_is_a_heading_without_a_value():
    text = GUIDED.replace("scalars = [('H', 'Float', 0.5, 0.0, 1.0, 2)]", "scalars = [('Growth', 'Category'), ('H', 'Float', 0.5, 0.0, 1.0, 2)]")
    plant = sprout.parse(text, kind="lpy")
    assert [s["kind"] for s in sprout.lpy_scalars(plant.text)] == ["Category", "Float"]
    growth = plant.parameters["Growth"]
    assert growth.kind == "category"
    with pytest.raises(AttributeError):
        growth.value
    with pytest.raises(ValueError):
        sprout.set_lpy_scalar(plant.text, "Growth", 1.0)
    plant.parameters["H"].value = 0.25
    assert "('Growth', 'Category'), ('H', 'Float', 0.25, 0.0, 1.0, 2)" in plant.text


def test_a_texture_materials_image_is_listed_and_set():
    text = GUIDED.replace("\tcontext.turtle.setMaterial(1,Color_1)\n",
                          "\tcontext.turtle.setMaterial(1,Color_1)\n\tcontext.turtle.setMaterial(2,pgl.ImageTexture('leaf.png'))\n")
    plant = sprout.parse(text, kind="lpy")
    leaf = plant.parameters["material 2"]
    assert leaf.kind == "texture"
    assert leaf.image == "leaf.png"
    leaf.image = "bark.jpg"
    assert "setMaterial(2,pgl.ImageTexture('bark.jpg'))" in plant.text
    with pytest.raises(AttributeError):
        leaf.ambient
    with pytest.raises(ValueError):
        leaf.image = "it's.png"


def test_an_earlier_panels_version_of_a_curve_has_its_key():
    earlier = ("\tpath = pgl.NurbsCurve2D(pgl.Point3Array([(-0.5, 0, 1),(0, 0.3, 1),(0.5, 0, 1)]), degree = 2)\n"
               "\tpanel_9 = ({'name': 'Old'},[('Curve2D',path)])\n")
    text = GUIDED.replace("\tpath = pgl.NurbsCurve2D(\t\n", earlier + "\tpath = pgl.NurbsCurve2D(\t\n", 1)
    plant = sprout.parse(text, kind="lpy")
    assert "path#0" in plant.parameters and "path" in plant.parameters
    assert plant.parameters["path#0"].points[1] == (0.0, 0.3, 1.0)
    plant.parameters["path#0"].points = [(-0.5, 0, 1), (0, 0.9, 1), (0.5, 0, 1)]
    assert "[(-0.5, 0, 1),(0, 0.9, 1),(0.5, 0, 1)]" in plant.text
    assert plant.parameters["path"].points[2] == (0.2, -0.05, 1.0), "the last one as it was"

