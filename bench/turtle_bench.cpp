// Turtle interpretation throughput against a straightforward glm turtle, in one run.
//
//   build/bench/turtle_bench
//
// Fractal plant n=10: 6.46 M modules, 1.57 M segments. Sprout reuses its output buffers
// between interpretations. It draws this D0L string from its derivation tree (the default);
// the string-reading turtle, which every other grammar takes, is measured too.
#include <benchmark/benchmark.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <string>
#include <vector>

#include "core/derive/derive.hpp"
#include "core/turtle/turtle.hpp"

namespace {
using namespace sprout;

struct Fixture {
    std::shared_ptr<const Grammar> grammar;
    std::shared_ptr<const ModuleString> string;
    std::string text;  // for the baseline
    Fixture() {
        grammar = parse("angle: 22.5\naxiom: X\nX -> F-[[X]+X]+F[+FX]-X\nF -> FF\n").grammar;
        string = derive(grammar, 10).string;
        text = toString(*string, grammar->alphabet);
    }
};
Fixture& fixture() {
    static Fixture f;
    return f;
}

size_t g_segments = 0;

void sproutTurtle(benchmark::State& state) {
    Fixture& f = fixture();
    Geometry geo;
    for (auto _ : state) {
        interpret(*f.string, *f.grammar, {10, 1, nullptr}, geo);
        benchmark::DoNotOptimize(geo.cylinders.data());
    }
    g_segments = geo.cylinders.size();
    state.counters["segments/s"] = benchmark::Counter(double(g_segments), benchmark::Counter::kIsIterationInvariantRate);
}

// The same turtle reading the string module by module (what every non-D0L grammar takes).
void sproutStringTurtle(benchmark::State& state) {
    Fixture& f = fixture();
    Geometry geo;
    TurtleOptions o{10, 1, nullptr};
    o.fromTree = false;
    for (auto _ : state) {
        interpret(*f.string, *f.grammar, o, geo);
        benchmark::DoNotOptimize(geo.cylinders.data());
    }
    state.counters["segments/s"] = benchmark::Counter(double(geo.cylinders.size()), benchmark::Counter::kIsIterationInvariantRate);
}

// The textbook turtle: a glm::mat4 per state, rotations with glm::rotate, a std::vector
// stack, one push_back per segment.
void naiveTurtle(benchmark::State& state) {
    Fixture& f = fixture();
    struct Seg {
        glm::vec3 a, b;
    };
    for (auto _ : state) {
        std::vector<Seg> segs;
        std::vector<glm::mat4> stack;
        glm::mat4 m(1.0f);
        const float a = glm::radians(22.5f);
        for (char c : f.text) {
            switch (c) {
                case 'F': {
                    glm::vec3 p0 = glm::vec3(m[3]);
                    m = glm::translate(m, glm::vec3(0, 1, 0));
                    segs.push_back({p0, glm::vec3(m[3])});
                    break;
                }
                case '+': m = glm::rotate(m, a, glm::vec3(0, 0, 1)); break;
                case '-': m = glm::rotate(m, -a, glm::vec3(0, 0, 1)); break;
                case '[': stack.push_back(m); break;
                case ']': m = stack.back(); stack.pop_back(); break;
                default: break;
            }
        }
        benchmark::DoNotOptimize(segs.data());
    }
}

class RatioReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const auto& r : runs)
            if (r.run_type == Run::RT_Iteration) seconds[r.benchmark_name()] = r.real_accumulated_time / double(r.iterations);
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

int main(int argc, char** argv) {
    benchmark::RegisterBenchmark("turtle/sprout_fractal_plant_n10", sproutTurtle)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("turtle/sprout_string_fractal_plant_n10", sproutStringTurtle)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("turtle/naive_glm_fractal_plant_n10", naiveTurtle)->Unit(benchmark::kMillisecond);
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    double s = reporter.seconds["turtle/sprout_fractal_plant_n10"], n = reporter.seconds["turtle/naive_glm_fractal_plant_n10"];
    double str = reporter.seconds["turtle/sprout_string_fractal_plant_n10"];
    if (s > 0 && n > 0 && str > 0)
        std::printf("\nSummary: turtle fractal plant n=10: %zu segments, %.0f M segments/s from the derivation tree "
                    "(bar >= 100), %.0f M/s reading the string, naive glm turtle %.0f M segments/s; "
                    "ratios to naive %.1fx (tree) and %.1fx (string)\n",
                    g_segments, g_segments / s / 1e6, g_segments / str / 1e6, g_segments / n / 1e6, n / s, n / str);
    return 0;
}
