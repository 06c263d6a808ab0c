// The growth budget on L-Py's Python path (issue 39): which rules make the same successor
// whenever they match (read by the translation), growth through them refused before the first
// step, at the `derivation length:` line, and no refusal where Python may steer the derivation.
#include <gtest/gtest.h>

#include <string>

#include "core/language/diagnostic.hpp"
#include "lpy/lpy.hpp"
#include "tests/lpy/lpy_messages.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout {
namespace {

TEST(LpyGrowth, PlainBodiesAlwaysProduce) {
    const lpy::Translation t = lpy::translate(
        "Axiom: A(1)\nproduction:\n"
        "A(x):\n    y = x * 2\n    produce A(x+1) A(y)\n"               // 0: plain
        "B(x): produce B(x)B(x)\n"                                    // 1: plain, on the header's line
        "C(x):\n    if x > 1:\n        produce C(x)C(x)\n"            // 2: a branch
        "D(x):\n    nproduce D(x)\n    produce D(x)\n"                // 3: nproduce
        "E(x):\n    produce E(x)\n    x = 1\n"                        // 4: produce not last
        "G(x):\n    produce (G(x)\n             G(x))\n"              // 5: over two lines
        "H(x):\n    return\n"                                         // 6: no produce
        "I --> I I\n"                                                 // 7: an arrow
        "J(x):\n    y = [k for k in range(3)]\n    produce J(y);(2)J(y)\n"  // 8: plain, ';' a module
        "endlsystem\n");
    ASSERT_TRUE(t.ok());
    ASSERT_EQ(t.rules.size(), 9u);
    const bool expected[] = {true, true, false, false, false, false, false, true, true};
    for (size_t r = 0; r < 9; ++r) EXPECT_EQ(t.rules[r].alwaysProduces, expected[r]) << "rule " << r << ": " << t.rules[r].header;
    EXPECT_EQ(t.rules[0].successor.size(), 2u);
    EXPECT_EQ(t.rules[8].successor.size(), 3u);
    EXPECT_FALSE(t.writesCut);
    EXPECT_TRUE(lpy::translate("Axiom: A\nproduction:\nA :\n    produce [A%]A\nendlsystem\n").writesCut);
}

TEST(LpyGrowth, DoublingBodyIsRefusedBeforeItsFirstStep) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // The row: 2^40 modules asked for; step 26 is the first over 50 M modules. Deriving
    // the 25 steps before it took 21 s and 5.2 GB.
    const std::string text = "Axiom: A(1)\nderivation length: 40\nproduction:\nA(x):\n    y = x*2\n    produce A(x+1) A(y)\nendlsystem\n";
    lpy::Model m = lpy::runModel(text, {});
    ASSERT_FALSE(m.ok());
    ASSERT_EQ(m.diagnostics.size(), 1u) << messages(m);
    EXPECT_EQ(m.diagnostics[0].line, 2);  // derivation length: 40
    // The exact count (no "about"): the prediction made before the first step, not the guess
    // from a step already derived.
    EXPECT_EQ(m.diagnostics[0].message.rfind("step 26 would make 67,108,864 modules", 0), 0u) << messages(m);
    EXPECT_NE(m.diagnostics[0].message.find("lower the derivation length (to 25 at most)"), std::string::npos) << messages(m);

    // Crossing only at the last step asked for: refused all the same, at once.
    lpy::RunOptions o;
    o.steps = 26;
    lpy::Model last = lpy::runModel(text, o);
    ASSERT_FALSE(last.ok());
    EXPECT_NE(messages(last).find("step 26 would make"), std::string::npos) << messages(last);
    o.steps = 12;  // under the limits: derived
    lpy::Model under = lpy::runModel(text, o);
    ASSERT_TRUE(under.ok()) << messages(under);
    EXPECT_EQ(under.stepsDone, 12);
}

TEST(LpyGrowth, ParametersMeasuredCountTowardsTheBudget) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // Lists of 20 numbers: a module takes some 290 bytes, not 80; the budget is crossed by bytes
    // long before the module limit, and the message says the parameters were measured.
    lpy::RunOptions o;
    o.maxBytes = 64u << 20;
    lpy::Model m = lpy::runModel("Axiom: A([1.0] * 20)\nderivation length: 40\nproduction:\nA(x) :\n    y = list(x)\n    produce A(x) A(y)\nendlsystem\n", o);
    ASSERT_FALSE(m.ok());
    const std::string said = messages(m);
    EXPECT_NE(said.find("step 18 would make 262,144 modules"), std::string::npos) << said;
    EXPECT_NE(said.find("their Python parameters measured"), std::string::npos) << said;
    EXPECT_NE(said.find("over the memory budget of 64.0 MB"), std::string::npos) << said;
}

TEST(LpyGrowth, NoRefusalWherePythonSteersTheDerivation) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::string doubling = "production:\nA(x):\n    produce A(x) A(x)\n";
    const char* models[] = {
        // Stopped by EndEach after 4 steps.
        "Axiom: A(1)\nderivation length: 60\ndef EndEach():\n    if getIterationNb() >= 3:\n        Stop()\n",
        // Another group of rules used from step 2 on: it does not double.
        "Axiom: A(1)\nderivation length: 60\ndef StartEach():\n    if getIterationNb() >= 2:\n        useGroup(1)\n",
        // A branch in the body: the rule may not apply.
        "Axiom: A(1)\nderivation length: 60\nproduction:\nA(x):\n    if x < 0:\n        produce A(x) A(x)\nendlsystem\n",
        // A cut ends each branch: the string stays small.
        "Axiom: [A(1)]\nderivation length: 60\nproduction:\nA(x):\n    produce A(x) % A(x)\nendlsystem\n",
    };
    for (size_t k = 0; k < 4; ++k) {
        std::string text = models[k];
        if (k == 0) text += doubling + "endlsystem\n";
        if (k == 1) text += doubling + "group 1:\nA(x) --> A(x)\nendlsystem\n";
        lpy::Model m = lpy::runModel(text, {});
        EXPECT_TRUE(m.ok()) << k << ": " << messages(m);
    }
}

}  // namespace
}  // namespace sprout
