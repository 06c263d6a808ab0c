"""Sprout's openalea.plantgl: the cardinal splines (scenegraph.cspline), the light model
(openalea.plantgl.light) and its z-buffer, and members models call. Every expected number here
was printed by the reference PlantGL 3.22.3 (plantgl 6e01c6d, built by
../shared/tools/build-lpy-reference.sh) on the same code; tests/reference/plantgl_differential.py
compares the two directly where the reference is built."""
import math

import pytest

import sprout

sprout.use_as_openalea()

import openalea.plantgl.all as pgl  # noqa: E402
from openalea.plantgl.all import (Box, BoundingBox, Color4, Material, Matrix3, NurbsCurve, Polyline, Scene,  # noqa: E402
                                  Shape, Sphere, Translated, TriangleSet, Scaled, Vector3, ZBufferEngine)


def close(a, b, tol=1e-12):
    a, b = list(a), list(b)
    return len(a) == len(b) and all(abs(x - y) <= tol * max(1.0, abs(x), abs(y)) for x, y in zip(a, b))


def test_cspline_makes_plantgls_control_points_knots_and_stride():
    from openalea.plantgl.scenegraph.cspline import CSpline
    n = CSpline([Vector3(0, 0, 0), Vector3(1, 1, 0), Vector3(2, 0, 1), Vector3(3, 2, 2)]).curve()
    assert type(n).__name__ == 'NurbsCurve' and n.degree == 3 and n.stride == 30
    # From the reference:
    expected = [(0, 0, 0, 1), (1 / 6, 1 / 6, 0, 1), (2 / 3, 1, -1 / 6, 1), (1, 1, 0, 1), (4 / 3, 1, 1 / 6, 1),
                (5 / 3, -1 / 6, 2 / 3, 1), (2, 0, 1, 1), (7 / 3, 1 / 6, 4 / 3, 1), (17 / 6, 5 / 3, 11 / 6, 1), (3, 2, 2, 1)]
    assert all(close(p, q) for p, q in zip(n.ctrlPointList, expected)) and len(n.ctrlPointList) == 10
    assert close(n.knotList, [0.0] * 4 + [1.4142135623730951] * 3 + [3.1462643699419726] * 3 + [5.59575411272515] * 4)
    # Evaluated: the reference's getPointAt and getLength.
    assert close(n.getPointAt(n.lastKnot / 7), (0.5118392501384963, 0.6507462851550093, -0.06945351750825657), 1e-9)
    assert abs(n.getLength() - 5.615454374272969) < 1e-9


def test_cspline_2d_closed_linear_and_its_errors():
    from openalea.plantgl.scenegraph.cspline import CSpline, cspline
    n = cspline([(0, 0), (1, 2), (3, 1), (4, 4)])
    assert type(n).__name__ == 'NurbsCurve2D' and n.stride == 30
    assert close(n.ctrlPointList[2], (0.5, 11 / 6, 1)) and close(n.knotList[4:7], [math.sqrt(5)] * 3)
    c = cspline([Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(1, 1, 0), Vector3(0, 1, 0)], is_closed=True)
    assert len(c.ctrlPointList) == 13 and close(c.ctrlPointList[1], (5 / 6, -1 / 6, 0, 1))  # reference
    lin = CSpline([Vector3(0, 0, 0), Vector3(2, 1, 0), Vector3(3, 3, 1)]).curve(is_linear=True, stride_factor=4)
    assert close(lin.knotList, [0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2]) and lin.stride == 8
    closed = CSpline([Vector3(0, 0, 0), Vector3(1, 0, 0)], is_closed=True)
    with pytest.raises(Exception, match="Unable to add a point to a closed curve"):
        closed.add_point(Vector3(1, 1, 1))
    with pytest.raises(Exception, match=r"Index 5 out of range \[0,3\["):
        closed.move_point(5, Vector3(1, 1, 1))
    assert NurbsCurve.CSpline is not None and pgl.cspline.CSpline is CSpline


def test_light_model_imports_as_models_write_them():
    from openalea.plantgl.light.light import diffuseInterception, directInterception  # noqa: F401
    from openalea.plantgl.light import directionalInterception  # noqa: F401
    from openalea.plantgl.light.utils import azel2vect
    from openalea.plantgl.light.sky import soc_sky_sources
    assert len(soc_sky_sources(1)) == 46
    assert close(azel2vect(30, 45), (-0.6123724356957945, 0.3535533905932737, -0.7071067811865476), 1e-12)  # reference
    with pytest.raises(TypeError):
        diffuseInterception(Scene())  # PlantGL 3.22's takes the global horizontal irradiance: ghi


