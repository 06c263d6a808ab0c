// Building the forest preset (10x10 plants with grass, seed document 003): CPU time to grow
// every specimen and gather them, against the 1 s bar, and the single-plant cost in the
// same run as the baseline. Then the shaded forest row (env_forest_row: trees that share one
// light environment and grow in lockstep) against the 2 s bar, with the same trees each in
// its own light (no shared environment) as the baseline in the same run.
//
//   build/bench/forest_bench
#include <chrono>
#include <cstdlib>
#include <cstdio>

#include "app/plant/presets.hpp"
#include "core/scene/forest.hpp"
#include "core/turtle/turtle.hpp"

namespace {

// The best of three builds, in seconds of CPU time.
double bestBuild(const sprout::Forest& f, const sprout::GrammarSource& presets, sprout::ForestStats& stats) {
    double best = 1e9;
    for (int i = 0; i < 3; ++i) {
        sprout::Geometry g;
        std::string error;
        auto t0 = std::clock();
        if (!sprout::buildForest(f, presets, g, stats, error)) {
            std::printf("%s\n", error.c_str());
            std::exit(1);
        }
        best = std::min(best, double(std::clock() - t0) / CLOCKS_PER_SEC);
    }
    return best;
}

}  // namespace

int main() {
    using namespace sprout;
    auto presets = [](const std::string& name) -> std::optional<std::string> {
        auto t = presetText(name);
        return t ? std::optional<std::string>(std::string(*t)) : std::nullopt;
    };
    Forest f = *parseForest(*presetText("forest")).forest;
    ForestStats stats;
    const double best = bestBuild(f, presets, stats);
    // One plant of the first species, for scale.
    auto one = parse(*presetText(f.species[0].name)).grammar;
    auto t0 = std::clock();
    DeriveResult d = derive(one, one->settings.iterations);
    Geometry g;
    interpret(*d.string, *one, {one->settings.iterations, 1, nullptr}, g);
    double single = double(std::clock() - t0) / CLOCKS_PER_SEC;
    std::printf("forest: %d plants + %d grasses, %s segments built in %.0f ms of CPU time (bar 1000 ms, %.2fx of the bar); "
                "one %s alone %.1f ms\n",
                stats.plants, stats.grasses, withThousands(stats.segments).c_str(), best * 1e3, best, f.species[0].name.c_str(),
                single * 1e3);
    Forest row = *parseForest(*presetText("env_forest_row")).forest;
    ForestStats shared, own;
    const double together = bestBuild(row, presets, shared);
    row.environment = Environment();  // each tree in its own light
    const double apart = bestBuild(row, presets, own);
    std::printf("forest row with one shared light: %d trees in lockstep, %s segments grown in %.0f ms of CPU time (bar 2000 ms, "
                "%.2fx of the bar); each in its own light %.0f ms (%s segments): ratio %.2f\n",
                shared.sharing, withThousands(shared.segments).c_str(), together * 1e3, together / 2.0, apart * 1e3,
                withThousands(own.segments).c_str(), together / apart);
    return best < 1.0 && together < 2.0 ? 0 : 1;
}
