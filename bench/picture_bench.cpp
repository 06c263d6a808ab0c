// The still picture of one plant drawn again and again in one headless context (OSMesa's
// llvmpipe), as the window's view draws it: at 1140x860 (the view beside the panel in a
// 1440x860 window), at the viewer's detail, whole and then in the viewer's 8 ms pieces. No
// derivation, no upload, no read-back of the image in the times: only the picture. The
// baseline in the same run is the picture of an empty scene (sky, ground, the resolve), so
// the ratio shows what the plant and its shadow cost.
//
//   build/bench/picture_bench [FILE|PRESET] [pictures]   (default: lsystem9.lpy of ../shared's
//                                                          L-Py corpus, else the preset bush)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli/load.hpp"
#include "app/plant/growth.hpp"
#include "app/headless.hpp"
#include "app/render/camera.hpp"
#include "app/render/renderer.hpp"
#include "app/snapshot.hpp"

namespace {
using namespace sprout;
constexpr int kWidth = 1140, kHeight = 860;

struct Times {
    double wholeMin = 0, wholeMedian = 0, piecesMedian = 0;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// `pictures` still pictures of the geometry, drawn at once, then as many in pieces.
Times timePictures(const Geometry& g, int pictures, std::string& error) {
    Times t;
    auto context = HeadlessContext::create(kWidth, kHeight, error);
    if (!context) return t;
    render::Renderer renderer;
    if (!renderer.init(context->loader(), error)) return t;
    renderer.setDetail(render::viewerDetail(g.cylinders.size()));
    renderer.upload(g);
    const render::Camera camera = snapshotCamera(g, SnapshotOptions{});
    render::RenderOptions o;
    o.quickLines = renderer.software();
    std::vector<double> whole, pieces;
    for (int i = 0; i <= pictures; ++i) {  // the first warms the shaders up: not counted
        const auto t0 = std::chrono::steady_clock::now();
        renderer.draw(camera, kWidth, kHeight, o, 0);
        renderer.readPixels(1, 1, 0);  // waits for the picture (one pixel read back)
        if (i > 0) whole.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    for (int i = 0; i <= pictures; ++i) {
        renderer.beginDraw(camera, kWidth, kHeight, o, 0);
        while (!renderer.continueDrawFor(8.0)) {
        }
        if (i > 0) pieces.push_back(renderer.lastPictureMs());
    }
    t.wholeMin = *std::min_element(whole.begin(), whole.end());
    t.wholeMedian = median(whole);
    t.piecesMedian = median(pieces);
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    std::string source = argc > 1 ? argv[1] : "";
    const int pictures = argc > 2 ? std::max(1, std::atoi(argv[2])) : 15;
    if (source.empty()) {
        const std::filesystem::path l9 = "../shared/corpus/lpy/tutorial/lpy-paper12-examples/lsystem9.lpy";
        source = std::filesystem::exists(l9) ? l9.string() : "bush";
    }
    Geometry plant, empty;
    const auto loaded = cli::loadGrammar(source);
    std::string error;
    auto grown = [&](std::shared_ptr<const Grammar> g, Geometry& out) {
        return g && growAndDraw(g, g->settings.iterations, DeriveOptions{}, out, error);
    };
    if (!loaded || !grown(loaded->grammar, plant) || !grown(parse("axiom: X\n").grammar, empty)) {
        std::fprintf(stderr, "picture_bench: %s makes no plant %s\n", source.c_str(), error.c_str());
        return 1;
    }
    const Times base = timePictures(empty, pictures, error), it = timePictures(plant, pictures, error);
    if (!error.empty()) {
        std::fprintf(stderr, "picture_bench: %s\n", error.c_str());
        return 1;
    }
    std::printf("%d still pictures each at %dx%d on this machine's GL:\n", pictures, kWidth, kHeight);
    std::printf("baseline (empty scene): whole %.1f ms (min %.1f), in pieces %.1f ms\n", base.wholeMedian, base.wholeMin, base.piecesMedian);
    std::printf("%s: whole %.1f ms (min %.1f), in pieces %.1f ms\n", std::filesystem::path(source).filename().c_str(), it.wholeMedian,
                it.wholeMin, it.piecesMedian);
    std::printf("ratios to the baseline: whole %.2fx, in pieces %.2fx\n", it.wholeMedian / base.wholeMedian,
                it.piecesMedian / base.piecesMedian);
    return 0;
}
