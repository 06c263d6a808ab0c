// Derivation throughput, each figure a ratio to a baseline measured in the same run
// (absolute times on shared machines move by 20%).
//
//   build/bench/derive_bench
//
// D0L: fractal plant n=10 (6.46 M modules) and Koch n=9 against memcpy of the same bytes and
// against a straightforward std::string expander. Parametric: A(x) -> F(x)[+A(x*0.7)][-A(x*0.7)]
// n=22 (33.5 M modules) against a straightforward expander with a std::vector<double> per module.
#include <benchmark/benchmark.h>

#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "core/derive/derive.hpp"

namespace {

using namespace sprout;

const char* kFractalPlant = "axiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n";
const char* kKoch = "axiom: F\nF -> F+F-F-F+F\n";
const char* kParametric = "axiom: A(1)\nA(x) -> F(x)[+A(x*0.7)][-A(x*0.7)]\n";

std::shared_ptr<const Grammar> grammarOf(const char* text) {
    auto r = parse(text);
    if (!r.ok()) std::abort();
    return r.grammar;
}

std::map<std::string, double> g_modules;  // output modules per benchmark, for the summary

void deriveBench(benchmark::State& state, const char* text, int n, const std::string& name) {
    auto g = grammarOf(text);
    std::uint64_t modules = 0;
    for (auto _ : state) {
        DeriveResult r = derive(g, n);
        modules = r.string->size();
        benchmark::DoNotOptimize(r.string->symbols.data());
    }
    g_modules[name] = double(modules);
    state.counters["modules/s"] =
        benchmark::Counter(double(modules), benchmark::Counter::kIsIterationInvariantRate);
}

// memcpy of the same number of bytes into freshly allocated memory, as a derivation writes.
void memcpyBench(benchmark::State& state, const char* text, int n, const std::string& name) {
    auto g = grammarOf(text);
    DeriveResult r = derive(g, n);
    const size_t bytes = r.string->size() * sizeof(SymbolId);
    for (auto _ : state) {
        PodBuffer<SymbolId> out;
        out.resizeUninitialized(r.string->size());
        std::memcpy(out.data(), r.string->symbols.data(), bytes);
        benchmark::DoNotOptimize(out.data());
    }
    g_modules[name] = double(r.string->size());
}

// The textbook expander: one std::string per step, one append per module.
std::string naiveExpand(const std::map<char, std::string>& rules, std::string s, int n) {
    for (int k = 0; k < n; ++k) {
        std::string next;
        for (char c : s) {
            auto it = rules.find(c);
            if (it == rules.end()) next += c;
            else next += it->second;
        }
        s = std::move(next);
    }
    return s;
}

void naiveBench(benchmark::State& state, std::map<char, std::string> rules, std::string axiom, int n,
                const std::string& name) {
    size_t modules = 0;
    for (auto _ : state) {
        std::string s = naiveExpand(rules, axiom, n);
        modules = s.size();
        benchmark::DoNotOptimize(s.data());
    }
    g_modules[name] = double(modules);
}

// A straightforward parametric expander: a vector of modules, each with its own parameters.
struct NaiveModule {
    char symbol;
    std::vector<double> params;
};

void naiveParametricBench(benchmark::State& state, int n, const std::string& name) {
    size_t modules = 0;
    for (auto _ : state) {
        std::vector<NaiveModule> s{{'A', {1.0}}};
        for (int k = 0; k < n; ++k) {
            std::vector<NaiveModule> next;
            for (const auto& m : s) {
                if (m.symbol != 'A') {
                    next.push_back(m);
                    continue;
                }
                double x = m.params[0];
                next.push_back({'F', {x}});
                next.push_back({'[', {}});
                next.push_back({'+', {}});
                next.push_back({'A', {x * 0.7}});
                next.push_back({']', {}});
                next.push_back({'[', {}});
                next.push_back({'-', {}});
                next.push_back({'A', {x * 0.7}});
                next.push_back({']', {}});
            }
            s = std::move(next);
        }
        modules = s.size();
        benchmark::DoNotOptimize(s.data());
    }
    g_modules[name] = double(modules);
}

// Collects each run's time per iteration for the ratio summary.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const auto& r : runs)
            if (r.run_type == Run::RT_Iteration)
                seconds[r.benchmark_name()] = r.real_accumulated_time / double(r.iterations);
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

int main(int argc, char** argv) {
    benchmark::RegisterBenchmark("d0l/fractal_plant_n10", deriveBench, kFractalPlant, 10, "d0l/fractal_plant_n10");
    benchmark::RegisterBenchmark("memcpy/fractal_plant_n10", memcpyBench, kFractalPlant, 10, "memcpy/fractal_plant_n10");
    benchmark::RegisterBenchmark("naive_string/fractal_plant_n10", naiveBench,
                                 std::map<char, std::string>{{'X', "F-[[X]+X]+F[+FX]-X"}, {'F', "FF"}}, "X", 10,
                                 "naive_string/fractal_plant_n10");
    benchmark::RegisterBenchmark("d0l/koch_n9", deriveBench, kKoch, 9, "d0l/koch_n9");
    benchmark::RegisterBenchmark("memcpy/koch_n9", memcpyBench, kKoch, 9, "memcpy/koch_n9");
    benchmark::RegisterBenchmark("naive_string/koch_n9", naiveBench,
                                 std::map<char, std::string>{{'F', "F+F-F-F+F"}}, "F", 9, "naive_string/koch_n9");
    benchmark::RegisterBenchmark("parametric/tree_n22", deriveBench, kParametric, 22, "parametric/tree_n22");
    benchmark::RegisterBenchmark("naive_parametric/tree_n22", naiveParametricBench, 22, "naive_parametric/tree_n22");

    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    auto rate = [&](const std::string& name) {
        auto it = reporter.seconds.find(name);
        return it == reporter.seconds.end() ? 0.0 : g_modules[name] / it->second;
    };
    auto ratio = [&](const std::string& a, const std::string& b) {
        auto ia = reporter.seconds.find(a), ib = reporter.seconds.find(b);
        return ia == reporter.seconds.end() || ib == reporter.seconds.end() ? 0.0 : ia->second / ib->second;
    };
    std::printf("\nSummary (bars from the core issue)\n");
    for (const char* plant : {"fractal_plant_n10", "koch_n9"}) {
        std::string p(plant);
        std::printf("  D0L %-18s %6.2f G modules/s  time/memcpy %5.2fx (bar <= 8x)  naive/sprout %5.1fx\n",
                    plant, rate("d0l/" + p) / 1e9, ratio("d0l/" + p, "memcpy/" + p),
                    ratio("naive_string/" + p, "d0l/" + p));
    }
    std::printf("  parametric tree_n22     %6.0f M modules/s (bar >= 200)  naive/sprout %5.1fx\n",
                rate("parametric/tree_n22") / 1e6, ratio("naive_parametric/tree_n22", "parametric/tree_n22"));
    // Memory is exact, not timed: bytes per module of the final strings.
    for (auto [text, n, label] : {std::tuple{kFractalPlant, 10, "fractal_plant_n10"}, std::tuple{kParametric, 22, "tree_n22"}}) {
        auto g = grammarOf(text);
        DeriveResult r = derive(g, n);
        std::printf("  memory %-18s %5.2f bytes/module (%zu modules, %zu parameters; bar: 2 per module + 8 per parameter)\n",
                    label, double(r.string->bytes()) / double(r.string->size()), r.string->size(), r.string->params.size());
    }
    return 0;
}
