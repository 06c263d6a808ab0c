// Iterated function systems: parsing, the chaos game, tone mapping.
#include <gtest/gtest.h>

#include "core/scene/ifs.hpp"

namespace sprout {
namespace {

const char* kFern =
    "# Barnsley fern\n0 0 0 0.16 0 0 0.01\n0.85 0.04 -0.04 0.85 0 1.6 0.85\n"
    "0.2 -0.26 0.23 0.22 0 1.6 0.07\n-0.15 0.28 0.26 0.24 0 0.44 0.07\npoints: 2000000\nseed: 3\ncolour: #1f5e22\n";

TEST(Ifs, ParsesMapsAndSettings) {
    auto r = parseIfs(kFern);
    ASSERT_TRUE(r.ifs);
    ASSERT_EQ(r.ifs->maps.size(), 4u);
    EXPECT_DOUBLE_EQ(r.ifs->maps[1].a, 0.85);
    EXPECT_DOUBLE_EQ(r.ifs->maps[3].p, 0.07);
    EXPECT_EQ(r.ifs->points, 2000000u);
    EXPECT_EQ(r.ifs->seed, 3u);
    EXPECT_EQ(r.ifs->colour, 0x1F5E22FFu);
    auto bad = parseIfs("0 0 0 0.16 0\n1 2 3 4 5 6 -1\npoints: 0\n");
    ASSERT_EQ(bad.diagnostics.size(), 3u);
    EXPECT_EQ(bad.diagnostics[0].line, 1);
    EXPECT_EQ(bad.diagnostics[0].message, "expected a map 'a b c d e f p' (7 numbers)");
    EXPECT_EQ(bad.diagnostics[1].message, "a probability cannot be negative");
    EXPECT_FALSE(parseIfs("# nothing\n").ifs);
}

TEST(Ifs, ChaosGameFillsTheFernAndIsReproducible) {
    Ifs fern = *parseIfs(kFern).ifs;
    Density a, b;
    ASSERT_TRUE(chaosGame(fern, 200, 300, a, 2));
    ASSERT_TRUE(chaosGame(fern, 200, 300, b, 2));
    EXPECT_EQ(a.counts, b.counts);  // same seed, same image
    std::uint64_t total = 0;
    int lit = 0;
    for (auto c : a.counts) {
        total += c;
        lit += c > 0;
    }
    EXPECT_GT(total, 1'990'000u);  // nearly every point lands in the fitted frame
    EXPECT_GT(lit, 200 * 300 / 10);
    EXPECT_LT(lit, 200 * 300 / 2);
    // The attractor spans x in [-2.2, 2.7] and y in [0, 10]: the frame fits it.
    EXPECT_LT(a.minY, 0.0);
    EXPECT_GT(a.maxY, 9.9);
    EXPECT_LT(a.maxY, 11.0);
    fern.seed = 4;
    Density c;
    chaosGame(fern, 200, 300, c, 2);
    EXPECT_NE(a.counts, c.counts);
}

TEST(Ifs, ToneMapKeepsTheBackgroundAndDarkensDensity) {
    Density d;
    d.width = 3;
    d.height = 1;
    d.counts = {0, 1, 1000};
    auto px = toneMap(d, 0x000000FF, 0xFFFFFFFF);
    EXPECT_EQ(px[0], 255);  // nothing landed: background
    EXPECT_LT(px[4], 255);  // one hit shows
    EXPECT_LT(px[8], px[4]);
    EXPECT_EQ(px[8], 0);    // the densest pixel takes the colour
}

}  // namespace
}  // namespace sprout
