// PlantGL's curves (lpy/plantgl/curves.hpp): points, derivatives, normals, lengths, arc-length
// mappings and QuantisedFunction values against the real PlantGL's, to within 1e-12 (PlantGL
// rounds in another order: the last bits differ), and against the Python this replaced
// (lpy/plantgl/plantgl_curves.py before the C++, which drew every .lpy model so far) to the
// last bit: a model's drawing must not move.
//
// The PlantGL numbers came from PlantGL 3.22 via the reference build (/work/lpy-reference,
// its venv's python), printed with repr() from:
//
//   from openalea.plantgl.all import *
//   c2 = NurbsCurve2D([(0,0,1),(1,2,1),(2,-1,2),(3,1,1),(4,0,1)])
//   c2.getPointAt(0.3); c2.getTangentAt(0.3); c2.getNormalAt(0.3); c2.getLength()
//   c2.getLength(0.13, 0.77)
//   c3 = NurbsCurve([(0,0,0,1),(1,0,1,1),(1,1,2,0.5),(0,1,3,1),(0.5,0.5,4,1),(0,0,5,1)],
//                   degree=2, knotList=[0,0,0,0.2,0.5,0.6,1,1,1])
//   c3.getPointAt(0.55); c3.getTangentAt(0.55); c3.getNormalAt(0.55); c3.getLength()
//   c3.getArcLengthToUMapping()(0.5); c3.getUToArcLengthMapping()(0.4)
//   QuantisedFunction(NurbsCurve2D([(0,0.5,1),(0.3,1.5,1),(0.7,0.2,1),(1,1,1)]))(0.123)
//   BezierCurve2D([(0,0,1),(1,3,1),(2,0,1)]).getPointAt(0.4)
//   Polyline2D([(0,0),(1,2),(3,3)]).getPointAt(1.25)
//   NurbsPatch([[(0,0,0,1),(0,1,0,1),(0,2,0,1)],[(1,0,1,1),(1,1,2,1),(1,2,1,1)],
//               [(2,0,0,1),(2,1,1,1),(2,2,0,1)]], 2, 2).getPointAt(0.3, 0.6)
//
// The Python's numbers (ExactlyThePythons) came from the same calls on git's
// lpy/plantgl/plantgl_curves.py of commit d2e0dfc, run by Sprout's `sprout` module.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lpy/plantgl/curves.hpp"

