// The curve editor's operations (app/plant/curve_edit.hpp): what the panel, the script and
// Python do to a curve's points, checked on the points they give.
#include <gtest/gtest.h>

#include <cmath>

#include "app/plant/curve_edit.hpp"

namespace sprout {
namespace {

const CurvePoints kFour = {{-0.5, 0, 1}, {-0.1, 0.05, 1}, {0.2, -0.05, 1}, {0.5, 0, 1}};
const CurvePoints kFunction = {{0, 0, 1}, {0.3, 0.5, 1}, {0.7, 0.2, 1}, {1, 1, 1}};

TEST(CurveEdit, AFunctionKeepsItsOrderAndItsEnds) {
    CurveRules f;
    f.function = true;
    EXPECT_EQ(movedPoint(kFunction, f, 1, 0.9, 2)[1], (std::array<double, 3>{0.7, 2, 1})) << "x stops at the next point";
    EXPECT_EQ(movedPoint(kFunction, f, 0, 0.4, 3)[0], (std::array<double, 3>{0, 3, 1})) << "the first stays at x = 0";
    EXPECT_EQ(movedPoint(kFunction, f, 3, 0.2, 3)[3], (std::array<double, 3>{1, 3, 1})) << "the last stays at x = 1";
    EXPECT_FALSE(removedPoint(kFunction, f, 0)) << "an end cannot go";
    EXPECT_FALSE(insertedPoint(kFunction, f, 3)) << "nothing beyond x = 1";
    auto in = insertedPoint(kFunction, f, 1);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->size(), 5u);
    EXPECT_DOUBLE_EQ((*in)[2][0], 0.5);
    EXPECT_DOUBLE_EQ((*in)[2][1], 0.35);
}

TEST(CurveEdit, PointsAddedAndTakenAway) {
    CurveRules r;
    r.fewest = 4;  // a cubic NURBS
    EXPECT_FALSE(removedPoint(kFour, r, 1)) << "a cubic needs four points";
    auto five = insertedPoint(kFour, r, 3);  // the end: on as far again
    ASSERT_TRUE(five);
    EXPECT_DOUBLE_EQ((*five)[4][0], 0.8);
    EXPECT_DOUBLE_EQ((*five)[4][1], 0.05);
    auto back = removedPoint(*five, r, 4);
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, kFour);
    CurveRules closed;
    closed.closed = true;
    auto wrap = insertedPoint(kFour, closed, 3);  // between the last and the first
    ASSERT_TRUE(wrap);
    EXPECT_DOUBLE_EQ((*wrap)[4][0], 0);
    EXPECT_EQ(nearestSegment(kFour, closed, -0.3, -0.5), 3u) << "the closing segment is nearest below";
    EXPECT_EQ(nearestSegment(kFour, CurveRules{}, 0.35, 0), 2u);
}

TEST(CurveEdit, WeightsSnapAndPresets) {
    EXPECT_FALSE(weightedPoint(kFour, 1, 0));
    EXPECT_FALSE(weightedPoint(kFour, 1, NAN));
    EXPECT_DOUBLE_EQ((*weightedPoint(kFour, 1, 2.5))[1][2], 2.5);
    EXPECT_EQ(snapped(0.26, -0.74, 0.25), (std::array<double, 2>{0.25, -0.75}));
    CurveRules f;
    f.function = true;
    EXPECT_FALSE(presetPoints(CurvePreset::Circle, f, 4)) << "a function is no circle";
    auto line = presetPoints(CurvePreset::Line, f, 4);
    ASSERT_TRUE(line);
    EXPECT_EQ(line->front(), (std::array<double, 3>{0, 0, 1}));
    EXPECT_EQ(line->back(), (std::array<double, 3>{1, 1, 1}));
    auto circle = presetPoints(CurvePreset::Circle, CurveRules{}, 4);
    ASSERT_TRUE(circle);
    ASSERT_EQ(circle->size(), 9u);
    EXPECT_EQ(circle->front(), circle->back()) << "an open curve closes on itself";
    for (const auto& p : *circle) EXPECT_NEAR(std::hypot(p[0], p[1]), 0.5, 1e-12);
    auto s = presetPoints(CurvePreset::S, CurveRules{}, 4);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->size(), 7u);
    EXPECT_GT((*s)[1][1], 0);
    EXPECT_LT((*s)[5][1], 0);
    EXPECT_EQ(curvePresetNamed("arc"), CurvePreset::Arc);
    EXPECT_FALSE(curvePresetNamed("spiral"));
}

}  // namespace
}  // namespace sprout
