// The size cap, cancellation and progress of the derivation engine.
#include <gtest/gtest.h>

#include <thread>

#include "core/language/file_kind.hpp"
#include "test_util.hpp"

namespace sprout::test {
namespace {

TEST(Limits, ExplosiveD0LIsRefusedBeforeAllocating) {
    auto g = grammarOf("axiom: F\nF -> FFFFFFFFFF\n");
    DeriveOptions opts;
    opts.limits.maxModules = 1'000'000;
    Derivation d(g, opts);
    DeriveOutcome o = d.deriveTo(40);
    EXPECT_EQ(o.status, DeriveStatus::TooBig);
    EXPECT_EQ(o.step, 7);  // the first step over the cap: 10^7 modules
    EXPECT_EQ(o.predictedModules, 10'000'000u);
    EXPECT_EQ(o.message,
              "step 7 would produce 10,000,000 modules (19.1 MB), over the limit of 1,000,000 modules; "
              "lower n (to 6 at most) or raise the limit (--max-modules)");
    EXPECT_TRUE(d.deriveTo(6).ok());  // below the cap still works
}

TEST(Limits, DefaultCapRefusesAHugeDerivationInstantly) {
    // 2^10000 modules would exhaust any machine; the prediction saturates and refuses.
    auto g = grammarOf("axiom: F\nF -> FF\n");
    DeriveResult r = derive(g, 10000);
    EXPECT_EQ(r.outcome.status, DeriveStatus::TooBig);
    EXPECT_EQ(r.outcome.step, 29);  // 2^29 = 536,870,912 > 500 M
}

TEST(Limits, GeneralPathPredictsAnUpperBound) {
    auto g = grammarOf("seed: 1\naxiom: F\nF -> FFFF : 0.5\nF -> F : 0.5\n");
    DeriveOptions opts;
    opts.limits.maxModules = 5000;
    DeriveResult r = derive(g, 30, opts);
    EXPECT_EQ(r.outcome.status, DeriveStatus::TooBig);
    EXPECT_NE(r.outcome.message.find("up to"), std::string::npos);
    EXPECT_LE(r.outcome.predictedModules, 4 * 5000u);
}

TEST(Limits, ParametersCountTowardsMemory) {
    auto g = grammarOf("axiom: A(1)\nA(x) -> A(x)A(x)\n");
    DeriveOptions opts;
    opts.limits.maxBytes = 1 << 20;  // 1 MB: ~100 k modules of 10 bytes
    Derivation d(g, opts);
    DeriveOutcome o = d.deriveTo(20);
    EXPECT_EQ(o.status, DeriveStatus::TooBig);
    // Step 16: 65,536 modules of 10 bytes (640 KB) on top of the 15 steps before (640 KB).
    EXPECT_EQ(o.step, 16);
    EXPECT_EQ(o.message, "step 16 would need 0.6 MB for 65,536 modules on top of 0.6 MB already kept, over the memory "
                         "budget of 1.0 MB; lower n (to 15 at most) or raise the budget (--max-memory)");
    EXPECT_EQ(d.stepsDerived(), 0);  // refused before the first step: nothing was derived
    EXPECT_TRUE(d.deriveTo(15).ok());  // the step before still fits
}

// Issue 39: growth that every rule makes for certain is refused before the first step, at the
// step that crosses the limit, and growth that may stop is not refused for what it might do.
TEST(Limits, CertainParametricGrowthIsRefusedBeforeTheFirstStep) {
    auto g = grammarOf("n: 60\naxiom: A(1)\nA(x) -> A(x+1)A(x*2)A(x)\n");
    Derivation d(g);
    DeriveOutcome o = d.deriveTo(60);
    EXPECT_EQ(o.status, DeriveStatus::TooBig);
    EXPECT_EQ(o.step, 19);  // 3^19 = 1,162,261,467 modules: over the 500 M limit
    EXPECT_EQ(o.predictedModules, 1'162'261'467u);
    EXPECT_EQ(d.stepsDerived(), 0);
    EXPECT_NE(o.message.find("lower n (to 18 at most)"), std::string::npos) << o.message;
    // A symbol whose rule has a condition may stay as it is: no refusal for growth that stops.
    auto stops = grammarOf("axiom: A(1)\nA(x) : x < 6 -> A(x+1)A(x+1)A(x+1)\n");
    DeriveOptions small;
    small.limits.maxModules = 1000;
    EXPECT_TRUE(derive(stops, 60, small).outcome.ok());  // 3^5 = 243 modules, then no more growth
    // A conditional rule before one that always applies: A at least doubles each step. The
    // bound crosses 100 at step 7 (128), said as a bound; the string itself grows faster.
    auto mixed = grammarOf("axiom: A(1)\nA(x) : x > 3 -> A(x)A(x)A(x)\nA(x) -> A(x+1)A(x+1)\n");
    DeriveOptions tiny;
    tiny.limits.maxModules = 100;
    Derivation dm(mixed, tiny);
    DeriveOutcome m = dm.deriveTo(30);
    EXPECT_EQ(m.status, DeriveStatus::TooBig);
    EXPECT_EQ(m.step, 7);
    EXPECT_EQ(m.message, "step 7 would produce at least 128 modules (0.0 MB), over the limit of 100 modules; lower n below 7 "
                         "or raise the limit (--max-modules)");
    EXPECT_EQ(dm.stepsDerived(), 0);
    // Asked for fewer steps than the bound refuses, the derivation runs and refuses where the
    // string itself crosses: step 6 (8 x 27 = 216 modules, at most).
    DeriveOutcome six = Derivation(mixed, tiny).deriveTo(6);
    EXPECT_EQ(six.status, DeriveStatus::TooBig);
    EXPECT_EQ(six.step, 6);
}

// A decomposition whose rules always apply is followed on the counts of its symbols: one that
// doubles each pass is refused before its first pass, at the pass over the limit.
TEST(Limits, ExplodingDecompositionIsRefusedBeforeItsPasses) {
    ParseResult r = parse("derivation length: 30\nAxiom: A\nA --> AB\ndecomposition:\nmaximum depth: 40\nB --> BB\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    DeriveOptions opts;
    opts.limits.maxModules = 1000;
    Derivation d(r.grammar, opts);
    DeriveOutcome o = d.deriveTo(30);
    EXPECT_EQ(o.status, DeriveStatus::TooBig);
    EXPECT_EQ(o.step, 1);
    // Step 1 is A B, then B doubles each pass: 1 + 2^10 = 1025 modules at pass 10.
    EXPECT_EQ(o.message.rfind("step 1, decomposition pass 10, would produce 1,025 modules", 0), 0u) << o.message;
    EXPECT_EQ(d.stepsDerived(), 0);
    // A decomposition that ends (B --> C, C has none) is not refused.
    ParseResult ends = parse("derivation length: 3\nAxiom: A\nA --> AB\ndecomposition:\nB --> CC\n", parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(ends.ok());
    EXPECT_TRUE(derive(ends.grammar, 3, opts).outcome.ok());
}

TEST(Limits, CancellationStopsAStep) {
    auto g = grammarOf("axiom: A(1)\nA(x) -> F(x)[+A(x*0.7)][-A(x*0.7)]\n");
    std::atomic<bool> cancel{true};
    DeriveOptions opts;
    opts.cancel = &cancel;
    Derivation d(g, opts);
    DeriveOutcome o = d.deriveTo(22);
    EXPECT_EQ(o.status, DeriveStatus::Cancelled);
    EXPECT_LT(d.stepsDerived(), 22);
}

TEST(Limits, CancellationFromAnotherThread) {
    auto g = grammarOf("axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\nQ < Z -> Z\n");  // general path
    std::atomic<bool> cancel{false};
    std::atomic<int> calls{0};
    DeriveOptions opts;
    opts.cancel = &cancel;
    opts.progress = [&](int, int, double) {
        if (++calls == 3) cancel = true;
    };
    Derivation d(g, opts);
    DeriveOutcome o = d.deriveTo(12);  // about 50 M modules: (14 would be refused at once, over the limit)
    EXPECT_EQ(o.status, DeriveStatus::Cancelled);
    EXPECT_GE(calls.load(), 3);
}

TEST(Limits, ProgressReportsEveryStep) {
    auto g = grammarOf("axiom: A(1)\nA(x) -> A(x)B\n");
    std::vector<int> steps;
    DeriveOptions opts;
    opts.progress = [&](int step, int total, double fraction) {
        EXPECT_EQ(total, 5);
        if (fraction == 1.0) steps.push_back(step);
    };
    ASSERT_TRUE(derive(g, 5, opts).outcome.ok());
    EXPECT_EQ(steps, (std::vector<int>{1, 2, 3, 4, 5}));
}

TEST(Limits, NonParametricStringsUseTwoBytesPerModule) {
    auto g = grammarOf("axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n");
    DeriveResult r = derive(g, 8);
    ASSERT_TRUE(r.outcome.ok());
    EXPECT_EQ(r.string->bytes(), r.string->size() * 2);
    EXPECT_LE(r.string->symbols.capacity(), r.string->size() + 16);
}

TEST(Limits, ParametricStringsUseEightBytesPerParameter) {
    auto g = grammarOf("axiom: A(1)\nA(x) -> F(x)[+A(x*0.7)][-A(x*0.7)]\n");
    DeriveResult r = derive(g, 12);
    ASSERT_TRUE(r.outcome.ok());
    EXPECT_EQ(r.string->bytes(), r.string->size() * 2 + r.string->params.size() * 8);
}

}  // namespace
}  // namespace sprout::test

namespace sprout::test {
namespace {

TEST(PodBuffer, GrowingPastTheHugePageThresholdKeepsTheContents) {
    PodBuffer<std::uint32_t> b;
    for (std::uint32_t i = 0; i < 5'000'000; ++i) b.push_back(i);  // 20 MB: crosses 8 MB mid-way
    ASSERT_EQ(b.size(), 5'000'000u);
    for (std::uint32_t i = 0; i < 5'000'000; i += 99991) EXPECT_EQ(b[i], i);
    EXPECT_EQ(b.back(), 4'999'999u);
    PodBuffer<std::uint32_t> copy(b);
    EXPECT_TRUE(copy == b);
    copy.resizeUninitialized(10);
    copy.shrinkToFit();
    EXPECT_EQ(copy.size(), 10u);
    EXPECT_EQ(copy[9], 9u);
    copy.push_back(7);
    EXPECT_EQ(copy.back(), 7u);
}

// A big buffer given back keeps its mapping for the next one (its pages already in: the kernel
// does not clear them again), and a buffer in it grows and shrinks like any other.
TEST(PodBuffer, ABigBufferGivenBackIsTakenAgain) {
    const std::uint32_t* first = nullptr;
    {
        PodBuffer<std::uint32_t> b;
        b.resizeUninitialized(3'000'000);  // 12 MB: mapped
        first = b.data();
    }
    PodBuffer<std::uint32_t> again;
    again.resizeUninitialized(2'900'000);
    EXPECT_EQ(again.data(), first) << "the mapping given back";
    for (std::uint32_t i = 0; i < again.size(); ++i) again[i] = i;
    again.resizeUninitialized(9'000'000);  // 36 MB: grown past what it was
    for (std::uint32_t i = 0; i < 2'900'000; i += 9973) EXPECT_EQ(again[i], i);
    again.resizeUninitialized(100);
    again.shrinkToFit();
    EXPECT_EQ(again[99], 99u);
    again.clear();
    again.resizeUninitialized(2'000'000);  // nothing kept: taken afresh (or given back and taken)
    again[1'999'999] = 5;
    EXPECT_EQ(again[1'999'999], 5u);
}

}  // namespace
}  // namespace sprout::test
