// L-Py rules, rule applications per second of the same doubling model
//   A(x) --> A(x + 1) A(x * 0.5)          (every module matches; 2^n - 1 matches in n steps)
// run each way, measured in the same run:
//   - the native path: a produce-only rule compiled to Sprout's expressions (lpy/native.cpp),
//     its x * a + b arguments without them, steps of 8 k modules or more shared with a
//     second thread where the process may use two processors;
//   - the Python path: the same file with the native path off (one Python call per match);
//   - the same rule with a Python statement in its body (always the Python path);
//   - Sprout's own grammar (.lsys) with the same rule, for reference.
// Times the derivation alone (lpy::Model::deriveSeconds): Python's start, the preamble and
// the drawing of the result cost the same both ways and are left out.
// Prints matches per second for each and the ratio of the native path to the Python path
// (goal: 100x). The best of kRuns runs each: the native derivation takes about a millisecond,
// and a process's first ones pay for fresh memory (page faults) and the helper thread's start.
//
//   build/bench/lpy_bench [STEPS]      (default 18: 262,143 matches)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "lpy/host.hpp"

namespace {

using namespace sprout;

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

constexpr int kRuns = 10;

double lpyRun(const std::string& text, int steps, bool native, bool expectNative) {
    double best = 1e18;
    for (int run = 0; run < kRuns; ++run) {
        lpy::RunOptions o;
        o.steps = steps;
        o.native = native;
        lpy::Model m = lpy::runModel(text, o);
        const double s = m.deriveSeconds;  // the rules at work, not the start of Python or the drawing
        if (!m.ok()) {
            for (const auto& d : m.diagnostics) std::fprintf(stderr, "%s\n", formatDiagnostic(d, "bench.lpy").c_str());
            std::exit(1);
        }
        if (m.ranNative != expectNative) {
            std::fprintf(stderr, "the model %s the native path\n", m.ranNative ? "took" : "did not take");
            std::exit(1);
        }
        best = std::min(best, s);
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    if (!lpy::pythonAvailable()) {
        std::printf("built without Python: nothing to measure\n");
        return 0;
    }
    const int steps = argc > 1 ? std::clamp(std::atoi(argv[1]), 1, 24) : 18;
    const double matches = double((1ull << steps) - 1);
    const std::string produceOnly = "Axiom: A(1)\nderivation length: 1\nproduction:\nA(x) --> A(x + 1) A(x * 0.5)\nendlsystem\n";
    const std::string pythonBody =
        "Axiom: A(1)\nderivation length: 1\nproduction:\nA(x) :\n    y = x + 1\n    produce A(y) A(x * 0.5)\nendlsystem\n";
    const double nativePathS = lpyRun(produceOnly, steps, true, true);
    const double produceS = lpyRun(produceOnly, steps, false, false);
    const double bodyS = lpyRun(pythonBody, steps, true, false);

    auto g = parse("axiom: A(1)\nA(x) -> A(x + 1) A(x * 0.5)\n", parseOptionsFor(FileKind::Lsys, "")).grammar;
    if (!g) {
        std::fprintf(stderr, "the native grammar does not parse\n");
        return 1;
    }
    double nativeS = 1e18;
    for (int run = 0; run < kRuns; ++run) {
        Derivation d(g);
        const auto t0 = std::chrono::steady_clock::now();
        if (!d.deriveTo(steps).ok()) return 1;
        nativeS = std::min(nativeS, seconds(t0));
    }
    std::printf("lpy_bench: %d steps, %.0f rule applications each way (best of %d)\n", steps, matches, kRuns);
    std::printf("  L-Py produce-only rule, native path:            %8.3f s  %12.0f matches/s\n", nativePathS, matches / nativePathS);
    std::printf("  L-Py produce-only rule, Python path:            %8.3f s  %12.0f matches/s\n", produceS, matches / produceS);
    std::printf("  L-Py rule with a Python statement in its body:  %8.3f s  %12.0f matches/s\n", bodyS, matches / bodyS);
    std::printf("  Sprout's .lsys derivation of the same rule:     %8.3f s  %12.0f matches/s\n", nativeS, matches / nativeS);
    std::printf("  ratio native path / Python path: %.0fx (goal: 100x)\n", produceS / nativePathS);
    std::printf("  ratio native path / Python-body rule: %.0fx\n", bodyS / nativePathS);
    std::printf("  ratio .lsys / native path: %.1fx\n", nativePathS / nativeS);
    return 0;
}