SQUARE = TriangleSet([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3)])


def square_scene():
    return Scene([Shape(SQUARE, Material(), 7), Shape(Translated((0.25, 0.25, 1), Scaled((0.5, 0.5, 1), SQUARE)), Material(), 8)])


def test_directional_interception_gives_plantgls_numbers():
    # From above, a square under a square half its side: the reference's 0.75 and 0.25.
    light = pgl.directionalInterception(square_scene(), [(90, 0, 1)])
    assert sorted(light) == [7, 8] and abs(light[7] - 0.75) < 1e-9 and abs(light[8] - 0.25) < 1e-9
    # From the side (elevation 10, azimuth 30, weight 2): the reference's 0.3462 and 0.0868.
    light = pgl.directionalInterception(square_scene(), [(10, 30, 2)])
    assert abs(light[7] - 0.3462) < 1e-9 and abs(light[8] - 0.0868) < 1e-9


def test_diffuse_interception_of_a_sphere_and_a_box():
    sc = Scene([Shape(Sphere(1), Material(), 3), Shape(Translated((0, 0, 3), Box((1, 1, 1))), Material(), 5)])
    light = pgl.diffuseInterception(sc, 1)
    # The reference: {3: 3.9437312483899456, 5: 10.073104888425116} (the box's pixels are the
    # reference's; the sphere's mesh differs from PlantGL's in its last bits: 1e-4).
    assert abs(light[5] - 10.073104888425116) < 1e-9
    assert abs(light[3] - 3.9437312483899456) < 1e-3 * 3.94


def test_zbuffer_counts_the_pixels_of_each_shape():
    z = ZBufferEngine(20, 20, renderingStyle=pgl.eIdBased)
    z.setOrthographicCamera(-1, 1, -1, 1, 1, 5)
    z.lookAt(Vector3(0.5, 0.5, 3), Vector3(0.5, 0.5, 0), Vector3(0, 1, 0))
    z.process(square_scene())
    assert dict(z.idhistogram(False)) == {7: 96, 8: 25}  # the reference's


def test_surfaces_bounds_and_projection_as_plantgl():
    got = [pgl.surface(Sphere(2)), pgl.surface(Box((1, 2, 3))), pgl.surface(pgl.Cylinder(1, 2)),
           pgl.surface(pgl.Cone(1, 3)), pgl.surface(pgl.Frustum(1, 2, 0.5)), pgl.surface(pgl.Disc(2))]
    assert close(got, [50.2654824576, 88.0, 18.8495559216, 13.07618091942838, 14.427227737992956, 12.5663706144])
    b = BoundingBox(Scene([Shape(Sphere(1)), Shape(Translated((0, 0, 3), Box((1, 1, 1))))]))
    assert close(b.lowerLeftCorner, (-1, -1, -1)) and close(b.upperRightCorner, (1, 1, 4))
    m = pgl.getProjectionMatrix(Vector3(1, 1, -1), Vector3(0, 0, 1))
    assert close(m.getRow(1), (0.40824829046386296, 0.40824829046386296, 0.8164965809277259))  # reference


def test_members_models_call_give_plantgls_values():
    assert close(Vector3(1, 2, 2).anOrthogonalVector(), (-2 / 3, 1 / 3, 0))  # reference: (-y, x, 0) / |v|
    m = Matrix3(Vector3(1, 0, 2), Vector3(0, 3, 0), Vector3(1, 1, 1))  # columns, as PlantGL
    assert close(m.getRow(0), (1, 0, 1)) and close(m.inverse().getRow(2), (2, 0, -1))
    assert Color4(10, 20, 30, 40).toUint() == 337520650 and Color4.fromUint(337520650) == Color4(10, 20, 30, 40)
    p = Polyline([(0, 0, 0), (1, 0, 0), (1, 2, 0), (1, 2, 3)])
    assert p.stride == 3 and close(p.getTangentAt(1), (1.5, 1.5, 0)) and abs(p.getLength() - 6) < 1e-12
    assert abs(p.getLength(0.5, 2.5) - 4) < 1e-12
    sh = Shape(Sphere(), Material(), 5)
    assert sh.name.startswith('SHAPEID_5_') and sh.appearance.name.startswith('APPID_5_')
    assert Sphere().radius == 0.5 and Sphere.DEFAULT_STACKS == 8 and not Sphere(2).isRadiusToDefault()
    with pytest.raises(IndexError):
        Scene([sh]).find(6)
    with pytest.raises(NotImplementedError, match=r"\.bgeom"):
        Scene([sh]).save("tree.bgeom")
