// Building the forest preset (10x10 plants with grass, seed document 003): CPU time to grow
// every specimen and gather them, against the 1 s bar, and the single-plant cost in the
// same run as the baseline.
//
//   build/bench/forest_bench
#include <chrono>
#include <cstdio>

#include "app/presets.hpp"
#include "core/forest.hpp"
#include "core/turtle.hpp"

int main() {
    using namespace sprout;
    auto presets = [](const std::string& name) -> std::optional<std::string> {
        auto t = presetText(name);
        return t ? std::optional<std::string>(std::string(*t)) : std::nullopt;
    };
    Forest f = *parseForest(*presetText("forest")).forest;
    double best = 1e9;
    ForestStats stats;
    for (int i = 0; i < 3; ++i) {
        Geometry g;
        std::string error;
        auto t0 = std::clock();
        if (!buildForest(f, presets, g, stats, error)) {
            std::printf("%s\n", error.c_str());
            return 1;
        }
        best = std::min(best, double(std::clock() - t0) / CLOCKS_PER_SEC);
    }
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
    return 0;
}
