// The .lsys language: directives, rule syntax, comments, notation variants.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace sprout::test {
namespace {

TEST(Parser, FractalPlantFromTheBook) {
    auto g = grammarOf(
        "# Fractal plant, ABOP fig. 1.24f\n"
        "n: 5\n"
        "angle: 22.5\n"
        "axiom: X\n"
        "X -> F-[[X]+X]+F[+FX]-X\n"
        "F -> FF\n");
    ASSERT_TRUE(g);
    EXPECT_EQ(g->settings.iterations, 5);
    EXPECT_DOUBLE_EQ(g->settings.angle.mean, 22.5);
    EXPECT_EQ(g->rules.productions.size(), 2u);
    EXPECT_EQ(toString(g->axiom, g->alphabet), "X");
}

TEST(Parser, DirectivesAndAliases) {
    auto g = grammarOf(
        "iterations: 7\nangle: 22 ~ 4\nstep: 10 ~ 2\nwidth: 0.5\nseed: 18446744073709551615\naxiom: F\n");
    ASSERT_TRUE(g);
    EXPECT_EQ(g->settings.iterations, 7);
    EXPECT_DOUBLE_EQ(g->settings.angle.mean, 22);
    EXPECT_DOUBLE_EQ(g->settings.angle.sigma, 4);
    EXPECT_DOUBLE_EQ(g->settings.step.mean, 10);
    EXPECT_DOUBLE_EQ(g->settings.step.sigma, 2);
    EXPECT_DOUBLE_EQ(g->settings.width, 0.5);
    EXPECT_EQ(g->settings.seed, 18446744073709551615ull);
}

TEST(Parser, SettingsMayUseDefines) {
    auto g = grammarOf("define: k = 7\nn: k - 2\nangle: 360 / k\naxiom: F\n");
    ASSERT_TRUE(g);
    EXPECT_EQ(g->settings.iterations, 5);
    EXPECT_DOUBLE_EQ(g->settings.angle.mean, 360.0 / 7);
    EXPECT_EQ(g->defineOrder, std::vector<std::string>{"k"});
}

TEST(Parser, ArrowVariantsAndLabels) {
    EXPECT_EQ(expand("axiom: F\nF \xE2\x86\x92 F+F\n", 1), "F+F");  // →
    EXPECT_EQ(expand("axiom: F\nF --> F+F\n", 1), "F+F");           // L-Py
    EXPECT_EQ(expand("axiom: F\np1: F -> F+F\n", 1), "F+F");        // ABOP labels
    EXPECT_EQ(expand("\xCF\x89: F\nF -> F-F\n", 1), "F-F");          // ω: axiom
}

TEST(Parser, CommentsAndBlankLines) {
    EXPECT_EQ(expand("# a comment\n\n   # indented\n// also a comment\naxiom: F#F\nF -> F!\n", 1),
              "F!#F!");  // '#' after content is the width module, not a comment
}

TEST(Parser, WindowsLineEndingsAndByteOrderMark) {
    EXPECT_EQ(expand("\xEF\xBB\xBF" "axiom: F\r\nF -> FF\r\n", 2), "FFFF");
}

TEST(Parser, UnicodeMinusIsAcceptedWithAWarning) {
    EXPECT_EQ(expand("axiom: F\nF -> F\xE2\x88\x92" "F\n", 1), "F-F");
    auto diags = diagnosticsOf("axiom: F\nF -> F\xE2\x88\x92" "F\n");
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0], "2:7: warning: the Unicode minus sign '\xE2\x88\x92' was read as '-'");
}

TEST(Parser, InterpretationSectionIsSeparate) {
    auto g = grammarOf("axiom: A\nA -> AB\ninterpretation:\nA -> F\nB -> +F\n");
    ASSERT_TRUE(g);
    EXPECT_EQ(g->rules.productions.size(), 1u);
    EXPECT_EQ(g->interpretation.productions.size(), 2u);
}

TEST(Parser, ContextAndConditionAndProbabilityTogether) {
    auto g = grammarOf("axiom: A(1)B(2)\nA(x) < B(y) > * : x < y -> C(x+y) : 0.5\n");
    ASSERT_TRUE(g);
    const Production& p = g->rules.productions.at(0);
    EXPECT_EQ(p.left.size(), 1u);
    EXPECT_TRUE(p.right.empty());  // '*' alone means no right context
    EXPECT_TRUE(p.condition.has_value());
    EXPECT_DOUBLE_EQ(p.probability, 0.5);
    EXPECT_EQ(p.slotCount, 2);
}

TEST(Parser, GrammarProperties) {
    EXPECT_FALSE(grammarOf("axiom: F\nF -> FF\n")->parametric());
    EXPECT_TRUE(grammarOf("axiom: F(1)\n")->parametric());
    EXPECT_TRUE(grammarOf("axiom: F\nA < F -> F\n")->hasContext());
    EXPECT_TRUE(grammarOf("axiom: F\nF -> F : 1\n")->stochastic());
    EXPECT_TRUE(grammarOf("axiom: F\nF -> F%\n")->usesCut());
}

}  // namespace
}  // namespace sprout::test
