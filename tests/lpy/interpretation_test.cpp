// L-Py's interpretation with its turtle (lpy/engine.cpp interpret): StartInterpretation and
// EndInterpretation draw what they produce first and last; the `turtle` of interpretation rules
// draws where the rule runs, and the parameters a model adds to it follow the turtle's
// branches.
#include <gtest/gtest.h>

#include <cmath>

#include "core/derive/draw.hpp"
#include "lpy/host.hpp"
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
