// L-Py's interpretation with its turtle (lpy/engine/engine.cpp interpret): StartInterpretation and
// EndInterpretation draw what they produce first and last; the `turtle` of interpretation rules
// draws where the rule runs, and the parameters a model adds to it follow the turtle's
// branches.
#include <gtest/gtest.h>

#include <cmath>

#include "core/derive/draw.hpp"
#include "core/language/module_string.hpp"
#include "lpy/lpy.hpp"
#include "tests/lpy/lpy_messages.hpp"

namespace sprout {
namespace {

Geometry drawn(const lpy::Model& m) {
    Geometry geo;
    TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
    return geo;
}

TEST(LpyInterpretation, StartAndEndInterpretationDrawFirstAndLast) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::Model m = lpy::runModel("def StartInterpretation():\n    produce F(1)\n\ndef EndInterpretation():\n    produce F(3)\n\n"
                                 "Axiom: F(2)\nderivation length: 0\nproduction:\nendlsystem\n",
                                 {});
    ASSERT_TRUE(m.ok()) << messages(m);
    const Geometry geo = drawn(m);
    ASSERT_EQ(geo.cylinders.size(), 3u);
    EXPECT_NEAR(geo.cylinders[0].end.y, 1.0f, 1e-5f);  // L-Py's turtle heads up: Sprout's +Y
    EXPECT_NEAR(geo.cylinders[1].end.y, 3.0f, 1e-5f);
    EXPECT_NEAR(geo.cylinders[2].end.y, 6.0f, 1e-5f);
}

TEST(LpyInterpretation, TheTurtleDrawsWhereTheRuleRunsAndItsParametersFollowBranches) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // Each K counts itself into the turtle's `depth` and draws a step turned 90 degrees; A
    // checks the count the walk has at its place: a branch's Ks are forgotten after its ']'.
    const char* model =
        "def StartInterpretation(turtle):\n"
        "    turtle.add_parameter('depth', 0)\n"
        "\n"
        "Axiom: K [ K K A(3) ] A(1) K A(2)\n"
        "derivation length: 0\n"
        "production:\n"
        "interpretation:\n"
        "K :\n"
        "    turtle.depth += 1\n"
        "    turtle.left(90)\n"
        "    turtle.F(2)\n"
        "A(expected) :\n"
        "    assert turtle.depth == expected, (turtle.depth, expected)\n"
        "endlsystem\n";
    lpy::Model m = lpy::runModel(model, {});
    ASSERT_TRUE(m.ok()) << messages(m);
    const Geometry geo = drawn(m);
    ASSERT_EQ(geo.cylinders.size(), 4u);
    // The first step, turned 90 degrees from up, lies flat, 2 long.
    const auto& c = geo.cylinders[0];
    EXPECT_NEAR(c.end.y - c.start.y, 0.0f, 1e-4f);
    EXPECT_NEAR(std::hypot(c.end.x - c.start.x, c.end.z - c.start.z), 2.0f, 1e-4f);
    // A count that is off fails the model at A's line.
    lpy::Model wrong = lpy::runModel(std::string(model).replace(std::string(model).find("A(1)"), 4, "A(2)"), {});
    ASSERT_FALSE(wrong.ok());
    EXPECT_NE(wrong.diagnostics.back().message.find("AssertionError"), std::string::npos) << messages(wrong);
    // What the turtle does not have is said so.
    lpy::Model unknown = lpy::runModel("Axiom: K\nderivation length: 0\nproduction:\ninterpretation:\nK :\n    turtle.fly(3)\nendlsystem\n", {});
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.diagnostics.back().message.find("the turtle has no 'fly'"), std::string::npos) << messages(unknown);
}

}  // namespace
}  // namespace sprout

namespace sprout {
namespace {

// Steps drawn later (RunOptions::drawLater: `import sprout`, the viewer) are the steps drawn at
// once: the same strings to draw, the same modules they come from, for a model of the Python
// path with interpretation rules and one of the native path; and each step's record read
// later is the one the run keeps.
TEST(LpyInterpretation, StepsDrawnLaterAreTheStepsDrawnAtOnce) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const char* models[] = {
        "Axiom: A(1)\nderivation length: 3\nproduction:\nA(x) :\n    produce A(x + 1) [+B(x)]\ninterpretation:\nB(x) --> F(x) X\nendlsystem\n",
        "Axiom: A(1)\nderivation length: 4\nproduction:\nA(x) --> F(x) [+A(x * 0.5)] A(x + 1)\nendlsystem\n",
    };
    for (const char* model : models) {
        SCOPED_TRACE(model);
        lpy::RunOptions o;
        o.keepSteps = true;
        const lpy::Model now = lpy::runModel(model, o);
        o.drawLater = true;
        const lpy::Model later = lpy::runModel(model, o);
        o.keepRecord = false;
        const lpy::Model bare = lpy::runModel(model, o);
        ASSERT_TRUE(now.ok() && later.ok() && bare.ok()) << messages(later) << messages(bare);
        ASSERT_TRUE(later.later && bare.later);
        EXPECT_TRUE(later.steps.empty());
        EXPECT_TRUE(bare.record.steps.empty());
        ASSERT_EQ(size_t(later.later->steps()), now.steps.size());
        ASSERT_EQ(later.record.steps.size(), now.record.steps.size());
        for (int k = 0; k < later.later->steps(); ++k) {
            SCOPED_TRACE(k);
            std::vector<std::uint32_t> from;
            auto g = later.later->draw(k, &from);
            ASSERT_TRUE(g);
            EXPECT_EQ(toString(g->axiom, g->alphabet), toString(now.steps[size_t(k)]->axiom, now.steps[size_t(k)]->alphabet));
            EXPECT_EQ(from, *now.drawnFrom[size_t(k)]);
            auto plain = bare.later->draw(k);
            EXPECT_EQ(toString(plain->axiom, plain->alphabet), toString(g->axiom, g->alphabet));
            const DerivationRecord r = bare.later->derived(k);
            EXPECT_EQ(toString(*r.steps.at(0), r.grammar->alphabet),
                      toString(*now.record.steps[size_t(k)], now.record.grammar->alphabet));
            auto list = [](const auto& v) {
                std::string out;
                for (size_t i = 0; i < v.size(); ++i) out += std::to_string(v[i]) + " ";
                return out;
            };
            EXPECT_EQ(list(r.origins.at(0)->parent), list(now.record.origins[size_t(k)]->parent));
            EXPECT_EQ(list(r.origins.at(0)->rule), list(now.record.origins[size_t(k)]->rule));
            EXPECT_EQ(toString(*later.record.steps[size_t(k)], later.record.grammar->alphabet),
                      toString(*now.record.steps[size_t(k)], now.record.grammar->alphabet));
        }
        EXPECT_THROW(bare.later->draw(99), std::out_of_range);
    }
}

// An interpretation rule's Python error, met when the step is drawn, says where it is.
TEST(LpyInterpretation, AnErrorDrawingLaterSaysItsLine) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::RunOptions o;
    o.keepSteps = true;
    o.drawLater = true;
    const lpy::Model m = lpy::runModel("Axiom: B\nderivation length: 1\nproduction:\ninterpretation:\nB :\n    x = 1 / 0\n    produce F\nendlsystem\n", o);
    ASSERT_TRUE(m.ok() && m.later) << messages(m);
    try {
        m.later->draw(1);
        FAIL() << "no error";
    } catch (lpy::DrawError& e) {
        EXPECT_EQ(e.diagnostic.line, 6);
        EXPECT_NE(std::string(e.what()).find("ZeroDivisionError"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sprout
