// Headless render of every preset at 1280x720 through OSMesa (llvmpipe), as `sprout render`
// does it: derive, interpret, create the context, upload, draw, read back.
//
//   build/bench/render_bench
//
// The baseline in the same run is an empty scene (context, shaders, background, read back),
// so the ratio shows what the plant itself costs; the bar is 1 s per preset.
#include <benchmark/benchmark.h>

#include <map>

#include "app/cli/load.hpp"
#include "app/plant/presets.hpp"
#include "app/snapshot.hpp"

namespace {
using namespace sprout;

void renderPreset(benchmark::State& state, std::shared_ptr<const Grammar> g) {
    if (!g) {
        state.SkipWithError("does not load");
        for (auto _ : state) {
        }
        return;
    }
    SnapshotOptions o;
    for (auto _ : state) {
        Snapshot shot;
        std::string error;
        if (!renderSnapshot(g, o, shot, error)) state.SkipWithError(error.c_str());
        benchmark::DoNotOptimize(shot.image.rgba.data());
    }
}

class Reporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const auto& r : runs) {
            std::string name = r.benchmark_name();
            name = name.substr(0, name.find("/iterations"));
            seconds[name] = r.real_accumulated_time / double(r.iterations);
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

// Loaded as `sprout render PRESET` loads it (an L-Py preset runs its Python once, here).
std::shared_ptr<const Grammar> loadPreset(const std::string& name) {
    auto loaded = cli::loadGrammar(name);
    return loaded ? loaded->grammar : nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::RegisterBenchmark("render/empty_scene", renderPreset, parse("axiom: X\n").grammar)->Unit(benchmark::kMillisecond)->Iterations(3);
    for (const auto& name : presetNames())
        benchmark::RegisterBenchmark(("render/" + name).c_str(), renderPreset, loadPreset(name))
            ->Unit(benchmark::kMillisecond)
            ->Iterations(2);
    benchmark::Initialize(&argc, argv);
    Reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const double empty = reporter.seconds["render/empty_scene"];
    double worst = 0;
    std::string worstName;
    std::printf("\nSummary: 1280x720 headless renders (bar: under 1 s each)\n");
    for (const auto& [name, s] : reporter.seconds) {
        if (name == "render/empty_scene") continue;
        std::printf("  %-24s %7.0f ms  %5.1fx the empty scene  %s\n", name.c_str(), s * 1e3, empty > 0 ? s / empty : 0,
                    s < 1.0 ? "ok" : "OVER 1 s");
        if (s > worst) {
            worst = s;
            worstName = name;
        }
    }
    std::printf("  slowest: %s, %.0f ms\n", worstName.c_str(), worst * 1e3);
    return 0;
}
