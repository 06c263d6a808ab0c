#include "app/plant/vlab_curves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "app/plant/vlab_view.hpp"
#include "core/base/read_file.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/view_file.hpp"

namespace sprout {

namespace fs = std::filesystem;

namespace {

// An image file's width over its height, from its header (PNG's IHDR, SGI's sizes); 1 for
// another or a file that cannot be read (the renderer reads the pixels).
float imageAspect(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char h[24] = {};
    in.read(reinterpret_cast<char*>(h), sizeof h);
    auto be32 = [&](int at) { return double(std::uint32_t(h[at]) << 24 | std::uint32_t(h[at + 1]) << 16 | std::uint32_t(h[at + 2]) << 8 | h[at + 3]); };
    double w = 0, hgt = 0;
    if (in.gcount() == 24 && h[0] == 0x89 && h[1] == 'P' && h[2] == 'N' && h[3] == 'G') w = be32(16), hgt = be32(20);
    else if (in.gcount() >= 10 && h[0] == 0x01 && h[1] == 0xDA) w = double(h[6] << 8 | h[7]), hgt = double(h[8] << 8 | h[9]);
    return w > 0 && hgt > 0 ? float(w / hgt) : 1.0f;
}

}  // namespace

VlabCurves readVlabCurves(const std::string& lsystemPath, ParseOptions& options) {
    VlabCurves out;
    const std::optional<VlabObject> object = vlabObjectAt(lsystemPath);
    if (!object || object->view.empty()) return out;
    std::error_code ec;
    if (!fs::equivalent(object->lsystem, lsystemPath, ec)) return out;
    out.object = true;
    const std::optional<std::string> text = readFile(object->view);
    if (!text) return out;  // the view file's own reader says so (vlab_view.cpp)
    const vlab::ViewFile view = vlab::readViewFile(*text);
    const fs::path folder = fs::path(object->view).parent_path();
    auto tables = std::make_shared<CurveTables>();
    tables->contourSides = view.contourSides;
    bool any = false;
    auto note = [&](const auto& diagnostics) {
        for (const auto& d : diagnostics) out.problems.push_back(d.text());
    };
    // In the view file's order, as cpfg reads it (a function set replaces the functions before).
    for (const vlab::FileReference& f : view.files) {
        const fs::path path = folder / f.file;
        if (f.command == "function") {
            FunctionRead r = loadFunction(path, f.numbers.empty() ? -1 : int(f.numbers[0]));
            note(r.diagnostics);
            tables->addFunction(std::move(r.function));
            any = true;
        } else if (f.command == "function set") {
            FunctionSetRead r = loadFunctionSet(path);
            note(r.diagnostics);
            tables->setFunctionSet(std::move(r.functions));
            any = true;
        } else if (f.command == "curve") {  // ids from 1 in the lines' order, a file unread too (cpfg)
            int samples = 100;                // cpfg's `curve: FILE [SAMPLES]`
            if (!f.numbers.empty()) {
                const double n = std::trunc(f.numbers[0]);  // fscanf's %d
                const int most = CurveXYZ::kMaxSamples;
                samples = !(n >= 2) ? 2 : n > most ? most : int(n);
                if (samples != n)
                    out.problems.push_back(object->view + ":" + std::to_string(f.line) + ": 'curve: " + f.file +
                                           " SAMPLES' measures the curve at 2 to " + std::to_string(most) +
                                           " points (cpfg's count, 100 by default): " + std::to_string(samples) + " used");
            }
            CurveRead r = loadCurve(path, samples);
            note(r.diagnostics);
            tables->curves.push_back(std::move(r.curve));
            any = true;
        } else if (f.command == "contour" && !f.numbers.empty()) {
            ContourRead r = loadContour(path);
            note(r.diagnostics);
            if (r.contour) tables->contours.emplace(int(f.numbers[0]), std::move(*r.contour));
            any = true;
        } else if (f.command == "surface" && f.id) {
            options.surfaces.emplace_back(std::string(1, f.id), f.file);
        } else if (f.command == "texture") {  // @Tx(n): the n-th; `S:` spans each surface whole
            std::error_code missing;
            if (!fs::is_regular_file(path, missing))
                out.problems.push_back(object->view + ":" + std::to_string(f.line) + ": texture image '" + f.file +
                                       "' is not there: the surfaces keep their colour");
            bool perSurface = false;
            for (size_t at = 0; (at = f.options.find('S', at)) != std::string::npos; ++at)
                perSurface |= (at == 0 || f.options[at - 1] == ' ') && (at + 1 == f.options.size() || f.options[at + 1] == ':' || f.options[at + 1] == ' ');
            float ratio = 1;  // R: ratio
            if (const size_t r = f.options.find("R:"); r != std::string::npos && (r == 0 || f.options[r - 1] == ' ')) {
                const double v = std::strtod(f.options.c_str() + r + 2, nullptr);
                if (v > 0 && std::isfinite(v)) ratio = float(std::clamp(v, 1e-6, 1e6));
            }
            options.viewTextures.push_back({path.string(), perSurface, imageAspect(path), ratio});
        }
    }
    if (any) options.curves = std::move(tables);
    return out;
}

}  // namespace sprout
