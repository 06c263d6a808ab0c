// A VLab object's functions and contours, edited and written back (vlab_edit.hpp).
#include "app/plant/vlab_edit.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/plant/vlab_view.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/read_file.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/surface_patches.hpp"
#include "core/language/vlab/view_file.hpp"

namespace sprout {
namespace fs = std::filesystem;
namespace {

CurvePoints pointsOf(const std::vector<std::array<double, 3>>& pts) { return pts; }
CurvePoints pointsOf(const std::vector<std::array<double, 4>>& pts) {
    CurvePoints out;
    for (const auto& p : pts) out.push_back({p[0], p[1], p[3]});
    return out;
}

VlabCurveFile functionEntry(const FunctionFile& f, const std::string& path, const std::string& label, int item) {
    VlabCurveFile e;
    e.kind = VlabCurveFile::Kind::Function;
    e.label = label, e.path = path, e.item = item;
    e.points = pointsOf(f.points);
    e.rules.function = true, e.rules.fewest = 2, e.rules.newWeight = 1;
    e.samples = f.samples;
    return e;
}

// Multiplicities as cpfg counts them: whole, at least 1.
long expanded(const CurvePoints& pts) {
    long n = 0;
    for (const auto& p : pts) n += std::max(1L, long(p[2]));
    return n;
}

}  // namespace

std::vector<VlabCurveFile> vlabCurveFiles(const std::string& lsystemPath) {
    std::vector<VlabCurveFile> out;
    const std::optional<VlabObject> object = vlabObjectAt(lsystemPath);
    if (!object || object->view.empty()) return out;
    std::error_code ec;
    if (!fs::equivalent(object->lsystem, lsystemPath, ec)) return out;  // the object runs another L-system
    const std::optional<std::string> text = readFile(object->view);
    if (!text) return out;
    const vlab::ViewFile view = vlab::readViewFile(*text);
    const fs::path folder = fs::path(object->view).parent_path();
    for (const vlab::FileReference& f : view.files) {
        const fs::path path = folder / f.file;
        if (f.command == "function") {
            const FunctionRead r = loadFunction(path, -1);
            if (!r.ok() || !r.file) continue;
            out.push_back(functionEntry(*r.file, path.string(), f.file, -1));
            // The first format has no `samples:`: cpfg takes the view file's count (none: the
            // curve itself), which the file written in funcedit's format must keep.
            if (r.file->original) out.back().samples = f.numbers.empty() ? 0 : int(std::clamp(f.numbers[0], 0.0, 10000.0));
        } else if (f.command == "function set") {
            const FunctionSetRead r = loadFunctionSet(path);
            if (r.ok())
                for (size_t i = 0; i < r.files.size(); ++i)
                    out.push_back(functionEntry(r.files[i], path.string(), f.file + ": " + r.files[i].name, int(i)));
        } else if (f.command == "contour" && !f.numbers.empty()) {
            const ContourRead r = loadContour(path);
            if (!r.ok() || !r.file) continue;
            VlabCurveFile e;
            e.kind = VlabCurveFile::Kind::Contour;
            e.label = f.file, e.path = path.string();
            e.points = pointsOf(r.file->points);
            e.rules.closed = r.file->closed, e.rules.fewest = r.file->closed ? 3 : 4, e.rules.newWeight = 1;
            e.samples = view.contourSides;
            out.push_back(std::move(e));
        }
    }
    return out;
}

std::vector<std::array<double, 2>> vlabCurveSamples(const VlabCurveFile& f, const CurvePoints& pts) {
    std::vector<std::array<double, 2>> out;
    if (f.kind == VlabCurveFile::Kind::Function) {
        if (expanded(pts) < 4) return out;
        FunctionFile file;
        for (const auto& p : pts) file.points.push_back({p[0], p[1], double(std::max(1L, long(p[2])))});
        const CurveFunction fn = file.function();
        for (int i = 0; i <= 100; ++i) out.push_back({i / 100.0, fn.curveValue(i / 100.0)});
        return out;
    }
    Contour c;
    c.closed = f.rules.closed;
    for (const auto& p : pts)
        for (long k = 0; k < std::max(1L, long(p[2])); ++k) c.points.push_back({float(p[0]), float(p[1]), 0});
    for (const auto& p : c.sampled(std::max(64, f.samples))) out.push_back({p[0], p[1]});
    return out;
}

std::optional<std::string> vlabCurveText(const VlabCurveFile& f, const CurvePoints& pts, std::string& error) {
    for (const auto& p : pts)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return error = "a point that is not a finite number", std::nullopt;
    const long n = expanded(pts);
    if (f.kind == VlabCurveFile::Kind::Function && n < 4) return error = "a function needs at least 4 points (cpfg)", std::nullopt;
    if (f.kind == VlabCurveFile::Kind::Contour && n < (f.rules.closed ? 3 : 4))
        return error = std::string("a") + (f.rules.closed ? " closed contour needs 3 points" : "n open contour needs 4 points"), std::nullopt;
    auto fill = [&](std::vector<std::array<double, 3>>& out) {
        out.clear();
        for (const auto& p : pts) out.push_back({p[0], p[1], double(std::max(1L, long(p[2])))});
    };
    if (f.kind == VlabCurveFile::Kind::Function && f.item < 0) {
        FunctionRead r = loadFunction(f.path, -1);
        if (!r.ok() || !r.file) return error = f.label + " cannot be read again", std::nullopt;
        fill(r.file->points);
        if (r.file->original) r.file->samples = f.samples;  // the view file's count, as cpfg used it
        return writeFunction(*r.file);
    }
    if (f.kind == VlabCurveFile::Kind::Function) {
        FunctionSetRead r = loadFunctionSet(f.path);
        if (!r.ok() || size_t(f.item) >= r.files.size()) return error = f.label + " cannot be read again", std::nullopt;
        fill(r.files[size_t(f.item)].points);
        return writeFunctionSet(r.files);
    }
    ContourRead r = loadContour(f.path);
    if (!r.ok() || !r.file) return error = f.label + " cannot be read again", std::nullopt;
    r.file->points.clear();
    for (const auto& p : pts) r.file->points.push_back({p[0], p[1], 0, double(std::max(1L, long(p[2])))});
    return writeContour(*r.file);
}

std::optional<std::string> vlabFunctionSamplesText(const VlabCurveFile& f, int samples, std::string& error) {
    if (f.kind != VlabCurveFile::Kind::Function) return error = "a contour has no samples", std::nullopt;
    if (samples < 0 || samples > 10000) return error = "samples are 0 to 10000", std::nullopt;
    if (f.item < 0) {
        FunctionRead r = loadFunction(f.path, -1);
        if (!r.ok() || !r.file) return error = f.label + " cannot be read again", std::nullopt;
        r.file->samples = samples;
        return writeFunction(*r.file);
    }
    FunctionSetRead r = loadFunctionSet(f.path);
    if (!r.ok() || size_t(f.item) >= r.files.size()) return error = f.label + " cannot be read again", std::nullopt;
    r.files[size_t(f.item)].samples = samples;
    return writeFunctionSet(r.files);
}

std::vector<VlabSurfacePatch> vlabSurfacePatches(const std::string& lsystemPath) {
    std::vector<VlabSurfacePatch> out;
    const std::optional<VlabObject> object = vlabObjectAt(lsystemPath);
    std::error_code ec;
    if (!object || object->view.empty() || !fs::equivalent(object->lsystem, lsystemPath, ec)) return out;
    const std::optional<std::string> text = readFile(object->view);
    if (!text) return out;
    const fs::path folder = fs::path(object->view).parent_path();
    for (const vlab::FileReference& f : vlab::readViewFile(*text).files) {
        if (f.command != "surface" || !f.id) continue;
        const SurfacePatchesRead r = loadSurfacePatches(folder / f.file);
        if (!r.surface) continue;
        for (size_t i = 0; i < r.surface->patches.size(); ++i)
            out.push_back({f.file + ": " + r.surface->patches[i].name, (folder / f.file).string(), i, r.surface->patches[i].points});
    }
    return out;
}

std::optional<std::string> vlabSurfaceText(const VlabSurfacePatch& p, const std::array<std::array<float, 3>, 16>& points, std::string& error) {
    for (const auto& q : points)
        for (float x : q)
            if (!std::isfinite(x)) return error = "a point that is not a finite number", std::nullopt;
    SurfacePatchesRead r = loadSurfacePatches(p.path);
    if (!r.surface || p.patch >= r.surface->patches.size()) return error = p.label + " cannot be read again", std::nullopt;
    r.surface->patches[p.patch].points = points;
    return writeSurfacePatches(*r.surface);
}

std::vector<std::vector<std::array<double, 3>>> bezierPatchSamples(const std::array<std::array<float, 3>, 16>& points, int samples) {
    auto bernstein = [](double t, int i) {
        const double s = 1 - t;
        const double b[4] = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
        return b[i];
    };
    std::vector<std::vector<std::array<double, 3>>> out;
    samples = std::max(2, samples);
    for (int a = 0; a < samples; ++a) {
        const double u = double(a) / (samples - 1);
        std::vector<std::array<double, 3>> line;
        for (int b = 0; b < samples; ++b) {
            const double v = double(b) / (samples - 1);
            std::array<double, 3> p{0, 0, 0};
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    for (size_t c = 0; c < 3; ++c) p[c] += bernstein(u, i) * bernstein(v, j) * points[size_t(i * 4 + j)][c];
            line.push_back(p);
        }
        out.push_back(std::move(line));
    }
    return out;
}

std::vector<VlabColourFile> vlabColourFiles(const std::string& lsystemPath) {
    std::vector<VlabColourFile> out;
    const std::optional<VlabObject> object = vlabObjectAt(lsystemPath);
    std::error_code ec;
    if (!object || object->colourFiles.empty() || !fs::equivalent(object->lsystem, lsystemPath, ec)) return out;
    const bool materials = object->colourFiles.back().material;  // the kind cpfg reads
    for (const auto& f : object->colourFiles) {
        if (f.material != materials) continue;
        VlabColourFile c;
        c.path = f.path, c.material = f.material, c.set = f.set;
        c.label = fs::path(f.path).filename().string() + (f.material ? " (materials, set " : " (colour map, set ") + std::to_string(f.set) + ")";
        out.push_back(std::move(c));
    }
    return out;
}

std::optional<std::string> colourMapWith(const std::string& bytes, int k, std::uint32_t rgb, std::string& error) {
    auto map = vlab::readColourMap(bytes, error);
    if (!map || k < 0 || k > 255) return error = error.empty() ? "no colour " + std::to_string(k) : error, std::nullopt;
    map->colours[size_t(k)] = rgb & 0xFFFFFF;
    return vlab::writeColourMap(*map);
}

std::optional<std::string> colourMapInterpolated(const std::string& bytes, int from, int to, std::string& error) {
    auto map = vlab::readColourMap(bytes, error);
    if (!map) return std::nullopt;
    if (from > to) std::swap(from, to);
    if (from < 0 || to > 255) return error = "entries are 0 to 255", std::nullopt;
    const std::uint32_t a = map->colours[size_t(from)], b = map->colours[size_t(to)];
    for (int k = from + 1; k < to; ++k) {
        const float t = float(k - from) / float(to - from);
        std::uint32_t c = 0;
        for (int shift : {16, 8, 0}) {
            const float x = float(a >> shift & 0xFF) / 255.0f, y = float(b >> shift & 0xFF) / 255.0f;
            c |= std::uint32_t(static_cast<unsigned char>(((1 - t) * x + t * y) * 255.0f)) << shift;  // palette: (GLubyte)(v * 255)
        }
        map->colours[size_t(k)] = c;
    }
    return vlab::writeColourMap(*map);
}

std::optional<std::string> materialsWith(const std::string& bytes, int k, const vlab::Material& m, std::string& error) {
    auto set = vlab::readMaterials(bytes, error);
    if (!set || k < 0 || k > 255) return error = error.empty() ? "no material " + std::to_string(k) : error, std::nullopt;
    if (!set->materials[size_t(k)]) ++set->count;
    set->materials[size_t(k)] = m;
    return vlab::writeMaterials(*set);
}

bool FileEdits::write(const std::string& path, const std::string& text, std::uint64_t gesture, std::string& error) {
    const std::string before = readFile(path).value_or("");
    if (before == text) return true;
    if (!writeFileAtomically(path, text, error)) return false;
    m_undone.clear();
    if (gesture == 0 || m_done.empty() || m_done.back().gesture != gesture) m_done.push_back(Step{gesture, {}});
    auto& files = m_done.back().files;
    for (auto& f : files)
        if (f[0] == path) return f[2] = text, true;  // the gesture's first `before` stays
    files.push_back({path, before, text});
    return true;
}

bool FileEdits::undo(std::string& error) {
    if (m_done.empty()) return false;
    Step s = std::move(m_done.back());
    m_done.pop_back();
    for (auto it = s.files.rbegin(); it != s.files.rend(); ++it)
        if (!writeFileAtomically((*it)[0], (*it)[1], error)) return false;
    m_undone.push_back(std::move(s));
    return true;
}

bool FileEdits::redo(std::string& error) {
    if (m_undone.empty()) return false;
    Step s = std::move(m_undone.back());
    m_undone.pop_back();
    for (const auto& f : s.files)
        if (!writeFileAtomically(f[0], f[2], error)) return false;
    m_done.push_back(std::move(s));
    return true;
}

}  // namespace sprout
