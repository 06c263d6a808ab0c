// Forest scenes: species by share on a jittered grid, each plant its own specimen.
#include <gtest/gtest.h>

#include "core/forest.hpp"
#include "test_util.hpp"

namespace sprout::test {
namespace {

const char* kScene =
    "scene: forest\ngrid: 4 3\nspacing: 10\nseed: 5\nspecies: tree 0.5\nspecies: bush 0.5\ngrass: grass 1\n";

std::optional<std::string> source(const std::string& name) {
    if (name == "tree") return std::string("seed: 1\nn: 3\nangle: 25 ~ 5\naxiom: F\nF -> F[+F]F[-F]F : 0.5\nF -> F[+F]F : 0.5\n");
    if (name == "bush") return std::string("n: 2\nangle: 30\naxiom: F\nF -> F[+F][-F]F\n");
    if (name == "grass") return std::string("n: 1\nangle: 20\naxiom: F\nF -> F[+F][-F]\n");
    return std::nullopt;
}

TEST(Forest, ParsesAScene) {
    auto r = parseForest(kScene);
    ASSERT_TRUE(r.forest);
    EXPECT_EQ(r.forest->columns, 4);
    EXPECT_EQ(r.forest->rows, 3);
    EXPECT_EQ(r.forest->species.size(), 2u);
    EXPECT_EQ(r.forest->grassPerCell, 1);
    EXPECT_TRUE(isForestScene(kScene));
    EXPECT_FALSE(isForestScene("axiom: F\n"));
    auto bad = parseForest("scene: forest\ngrid: 0 3\nspecies: x -1\ncolour: red\n");
    ASSERT_EQ(bad.diagnostics.size(), 3u);
    EXPECT_EQ(bad.diagnostics[2].message, "unknown scene setting 'colour:'");
}

TEST(Forest, EveryCellGetsAPlantAndTheSceneIsReproducible) {
    Forest f = *parseForest(kScene).forest;
    Geometry a, b;
    ForestStats sa, sb;
    std::string error;
    ASSERT_TRUE(buildForest(f, source, a, sa, error)) << error;
    ASSERT_TRUE(buildForest(f, source, b, sb, error)) << error;
    EXPECT_EQ(sa.plants, 12);
    EXPECT_EQ(sa.grasses, 12);
    EXPECT_EQ(a.cylinders.size(), b.cylinders.size());
    EXPECT_EQ(a.bounds.max.x, b.bounds.max.x);  // same seed, same forest
    // Spread over the grid: about 4 x 10 by 3 x 10 units, on the ground.
    EXPECT_GT(a.bounds.size().x, 25);
    EXPECT_GT(a.bounds.size().z, 15);
    EXPECT_NEAR(a.bounds.min.y, 0, 1e-4);
    f.seed = 6;
    Geometry c;
    ASSERT_TRUE(buildForest(f, source, c, sa, error));
    EXPECT_NE(c.bounds.max.x, a.bounds.max.x);
}

TEST(Forest, UnknownSpeciesIsAMessage) {
    Forest f = *parseForest("scene: forest\nspecies: oak 1\n").forest;
    Geometry g;
    ForestStats s;
    std::string error;
    EXPECT_FALSE(buildForest(f, source, g, s, error));
    EXPECT_EQ(error, "no preset or file named 'oak'");
}

}  // namespace
}  // namespace sprout::test
