// The 3D turtle: exact geometry for small strings, stacks, polygons, tropism, jitter.
#include <gtest/gtest.h>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/turtle/turtle.hpp"
#include "core/turtle/unit_surfaces.hpp"
#include "same_drawing.hpp"
#include "test_util.hpp"

namespace sprout::test {
namespace {

Geometry draw(const std::string& text, int n = -1) {
    auto g = grammarOf(text);
    Geometry geo;
    if (!g) return geo;
    int steps = n < 0 ? g->settings.iterations : n;
    DeriveResult r = derive(g, steps);
    EXPECT_TRUE(r.outcome.ok());
    interpret(*r.string, *g, {steps, g->settings.seed, nullptr}, geo);
    return geo;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, const char* what) {
    EXPECT_NEAR(a.x, b.x, 1e-5) << what;
    EXPECT_NEAR(a.y, b.y, 1e-5) << what;
    EXPECT_NEAR(a.z, b.z, 1e-5) << what;
}

TEST(Turtle, ForwardTurnForward) {
    Geometry g = draw("angle: 90\nwidth: 0.1\naxiom: F+F-F\n");
    ASSERT_EQ(g.cylinders.size(), 3u);
    expectNear(g.cylinders[0].start, {0, 0, 0}, "start at the origin");
    expectNear(g.cylinders[0].end, {0, 1, 0}, "heading +Y");
    expectNear(g.cylinders[1].end, {-1, 1, 0}, "+ turns left (counter-clockwise from the front)");
    expectNear(g.cylinders[2].end, {-1, 2, 0}, "- turns back");
    EXPECT_FLOAT_EQ(g.cylinders[0].startRadius, 0.05f);
    expectNear(g.bounds.min, {-1, 0, 0}, "bounds min");
    expectNear(g.bounds.max, {0, 2, 0}, "bounds max");
}

TEST(Turtle, PitchAndBranches) {
    Geometry g = draw("angle: 90\nwidth: 0.1\naxiom: F[&F]^F\n");
    ASSERT_EQ(g.cylinders.size(), 3u);
    expectNear(g.cylinders[1].start, {0, 1, 0}, "branch starts at the tip");
    expectNear(g.cylinders[1].end, {0, 1, -1}, "& pitches down, away from the viewer");
    expectNear(g.cylinders[2].end, {0, 1, 1}, "after ], ^ pitches up from the restored frame");
    EXPECT_EQ(g.cylinders[1].order, 1);
    EXPECT_EQ(g.cylinders[2].order, 0);
}

TEST(Turtle, TurnAroundAndRoll) {
    Geometry g = draw("angle: 90\nwidth: 0.1\naxiom: F|F\n");
    expectNear(g.cylinders[1].end, {0, 0, 0}, "| reverses the heading");
    // Roll 90 about H moves L onto U, so a later turn about U becomes a pitch.
    Geometry r = draw("angle: 90\nwidth: 0.1\naxiom: F/+F\n");
    EXPECT_NEAR(std::fabs(r.cylinders[1].end.z), 1, 1e-5);
    EXPECT_NEAR(r.cylinders[1].end.x, 0, 1e-5);
}

TEST(Turtle, DollarRollsLeftHorizontal) {
    // After any roll, $ brings L back to horizontal: what follows no longer depends on the roll.
    Geometry rolled = draw("angle: 30\nwidth: 0.1\naxiom: &/(50)$+F\n");
    Geometry plain = draw("angle: 30\nwidth: 0.1\naxiom: &$+F\n");
    Geometry noDollar = draw("angle: 30\nwidth: 0.1\naxiom: &/(50)+F\n");
    expectNear(rolled.cylinders[0].end, plain.cylinders[0].end, "$ undoes the roll");
    EXPECT_GT(glm::length(noDollar.cylinders[0].end - plain.cylinders[0].end), 0.1);
    // With L horizontal a turn keeps the height of the pitched heading times cos(angle).
    EXPECT_NEAR(plain.cylinders[0].end.y, std::cos(glm::radians(30.0f)) * std::cos(glm::radians(30.0f)), 1e-5);
}

TEST(Turtle, ParametersOverrideDefaults) {
    Geometry g = draw("angle: 90\nwidth: 0.1\naxiom: F(2)+(45)F(1)!(0.4)F\n");
    expectNear(g.cylinders[0].end, {0, 2, 0}, "F(2)");
    float s = std::sqrt(0.5f);
    expectNear(g.cylinders[1].end, {-s, 2 + s, 0}, "+(45)");
    EXPECT_FLOAT_EQ(g.cylinders[2].startRadius, 0.2f);
}

TEST(Turtle, WidthStackAndTaper) {
    Geometry g = draw("width: 1\nwidth_factor: 0.5\naxiom: F!F[!F]F\n");
    ASSERT_EQ(g.cylinders.size(), 4u);
    EXPECT_FLOAT_EQ(g.cylinders[0].startRadius, 0.5f);
    EXPECT_FLOAT_EQ(g.cylinders[0].endRadius, 0.25f);  // tapers into the next segment
    EXPECT_FLOAT_EQ(g.cylinders[1].startRadius, 0.25f);
    EXPECT_FLOAT_EQ(g.cylinders[2].startRadius, 0.125f);  // inside the branch
    EXPECT_FLOAT_EQ(g.cylinders[1].endRadius, 0.25f);     // the branch does not taper its parent
    EXPECT_FLOAT_EQ(g.cylinders[3].startRadius, 0.25f);   // restored after ]
}

TEST(Turtle, ColourStack) {
    Geometry g = draw("width: 0.1\npalette: #ff0000 #00ff00 #0000ff\naxiom: F;F[;F],F\n");
    ASSERT_EQ(g.cylinders.size(), 4u);
    EXPECT_EQ(g.cylinders[0].colour, 0xFF0000FFu);
    EXPECT_EQ(g.cylinders[1].colour, 0x00FF00FFu);
    EXPECT_EQ(g.cylinders[2].colour, 0x0000FFFFu);
    EXPECT_EQ(g.cylinders[3].colour, 0xFF0000FFu);
}

TEST(Turtle, GradientFromBarkToTips) {
    Geometry g = draw("width: 0.1\ngradient: #000000 #ffffff\naxiom: F[F[F]]\n");
    ASSERT_EQ(g.cylinders.size(), 3u);
    EXPECT_EQ(g.cylinders[0].colour, 0x000000FFu);
    // Each order moves 45% of the remaining way to the tip colour: 0, 0.45, 0.6975.
    EXPECT_EQ(g.cylinders[1].colour, 0x737373FFu);
    EXPECT_EQ(g.cylinders[2].colour, 0xB2B2B2FFu);
}

TEST(Turtle, BranchScale) {
    Geometry g = draw("width: 1\nbranch_scale: 0.5 0.25\naxiom: F[F[F]]\n");
    EXPECT_FLOAT_EQ(glm::length(g.cylinders[1].end - g.cylinders[1].start), 0.5f);
    EXPECT_FLOAT_EQ(glm::length(g.cylinders[2].end - g.cylinders[2].start), 0.25f);
    EXPECT_FLOAT_EQ(g.cylinders[2].startRadius, 0.5f * 0.25f * 0.25f);
}

TEST(Turtle, StepScaleKeepsAKochCurveTheSameSize) {
    const std::string koch = "angle: 90\nwidth: 0.01\nstep_scale: 1/3\naxiom: F\nF -> F+F-F-F+F\n";
    for (int n = 1; n <= 4; ++n) {
        Geometry g = draw(koch, n);
        EXPECT_NEAR(g.bounds.max.y - g.bounds.min.y, 1.0, 1e-4) << "n=" << n;
    }
}

TEST(Turtle, TropismBendsAStemDownward) {
    Geometry straight = draw("angle: 90\nwidth: 0.1\naxiom: +(60)FFFFFFFFFF\n");
    Geometry bent = draw("angle: 90\nwidth: 0.1\ntropism: 0 -1 0 0.2\naxiom: +(60)FFFFFFFFFF\n");
    EXPECT_LT(bent.cylinders.back().end.y, straight.cylinders.back().end.y - 1);
    // Each segment points lower than the one before.
    for (size_t i = 1; i < bent.cylinders.size(); ++i) {
        glm::vec3 a = glm::normalize(bent.cylinders[i - 1].end - bent.cylinders[i - 1].start);
        glm::vec3 b = glm::normalize(bent.cylinders[i].end - bent.cylinders[i].start);
        EXPECT_LT(b.y, a.y + 1e-6f);
    }
}

TEST(Turtle, JitterIsReproducibleBySeed) {
    const std::string g = "angle: 22 ~ 4\nstep: 1 ~ 0.2\nwidth: 0.1\naxiom: F+F+F-F+F\n";
    Geometry a = draw("seed: 5\n" + g), b = draw("seed: 5\n" + g), c = draw("seed: 6\n" + g);
    expectNear(a.cylinders.back().end, b.cylinders.back().end, "same seed");
    EXPECT_GT(glm::length(a.cylinders.back().end - c.cylinders.back().end), 1e-3);
}

TEST(Turtle, PolygonIsTriangulated) {
    // A concave arrow-head outline: 5 vertices, 3 triangles, all inside the outline.
    Geometry g = draw("angle: 90\naxiom: {.F.+F.+F.+(45)f.}\n");
    EXPECT_TRUE(g.cylinders.empty());  // inside { }, F outlines instead of drawing stems
    EXPECT_EQ(g.polygons.positions.size(), 5u);
    EXPECT_EQ(g.polygons.indices.size(), 9u);
    // Concave L-shape: area of the triangles equals the polygon's area.
    Geometry l = draw("angle: 90\naxiom: {.F(2).+F(1).+F(1).-F(1).-F(1).+F(1).}\n");
    const auto& P = l.polygons.positions;
    double area = 0;
    for (size_t t = 0; t + 2 < l.polygons.indices.size(); t += 3) {
        glm::vec3 a = P[l.polygons.indices[t]], b = P[l.polygons.indices[t + 1]], c = P[l.polygons.indices[t + 2]];
        area += glm::length(glm::cross(b - a, c - a)) / 2;
    }
    EXPECT_NEAR(area, 3.0, 1e-5);  // 2x1 + 1x1
}

TEST(Turtle, AnOutlineNoWiderThanItsRoundingIsALine) {
    // Three points on one line, 25 units out, turned there by angles whose cosines round: the
    // area is rounding noise, so nothing is filled (the tree and the string turtle filled
    // different ones of these when an absolute 1e-12 decided).
    const std::string far = "angle: 18\naxiom: f(20)+(1)&(7)f(5)/(13)";
    EXPECT_EQ(draw(far + "{.f.f.}\n").polygons.indices.size(), 0u);
    EXPECT_EQ(draw(far + "{.f.+(180)f.}\n").polygons.indices.size(), 0u);  // turned back on itself
    // A thin leaf there, a hundredth of a unit wide and a unit long, is filled.
    EXPECT_EQ(draw(far + "{.f.+(90)f(0.01).+(90)f.}\n").polygons.indices.size(), 6u);
    EXPECT_EQ(draw(far + "{.f.+(89.4)f.}\n").polygons.indices.size(), 3u);  // a sliver 0.01 wide
}

TEST(Turtle, SurfacesAndSpheres) {
    Geometry g = draw("width: 0.1\naxiom: F~leaf(2)[~l]@O(0.5)~petal\n");
    ASSERT_EQ(g.surfaces.size(), 4u);
    EXPECT_EQ(g.surfaces[0].kind, SurfaceKind::Leaf);
    EXPECT_FLOAT_EQ(g.surfaces[0].size, 2);
    EXPECT_EQ(g.surfaces[1].kind, SurfaceKind::Leaf);
    EXPECT_EQ(g.surfaces[2].kind, SurfaceKind::Sphere);
    EXPECT_FLOAT_EQ(g.surfaces[2].size, 0.5f);
    EXPECT_EQ(g.surfaces[3].kind, SurfaceKind::Petal);
    expectNear(g.surfaces[0].position, {0, 1, 0}, "at the turtle");
}

TEST(Turtle, PlanarCurvesAreRecognised) {
    EXPECT_TRUE(draw("angle: 60\naxiom: F--F--F\nF -> F+F--F+F\n", 3).planarCurve);
    EXPECT_FALSE(draw("angle: 25\naxiom: F\nF -> F[+F]F[-F]F\n", 3).planarCurve);  // branches: a plant
    EXPECT_FALSE(draw("angle: 25\naxiom: F&F\n").planarCurve);
    EXPECT_FALSE(draw("view: 3d\nangle: 60\naxiom: F--F--F\n").planarCurve);
}

TEST(Turtle, BadValuesAreSkippedNotDrawn) {
    // Written in the file, 0/0 is an error; computed while deriving, it is skipped when drawn.
    Geometry g = draw("width: 0.1\naxiom: A(0)\nA(x) -> F(x/x)F(1/x)F(1e300)FF\n", 1);
    ASSERT_EQ(g.cylinders.size(), 2u);  // NaN, infinity and beyond-float skipped
    for (const auto& c : g.cylinders) EXPECT_TRUE(std::isfinite(c.end.y));
    // An unbalanced ']' (possible from imported files) is harmless when drawing.
    auto gr = grammarOf("width: 0.1\naxiom: F\n");
    ModuleString s;
    for (SymbolId id : {SymbolId(Alphabet::kPop), SymbolId(Alphabet::kPop), gr->axiom.symbols[0]}) s.symbols.push_back(id);
    Geometry h;
    interpret(s, *gr, {}, h);
    EXPECT_EQ(h.cylinders.size(), 1u);
}

TEST(Turtle, AutomaticWidthFollowsThePlantsSize) {
    Geometry g = draw("angle: 25\naxiom: F\nF -> F[+F]F[-F]F\n", 3);
    float height = g.bounds.max.y - g.bounds.min.y;
    EXPECT_NEAR(g.cylinders[0].startRadius, height / 80 / 2, 1e-4);
    for (const auto& c : g.cylinders) {
        if (c.order > 0) {
            EXPECT_LT(c.startRadius, g.cylinders[0].startRadius);  // thinner branches
        }
    }
}

TEST(Turtle, InterpretationRulesAreApplied) {
    Geometry g = draw("angle: 45\nwidth: 0.1\naxiom: A\nA -> A[B]A\ninterpretation:\nA -> F\nB -> +F\n", 1);
    EXPECT_EQ(g.cylinders.size(), 3u);
}

}  // namespace
}  // namespace sprout::test

