// L-Py rules, rule applications per second of the same doubling model
//   A(x) --> A(x + 1) A(x * 0.5)          (every module matches; 2^n - 1 matches in n steps)
// run each way, measured in the same run:
//   - the native path: a produce-only rule compiled to Sprout's expressions (lpy/engine/native_derive.cpp),
//     its x * a + b arguments without them, steps of 8 k modules or more shared with a
//     second thread where the process may use two processors;
//   - the Python path: the same file with the native path off (one Python call per match);
//   - the same rule with a Python statement in its body (always the Python path);
//   - Sprout's own grammar (.lsys) with the same rule, for reference;
//   - the produce-only model driven from a Python script, as L-Py's documentation teaches
//     (Lsystem.derive() of openalea.lpy, sprout.use_as_openalea()), against the command
//     line's path above (goal: no more than 10% slower). Timed around derive() in Python: the
//     call, the axiom, the derivation and the Lstring it gives; the string before is let go
//     first, as the command line's runs let theirs go (else each derive() pays for fresh
//     memory while the last string holds the buffers it would reuse).
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

#ifdef SPROUT_BENCH_LSYSTEM_API
#include <pybind11/embed.h>
#endif

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "lpy/lpy.hpp"

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

#ifdef SPROUT_BENCH_LSYSTEM_API
// The best of kRuns Lsystem.derive() calls of `code` in the embedded interpreter (started by
// runModel before), in seconds.
double lsystemApiRun(const std::string& code, int steps) {
    namespace py = pybind11;
    py::gil_scoped_acquire gil;
    py::dict ns;
    ns["CODE"] = code;
    ns["STEPS"] = steps;
    ns["RUNS"] = kRuns;
    py::exec(R"(
import time
from openalea.lpy import Lsystem
lsys = Lsystem()
lsys.set(CODE)
lsys.derivationLength = STEPS
best = 1e18
for run in range(RUNS):
    s = None  # the last string let go first, as each run of the command line's does
    t0 = time.perf_counter()
    s = lsys.derive()
    best = min(best, time.perf_counter() - t0)
    assert len(s) == 2 ** STEPS
)",
             ns);
    return ns["best"].cast<double>();
}
#endif

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
#ifdef SPROUT_BENCH_LSYSTEM_API
    // The command line's way and the script's, alternated, each the best of its runs, at 21
    // steps or more (2 M matches: at 18 a derivation takes under a millisecond, and the
    // machine's noise is as big as what is compared).
    const int apiSteps = std::max(steps, 21);
    const double apiMatches = double((1ull << apiSteps) - 1);
    double cliS = 1e18, apiS = 1e18;
    for (int round = 0; round < 3; ++round) {
        cliS = std::min(cliS, lpyRun(produceOnly, apiSteps, true, true));
        apiS = std::min(apiS, lsystemApiRun(produceOnly, apiSteps));
    }
    std::printf("  at %d steps, sprout render's derivation:            %8.4f s  %12.0f matches/s\n", apiSteps, cliS, apiMatches / cliS);
    std::printf("  at %d steps, Lsystem.derive() from Python:          %8.4f s  %12.0f matches/s\n", apiSteps, apiS, apiMatches / apiS);
    std::printf("  ratio Lsystem.derive() / sprout render's derivation: %.2f (goal: 1.10 or less)\n", apiS / cliS);
#endif
    return 0;
}
