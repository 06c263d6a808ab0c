// Open L-systems: the built-in environments' answers on hand-made cases, and small open
// L-systems derived step by step (core/language/environment_spec.hpp, core/environment/environment.hpp).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/derive/derive.hpp"
#include "core/environment/environment.hpp"
#include "tests/core/test_util.hpp"

namespace sprout {
namespace {

std::vector<double> ask(const Environment& env, glm::dvec3 p, glm::dvec3 h, std::vector<double> params) {
    answer(env, p, glm::normalize(h), params.data(), int(params.size()));
    return params;
}

Environment declared(std::vector<std::vector<std::string>> words, std::vector<std::vector<double>> numbers) {
    Environment env;
    std::string error;
    for (size_t i = 0; i < words.size(); ++i) EXPECT_TRUE(env.declare(words[i], numbers[i], error)) << error;
    return env;
}

TEST(Environment, RegionsSayInsideAndTheDistanceToTheirSurface) {
    const Environment sphere = declared({{"sphere"}}, {{0, 0, 0, 2.5}});
    EXPECT_EQ(ask(sphere, {0, 1, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{1, 1.5}));
    EXPECT_EQ(ask(sphere, {0, 3, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{0, 0.5}));
    const Environment box = declared({{"box"}}, {{0, 0, 0, 1, 2, 1}});
    EXPECT_EQ(ask(box, {0.5, 0.5, 0.5}, {0, 1, 0}, {0, 0}), (std::vector<double>{1, 0.5}));
    EXPECT_EQ(ask(box, {3, 1, 0.5}, {0, 1, 0}, {0, 0}), (std::vector<double>{0, 2}));
    const Environment ellipsoid = declared({{"ellipsoid"}}, {{0, 0, 0, 2, 1, 1}});
    EXPECT_EQ(ask(ellipsoid, {1, 0, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{1, 1}));
    EXPECT_EQ(ask(ellipsoid, {0, 2, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{0, 1}));
    const Environment cylinder = declared({{"cylinder"}}, {{0, 0, 0, 1, 2}});
    EXPECT_EQ(ask(cylinder, {0, 0.5, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{1, 0.5}));
    EXPECT_EQ(ask(cylinder, {3, 1, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{0, 2}));
    // The union of two shapes: inside either, the distance to the nearer surface.
    const Environment two = declared({{"sphere"}, {"sphere"}}, {{0, 0, 0, 1}, {3, 0, 0, 1}});
    EXPECT_EQ(ask(two, {3.5, 0, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{1, 0.5}));
    EXPECT_EQ(ask(two, {1.5, 0, 0}, {0, 1, 0}, {0, 0}), (std::vector<double>{0, 0.5}));
}

TEST(Environment, ObstaclesSayWhetherASegmentHitsAndAFreeDirection) {
    const Environment env = declared({{"obstacle", "sphere"}, {"ground"}}, {{0, 5, 0, 1}, {0}});
    // Straight at the sphere's centre: a hit, head-on; the free way is along the surface,
    // n x (1,0,0) for the normal n = (0,-1,0) where it enters.
    EXPECT_EQ(ask(env, {0, 2, 0}, {0, 1, 0}, {4, 0, 0, 0, 0}), (std::vector<double>{4, 1, 0, 0, 1}));
    // Too short to reach it: no hit, the heading is free.
    EXPECT_EQ(ask(env, {0, 2, 0}, {0, 1, 0}, {1.5, 0, 0, 0, 0}), (std::vector<double>{1.5, 0, 0, 1, 0}));
    // Past it: no hit.
    EXPECT_EQ(ask(env, {3, 2, 0}, {0, 1, 0}, {6, 0, 0, 0, 0}), (std::vector<double>{6, 0, 0, 1, 0}));
    // Down into the ground at a slant: slid along it, horizontally.
    EXPECT_EQ(ask(env, {0, 1, 0}, {0.6, -0.8, 0}, {2, 0, 0, 0, 0}), (std::vector<double>{2, 1, 1, 0, 0}));
    // A glancing hit on the sphere slides along its surface: a unit vector at a right angle
    // to the normal where it enters.
    auto a = ask(env, {0.6, 2, 0}, {0, 1, 0}, {4, 0, 0, 0, 0});
    EXPECT_EQ(a[1], 1);
    EXPECT_NEAR(a[2] * a[2] + a[3] * a[3] + a[4] * a[4], 1.0, 1e-4);
    EXPECT_GT(a[2], 0.5) << "away from the centre";
}

TEST(Environment, DeclarationsAreChecked) {
    Environment env;
    std::string error;
    EXPECT_FALSE(env.declare({"cone"}, {1, 2, 3}, error));
    EXPECT_EQ(error, "unknown environment 'cone': Sprout's are sphere, box, ellipsoid, cylinder, mesh (a region to grow in), "
                     "obstacle sphere|box, ground, light and attraction");
    EXPECT_FALSE(env.declare({"sphere"}, {1, 2, 3}, error));
    EXPECT_EQ(error, "expected 4 numbers: 'environment: sphere CX CY CZ R'");
    EXPECT_FALSE(env.declare({"sphere"}, {0, 0, 0, -1}, error));
    EXPECT_EQ(error, "a sphere's radius must be above 0");
    EXPECT_TRUE(env.declare({"sphere"}, {0, 0, 0, 1}, error));
    EXPECT_FALSE(env.declare({"ground"}, {0}, error));
    EXPECT_EQ(error, "one grammar has one kind of environment: a region to grow in, or obstacles and ground (their ?E answers differ)");
}

// An apex grows while the environment says it is inside the sphere: the answers of step k
// decide step k+1.
TEST(Environment, OpenLSystemGrowsUntilTheRegionSaysStop) {
    const std::string g = "n: 5\nenvironment: sphere 0 0 0 2.5\naxiom: F(1) ?E(0,0) A\n"
                          "?E(inside, d) < A : inside == 1 -> F(1) ?E(0,0) A\n";
    EXPECT_EQ(test::expand(g, 0), "F(1)?E(1,1.5)A");
    EXPECT_EQ(test::expand(g, 1), "F(1)?E(1,1.5)F(1)?E(1,0.5)A");
    EXPECT_EQ(test::expand(g, 2), "F(1)?E(1,1.5)F(1)?E(1,0.5)F(1)?E(0,0.5)A");
    EXPECT_EQ(test::expand(g, 5), "F(1)?E(1,1.5)F(1)?E(1,0.5)F(1)?E(0,0.5)A");
}

// A shoot meets an obstacle and turns to the free direction the environment gives.
TEST(Environment, OpenLSystemTurnsAroundAnObstacle) {
    const std::string g = "n: 3\nenvironment: obstacle box -1 2.5 -1 1 4 1\n"
                          "axiom: F(1) ?E(1,0,0,0,0) A\n"
                          "?E(l, hit, x, y, z) < A : hit == 0 -> F(1) ?E(1,0,0,0,0) A\n"
                          "?E(l, hit, x, y, z) < A : hit == 1 -> @R(1,0,0) F(1) ?E(1,0,0,0,0) A\n";
    EXPECT_EQ(test::expand(g, 0), "F(1)?E(1,0,0,1,0)A");
    EXPECT_EQ(test::expand(g, 1), "F(1)?E(1,0,0,1,0)F(1)?E(1,1,0,0,1)A");
    EXPECT_EQ(test::expand(g, 2), "F(1)?E(1,0,0,1,0)F(1)?E(1,1,0,0,1)@R(1,0,0)F(1)?E(1,0,1,0,0)A");
}

// Light: a leaf at (0, 5, 0) in 1-unit voxels shades the cells below it, 0.5 in the first,
// halving with each cell down and one cell wider each time; nothing above or beside.
TEST(Environment, LightIsTheSkyLessTheShadowOfWhatGrewAbove) {
    const std::string g = "n: 0\nenvironment: light 1\n"
                          "axiom: @M(0,5,0) ~l(1) @M(0,3,0) ?E(0) @M(3,3,0) ?E(0) @M(0,6,0) ?E(0) @M(0,1.5,0) ?E(0) "
                          "@M(1,3,0) ?E(0)\n";
    // Two cells below: 0.25 of shadow; beside it at three cells: none; above: none; four cells
    // below: 0.0625; one cell aside two below: inside the spread, 0.25.
    EXPECT_EQ(test::expand(g, 0), "@M(0,5,0)~l(1)@M(0,3,0)?E(0.75)@M(3,3,0)?E(1)@M(0,6,0)?E(1)@M(0,1.5,0)?E(0.9375)@M(1,3,0)?E(0.75)");
    // A grid that would exhaust memory is refused, naming its size.
    auto r = parse("n: 0\nenvironment: light 0.0001\naxiom: F(100) ~l(1) ?E(0)\n");
    ASSERT_TRUE(r.ok());
    DeriveResult d = derive(r.grammar, 0);
    EXPECT_FALSE(d.outcome.ok());
    EXPECT_EQ(d.outcome.message, "step 0: the light grid would have 18 x 1010010 x 18 = 3.27e+08 cells (1.3 GB at 4 bytes "
                                 "each), over the limit of 32 million: make the voxels larger ('environment: light VOXEL')");
}

// A low sun casts the shadow away from it: from azimuth 90 (+X) at 45 degrees, the leaf's
// shadow runs down and towards -X, one cell aside for each cell down; straight below it and
// on the sunny side there is none.
TEST(Environment, LightFromTheSunsDirection) {
    const std::string g = "n: 0\nenvironment: light 1 sun 90 45\n"
                          "axiom: @M(0,5,0) ~l(1) @M(-2,3,0) ?E(0) @M(0,3,0) ?E(0) @M(2,3,0) ?E(0) @M(-1,4,0) ?E(0) "
                          "@M(-4,1,0) ?E(0)\n";
    EXPECT_EQ(test::expand(g, 0), "@M(0,5,0)~l(1)@M(-2,3,0)?E(0.75)@M(0,3,0)?E(1)@M(2,3,0)?E(1)@M(-1,4,0)?E(0.5)@M(-4,1,0)?E(0.9375)");
    // Overhead (the default) is the same as saying so.
    EXPECT_EQ(test::expand("n: 0\nenvironment: light 1 0.5 sun 0 90\naxiom: @M(0,5,0) ~l(1) @M(0,3,0) ?E(0)\n", 0),
              "@M(0,5,0)~l(1)@M(0,3,0)?E(0.75)");
    auto r = parse("n: 0\nenvironment: light 1 sun 30 0\naxiom: ?E(0)\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "the sun's elevation must be above 0 and at most 90 degrees (90: overhead)");
}

// A ?E whose parameters a rule made NaN is still asked: its parameters are for the answer
// (the turtle skips other modules with NaN parameters, and once that silently left every ?E
// of the step unanswered).
TEST(Environment, AQuestionHoldingNaNIsStillAnswered) {
    EXPECT_EQ(test::expand("n: 1\nenvironment: sphere 0 0 0 2\naxiom: B(0)\nB(x) -> F(1) ?E(x/0*0, 0) F(1) ?E(0,0)\n", 1),
              "F(1)?E(1,1)F(1)?E(1,0)");
}

// A stochastic plant in an environment comes back the same from the same seed (the rules'
// choices, the attraction points and the answers), and another seed grows another plant.
TEST(Environment, AStochasticOpenLSystemIsReproducibleFromItsSeed) {
    const std::string g = "n: 7\nseed: 5\nenvironment: attraction 150 sphere 0 6 0 4 influence 3 kill 0.6\n"
                          "axiom: F(2) ?E(0,0,0,0) A\n"
                          "?E(x,y,z,c) < A : c > 0 -> @R(x,y,z) F(0.8) [ +(30) ?E(0,0,0,0) A ] ?E(0,0,0,0) A : 0.6\n"
                          "?E(x,y,z,c) < A : c > 0 -> @R(x,y,z) F(0.8) ?E(0,0,0,0) A : 0.4\n";
    auto grammar = parse(g).grammar;
    ASSERT_TRUE(grammar);
    auto grow = [&](std::uint64_t seed) {
        DeriveOptions o;
        o.seed = seed;
        DeriveResult d = derive(grammar, 7, o);
        EXPECT_TRUE(d.outcome.ok()) << d.outcome.message;
        return d.string ? toString(*d.string, grammar->alphabet) : std::string();
    };
    const std::string a = grow(5), b = grow(5), c = grow(6);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_GT(a.size(), 400u);  // it grew: the points pulled its buds
}

// A closed mesh beside the grammar is a region like the built-in shapes; an open one is
// refused, naming what is wrong.
TEST(Environment, AClosedMeshIsARegion) {
    const std::string dir = std::string(SPROUT_TEST_DATA) + "/";
    ParseResult r = parse("n: 0\nenvironment: mesh env_cube.obj\naxiom: @M(0.5,0.5,0.5) ?E(0,0) @M(2,1,0.5) ?E(0,0) "
                          "@M(0.5,1.9,0.5) ?E(0,0)\n",
                          ParseOptions{false, includeFromFolder(dir), "grammar.lsys"});
    for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, "grammar.lsys");
    ASSERT_TRUE(r.ok());
    DeriveResult d = derive(r.grammar, 0);
    ASSERT_TRUE(d.outcome.ok()) << d.outcome.message;
    EXPECT_EQ(toString(*d.string, r.grammar->alphabet), "@M(0.5,0.5,0.5)?E(1,0.5)@M(2,1,0.5)?E(0,1)@M(0.5,1.9,0.5)?E(1,0.1)");
    ParseResult open = parse("n: 0\nenvironment: mesh env_open_cube.obj\naxiom: F\n",
                             ParseOptions{false, includeFromFolder(dir), "grammar.lsys"});
    ASSERT_FALSE(open.ok());
    EXPECT_EQ(open.diagnostics[0].message, "'env_open_cube.obj' cannot be the environment: it is not closed: 3 of its edges "
                                           "do not belong to exactly two faces");
    ParseResult typed = parse("n: 0\nenvironment: mesh env_cube.obj\naxiom: F\n");
    ASSERT_FALSE(typed.ok());
    EXPECT_EQ(typed.diagnostics[0].message, "the mesh 'env_cube.obj' needs the grammar's folder: save the grammar beside it first");
}

// Space colonisation: every point pulls only its nearest bud within the radius of influence;
// a bud's answer is the mean of the unit directions to its points, and their number.
TEST(Environment, AttractionPointsPullTheirNearestBud) {
    Environment env = declared({{"attraction", "sphere", "influence", "kill"}}, {{50, 0, 0, 0, 9, 4, 0.5}});
    ASSERT_TRUE(env.isAttraction());
    EXPECT_EQ(env.influence, 4);
    EXPECT_EQ(env.kill, 0.5);
    const std::vector<glm::dvec3> buds{{0, 0, 0}, {10, 0, 0}};
    const std::vector<glm::dvec3> points{{0, 2, 0}, {0, 0, 3}, {9, 1, 0}, {20, 0, 0}, {5.5, 0, 0}};
    std::vector<double> a(4, -1), b(4, -1);
    answerAttraction(env, buds, points, {a.data(), b.data()}, {4, 4});
    // (5.5, 0, 0) is 4.5 from one bud and 5.5 from the other: beyond the influence of both.
    EXPECT_EQ(a, (std::vector<double>{0, 0.70711, 0.70711, 2}));
    EXPECT_EQ(b, (std::vector<double>{-0.70711, 0.70711, 0, 1}));
    // A point nearer to the second bud pulls only it, even within the first's influence.
    std::vector<double> c(4, -1), d(4, -1);
    answerAttraction(env, buds, {{6.5, 0, 0}}, {c.data(), d.data()}, {4, 4});
    EXPECT_EQ(c, (std::vector<double>{0, 0, 0, 0}));
    EXPECT_EQ(d, (std::vector<double>{-1, 0, 0, 1}));
    // Points used up: exactly those within the kill distance (3 here) of a node of the plant.
    Environment dense = declared({{"attraction", "sphere", "kill"}}, {{400, 0, 0, 0, 9, 3}});
    Geometry plant;
    plant.cylinders.push_back({{0, -3, 0}, 0.1f, {0, 3, 0}, 0.1f, 0, 0, 0});
    const auto all = freePoints(dense, Geometry{}, 7), free = freePoints(dense, plant, 7);
    EXPECT_EQ(all.size(), 400u);
    auto nearest = [](const glm::dvec3& p) { return std::min(glm::length(p - glm::dvec3(0, -3, 0)), glm::length(p - glm::dvec3(0, 3, 0))); };
    size_t near = 0;
    for (const auto& p : all) near += nearest(p) <= 3;
    EXPECT_GT(near, 10u);
    EXPECT_EQ(free.size(), all.size() - near);
    for (const auto& p : free) EXPECT_GT(nearest(p), 3);
    // The same seed, the same points.
    EXPECT_EQ(freePoints(dense, Geometry{}, 7), all);
}

}  // namespace
}  // namespace sprout