namespace sprout::test {
namespace {

std::vector<int> agesOf(const std::string& text, int n) {
    DeriveOptions o;
    o.trackAges = true;
    Derivation d(grammarOf(text), o);
    EXPECT_TRUE(d.deriveTo(n).ok());
    auto a = d.ages(n);
    EXPECT_TRUE(a);
    EXPECT_EQ(a->size(), d.step(n)->size());
    return {a->begin(), a->end()};
}

TEST(Ages, EachModuleKnowsTheStepThatCreatedIt) {
    // F -> FF: the first F of the successor is the old F (it keeps its age), the second is new.
    EXPECT_EQ(agesOf("axiom: F\nF -> FF\n", 1), (std::vector<int>{0, 1}));
    EXPECT_EQ(agesOf("axiom: F\nF -> FF\n", 2), (std::vector<int>{0, 2, 1, 2}));
    // Modules no rule rewrites keep their age; new structure is young.
    // +A -> +F[-A] -> +F[-F[-A]]: the apex A stays the same module throughout.
    EXPECT_EQ(agesOf("axiom: +A\nA -> F[-A]\n", 2), (std::vector<int>{0, 1, 1, 1, 2, 2, 2, 0, 2, 1}));
    // The cut removes ages with their modules.
    // F[A]B -> F[%]FB -> F[]FB
    EXPECT_EQ(agesOf("axiom: F[A]B\nA -> %\nB -> FB\n", 1), (std::vector<int>{0, 0, 0, 1, 0}));
}

TEST(Ages, AgesDoNotChangeTheDerivedString) {
    const std::string g = "axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n";
    DeriveOptions o;
    o.trackAges = true;
    Derivation tracked(grammarOf(g), o);
    ASSERT_TRUE(tracked.deriveTo(5).ok());
    EXPECT_EQ(toString(*tracked.step(5), grammarOf(g)->alphabet), expand(g, 5));
}

TEST(Ages, GrowingSegmentsStartShortAndTheStepIsRecorded) {
    auto g = grammarOf("width: 0.1\naxiom: F\nF -> FF\n");
    DeriveOptions o;
    o.trackAges = true;
    Derivation d(g, o);
    ASSERT_TRUE(d.deriveTo(1).ok());
    Geometry half, full;
    TurtleOptions t{1, 1, d.ages(1)->data(), 1, 0.5f};
    interpret(*d.step(1), *g, t, half);
    ASSERT_EQ(half.cylinders.size(), 2u);
    EXPECT_EQ(half.cylinders[0].step, 0);
    EXPECT_EQ(half.cylinders[1].step, 1);
    EXPECT_FLOAT_EQ(half.cylinders[1].end.y - half.cylinders[1].start.y, 0.5f);  // growing
    EXPECT_FLOAT_EQ(half.bounds.max.y, 1.5f);
    t.growFraction = 1;
    interpret(*d.step(1), *g, t, full);
    EXPECT_FLOAT_EQ(full.bounds.max.y, 2.0f);
}


// ---- Drawing from the derivation tree (D0L) ----

// Draws the first step with at least 40,000 modules (the tree is for big strings) both
// ways and expects the same geometry; returns the tree's stats.
TurtleStats drawBothWays(const std::string& text) {
    auto g = grammarOf(text);
    if (!g) return {};
    int n = 1;
    DeriveResult r = derive(g, n);
    while (r.outcome.ok() && r.string->size() < 40000 && n < 40) r = derive(g, ++n);
    EXPECT_TRUE(r.outcome.ok());
    EXPECT_GE(r.string->size(), 40000u);
    Geometry fromString, fromTree;
    TurtleOptions o{n, g->settings.seed, nullptr};
    o.fromTree = false;
    EXPECT_FALSE(interpret(*r.string, *g, o, fromString).fromTree);
    o.fromTree = true;
    TurtleStats stats = interpret(*r.string, *g, o, fromTree);
    expectSameDrawing(fromTree, fromString, text);
    return stats;
}

// Whether step n of the grammar is drawn from the derivation tree.
bool drawnFromTree(const std::string& text, int n) {
    auto g = grammarOf(text);
    DeriveResult r = derive(g, n);
    EXPECT_TRUE(r.outcome.ok());
    Geometry geo;
    return interpret(*r.string, *g, {n, 1, nullptr}, geo).fromTree;
}

TEST(TreeTurtle, FractalPlantMatchesTheStringTurtle) {
    TurtleStats s = drawBothWays("angle: 22.5\naxiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n");
    EXPECT_TRUE(s.fromTree);
    EXPECT_GT(s.blocks, 5u);
}

TEST(TreeTurtle, ThreeDimensionalBushWithTaperAndBranchScale) {
    // Pitch, roll, turn around, taper (! after segments), branch_scale, gradient colours.
    TurtleStats s = drawBothWays(
        "angle: 22.5\nbranch_scale: 0.9\naxiom: A\n"
        "A -> [&FL!A]/////[&FL!A]///////[&FL!A]\nF -> S/////F\nS -> F|L\nL -> [^^-F+F+F-|-F+F+F]\n");
    EXPECT_TRUE(s.fromTree);
    EXPECT_GT(s.blocks, 0u);
}

TEST(TreeTurtle, BothTurtlesStayCloseToExactArithmetic) {
    // A reference turtle in double precision for F + - & ^ \ / | [ ]: both float turtles
    // stay within 1e-4 of it over 15,000 segments and thousands of rolls.
    const std::string text =
        "angle: 22.5\nbranch_scale: 0.9\naxiom: A\n"
        "A -> [&FL!A]/////[&FL!A]///////[&FL!A]\nF -> S/////F\nS -> F|L\nL -> [^^-F+F+F-|-F+F+F]\n";
    auto g = grammarOf(text);
    const int n = 7;
    DeriveResult r = derive(g, n);
    ASSERT_GE(r.string->size(), 40000u);
    Geometry tree;
    ASSERT_TRUE(interpret(*r.string, *g, {n, 1, nullptr}, tree).fromTree);
    struct State {
        glm::dvec3 pos{0, 0, 0}, H{0, 1, 0}, L{-1, 0, 0};
        double length = 1;
    } t;
    std::vector<State> stack;
    std::vector<glm::dvec3> ends;
    const double a = glm::radians(22.5);
    auto rotate = [](glm::dvec3& x, glm::dvec3& y, double r) {
        glm::dvec3 nx = x * std::cos(r) + y * std::sin(r);
        y = y * std::cos(r) - x * std::sin(r);
        x = nx;
    };
    for (char c : toString(*r.string, g->alphabet)) {
        glm::dvec3 U = glm::cross(t.H, t.L);
        switch (c) {
            case 'F': t.pos += t.H * t.length; ends.push_back(t.pos); break;
            case '+': rotate(t.H, t.L, a); break;
            case '-': rotate(t.H, t.L, -a); break;
            case '^': rotate(t.H, U, a); break;
            case '&': rotate(t.H, U, -a); break;
            case '\\': rotate(t.L, U, a); break;
            case '/': rotate(t.L, U, -a); break;
            case '|': t.H = -t.H; t.L = -t.L; break;
            case '[': stack.push_back(t); t.length *= 0.9; break;
            case ']': t = stack.back(); stack.pop_back(); break;
            default: break;
        }
    }
    Geometry fromString;
    TurtleOptions o{n, 1, nullptr};
    o.fromTree = false;
    interpret(*r.string, *g, o, fromString);
    for (const Geometry* geo : {&tree, &fromString}) {
        ASSERT_EQ(ends.size(), geo->cylinders.size());
        double worst = 0;
        for (size_t i = 0; i < ends.size(); ++i) worst = std::max(worst, glm::length(glm::dvec3(geo->cylinders[i].end) - ends[i]));
        EXPECT_LT(worst, 1e-4) << (geo == &tree ? "tree" : "string");
    }
}

TEST(Turtle, LongChainsOfPitchesKeepTheFrameUnitLength) {
    // A hundred '&' per rule: with U = H x L unnormalised, rounding in |H| and |L| fed back
    // through every pitch and stems grew to 10^13 units after 5 steps (found by fuzzing).
    auto g = grammarOf("angle: 25.7\naxiom: F\nF -> F[+F]" + std::string(100, '&') + "F[-F]F\n");
    DeriveResult r = derive(g, 5);
    for (bool fromTree : {false, true}) {
        TurtleOptions o{5, 1, nullptr};
        o.fromTree = fromTree;
        o.treeMinModules = 0;
        Geometry geo;
        interpret(*r.string, *g, o, geo);
        ASSERT_EQ(geo.cylinders.size(), 3125u);
        for (const auto& c : geo.cylinders) ASSERT_NEAR(glm::length(c.end - c.start), 1.0f, 1e-4f) << (fromTree ? "tree" : "string");
    }
}

TEST(TreeTurtle, MovesAndWidthsAndLengthScales) {
    // f moves (their places count in the bounds), # and ! change widths, @L scales steps.
    TurtleStats s = drawBothWays(
        "angle: 60\naxiom: A\nA -> F[+A]f[-A]#F@L!A\nF -> F\n");
    EXPECT_TRUE(s.fromTree);
}

TEST(TreeTurtle, InterpretationRulesAreDrawnAtTheLeaves) {
    // Edge rewriting with Fl and Fr drawn as F (ABOP 1.10): the homomorphism is applied where
    // the tree reaches a module, and blocks are made of what it draws.
    TurtleStats s = drawBothWays(
        "angle: 90\nmodule: Fl Fr\naxiom: Fl\nFl -> Fl+Fr+\nFr -> -Fl-Fr\ninterpretation:\nFl -> F[&F]\nFr -> F\n");
    EXPECT_TRUE(s.fromTree);
    EXPECT_GT(s.blocks, 5u);
    // Interpretation rules that are not one fixed string per symbol read the string.
    EXPECT_FALSE(drawnFromTree("angle: 90\nmodule: Fl Fr\naxiom: Fl\nFl -> Fl+Fr+\nFr -> -Fl-Fr\ninterpretation:\n"
                               "Fl -> F : 0.5\nFl -> FF : 0.5\nFr -> F\n",
                               16));
}

TEST(TreeTurtle, ABlockThatTapersTheSegmentBeforeItIsWalkedInstead) {
    // B starts with '!': it narrows the segment drawn before it, outside the block.
    TurtleStats s = drawBothWays("angle: 30\naxiom: A\nA -> FB[+A][-A]\nB -> !FC\nC -> F[+C][-C]\n");
    EXPECT_TRUE(s.fromTree);
}

TEST(TreeTurtle, RollsToHorizontalAndPolygonsAreWalked) {
    // Modules that cannot be in a block ($, polygons) are walked one by one, and so is all
    // of A, which holds them; so are blocks (F after n steps) inside an open polygon, where
    // F outlines it.
    TurtleStats s = drawBothWays(
        "angle: 22.5\naxiom: A\nA -> F[&B$A]/[^'A]~l{.-F.+F.}F\nB -> F[+F]B\nF -> FF\n");
    EXPECT_TRUE(s.fromTree);
    EXPECT_GT(s.blocks, 0u);
}

TEST(TreeTurtle, BlocksCarryPaletteStepsLeavesAndSpheres) {
    // ' and , step through the palette from the colour the turtle brings (wrapping past its
    // end); leaves, petals and spheres are placed with the segments.
    for (const char* axiom : {"A", "'''A", ",B[A]"}) {
        TurtleStats s = drawBothWays(std::string("angle: 30\naxiom: ") + axiom +
                                     "\nA -> F[+A'~l]F[-A,@O]F''''''''''''''''''''B\nB -> F[&~p]'B\n");
        EXPECT_TRUE(s.fromTree) << axiom;
        EXPECT_GT(s.blocks, 3u) << axiom;
    }
}

TEST(TreeTurtle, BlocksNestAsDeepAsTheDerivation) {
    // B after d steps is B F^d and holds B after d-1 steps: a thousand blocks built one
    // inside the other (on the heap, not the stack).
    auto g = grammarOf("angle: 1\naxiom: A\nA -> B+A\nB -> BF\n");
    const int n = 1000;
    DeriveResult r = derive(g, n);
    ASSERT_TRUE(r.outcome.ok());
    TurtleOptions o{n, 1, nullptr};
    Geometry tree, fromString;
    TurtleStats stats = interpret(*r.string, *g, o, tree);
    EXPECT_TRUE(stats.fromTree);
    EXPECT_GT(stats.blocks, 900u);
    o.fromTree = false;
    interpret(*r.string, *g, o, fromString);
    expectSameDrawing(tree, fromString, "nested blocks");
}

TEST(TreeTurtle, OnlyExactStepsOfD0LGrammarsAreDrawnFromTheTree) {
    const std::string plant = "angle: 22.5\naxiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n";
    auto g = grammarOf(plant);
    DeriveResult r = derive(g, 7);
    Geometry geo;
    // The wrong step number: the string is read.
    EXPECT_FALSE(interpret(*r.string, *g, {6, 1, nullptr}, geo).fromTree);
    ModuleString changed = *r.string;
    changed.symbols[2000] = SymbolId((changed.symbols[2000] + 1) % g->alphabet.size());
    EXPECT_FALSE(interpret(changed, *g, {7, 1, nullptr}, geo).fromTree);
    // Jitter and tropism depend on where the turtle is: the string is read.
    EXPECT_FALSE(drawnFromTree("angle: 22.5 ~ 3\n" + plant.substr(plant.find('\n') + 1), 7));
    EXPECT_FALSE(drawnFromTree("tropism: 0 -1 0 0.2\n" + plant, 7));
    EXPECT_TRUE(drawnFromTree(plant, 7));
}

}  // namespace
}  // namespace sprout::test

