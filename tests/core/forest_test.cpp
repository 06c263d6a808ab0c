// Forest scenes: species by share on a jittered grid, each plant its own specimen.
#include <gtest/gtest.h>

#include "core/scene/forest.hpp"
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

// One environment for several plants: each ?E is answered in the world, where its plant
// stands, and sees every plant. A leaf of plant A at (0, 5, 0) shades plant B's bud two cells
// below it, though B's own string has no leaf; alone, B would be in the open.
TEST(Forest, ASharedEnvironmentSeesEveryPlant) {
    auto a = parse("n: 0\naxiom: @M(0,5,0) ~l(1)\n").grammar;
    auto b = parse("n: 0\nenvironment: light 1\naxiom: @M(0,3,0) ?E(0) @M(4,3,0) ?E(0)\n").grammar;
    ASSERT_TRUE(a && b);
    Environment light = b->environment;
    ModuleString sa = a->axiom, sb = b->axiom;
    // B stands at (-4, 0, 0): its first bud is at (-4, 3, 0), in the open; its second at
    // (0, 3, 0), under A's leaf.
    std::vector<QueryTarget> together{{a.get(), &sa, 0, 1}, {b.get(), &sb, 0, 1, 0, glm::dvec3(-4, 0, 0)}};
    ASSERT_TRUE(answerQueriesTogether(light, 1, together));
    EXPECT_EQ(toString(sb, b->alphabet), "@M(0,3,0)?E(1)@M(4,3,0)?E(0.75)");
    // Directions come back in the plant's own frame: a plant turned 90 degrees about +Y heads
    // along its own (1, 0, 1) into a wall across the world's -Z, which in its own frame is a
    // wall across +X; it is told to go along its own +Z, as the same plant unturned before
    // that wall is.
    auto turnedPlant = parse("n: 0\nenvironment: obstacle box -10 -10 -3 10 10 -2\naxiom: @R(0.70711,0,0.70711) ?E(4,0,0,0,0)\n").grammar;
    auto samePlant = parse("n: 0\nenvironment: obstacle box 2 -10 -10 3 10 10\naxiom: @R(0.70711,0,0.70711) ?E(4,0,0,0,0)\n").grammar;
    ASSERT_TRUE(turnedPlant && samePlant);
    ModuleString st = turnedPlant->axiom, ss = samePlant->axiom;
    std::vector<QueryTarget> turned{{turnedPlant.get(), &st, 0, 1, 90.0, glm::dvec3(0.0)}};
    ASSERT_TRUE(answerQueriesTogether(turnedPlant->environment, 1, turned));
    ASSERT_TRUE(answerQueries(*samePlant, ss, 0, 1));
    EXPECT_EQ(toString(ss, samePlant->alphabet), "@R(0.70711,0,0.70711)?E(4,1,0,0,1)");
    EXPECT_EQ(toString(st, turnedPlant->alphabet), "@R(0.70711,0,0.70711)?E(4,1,0,0,1)");
}

// A forest with one light: the same trees grown in a tight row shade each other and grow
// less than the same trees far apart, and the scene is the same from the same seed.
TEST(Forest, TreesInARowShadeEachOther) {
    auto tree = [](const std::string& name) -> std::optional<std::string> {
        if (name != "tree") return std::nullopt;
        // Its own environment lets it be opened alone; the forest's replaces it.
        return std::string("n: 8\nangle: 30\nenvironment: light 5\naxiom: F(2) ?E(1) A\n"
                           "?E(l) < A : l > 0.6 -> F(1) [ ~l(1) ] [ +(35) ?E(1) A ] /(137.5) [ -(35) ?E(1) A ] ?E(1) A\n"
                           "?E(l) < A : l <= 0.6 -> ~l(1)\n");
    };
    auto scene = [](double spacing) {
        return "scene: forest\ngrid: 5 1\nspacing: " + std::to_string(spacing) + "\nseed: 3\nspecies: tree 1\n"
               "environment: light 1 0.3\n";
    };
    auto grow = [&](double spacing, Geometry& g, ForestStats& st) {
        auto r = parseForest(scene(spacing));
        ASSERT_TRUE(r.forest) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
        std::string error;
        ASSERT_TRUE(buildForest(*r.forest, tree, g, st, error)) << error;
    };
    Geometry tight, apart, again;
    ForestStats st, sa, sg;
    grow(2, tight, st);
    grow(60, apart, sa);
    grow(2, again, sg);
    EXPECT_EQ(st.sharing, 5);
    EXPECT_LT(tight.cylinders.size(), apart.cylinders.size() * 9 / 10);
    EXPECT_EQ(tight.cylinders.size(), again.cylinders.size());
    EXPECT_EQ(tight.bounds.max.x, again.bounds.max.x);
    // Messages about the environment keep the scene's line:col.
    auto bad = parseForest("scene: forest\nspecies: tree 1\n\nenvironment: light 0\n");
    ASSERT_FALSE(bad.forest);
    EXPECT_EQ(bad.diagnostics[0].line, 4);
    EXPECT_EQ(bad.diagnostics[0].message, "expected 'environment: light VOXEL [SHADOW] [sun AZIMUTH ELEVATION]', with a voxel size "
                                          "above 0 (and a shadow above 0)");
}

}  // namespace
}  // namespace sprout::test
