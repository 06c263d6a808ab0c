// PlantGL's point grid and asymmetric hull in C++ (lpy/plantgl/point_grid.hpp,
// asymmetric_hull.hpp), which Sprout's openalea.plantgl calls for L-Py models. Their numbers
// and orders against the real L-Py: tests/reference/compare.py (spacecolonization.lpy,
// tests/lpy/models/point_grid_queries.lpy, whose expected strings came from L-Py).
#include <gtest/gtest.h>

#include <cmath>

#include "lpy/plantgl/asymmetric_hull.hpp"
#include "lpy/plantgl/point_grid.hpp"

using namespace sprout;

namespace {
PointGrid smallGrid() {
    return PointGrid({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 2}, {0.5, 0.5, 0.5}}, {1, 1, 1}, {0, 0, 0}, {2, 2, 2});
}
}  // namespace

TEST(PointGrid, BallQueryWalksVoxelsLastCoordinateFastestEachInItsOrder) {
    PointGrid g = smallGrid();
    // Voxel (0,0,0) holds 0 then 4; then (0,1,0) holds 2; then (1,0,0) holds 1. 3 is too far.
    EXPECT_EQ(g.ballQuery({0, 0, 0}, 1.0), (std::vector<std::uint32_t>{0, 4, 2, 1}));
    // Enabling puts a point back at its voxel's end.
    EXPECT_TRUE(g.disable(0));
    EXPECT_FALSE(g.disable(0));
    EXPECT_FALSE(g.enabled(0));
    EXPECT_EQ(g.ballQuery({0, 0, 0}, 1.0), (std::vector<std::uint32_t>{4, 2, 1}));
    EXPECT_TRUE(g.enable(0));
    EXPECT_FALSE(g.enable(0));
    EXPECT_EQ(g.ballQuery({0, 0, 0}, 1.0), (std::vector<std::uint32_t>{4, 0, 2, 1}));
    EXPECT_EQ(g.ballQuery({2, 2, 2}, 0.1), (std::vector<std::uint32_t>{3}));
    EXPECT_FALSE(g.disable(99));
}

TEST(PointGrid, ConeQueryKeepsPointsWithinHalfTheAngle) {
    PointGrid g = smallGrid();
    // Along +x with a 90 degree cone (45 on each side): (1,0,0) only; (0.5,0.5,0.5) is 54.7
    // degrees off, and the point at the apex has no direction.
    EXPECT_EQ(g.coneQuery({0, 0, 0}, {1, 0, 0}, 3.0, M_PI / 2), (std::vector<std::uint32_t>{1}));
    // A wider cone (120 degrees) takes (0.5,0.5,0.5) and (2,2,2) too, in the walk's order.
    EXPECT_EQ(g.coneQuery({0, 0, 0}, {2, 0, 0}, 4.0, 2 * M_PI / 3), (std::vector<std::uint32_t>{4, 1, 3}));
    EXPECT_TRUE(g.coneQuery({0, 0, 0}, {1, 0, 0}, 0.5, M_PI / 2).empty());
}

TEST(AsymmetricHull, MeridiansFromBottomToTopThroughTheQuadrantPoints) {
    AsymmetricHull h;
    h.posXRadius = 2, h.negXRadius = 1, h.posYRadius = 3, h.negYRadius = 4;
    h.posXHeight = 0.25;
    h.bottom = {0, 0, -1}, h.top = {0, 0, 2};
    h.slices = 1, h.stacks = 2;
    const HullMesh m = meshOf(h);
    // 4 meridians of 3 points (bottom half-way, the quadrant point, top half-way), then the ends.
    ASSERT_EQ(m.points.size(), 4u * 3u + 2u);
    ASSERT_EQ(m.triangles.size(), 4u * (2u + 2u * 2u));
    const auto& p = m.points[1];  // the +x point
    EXPECT_DOUBLE_EQ(p[0], 2);
    EXPECT_DOUBLE_EQ(p[1], 0);
    EXPECT_DOUBLE_EQ(p[2], 0.25);
    // Half-way from the bottom: x halves, the height goes as 0.5 to the power 2.
    EXPECT_DOUBLE_EQ(m.points[0][0], 1);
    EXPECT_DOUBLE_EQ(m.points[0][2], -1 + 1.25 * 0.25);
    EXPECT_NEAR(m.points[4][1], 3, 1e-12);   // the +y point (second meridian)
    EXPECT_NEAR(m.points[10][1], -4, 1e-12);  // the -y point (fourth)
    EXPECT_EQ(m.points[12], (std::array<double, 3>{0, 0, -1}));
    EXPECT_EQ(m.points[13], (std::array<double, 3>{0, 0, 2}));
    // The first triangle closes the first meridian to the bottom, the last the last to the top.
    EXPECT_EQ(m.triangles.front(), (std::array<std::uint32_t, 3>{0, 12, 3}));
    EXPECT_EQ(m.triangles.back(), (std::array<std::uint32_t, 3>{11, 2, 13}));
    for (const auto& t : m.triangles)
        for (auto i : t) EXPECT_LT(i, m.points.size());
}
