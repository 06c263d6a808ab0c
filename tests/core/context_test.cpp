// Context-sensitive rewriting with ABOP / cpfg bracket semantics (ABOP section 1.8).
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace sprout::test {
namespace {

const char* kSignal = "axiom: S\nS -> FAT\nA > T -> [+FBF]\nA > F -> F\nB -> [-FAF]\nT -> F\n";

TEST(Context, LectureSlidesSignalSystem) {
    EXPECT_EQ(expand(kSignal, 0), "S");
    EXPECT_EQ(expand(kSignal, 1), "FAT");
    EXPECT_EQ(expand(kSignal, 2), "F[+FBF]F");
    EXPECT_EQ(expand(kSignal, 3), "F[+F[-FAF]F]F");
    EXPECT_EQ(expand(kSignal, 4), "F[+F[-FFF]F]F");  // A > F -> F
}

TEST(Context, SignalPropagatesAlongAFilament) {
    // ABOP fig. 1.30-style acropetal signal: b moves one cell per step.
    const std::string g = "axiom: baaaaaaaa\nb < a -> b\nb -> a\n";
    EXPECT_EQ(expand(g, 1), "abaaaaaaa");
    EXPECT_EQ(expand(g, 3), "aaabaaaaa");
    EXPECT_EQ(expand(g, 8), "aaaaaaaab");
}

TEST(Context, LeftContextSkipsCompletedBranchesAndLeavesTheCurrentOne) {
    // ABOP p. 32: in ABC[DE][SG[HI[JK]L]MNO], the left context of S ... is BC and the
    // right context of S is G[H]M.
    const std::string base = "axiom: ABC[DE][SG[HI[JK]L]MNO]\n";
    EXPECT_EQ(expand(base + "B C < S -> X\n", 1), "ABC[DE][XG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(base + "E < S -> X\n", 1), "ABC[DE][SG[HI[JK]L]MNO]");  // [DE] is complete
    EXPECT_EQ(expand(base + "S > G [ H ] M -> X\n", 1), "ABC[DE][XG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(base + "S > G M -> X\n", 1), "ABC[DE][XG[HI[JK]L]MNO]");  // side branch skipped
    EXPECT_EQ(expand(base + "S > G H -> X\n", 1), "ABC[DE][SG[HI[JK]L]MNO]");
    // Right context stops at the ']' closing the current branch.
    EXPECT_EQ(expand(base + "E > S -> X\n", 1), "ABC[DE][SG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(base + "O > * -> X\n", 1), "ABC[DE][SG[HI[JK]L]MNX]");
    // From inside a branch, the left context continues in the parent.
    EXPECT_EQ(expand(base + "C < D -> X\n", 1), "ABC[XE][SG[HI[JK]L]MNO]");
    EXPECT_EQ(expand(base + "G < H -> X\n", 1), "ABC[DE][SG[XI[JK]L]MNO]");
    EXPECT_EQ(expand(base + "I < J -> X\n", 1), "ABC[DE][SG[HI[XK]L]MNO]");
    EXPECT_EQ(expand(base + "G < M -> X\n", 1), "ABC[DE][SG[HI[JK]L]XNO]");
}

TEST(Context, IgnoredSymbolsAreSkipped) {
    const std::string rules = "axiom: F+A-F[-B]F\nF < A > F -> X\nA < F > * -> Y\n";
    EXPECT_EQ(expand(rules, 1), "F+A-F[-B]F");
    EXPECT_EQ(expand("ignore: + -\n" + rules, 1), "F+X-Y[-B]F");
    EXPECT_EQ(expand("#ignore +-\n" + rules, 1), "F+X-Y[-B]F");
}

TEST(Context, WildcardContextMeansAny) {
    // ABOP's `* < + > * -> -`: swap every turn regardless of neighbours.
    EXPECT_EQ(expand("axiom: F+F-F\n* < + > * -> -\n- -> +\n", 1), "F-F+F");
}

TEST(Context, MultiSymbolContexts) {
    const std::string g = "axiom: ABCDE\nA B < C > D E -> X\nB < C > E -> Y\n";
    EXPECT_EQ(expand(g, 1), "ABXDE");
    EXPECT_EQ(expand("axiom: ABCDF\nA B < C > D E -> X\nB < C > D -> Y\n", 1), "ABYDF");
}

TEST(Context, FirstApplicableRuleInFileOrderWins) {
    EXPECT_EQ(expand("axiom: ABC\nA < B -> X\nB > C -> Y\n", 1), "AXC");
    EXPECT_EQ(expand("axiom: ABC\nB > C -> Y\nA < B -> X\n", 1), "AYC");
    EXPECT_EQ(expand("axiom: ABC\nB > D -> Y\nB -> Z\n", 1), "AZC");
}

TEST(Context, ContextsSeeTheOldStringNotTheNewOne) {
    // Rewriting is parallel: every module's context is read from the previous step.
    EXPECT_EQ(expand("axiom: AAAA\nA < A -> B\n", 1), "ABBB");
}

TEST(Context, ParametricContextsBindParameters) {
    const std::string g =
        "axiom: A(1)B(2)C(3)\n"
        "A(x) < B(y) > C(z) : x + z > y -> B(x + y + z)\n";
    EXPECT_EQ(expand(g, 1), "A(1)B(6)C(3)");
    EXPECT_EQ(expand("axiom: A(5)B(20)C(3)\nA(x) < B(y) > C(z) : x + z > y -> B(0)\n", 1), "A(5)B(20)C(3)");
}

TEST(Context, ContextWithoutParenthesesMatchesAnyParameters) {
    EXPECT_EQ(expand("axiom: A(1)B\nA < B -> C\n", 1), "A(1)C");
    EXPECT_EQ(expand("axiom: A(1)B\nA() < B -> C\n", 1), "A(1)B");  // A() means exactly no parameters
}

}  // namespace
}  // namespace sprout::test