namespace sprout::curves {
namespace {

// NurbsCurve2D(points): degree 3, the uniform clamped knots (as the Python makes them).
Nurbs curve2D(std::vector<double> ctrl, int degree = 3) {
    const int n = int(ctrl.size() / 3);
    return Nurbs(2, degree, uniformClampedKnots(n, degree), std::move(ctrl));
}

Nurbs c2() { return curve2D({0, 0, 1, 1, 2, 1, 2, -1, 2, 3, 1, 1, 4, 0, 1}); }
Nurbs c3() {
    return Nurbs(3, 2, {0, 0, 0, 0.2, 0.5, 0.6, 1, 1, 1},
                 {0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 2, 0.5, 0, 1, 3, 1, 0.5, 0.5, 4, 1, 0, 0, 5, 1});
}

// PlantGL's numbers, to within 1e-12 of their size (or of 1, near 0).
void expectNear(double a, double b) { EXPECT_NEAR(a, b, 1e-12 * std::max(1.0, std::fabs(b))); }
void expectPoint(const Point& p, double x, double y, double z = 0.0) {
    expectNear(p[0], x);
    expectNear(p[1], y);
    expectNear(p[2], z);
}
// The Python's numbers: the same doubles.
void expectSame(const Point& p, double x, double y, double z = 0.0) {
    EXPECT_EQ(p[0], x);
    EXPECT_EQ(p[1], y);
    EXPECT_EQ(p[2], z);
}

TEST(Curves, Nurbs2DPointsAndDerivatives) {
    const Nurbs c = c2();
    expectPoint(c.pointAt(0.0), 0.0, 0.0);
    expectPoint(c.pointAt(0.3), 1.5226586102719029, 0.3942598187311178);
    expectPoint(c.pointAt(0.77), 2.728430639704147, 0.16939931020012072);
    expectPoint(c.pointAt(1.0), 4.0, 0.0);
    expectPoint(c.pointAt(7.0), 4.0, 0.0);  // clamped to the last knot
    expectPoint(c.derivativeAt(0.3, 1), 3.1475616323326743, -3.736959319465868);
    expectPoint(c.normalAt(0.3), -0.3010722172100607, -0.2535867475236966);
    expectPoint(c.derivativeAt(0.3, 4), 0.0, 0.0);  // past the degree
}

TEST(Curves, Nurbs2DLength) {
    const Nurbs c = c2();
    expectNear(c.length(c.firstKnot(), c.lastKnot(), 30), 4.973764997357748);
    expectNear(c.length(0.13, 0.77, 30), 2.4373495575850135);
}

TEST(Curves, Nurbs3DWithKnots) {
    const Nurbs c = c3();
    expectPoint(c.pointAt(0.1), 0.736842105263158, 0.05263157894736842, 0.7894736842105262);
    expectPoint(c.pointAt(0.55), 0.05806451612903223, 0.9741935483870966, 3.019354838709677);
    expectPoint(c.pointAt(0.9), 0.19374999999999998, 0.24374999999999997, 4.5125);
    expectPoint(c.derivativeAt(0.55, 1), -0.33298647242455515, -0.9989594172736745, 3.329864724245579);
    expectPoint(c.normalAt(0.55), 4.062409090909087, -1.3541363636363621, -3.582281698167404e-15);
    expectNear(c.length(c.firstKnot(), c.lastKnot(), 30), 6.163604489047469);
}

TEST(Curves, ArcLengthMappings) {
    const Nurbs c = c3();
    // getArcLengthToUMapping(): the polyline quantised with 5 * stride samples.
    const Quantised toU = quantise(Polyline2D(c.arcLengthToU(30)), 150);
    expectNear(toU(0.25), 0.17360687255859375);
    expectNear(toU(0.5), 0.40076446533203125);
    expectNear(toU(0.8), 0.7740295410156249);
    const Quantised toArc = quantise(Polyline2D(c.uToArcLength(30)), 150);
    expectNear(toArc(0.4), 0.49902250056111963);
}

TEST(Curves, QuantisedFunction) {
    const Quantised f = quantise(curve2D({0, 0.5, 1, 0.3, 1.5, 1, 0.7, 0.2, 1, 1, 1, 1}), 100);
    ASSERT_EQ(f.values.size(), 100u);
    expectNear(f(0.0), 0.5);
    expectNear(f(0.123), 0.784994050143106);
    expectNear(f(0.5), 0.824993069213815);
    expectNear(f(0.999), 0.9974199308223444);
    expectNear(f(1.0), 1.0);
    expectNear(f(-3.0), 0.5);  // clamped to its first x
}

TEST(Curves, BezierAndPolyline) {
    // BezierCurve2D: degree n - 1, knots n zeros then n ones.
    const Nurbs bezier(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1, 3, 1, 2, 0, 1});
    expectPoint(bezier.pointAt(0.4), 0.7999999999999999, 1.44);
    const Polyline2D line({{0, 0}, {1, 2}, {3, 3}});
    expectPoint(line.pointAt(1.25), 1.5, 2.25);
    expectPoint(line.pointAt(2.0 - 1e-6), 3.0, 3.0);  // within 1e-5 of a point: the point
}

TEST(Curves, NurbsPatch) {
    const NurbsPatch patch({{0, 0, 0, 1, 0, 1, 0, 1, 0, 2, 0, 1}, {1, 0, 1, 1, 1, 1, 2, 1, 1, 2, 1, 1}, {2, 0, 0, 1, 2, 1, 1, 1, 2, 2, 0, 1}},
                           2, 2, {}, {});
    expectPoint(patch.pointAt(0.3, 0.6), 0.6000000000000001, 1.2, 0.6648000000000001);
    // The grid is the same points, i outer.
    const std::vector<Point> grid = patch.grid(10);
    ASSERT_EQ(grid.size(), 121u);
    EXPECT_EQ(grid[3 * 11 + 6], patch.pointAt(0.3, 0.6));
}

TEST(Curves, ExactlyThePythons) {
    const Nurbs a = c2(), b = c3();
    expectSame(a.pointAt(0.3), 1.522658610271903, 0.3942598187311179);
    expectSame(a.normalAt(0.3), -0.30107221721006083, -0.25358674752369664);
    EXPECT_EQ(a.length(a.firstKnot(), a.lastKnot(), 30), 4.9737649973577485);
    EXPECT_EQ(a.length(0.13, 0.77, 30), 2.437349557585014);
    expectSame(b.derivativeAt(0.55, 2), 48.80937195797388, -18.733174448658996, 7.3901513880031295);
    EXPECT_EQ(b.length(b.firstKnot(), b.lastKnot(), 30), 6.1636044890474695);
    EXPECT_EQ(quantise(Polyline2D(b.arcLengthToU(30)), 150)(0.5), 0.40076446533203125);
    EXPECT_EQ(quantise(Polyline2D(b.uToArcLength(30)), 150)(0.4), 0.4990225005611195);
    const Quantised f = quantise(curve2D({0, 0.5, 1, 0.3, 1.5, 1, 0.7, 0.2, 1, 1, 1, 1}), 100);
    EXPECT_EQ(f(0.123), 0.7849940501431061);
    EXPECT_EQ(f.values[37], 0.8852704638720184);
    // A weight other than 1 inside: PlantGL keeps the weights along u (homogeneous
    // coordinates), as the patch now does (issue 51; the Python before gave (0.6, 1.17276,
    // 0.73563)). PlantGL 3.22.3's numbers, printed by the reference.
    const NurbsPatch patch({{0, 0, 0, 1, 0, 1, 0, 1, 0, 2, 0, 1}, {1, 0, 1, 1, 1, 1, 2, 2, 1, 2, 1, 1}, {2, 0, 0, 1, 2, 1, 1, 1, 2, 2, 0, 1}},
                           2, 2, {}, {});
    expectPoint(patch.pointAt(0.3, 0.6), 0.6671105193075899, 1.1664447403462048, 0.8888149134487351);
}

TEST(Curves, RefusesWhatThePythonCannotIndex) {
    EXPECT_THROW(Nurbs(2, 3, {0, 0, 1, 1}, {0, 0, 1, 1, 1, 1}), std::out_of_range);  // degree past the points
    EXPECT_THROW(Nurbs(2, 1, {0, 1}, {0, 0, 1, 1, 1, 1}), std::out_of_range);        // too few knots
    EXPECT_THROW(Polyline2D({}), std::out_of_range);
}

}  // namespace
}  // namespace sprout::curves
