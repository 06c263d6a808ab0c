// Stochastic L-systems: reproducible for a seed, different across seeds, frequencies right.
#include <gtest/gtest.h>

#include <map>

#include "core/language/file_kind.hpp"
#include "test_util.hpp"

namespace sprout::test {
namespace {

const char* kWeed =
    "seed: 7\naxiom: F\n"
    "F -> F[+F]F[-F]F : 0.33\n"
    "F -> F[+F]F : 0.33\n"
    "F -> F[-F]F : 0.34\n";

TEST(Stochastic, SameSeedSameString) {
    EXPECT_EQ(expand(kWeed, 5), expand(kWeed, 5));
    EXPECT_EQ(expand(kWeed, 5, 123), expand(kWeed, 5, 123));
}

TEST(Stochastic, DifferentSeedsGiveDifferentSpecimens) {
    std::set<std::string> specimens;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) specimens.insert(expand(kWeed, 4, seed));
    EXPECT_EQ(specimens.size(), 10u);
}

TEST(Stochastic, StepsAreAPrefixOfTheSameGrowth) {
    // Stepping keeps the seed: step 3 derived alone equals step 3 on the way to step 5.
    auto g = grammarOf(kWeed);
    Derivation d(g);
    ASSERT_TRUE(d.deriveTo(5).ok());
    EXPECT_EQ(toString(*d.step(3), g->alphabet), expand(kWeed, 3));
}

TEST(Stochastic, ReproducibleAcrossMachines) {
    // Pinned output: Sprout's own PRNG makes this the same with every compiler and library.
    EXPECT_EQ(expand(kWeed, 2, 1), expand(kWeed, 2, 1));
    EXPECT_EQ(expand("seed: 3\naxiom: AAAAAAAAAAAAAAAA\nA -> B : 0.5\nA -> C : 0.5\n", 1),
              expand("seed: 3\naxiom: AAAAAAAAAAAAAAAA\nA -> B : 0.5\nA -> C : 0.5\n", 1));
    EXPECT_EQ(expand("seed: 3\naxiom: AAAAAAAAAAAAAAAA\nA -> B : 0.5\nA -> C : 0.5\n", 1),
              "BCCCBBBBBCBBBBBB");
}

TEST(Stochastic, FrequenciesFollowTheProbabilities) {
    std::string axiom(20000, 'A');
    std::string g = "axiom: " + axiom + "\nA -> B : 0.2\nA -> C : 0.5\nA -> D : 0.3\n";
    std::string s = expand(g, 1);
    std::map<char, int> count;
    for (char c : s) ++count[c];
    EXPECT_NEAR(count['B'] / 20000.0, 0.2, 0.015);
    EXPECT_NEAR(count['C'] / 20000.0, 0.5, 0.015);
    EXPECT_NEAR(count['D'] / 20000.0, 0.3, 0.015);
}

TEST(Stochastic, ProbabilitiesBelowOneLeaveTheModuleUnchangedTheRestOfTheTime) {
    std::string g = "axiom: " + std::string(20000, 'A') + "\nA -> B : 0.25\n";
    std::string s = expand(g, 1);
    EXPECT_NEAR(std::count(s.begin(), s.end(), 'B') / 20000.0, 0.25, 0.015);
    EXPECT_EQ(std::count(s.begin(), s.end(), 'A') + std::count(s.begin(), s.end(), 'B'), 20000);
}

TEST(Stochastic, RandInSuccessorsIsSeeded) {
    const std::string g = "seed: 5\naxiom: A\nA -> F(rand(1, 2))A\n";
    EXPECT_EQ(expand(g, 3), expand(g, 3));
    EXPECT_NE(expand(g, 3), expand(g, 3, 6));
}

TEST(Stochastic, WarnsWhenProbabilitiesDoNotAddUpToOne) {
    auto diags = diagnosticsOf("axiom: F\nF -> FF : 0.5\nF -> F : 0.7\n");
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0], "2:1: warning: the probabilities of the rules for 'F' add up to 1.2, not 1: "
                        "they are used as weights");
}

}  // namespace
}  // namespace sprout::test

// cpfg's generator is drand48's: the values glibc gives for the same states (checked with a C
// program calling drand48, erand48 and seed48), so cpfg's stochastic objects derive its strings.
TEST(Stochastic, CpfgRandomNumbersAreDrand48s) {
    using sprout::Rng;
    Rng unseeded = Rng::cpfg(0);  // cpfg -g: drand48 never seeded
    EXPECT_DOUBLE_EQ(unseeded.uniform(), 3.907985046680551e-14);
    EXPECT_DOUBLE_EQ(unseeded.exprUniform(), 0.17082803610628972);  // erand48 of {0x330E, 0, 0}
    Rng seeded = Rng::cpfg(2454);  // seed48({2454, 0, 155})
    EXPECT_DOUBLE_EQ(seeded.uniform(), 0.73544233498333611);
    // srand(a) starts the expressions' stream at {0x330E, a, a >> 16}, and nrand's first
    // value after it is drawn (before any srand, cpfg's first nran is the mean).
    Rng fresh = Rng::cpfg(0);
    EXPECT_EQ(fresh.exprNormal(5, 2), 5.0);
    fresh.exprSeed(0);
    Rng again = Rng::cpfg(0);
    EXPECT_DOUBLE_EQ(again.exprUniform(), fresh.exprUniform());
}

// A cpfg L-system derives cpfg's string whether the caller passes no seed or the grammar's own
// (the viewer always passes one); another seed gives another plant.
TEST(Stochastic, CpfgSeedOfItsOwnGivesCpfgsString) {
    using namespace sprout;
    ParseResult r = parse("Lsystem: 1\nseed: 5\nderivation length: 4\nAxiom: F\nF --> F[+F]F : 1\nF --> F[-F]F : 1\n"
                          "F --> FF : 1\nendlsystem\n", parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    auto stringWith = [&](std::optional<std::uint64_t> seed) {
        DeriveOptions o;
        o.seed = seed;
        return toString(*derive(r.grammar, 4, o).string, r.grammar->alphabet);
    };
    EXPECT_EQ(stringWith(std::nullopt), stringWith(5));
    EXPECT_NE(stringWith(std::nullopt), stringWith(99));
}
