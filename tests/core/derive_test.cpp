// D0L derivation: exact strings from ABOP chapter 1, on the fast path and the general one.
#include <gtest/gtest.h>

#include "core/derive/d0l.hpp"
#include "test_util.hpp"

namespace sprout::test {
namespace {

TEST(Derive, AlgaeLengthsAreFibonacci) {
    const std::string g = "axiom: A\nA -> AB\nB -> A\n";
    EXPECT_EQ(expand(g, 0), "A");
    EXPECT_EQ(expand(g, 1), "AB");
    EXPECT_EQ(expand(g, 2), "ABA");
    EXPECT_EQ(expand(g, 3), "ABAAB");
    EXPECT_EQ(expand(g, 4), "ABAABABA");
    size_t a = 1, b = 2;
    for (int n = 1; n <= 25; ++n) {
        EXPECT_EQ(expand(g, n).size(), b) << "n=" << n;
        size_t c = a + b;
        a = b;
        b = c;
    }
}

TEST(Derive, ApexWithGrowingInternodes) {
    EXPECT_EQ(expand("axiom: FA\nA -> +FA\nF -> FF\n", 4), "FFFFFFFFFFFFFFFF+FFFFFFFF+FFFF+FF+FA");
}

TEST(Derive, KochHasFivePowerNSegments) {
    const std::string g = "axiom: F\nF -> F+F-F-F+F\n";
    for (int n = 0; n <= 7; ++n) {
        std::string s = expand(g, n);
        size_t fs = std::count(s.begin(), s.end(), 'F');
        size_t expected = 1;
        for (int k = 0; k < n; ++k) expected *= 5;
        EXPECT_EQ(fs, expected) << "n=" << n;
    }
    EXPECT_EQ(expand(g, 1), "F+F-F-F+F");
    EXPECT_EQ(expand(g, 2), "F+F-F-F+F+F+F-F-F+F-F+F-F-F+F-F+F-F-F+F+F+F-F-F+F");
}

TEST(Derive, FractalPlantFirstSteps) {
    const std::string g = "axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n";
    EXPECT_EQ(expand(g, 1), "F-[[X]+X]+F[+FX]-X");
    EXPECT_EQ(expand(g, 2),
              "FF-[[F-[[X]+X]+F[+FX]-X]+F-[[X]+X]+F[+FX]-X]+FF[+FFF-[[X]+X]+F[+FX]-X]-F-[[X]+X]+F[+FX]-X");
}

TEST(Derive, FractalPlantN10HasTheExpectedSize) {
    auto g = grammarOf("axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n");
    DeriveResult r = derive(g, 10);
    ASSERT_TRUE(r.outcome.ok());
    // 6.46 M modules, the benchmark figure quoted by the core issue.
    EXPECT_EQ(r.string->size(), 6464679u);
}

TEST(Derive, NodeRewritingAndEmptySuccessor) {
    EXPECT_EQ(expand("axiom: X\nX -> F[+X][-X]FX\nF -> FF\n", 1), "F[+X][-X]FX");
    EXPECT_EQ(expand("axiom: AXBX\nX ->\n", 1), "AB");
    EXPECT_EQ(expand("axiom: AXBX\nX ->\nA -> AA\n", 2), "AAAAB");
}

TEST(Derive, MultiLetterModulesUseLongestMatch) {
    const std::string g =
        "module: plant internode seg\n"
        "axiom: plant\n"
        "plant -> internode[+plant]seg\n"
        "seg -> seg seg\n";
    EXPECT_EQ(expand(g, 1), "internode[+plant]seg");
    EXPECT_EQ(expand(g, 2), "internode[+internode[+plant]seg]segseg");
}

TEST(Derive, WhitespaceInSuccessorsIsInsignificant) {
    EXPECT_EQ(expand("axiom: F\nF -> F [ + F ] F\n", 1), "F[+F]F");
}

TEST(Derive, FastPathAndGeneralPathAgree) {
    // The same D0L grammar through both engines: adding a never-true context forces the
    // general path without changing the result.
    const std::string d0l = "axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n";
    const std::string general = d0l + "Q < Z -> Z\n";
    ASSERT_TRUE(D0LExpander::applicable(*grammarOf(d0l)));
    ASSERT_FALSE(D0LExpander::applicable(*grammarOf(general)));
    for (int n = 0; n <= 7; ++n) EXPECT_EQ(expand(d0l, n), expand(general, n)) << "n=" << n;
}

TEST(Derive, StepsCanBeRevisitedInAnyOrder) {
    auto g = grammarOf("axiom: F\nF -> F+F-F-F+F\n");
    Derivation d(g);
    ASSERT_TRUE(d.deriveTo(6).ok());
    EXPECT_EQ(d.step(6)->size(), 15625u + 15624u);  // 5^6 F and 5^6-1 turns
    EXPECT_EQ(toString(*d.step(1), g->alphabet), "F+F-F-F+F");
    EXPECT_EQ(d.step(3)->size(), 125u + 124u);
    EXPECT_EQ(d.step(7), nullptr);  // not derived yet
    ASSERT_TRUE(d.deriveTo(7).ok());
    EXPECT_EQ(d.step(7)->size(), 78125u + 78124u);
}

TEST(Derive, GeneralPathKeepsEveryStep) {
    auto g = grammarOf("axiom: S\nS -> FAT\nA > T -> [+FBF]\nA > F -> F\nB -> [-FAF]\nT -> F\n");
    Derivation d(g);
    ASSERT_TRUE(d.deriveTo(4).ok());
    EXPECT_EQ(d.stepsDerived(), 4);
    EXPECT_EQ(d.stats().size(), 5u);
    auto s2 = d.step(2);
    ASSERT_TRUE(d.deriveTo(4).ok());
    EXPECT_EQ(d.step(2), s2);  // the same object: nothing re-derived
}

TEST(Derive, CutRemovesTheRestOfTheBranch) {
    EXPECT_EQ(expand("axiom: F[+AFF]F\nA -> %\n", 1), "F[+]F");
    EXPECT_EQ(expand("axiom: FAF[+F]F\nA -> %\n", 1), "F");
    EXPECT_EQ(expand("axiom: F[A[+F]F]G\nA -> B%\n", 1), "F[B]G");
}

TEST(Derive, InterpretationRulesAreNotStored) {
    auto g = grammarOf(
        "axiom: 0\n0 -> 1[0]0\n1 -> 11\n"
        "interpretation:\n0 -> F\n1 -> F\n[ -> [+(45)\n] -> ]-(45)\n");
    DeriveResult r = derive(g, 2);
    ASSERT_TRUE(r.outcome.ok());
    EXPECT_EQ(toString(*r.string, g->alphabet), "11[1[0]0]1[0]0");
    EXPECT_EQ(toString(applyInterpretation(*g, *r.string, 1), g->alphabet),
              "FF[+(45)F[+(45)F]-(45)F]-(45)F[+(45)F]-(45)F");
}

}  // namespace
}  // namespace sprout::test
