// Conversions of a grammar's numbers to integers (core/base/bounded.hpp), at and beyond their
// limits, and the places that use them with numbers no plant should reach: each must give a
// defined answer (the sanitizer build checks there is no undefined cast on the way).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/base/bounded.hpp"
#include "core/environment/environment.hpp"

namespace sprout {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Bounded, SaturateIsTheCastInsideTheRangeAndTheLimitBeyondIt) {
    EXPECT_EQ(saturate<int>(41.9), 41);
    EXPECT_EQ(saturate<int>(-41.9), -41);
    EXPECT_EQ(saturate<int>(2147483647.0), 2147483647);
    EXPECT_EQ(saturate<int>(2147483648.0), 2147483647);
    EXPECT_EQ(saturate<int>(-2147483648.0), -2147483647 - 1);
    EXPECT_EQ(saturate<int>(-2147483649.0), -2147483647 - 1);
    EXPECT_EQ(saturate<int>(1e300), std::numeric_limits<int>::max());
    EXPECT_EQ(saturate<int>(kInf), std::numeric_limits<int>::max());
    EXPECT_EQ(saturate<int>(-kInf), std::numeric_limits<int>::min());
    EXPECT_EQ(saturate<int>(kNaN), 0);
    EXPECT_EQ(saturate<int>(-kNaN), 0);
}

TEST(Bounded, SaturateHandlesSixtyFourBitLimitsThatADoubleCannotHold) {
    using L = std::numeric_limits<std::int64_t>;
    // 2^63 is the first double past int64's range; the double just below it casts exactly.
    EXPECT_EQ(saturate<std::int64_t>(9223372036854775808.0), L::max());
    EXPECT_EQ(saturate<std::int64_t>(std::nextafter(9223372036854775808.0, 0.0)), std::int64_t(9223372036854774784));
    EXPECT_EQ(saturate<std::int64_t>(-9223372036854775808.0), L::min());
    EXPECT_EQ(saturate<std::int64_t>(6.83761e+36), L::max());  // the cell key of issue 26
    EXPECT_EQ(saturate<std::uint64_t>(1.8446744073709552e19), std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(saturate<std::uint64_t>(-1.0), 0u);
    EXPECT_EQ(saturate<std::uint8_t>(255.9), 255);
    EXPECT_EQ(saturate<std::uint8_t>(256.0), 255);
    EXPECT_EQ(saturate<std::uint8_t>(-0.5), 0);
    EXPECT_EQ(saturate<std::size_t>(kNaN), 0u);
}

TEST(Bounded, FloorCellRoundsDownThenSaturates) {
    EXPECT_EQ(floorCell<int>(-0.5), -1);
    EXPECT_EQ(floorCell<int>(2.999), 2);
    EXPECT_EQ(floorCell<int>(-1e30), std::numeric_limits<int>::min());
    EXPECT_EQ(floorCell<std::int64_t>(1e30), std::numeric_limits<std::int64_t>::max());
    EXPECT_EQ(floorCell<std::int64_t>(kNaN), 0);
}

TEST(Bounded, WholeInTakesWholeFiniteNumbersInTheRangeOnly) {
    EXPECT_EQ(wholeIn(0, 0, 10), 0);
    EXPECT_EQ(wholeIn(10, 0, 10), 10);
    EXPECT_FALSE(wholeIn(10.5, 0, 20));
    EXPECT_FALSE(wholeIn(11, 0, 10));
    EXPECT_FALSE(wholeIn(-1, 0, 10));
    EXPECT_FALSE(wholeIn(kNaN, 0, 10));
    EXPECT_FALSE(wholeIn(kInf, 0, 10));
    EXPECT_FALSE(wholeIn(-kInf, -10, 10));
    EXPECT_EQ(wholeIn(-1e6, -1000000, 0), -1000000);
    EXPECT_TRUE(inRange(1e9, -1e9, 1e9));
    EXPECT_FALSE(inRange(1e9 + 1, -1e9, 1e9));
    EXPECT_FALSE(inRange(kNaN, -1e9, 1e9));
    EXPECT_EQ(formatNumber(8.8888888e36), "8.88889e+36");
}

TEST(Bounded, CellKeysAreDefinedForAnyPointAndSeparateNearCells) {
    // Near the origin, neighbouring cells have different keys; far away the index saturates
    // and the key is still a value (the sanitizer build checks the casts).
    EXPECT_NE(cellKey({0.5, 0.5, 0.5}, 1.0), cellKey({1.5, 0.5, 0.5}, 1.0));
    EXPECT_NE(cellKey({0.5, 0.5, 0.5}, 1.0), cellKey({0.5, -0.5, 0.5}, 1.0));
    EXPECT_EQ(cellKey({0.2, 0.3, 0.9}, 1.0), cellKey({0.7, 0.1, 0.4}, 1.0));
    // Far points (and NaN) share one key that no near cell has: not even the cells that alias
    // near the origin (index -1 is all ones in 21 bits).
    const std::uint64_t far = cellKey({1e30, 0, 0}, 1.0);
    EXPECT_EQ(far, cellKey({1e35, -1e35, 0}, 1.0));
    EXPECT_EQ(far, cellKey({kNaN, 0, 0}, 1.0));
    EXPECT_EQ(far, cellKey({-kInf, kInf, 1e308}, 1e-6));
    EXPECT_EQ(far, cellKey({0, 0, 1.2e15}, 1.0));
    EXPECT_NE(far, cellKey({-0.5, -0.5, -0.5}, 1.0));
    EXPECT_NE(far, cellKey({1e9, 1e9, 1e9}, 1e-6));  // the farthest an environment's points reach
}

TEST(Bounded, TheLightAtAPointFarBeyondTheGridIsTheOpenSky) {
    LightGrid grid;
    grid.voxel = 1;
    grid.nx = grid.ny = grid.nz = 2;
    grid.shadow.assign(8, 0.75f);
    EXPECT_DOUBLE_EQ(grid.lightAt({0.5, 0.5, 0.5}), 0.25);
    EXPECT_DOUBLE_EQ(grid.lightAt({1e30, 0.5, 0.5}), 1.0);
    EXPECT_DOUBLE_EQ(grid.lightAt({0.5, -1e30, 0.5}), 1.0);
    EXPECT_DOUBLE_EQ(grid.lightAt({0.5, 0.5, kInf}), 1.0);
    EXPECT_DOUBLE_EQ(grid.lightAt({kNaN, 0.5, 0.5}), 1.0);
}

TEST(Bounded, EnvironmentDistancesBelowTheirLimitAreRefused) {
    Environment env;
    std::string error;
    EXPECT_FALSE(env.declare({"attraction", "sphere", "kill"}, {100, 0, 0, 0, 5, 1e-300}, error));
    EXPECT_EQ(error, "'kill' must be a distance of at least 1e-6");
    Environment ok;
    EXPECT_TRUE(ok.declare({"attraction", "sphere", "kill"}, {100, 0, 0, 0, 5, 1e-6}, error)) << error;
    Environment light;
    EXPECT_FALSE(light.declare({"light"}, {1e-7}, error));
    EXPECT_EQ(error, "the light's voxel size must be at least 1e-6 (a grid of smaller cells holds no plant)");
    EXPECT_TRUE(light.declare({"light"}, {1e-6}, error)) << error;
}

}  // namespace
}  // namespace sprout
