// Parametric L-systems (ABOP chapter 1.10): formal parameters, conditions, expressions.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace sprout::test {
namespace {

TEST(Parametric, ApexAgesThenBecomesASegment) {
    // Lecture slides 002: A(t) -> A(t+0.01), A(t) : t >= 1.0 -> F (conditional rule first).
    const std::string g = "axiom: A(0)\nA(t) : t >= 1.0 -> F\nA(t) -> A(t+0.01)\n";
    EXPECT_EQ(expand(g, 1), "A(0.01)");
    EXPECT_EQ(expand(g, 2), "A(0.02)");
    EXPECT_EQ(expand(g, 3), "A(0.03)");
    // 0.01 added 100 times is 1.0000000000000007 in doubles: at step 100 the apex is old
    // enough, so step 101 draws it.
    EXPECT_EQ(expand(g, 100), "A(1.0000000000000007)");
    EXPECT_EQ(expand(g, 101), "F");
    EXPECT_EQ(expand(g, 120), "F");
}

TEST(Parametric, WarnsWhenAnEarlierRuleHidesALaterOne) {
    // Written in the slides' order, the unconditional rule always wins: say so.
    auto diags = diagnosticsOf("axiom: A(0)\nA(t) -> A(t+0.01)\nA(t) : t >= 1.0 -> F\n");
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0],
              "3:1: warning: this rule never applies: the rule on line 2 always rewrites 'A' first "
              "(put rules with conditions or contexts before it)");
}

TEST(Parametric, BranchingTreeExpressions) {
    const std::string g = "axiom: A(1)\nA(x) -> F(x)[+A(x*0.5)][-A(x*0.5)]\n";
    EXPECT_EQ(expand(g, 1), "F(1)[+A(0.5)][-A(0.5)]");
    EXPECT_EQ(expand(g, 2), "F(1)[+F(0.5)[+A(0.25)][-A(0.25)]][-F(0.5)[+A(0.25)][-A(0.25)]]");
}

TEST(Parametric, SameNameWithAndWithoutParameters) {
    // F and F(2) are different modules: each has its own rule.
    const std::string g = "axiom: F F(2)\nF -> FF\nF(x) -> F(x*3)\n";
    EXPECT_EQ(expand(g, 1), "FFF(6)");
    EXPECT_EQ(expand(g, 2), "FFFFF(18)");
}

TEST(Parametric, DefinesAndMultipleParameters) {
    const std::string g =
        "define: R = 1.456\n#define W 0.5\n"
        "axiom: A(1, 10)\n"
        "A(s, w) : s >= 1 -> F(s)!(w)[+A(s/R, w*W)]\n";
    EXPECT_EQ(expand(g, 1), "F(1)!(10)[+A(0.6868131868131868,5)]");
    EXPECT_EQ(expand(g, 2), "F(1)!(10)[+A(0.6868131868131868,5)]");  // condition now false
}

TEST(Parametric, ConditionsWithLogic) {
    const std::string g =
        "axiom: B(1)B(5)B(9)\n"
        "B(x) : x > 2 && x < 8 -> M\n"
        "B(x) : !(x < 8) -> H\n";
    EXPECT_EQ(expand(g, 1), "B(1)MH");
}

TEST(Parametric, ShortestRoundTripNumbers) {
    EXPECT_EQ(expand("axiom: A(0.1)\nA(x) -> A(x*3)\n", 1), "A(0.30000000000000004)");
    EXPECT_EQ(expand("axiom: A(1e21, -0.5, 100)\n", 0), "A(1e+21,-0.5,100)");
}

TEST(Parametric, ParametricContextSignalAlongAStem) {
    // Lecture slides 002: A(t0) < A(t1) > A(t2) : t2 > t1 & t1 > t0 -> A(t1 + 0.01)
    const std::string g =
        "axiom: A(1)A(2)A(3)A(3)\n"
        "A(a) < A(b) > A(c) : c > b & b > a -> A(b + 0.01)\n";
    EXPECT_EQ(expand(g, 1), "A(1)A(2.01)A(3)A(3)");
}

TEST(Parametric, AxiomParametersAreExpressions) {
    EXPECT_EQ(expand("define: L = 2\naxiom: F(L * 3) +(90 / 4)\n", 0), "F(6)+(22.5)");
}

}  // namespace
}  // namespace sprout::test
