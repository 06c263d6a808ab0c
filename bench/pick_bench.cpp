// Picking a stem with the mouse: one ray against the 1.57 M-segment fractal plant (n = 10)
// and its leaves, as a click in the viewer does, against the 20 ms bar. The baseline in the
// same run is one plain pass summing the segments' end points (the memory the pick must read
// at least once). Also prints what it costs to draw the plant with the turtle recording which
// module drew each segment (only done once picking is asked for) against drawing it plain.
//
//   build/bench/pick_bench
#include <algorithm>
#include <chrono>
#include <cstdio>

#include <glm/geometric.hpp>

#include "app/plant/presets.hpp"
#include "core/derive/derive.hpp"
#include "core/turtle/pick.hpp"
#include "core/turtle/turtle.hpp"

namespace {
double ms(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main() {
    using namespace sprout;
    auto g = parse(std::string(*presetText("fractal_plant")) + "\nn: 10\n").grammar;
    if (!g) return 1;
    DeriveResult d = derive(g, 10);
    TurtleOptions plainOptions{10, 1, nullptr};
    plainOptions.fromTree = false;
    Geometry geometry;
    double plainDraw = 1e9, mappedDraw = 1e9;
    std::vector<std::uint32_t> segmentModules, surfaceModules;
    for (int run = 0; run < 3; ++run) {
        auto t0 = std::chrono::steady_clock::now();
        interpret(*d.string, *g, plainOptions, geometry);
        plainDraw = std::min(plainDraw, ms(t0));
        TurtleOptions mapped = plainOptions;
        segmentModules.clear();
        surfaceModules.clear();
        mapped.segmentModules = &segmentModules;
        mapped.surfaceModules = &surfaceModules;
        t0 = std::chrono::steady_clock::now();
        interpret(*d.string, *g, mapped, geometry);
        mappedDraw = std::min(mappedDraw, ms(t0));
    }
    // A ray from in front of the plant through its middle, and one through empty sky.
    const glm::vec3 centre = geometry.bounds.centre(), size = geometry.bounds.size();
    const glm::vec3 eye = centre + glm::vec3(0, 0, 2.0f * std::max(size.x, size.y));
    double best = 1e9, miss = 1e9, pass = 1e9;
    std::size_t hitIndex = 0;
    float sum = 0;
    for (int run = 0; run < 5; ++run) {
        auto t0 = std::chrono::steady_clock::now();
        auto hit = pick(geometry, eye, glm::normalize(centre - eye));
        best = std::min(best, ms(t0));
        hitIndex = hit ? hit->index : 0;
        t0 = std::chrono::steady_clock::now();
        auto none = pick(geometry, eye, glm::vec3(0, 0, 1));
        miss = std::min(miss, ms(t0));
        sum += none ? 1.0f : 0.0f;
        t0 = std::chrono::steady_clock::now();
        for (const CylinderInstance& c : geometry.cylinders) sum += c.end.x + c.start.y;
        pass = std::min(pass, ms(t0));
    }
    std::printf("pick_bench: %s segments, %s leaves: a click %.1f ms (bar 20 ms, %.2fx of the bar), a click on the sky %.1f ms; "
                "one pass over the segments %.1f ms: ratio %.1f (hit segment %zu, %g)\n",
                withThousands(geometry.cylinders.size()).c_str(), withThousands(geometry.surfaces.size()).c_str(), best,
                best / 20.0, miss, pass, best / pass, hitIndex, double(sum) * 0.0);
    std::printf("pick_bench: drawing it while recording the module of each segment %.0f ms, plain %.0f ms: ratio %.2f\n", mappedDraw,
                plainDraw, mappedDraw / plainDraw);
    return best < 20.0 ? 0 : 1;
}