// The predefined surfaces' unit meshes are finite everywhere, their tips too (a float pi's
// sine below 0 raised to a fraction made every leaf's and petal's tip NaN), and their texture
// coordinates one a point.
TEST(Turtle, TheUnitLeafPetalAndSphereAreFinite) {
    const sprout::SurfaceMesh meshes[] = {sprout::makeLeaf(), sprout::makeLeaf(3, 1), sprout::makePetal(), sprout::makePetal(3, 2),
                                          sprout::makeSphere(16, 10), sprout::makeSphere(6, 2)};
    for (const sprout::SurfaceMesh& m : meshes) {
        ASSERT_EQ(m.uvs.size(), m.positions.size());
        for (size_t k = 0; k < m.positions.size(); ++k) {
            const glm::vec3& p = m.positions[k];
            EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << "point " << k;
            EXPECT_NEAR(glm::length(m.normals[k]), 1.0f, 1e-4f) << "normal " << k;
        }
    }
    const sprout::SurfaceMesh leaf = sprout::makeLeaf();
    EXPECT_FLOAT_EQ(leaf.positions.back().y, 1.0f) << "the tip at the leaf's length";
    EXPECT_FLOAT_EQ(leaf.uvs.back()[1], 1.0f);
}

namespace sprout::test {
// A textured stem, leaf or sphere is drawn as triangles with texture coordinates, taken out
// of the instances; the first 40,000 of a drawing only (a stem's triangles take a hundred
// times its instance's memory): the rest stay instances in their colour.
TEST(Turtle, TexturedStemsAreTrianglesUpToTheirLimit) {
    const std::string head = "material: 1 #ffffff texture bark.png\nwidth: 0.1\naxiom: ;(1) F ~l(1) @O(0.5)\nF -> FF\n";
    const Geometry few = draw(head + "n: 3\n");
    EXPECT_EQ(few.cylinders.size(), 0u) << "every stem textured";
    EXPECT_EQ(few.surfaces.size(), 0u) << "the leaf and the sphere too";
    ASSERT_EQ(few.textures.size(), 1u);
    EXPECT_EQ(few.polygons.texcoords.size(), few.polygons.positions.size());
    for (const TexCoord& c : few.polygons.texcoords) EXPECT_EQ(c.texture, 1u);
    const Geometry many = draw(head + "n: 16\n");  // 65,536 stems
    EXPECT_EQ(many.cylinders.size(), 65536u - 40000u) << "those after the first 40,000 stay instances";
    EXPECT_EQ(many.surfaces.size(), 2u);
}
}  // namespace sprout::test
