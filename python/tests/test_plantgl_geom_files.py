"""Sprout's openalea.plantgl: PlantGL's text scene files (.geom) written by Scene.save and read by
Scene(file) (lpy/plantgl/plantgl_geomfile.py). The file read here is written by hand in the form
PlantGL's printer writes; tests/reference/plantgl_differential.py checks, where the reference
PlantGL is built, that it reads the same text and Sprout's saved files to the same numbers."""
import os

import pytest

import sprout

sprout.use_as_openalea()

from openalea.plantgl.all import (AxisRotated, Box, Color3, Cone, Cylinder, EulerRotated, Group, Material,  # noqa: E402
                                  Oriented, Polyline, Scene, Shape, Sphere, Translated, TriangleSet, Vector3)

TEXT = """# a scene, as PlantGL writes one
Translated T1 {
    Translation <1,2,3>
    Geometry Oriented {
        Primary <0,0,1>
        Secondary <1,0,0>
        Geometry Cylinder { Radius 0.1 Height 2.5 Solid False Slices 5 }
    }
}
Material M1 {
    Ambient <10,200,30>
    Diffuse 1.2
    Emission 1
    Transparency 0.25
}
Shape S1 { Id 4 Geometry T1 Appearance M1 }
AxisRotated A1 { Axis <0,1,0> Angle 30 Geometry Box { Size <1,2,3> } }
Shape S2 { Id 9 Geometry A1 Appearance M1 }
Shape S3 { Id 2 Geometry TriangleSet { PointList [ <0,0,0>, <1,0.5,0>, <0,1,0.25> ] IndexList [ [0,1,2] ] } }
Sphere Alone { Radius 2 }
"""


def test_a_file_as_plantgl_writes_it_is_read(tmp_path):
    path = tmp_path / "scene.geom"
    path.write_text(TEXT)
    sc = Scene(str(path))
    assert [sh.id for sh in sc[:3]] == [4, 9, 2]
    first = sc[0]
    assert type(first.geometry).__name__ == 'Translated' and tuple(first.geometry.translation) == (1, 2, 3)
    oriented = first.geometry.geometry
    assert tuple(oriented.primary) == (0, 0, 1) and tuple(oriented.secondary) == (1, 0, 0)
    cyl = oriented.geometry
    assert (cyl.radius, cyl.height, cyl.solid, cyl.slices) == (0.1, 2.5, False, 5)
    m = first.appearance
    assert tuple(m.ambient) == (10, 200, 30) and m.diffuse == 1.2 and tuple(m.emission) == (1, 1, 1)
    assert m.transparency == 0.25 and m.shininess == 0.2  # a field left out is its default
    assert sc[1].appearance is m  # one material, named twice
    # Degrees in the file, radians in the scene, with PlantGL's constant (GEOM_RAD).
    assert sc[1].geometry.angle == 30 * 0.01745329252
    assert [tuple(p) for p in sc[2].geometry.pointList] == [(0, 0, 0), (1, 0.5, 0), (0, 1, 0.25)]
    assert [tuple(i) for i in sc[2].geometry.indexList] == [(0, 1, 2)]
    # A geometry no shape names is a shape of its own, with the default material.
    assert len(sc) == 4 and sc[3].geometry.radius == 2 and sc[3].appearance is Material.DEFAULT_MATERIAL


def test_a_saved_scene_reads_back_the_same_numbers(tmp_path):
    m = Material((10, 200, 30))
    m.diffuse, m.specular, m.shininess = 1.2, Color3(5, 6, 7), 0.5
    shapes = [Shape(Translated(Vector3(1, 2, 3), Oriented(Vector3(0, 0, 1), Vector3(1, 0, 0), Cylinder(0.1, 2.5))), m, 10),
              Shape(AxisRotated((0, 1, 0), 1.0, Box((1, 2, 3))), Material((1, 2, 3)), 11),
              Shape(EulerRotated(0.1, 0.2, 0.3, Group([Sphere(1 / 3), Cone(1, 2)])), m, 12),
              Shape(TriangleSet([(0, 0, 0), (1, 0.1, 0), (0, 1, 0.7)], [(0, 1, 2)]), m, 13),
              Shape(Polyline([(0, 0, 0), (1e-7, 1, 2.5)]), m, 14)]
    path = str(tmp_path / "saved.geom")
    assert Scene(shapes).save(path)
    text = open(path).read()
    assert "Angle 57.295779513" in text and "Shape SHAPEID_10_" in text
    assert not [f for f in os.listdir(tmp_path) if f != "saved.geom"]  # no temporary left
    back = Scene(path)
    assert [sh.id for sh in back] == [10, 11, 12, 13, 14]
    assert tuple(back[0].geometry.translation) == (1, 2, 3) and back[0].geometry.geometry.geometry.radius == 0.1
    assert back[0].appearance is back[2].appearance and tuple(back[0].appearance.specular) == (5, 6, 7)
    assert abs(back[1].geometry.angle - 1.0) < 1e-10
    group = back[2].geometry.geometry
    assert group.geometryList[0].radius == 1 / 3 and group.geometryList[1].height == 2
    assert [tuple(p) for p in back[3].geometry.pointList] == [(0, 0, 0), (1, 0.1, 0), (0, 1, 0.7)]
    assert tuple(back[4].geometry.pointList[1]) == (1e-7, 1, 2.5)


def test_broken_files_say_where(tmp_path):
    from openalea.plantgl._geomfile import GeomError
    cases = {"Sphere { Radius 1 ": ":1: the file ends", "Shape S { Geometry Nowhere }": "names no object",
             "\n\nTeapot T { }": ":3: Teapot: a type of object", "Sphere { Radius @ }": "not PlantGL's text format",
             "Material M { Colour <1,2,3> }": "Material has no field colour"}
    for text, said in cases.items():
        path = tmp_path / "bad.geom"
        path.write_text(text)
        with pytest.raises(GeomError) as e:
            Scene(str(path))
        assert said in str(e.value), (text, str(e.value))
    with pytest.raises(NotImplementedError):
        Scene(str(tmp_path / "binary.bgeom"))
    with pytest.raises(NotImplementedError):
        Scene([]).save(str(tmp_path / "binary.bgeom"))
