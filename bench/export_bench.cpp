// .glb export of the fractal plant n=10 (1.57 M segments): wall time against the 2 s bar and
// peak memory against twice the written file. Baseline in the same run: the same triangles
// baked into one in-memory mesh and written with one fwrite (what a non-streaming exporter
// does), to show what streaming saves.
//
//   build/bench/export_bench [OUT_DIR]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/resource.h>

#include "app/export/export.hpp"
#include "app/export/scene.hpp"
#include "app/plant/presets.hpp"
#include "core/derive/derive.hpp"
#include "core/turtle/turtle.hpp"

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
double peakMb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}
}  // namespace

int main(int argc, char** argv) {
    using namespace sprout;
    const std::string dir = argc > 1 ? argv[1] : std::filesystem::temp_directory_path().string();
    const std::string out = dir + "/sprout_export_bench.glb";
    auto grammar = parse(*presetText("fractal_plant")).grammar;
    DeriveResult d = derive(grammar, 10);
    Geometry g;
    interpret(*d.string, *grammar, {10, 1, nullptr}, g);
    d.string.reset();  // the plant as a viewer or `sprout export` holds it: geometry only
    const double before = peakMb();

    double best = 1e9;
    exporter::ExportStats st;
    for (int i = 0; i < 3; ++i) {
        std::string error;
        double t0 = now();
        if (!exporter::exportGeometry(g, out, exporter::Format::Glb, {}, st, error)) {
            std::printf("%s\n", error.c_str());
            return 1;
        }
        best = std::min(best, now() - t0);
    }
    const double streamingPeak = peakMb();
    const double fileMb = double(st.bytes) / (1 << 20);

    // Baseline: every triangle in memory first, then one write.
    double t0 = now();
    exporter::ExportScene scene(g, 0);
    mesh::BakedMesh all;
    for (const auto& p : scene.primitives) {
        std::uint32_t base = std::uint32_t(all.vertices.size());
        scene.forEachChunk(p, [&](const mesh::BakedMesh& c) {
            std::uint32_t b = std::uint32_t(all.vertices.size());
            all.vertices.insert(all.vertices.end(), c.vertices.begin(), c.vertices.end());
            for (auto i : c.indices) all.indices.push_back(b - base + i);
        });
    }
    std::FILE* f = std::fopen(out.c_str(), "wb");
    std::fwrite(all.vertices.data(), sizeof(all.vertices[0]), all.vertices.size(), f);
    std::fwrite(all.indices.data(), 4, all.indices.size(), f);
    std::fclose(f);
    const double baseline = now() - t0;
    const double baselinePeak = peakMb();
    std::filesystem::remove(out);

    std::printf("glb export, fractal plant n=10: %s segments -> %zu tubes, %zu triangles, %.0f MB file\n",
                withThousands(g.cylinders.size()).c_str(), st.stems, st.triangles, fileMb);
    std::printf("  streaming export: %.2f s (bar 2 s: %.2fx of the bar); in-memory baseline %.2f s (%.2fx)\n", best, best / 2.0,
                baseline, best / baseline);
    std::printf("  peak memory: %.0f MB for the process, %.0f MB of it the plant before export; %.2fx the file (bar 2x); "
                "the in-memory baseline peaks at %.0f MB\n",
                streamingPeak, before, streamingPeak / fileMb, baselinePeak);
    return 0;
}
