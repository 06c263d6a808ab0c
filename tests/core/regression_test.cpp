// Bugs found in review, each kept as a test so it stays fixed.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace sprout::test {
namespace {

TEST(Regression, StochasticChoiceBindsTheChosenRulesParameters) {
    // The third rule's context bound z=7 into slot 0 while being tested; the chosen rule
    // must still see its own x=1.
    const std::string g =
        "axiom: B(7)A(1)\nA(x) -> C(x) : 0.5\nA(x) -> D(x) : 0.5\nB(z) < A(x) : 0 -> E : 0.5\n";
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::string s = expand(g, 1, seed);
        EXPECT_TRUE(s == "B(7)C(1)" || s == "B(7)D(1)") << s;
    }
}

TEST(Regression, RandOutsideRulesGivesNewValuesAndFollowsTheSeed) {
    std::string a = expand("seed: 5\naxiom: A(rand(0,1))B(rand(0,1))\n", 0);
    EXPECT_NE(a.substr(2, a.find(')') - 2), a.substr(a.find("B(") + 2, a.size() - a.find("B(") - 3)) << a;
    // `seed:` applies even when written after the values that use it.
    EXPECT_EQ(expand("axiom: A(rand(0,1))\nseed: 5\n", 0), expand("seed: 5\naxiom: A(rand(0,1))\n", 0));
    EXPECT_NE(expand("seed: 5\naxiom: A(rand(0,1))\n", 0), expand("seed: 6\naxiom: A(rand(0,1))\n", 0));
}

TEST(Regression, CutInTheAxiomIsApplied) {
    EXPECT_EQ(expand("axiom: A[B%C]D\nA -> A\n", 1), "A[B]D");
}

TEST(Regression, NoSumWarningWhenStochasticRulesHaveConditions) {
    auto d = diagnosticsOf("axiom: A(1)\nA(x) -> B : 0.2\nA(x) : x > 0 -> C : 0.3\nA(x) -> D : 0.5\n");
    EXPECT_TRUE(d.empty()) << d[0];
}

TEST(Regression, LongFlatExpressionIsAnErrorNotACrash) {
    std::string sum = "x";
    for (int i = 0; i < 200000; ++i) sum += "+x";
    auto d = diagnosticsOf("axiom: A(1)\nA(x) -> B(" + sum + ")\n");
    ASSERT_FALSE(d.empty());
    EXPECT_NE(d[0].find("expression is too long"), std::string::npos) << d[0];
}

TEST(Regression, LongNumbersAreRead) {
    EXPECT_EQ(expand("axiom: A(3.14159265358979323846264338327950288419716939937510582097494459)\n", 0),
              "A(3.141592653589793)");
    auto d = diagnosticsOf("axiom: A(1e999)\n");
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d[0], "1:10: number is too large");
}

TEST(Regression, SecondArrowsAndContextsAreErrors) {
    EXPECT_EQ(diagnosticsOf("axiom: A\nA > B > C -> D\n").at(0), "2:7: a second '>': write contexts as 'left < module > right'");
    EXPECT_EQ(diagnosticsOf("axiom: A\nA -> B -> C\n").at(0), "2:8: a second '->': a rule has one arrow, one rule per line");
    EXPECT_EQ(diagnosticsOf("axiom: A\nA -> F : 0.5 : 0.5\n").at(0),
              "2:8: a second ':' after '->': a rule has at most one probability");
}

TEST(Regression, HashDirectivesWithAColon) {
    EXPECT_EQ(expand("#ignore: +\naxiom: A+B\nA < B -> C\n", 1), "A+C");
    EXPECT_EQ(expand("#define: k 2\naxiom: A(k)\n", 0), "A(2)");
}

TEST(Regression, MessagesKeepWholeCharacters) {
    EXPECT_EQ(diagnosticsOf("axiom: A\nA -> G(\xC3\xBC + 1)\n").at(0),
              "2:8: expected a number, a name or '(' but found '\xC3\xBC'");
}

TEST(Regression, OldMacLineEnds) {
    EXPECT_EQ(expand("axiom: F\rF -> FF\r", 2), "FFFF");
}

}  // namespace
}  // namespace sprout::test
