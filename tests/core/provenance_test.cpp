// Which rule made this branch: module -> step -> rule -> ancestors, against lineages derived
// by hand for small grammars of each kind (core/derive/provenance.hpp).
#include <gtest/gtest.h>

#include "core/language/file_kind.hpp"
#include "core/language/import/import.hpp"
#include "core/turtle/pick.hpp"
#include "core/derive/provenance.hpp"
#include "core/derive/step_rewriter.hpp"
#include "core/turtle/turtle.hpp"
#include "tests/core/test_util.hpp"

namespace sprout {
namespace {

struct Traced {
    std::shared_ptr<const Grammar> grammar;
    std::unique_ptr<Derivation> derivation;
    std::string lineageOf(int step, std::uint32_t index) {
        return describeLineage(*grammar, lineage(*derivation, step, index));
    }
    std::string at(int step) { return toString(*derivation->step(step), grammar->alphabet); }
};

Traced trace(const std::string& text, int n, FileKind kind = FileKind::Lsys) {
    Traced t;
    ParseResult r = parse(text, parseOptionsFor(kind, ""));
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) ADD_FAILURE() << formatDiagnostic(d, "<test>");
    t.grammar = r.grammar;
    DeriveOptions o;
    o.trackOrigins = true;
    t.derivation = std::make_unique<Derivation>(t.grammar, o);
    EXPECT_TRUE(t.derivation->deriveTo(n).ok());
    return t;
}

// Lindenmayer's algae (A -> AB, B -> A), by hand:
//   0: A   1: A B   2: A B A   3: A B A A B
// Step 3's fourth module (an A) was made at step 3 by A -> AB (line 2) from step 2's third A,
// which B -> A (line 3) made at step 2 from step 1's B, which A -> AB made from the axiom.
TEST(Provenance, AlgaeLineageByHand) {
    Traced t = trace("axiom: A\nA -> AB\nB -> A\n", 3);
    ASSERT_EQ(t.at(3), "ABAAB");
    EXPECT_EQ(t.lineageOf(3, 3), "A at step 3 by line 2 <- A at step 2 by line 3 <- B at step 1 by line 2 <- A (axiom)");
    EXPECT_EQ(t.lineageOf(0, 0), "A (axiom)");
    auto links = lineage(*t.derivation, 3, 4);  // the last B: A -> AB at step 3, from step 2's last A
    ASSERT_EQ(links.size(), 4u);
    EXPECT_EQ(links[0].step, 3);
    EXPECT_EQ(links[0].ruleLine, 2);
    EXPECT_EQ(links[1].index, 2u);
    EXPECT_TRUE(lineage(*t.derivation, 3, 5).empty());  // past the end
    EXPECT_EQ(madeBy(DerivationRecord::of(*t.derivation), 3), (std::vector<std::int32_t>{0, 0, 1, 0, 0}));
}

// Context-sensitive: only the A right of B becomes B; the others are copied, so their lineage
// goes straight to the axiom, and the copy of a module keeps the step that made it.
TEST(Provenance, ContextSensitiveAndCopiedModules) {
    Traced t = trace("axiom: B A A A\nB < A -> B\nB -> A\n", 2);
    ASSERT_EQ(t.at(1), "ABAA");
    ASSERT_EQ(t.at(2), "AABA");
    EXPECT_EQ(t.lineageOf(1, 1), "B at step 1 by line 2 <- A (axiom)");
    EXPECT_EQ(t.lineageOf(1, 3), "A (axiom)");               // copied at step 1
    EXPECT_EQ(t.lineageOf(2, 3), "A (axiom)");               // copied twice
    EXPECT_EQ(t.lineageOf(2, 2), "B at step 2 by line 2 <- A (axiom)");
    EXPECT_EQ(t.lineageOf(2, 1), "A at step 2 by line 3 <- B at step 1 by line 2 <- A (axiom)");
    // Everything each rule made, in one pass: B -> A is rule 1, B < A -> B rule 0, -1 the axiom's.
    EXPECT_EQ(madeBy(DerivationRecord::of(*t.derivation), 2), (std::vector<std::int32_t>{1, 1, 0, -1}));
}

// Parametric with conditions: the rule that applied is the one whose condition held.
TEST(Provenance, ParametricConditionsPickTheLine) {
    Traced t = trace("axiom: A(0)\nA(x) : x < 2 -> A(x+1) [ B(x) ]\nA(x) : x >= 2 -> C(x)\nB(x) -> B(x) F\n", 3);
    ASSERT_EQ(t.at(3), "C(2)[B(1)F][B(0)FF]");
    EXPECT_EQ(t.lineageOf(3, 0), "C at step 3 by line 3 <- A at step 2 by line 2 <- A at step 1 by line 2 <- A (axiom)");
    // B(0)'s F's: B -> B F rewrites B(0) each step, so the F right after it (index 7) is new at
    // step 3, made from the B(0) that step 2 made; the next F (index 8) is step 2's, copied.
    EXPECT_EQ(t.lineageOf(3, 7), "F at step 3 by line 4 <- B at step 2 by line 4 <- B at step 1 by line 2 <- A (axiom)");
    EXPECT_EQ(t.lineageOf(3, 8), "F at step 2 by line 4 <- B at step 1 by line 2 <- A (axiom)");
}

// Stochastic: the lineage names whichever of the two rules the seed chose.
TEST(Provenance, StochasticNamesTheChosenRule) {
    for (std::uint64_t seed : {1, 2, 3, 4, 5, 6}) {
        ParseResult r = parse("axiom: A\nA -> AB : 0.5\nA -> BA : 0.5\n");
        DeriveOptions o;
        o.trackOrigins = true;
        o.seed = seed;
        Derivation d(r.grammar, o);
        ASSERT_TRUE(d.deriveTo(1).ok());
        const std::string s = toString(*d.step(1), r.grammar->alphabet);
        const int line = s == "AB" ? 2 : 3;
        EXPECT_EQ(lineage(d, 1, 0)[0].ruleLine, line) << s;
        EXPECT_EQ(lineage(d, 1, 1)[0].ruleLine, line) << s;
    }
}

// cpfg: a decomposition rule is what made the modules it writes, and they come from the
// module of the step before; a cut in the next step leaves indices that still lead home.
TEST(Provenance, DecompositionAndCutInTheNextStep) {
    Traced t = trace("Lsystem: 1\nderivation length: 2\nAxiom: A\nA --> I A\ndecomposition\nI --> F X\nendlsystem\n", 2,
                     FileKind::Cpfg);
    ASSERT_EQ(t.at(2), "FXFXA");
    EXPECT_EQ(t.lineageOf(2, 3), "X at step 2 by line 6 <- A at step 1 by line 4 <- A (axiom)");
    EXPECT_EQ(t.lineageOf(2, 0), "F at step 1 by line 6 <- A (axiom)");
    Traced cut = trace("Lsystem: 1\nderivation length: 2\nAxiom: A [ % B ] C\nA --> A A\nC --> D\nendlsystem\n", 2,
                       FileKind::Cpfg);
    ASSERT_EQ(cut.at(2), "AAAA[]D");
    EXPECT_EQ(cut.lineageOf(2, 6), "D at step 1 by line 5 <- C (axiom)");
    EXPECT_EQ(cut.lineageOf(2, 3), "A at step 2 by line 4 <- A at step 1 by line 4 <- A (axiom)");
}

// A click on a stem: the ray finds the segment, the turtle says which module drew it, and
// the lineage says which rule made it. Step 2 of A -> F [ + A ] F is F [ + F [ + A ] F ] F:
// the trunk's second F (module 10) came from step 1's last F.
TEST(Provenance, PickedSegmentLeadsToItsRule) {
    Traced t = trace("n: 2\nangle: 90\naxiom: A\nA -> F [ + A ] F\n", 2);
    ASSERT_EQ(t.at(2), "F[+F[+A]F]F");
    Geometry g;
    std::vector<std::uint32_t> segmentModules, surfaceModules;
    TurtleOptions o{2, 1, nullptr};
    o.segmentModules = &segmentModules;
    o.surfaceModules = &surfaceModules;
    interpret(*t.derivation->step(2), *t.grammar, o, g);
    ASSERT_EQ(g.cylinders.size(), 4u);
    ASSERT_EQ(segmentModules, (std::vector<std::uint32_t>{0, 3, 8, 10}));
    // Looking along -Z at the trunk's upper half, and at its lower half.
    auto upper = pick(g, {0, 1.5f, 10}, {0, 0, -1});
    ASSERT_TRUE(upper);
    EXPECT_EQ(upper->kind, PickHit::Kind::Segment);
    EXPECT_EQ(segmentModules[upper->index], 10u);
    EXPECT_NEAR(upper->distance, 10, 0.01);
    EXPECT_EQ(t.lineageOf(2, segmentModules[upper->index]), "F at step 1 by line 4 <- A (axiom)");
    auto lower = pick(g, {0, 0.5f, 10}, {0, 0, -1});
    ASSERT_TRUE(lower);
    EXPECT_EQ(segmentModules[lower->index], 0u);
    // Beside everything: nothing.
    EXPECT_FALSE(pick(g, {5, 5, 10}, {0, 0, -1}));
    // The branch's inner F, drawn to the side: made at step 2 from step 1's A.
    const CylinderInstance& inner = g.cylinders[2];
    const glm::vec3 mid = (inner.start + inner.end) * 0.5f;
    auto side = pick(g, mid + glm::vec3(0, 0, 10), {0, 0, -1});
    ASSERT_TRUE(side);
    EXPECT_EQ(t.lineageOf(2, segmentModules[side->index]), "F at step 2 by line 4 <- A at step 1 by line 4 <- A (axiom)");
}

// Which context matched: ABOP's bracketed context skips side branches; for B < A > C in
// B [ X ] A [ Y ] C the left context is the B before the branch and the right the C after.
TEST(Provenance, ContextThatMatched) {
    auto g = test::grammarOf("axiom: B [ X ] A [ Y ] C\nB < A > C -> D\n");
    ASSERT_TRUE(g);
    StepRewriter rewriter(*g, g->rules);
    std::vector<std::size_t> left, right;
    ASSERT_TRUE(rewriter.contextOf(g->axiom, 4, g->rules.productions[0], left, right));
    EXPECT_EQ(left, (std::vector<std::size_t>{0}));
    EXPECT_EQ(right, (std::vector<std::size_t>{8}));
    EXPECT_FALSE(rewriter.contextOf(g->axiom, 2, g->rules.productions[0], left, right));  // X is no A's place
    EXPECT_EQ(test::expand("axiom: B [ X ] A [ Y ] C\nB < A > C -> D\n", 1), "B[X]D[Y]C");
}

// An imported grammar (Fractint) is picked in the .lsys text it becomes: the rule line the
// lineage names is the translated rule the editor shows.
TEST(Provenance, ImportedGrammarNamesItsTranslatedRule) {
    ImportResult imported = importFractint("Koch {\n  Angle 6\n  Axiom F\n  F=F+F--F+F\n}\n", "Koch");
    ASSERT_TRUE(imported.ok());
    Traced t = trace(imported.text, 2);
    const auto links = lineage(*t.derivation, 2, 6);  // a module of step 2
    ASSERT_EQ(links.size(), 3u);
    EXPECT_EQ(links[0].step, 2);
    EXPECT_EQ(links[2].ruleLine, 0);  // the axiom
    // That line of the translated text is the rule F -> F+F--F+F.
    std::string line;
    size_t pos = 0;
    for (int l = 1; l < links[0].ruleLine; ++l) pos = imported.text.find('\n', pos) + 1;
    line = imported.text.substr(pos, imported.text.find('\n', pos) - pos);
    EXPECT_NE(line.find("F -> F+F--F+F"), std::string::npos) << imported.text;
}

}  // namespace
}  // namespace sprout
