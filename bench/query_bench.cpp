// Query modules (cpfg ?P): one derivation step of a plant of about 100,000 modules whose
// every apex carries a ?P, which its production reads through a context. The step costs the
// rewriting plus one interpretation of the new string to answer the queries; the baseline,
// measured in the same run, is the same plant with a plain module Q(x,y,z) in place of ?P
// (same string, same rules, no interpretation). Bar: the step with queries < 50 ms.
//
//   build/bench/query_bench
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"

namespace {

using namespace sprout;

std::string plant(const std::string& query) {
    return "Lsystem: 1\nderivation length: 13\nangle factor: 12\nAxiom: F(1) " + query + "(0,0,0) B\n" +
           query + "(x,y,z) < B : y > -1000 --> [ +(30) /(90) F(0.8) " + query + "(0,0,0) B ] [ -(30) /(90) F(0.8) " + query +
           "(0,0,0) B ]\n"
           "F(l) --> F(l * 1.02)\nendlsystem\n";
}

// The best of five runs of step n alone (step n-1 made before the clock starts).
double stepMillis(const std::string& text, int n, std::uint64_t& modules, std::uint64_t& queries) {
    auto g = parse(text, parseOptionsFor(FileKind::Cpfg, "")).grammar;
    if (!g) {
        std::fprintf(stderr, "the benchmark grammar does not parse\n");
        std::exit(1);
    }
    double best = 1e18;
    for (int run = 0; run < 5; ++run) {
        Derivation d(g);
        d.deriveTo(n - 1);
        const auto t0 = std::chrono::steady_clock::now();
        d.deriveTo(n);
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        modules = d.step(n)->size();
        queries = 0;
        for (SymbolId s : d.step(n)->symbols) queries += g->alphabet[s].name == "?P";
    }
    return best;
}

}  // namespace

// The same plant asking the light environment: ?E(1) at every apex instead of ?P.
std::string lightPlant(bool environment) {
    const std::string q = environment ? "?E" : "Q";
    return std::string("Lsystem: 1\nderivation length: 13\nangle factor: 12\n") + (environment ? "environment: light 0.5\n" : "") +
           "Axiom: F(1) " + q + "(1) B\n" + q + "(l) < B : l > -1 --> [ +(30) /(90) F(0.8) ~l(0.3) " + q + "(1) B ] [ -(30) /(90) F(0.8) " +
           q + "(1) B ]\nF(l) --> F(l * 1.02)\nendlsystem\n";
}

int main() {
    const int n = 13;
    std::uint64_t modules = 0, queries = 0, baseModules = 0, none = 0;
    const double withQueries = stepMillis(plant("?P"), n, modules, queries);
    const double without = stepMillis(plant("Q"), n, baseModules, none);
    std::printf("query_bench: step %d, %s modules, %s ?P queries: %.1f ms with queries (bar 50 ms, %.2fx of the bar); "
                "%.1f ms with a plain module instead (%s modules): ratio %.2f\n",
                n, withThousands(modules).c_str(), withThousands(queries).c_str(), withQueries, withQueries / 50.0, without,
                withThousands(baseModules).c_str(), withQueries / without);
    std::uint64_t lightModules = 0, lightQueries = 0, plainModules = 0, ignored = 0;
    const double withLight = stepMillis(lightPlant(true), n, lightModules, ignored);
    {
        auto g = parse(lightPlant(true), parseOptionsFor(FileKind::Cpfg, "")).grammar;
        DeriveResult d = derive(g, n);
        for (SymbolId s : d.string->symbols) lightQueries += g->alphabet[s].name == "?E";
    }
    const double plain = stepMillis(lightPlant(false), n, plainModules, ignored);
    std::printf("query_bench: step %d, %s modules, %s ?E(light) queries against the light voxel grid: %.1f ms (bar 50 ms, "
                "%.2fx of the bar); %.1f ms without the environment: ratio %.2f\n",
                n, withThousands(lightModules).c_str(), withThousands(lightQueries).c_str(), withLight, withLight / 50.0, plain,
                withLight / plain);
    return withQueries < 50.0 && withLight < 50.0 ? 0 : 1;
}
