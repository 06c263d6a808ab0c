// The panel's Surfaces section (issue 52): an L-Py model's NurbsPatch objects (written in its
// text as L-Py Studio writes them) and a VLab object's Bezier patches (its `.s` files, written
// as bezieredit writes them), each opened in the 3D surface editor (surface_canvas.hpp).
#include <algorithm>
#include <cstdio>

#include "app/plant/lpy_patches.hpp"
#include "app/plant/vlab_edit.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "app/viewer/window/surface_canvas.hpp"
#include "lpy/lpy.hpp"

namespace sprout::viewer::detail {
namespace {

// One surface the section lists: an L-Py patch (by name) or a VLab patch (its file, its index).
struct Listed {
    std::string label;
    bool lpy = true;
    LpyPatch patch;
    VlabSurfacePatch vlab;
};

std::vector<Listed> listed(App& app) {
    static std::string text, path;
    static std::uint64_t version = ~std::uint64_t(0);
    static std::vector<Listed> out;
    if (text == app.state.text() && path == app.state.path().string() && version == objectFilesVersion()) return out;
    text = app.state.text(), path = app.state.path().string(), version = objectFilesVersion();
    out.clear();
    if (app.state.kind() == FileKind::Lpy)
        for (const LpyPatch& p : lpyPatches(text)) out.push_back({p.name + "  (NurbsPatch " + std::to_string(p.rows.size()) + " x " +
                                                                      std::to_string(p.rows.front().size()) + ")",
                                                                  true, p, {}});
    if (app.state.vlabObject() && !path.empty())
        for (const VlabSurfacePatch& p : vlabSurfacePatches(path)) out.push_back({p.label + "  (Bezier 4 x 4)", false, {}, p});
    return out;
}

PatchGrid gridOf(const Listed& l) {
    PatchGrid g;
    if (l.lpy) {
        for (const auto& row : l.patch.rows) {
            g.emplace_back();
            for (const auto& p : row) g.back().push_back({p[0], p[1], p[2]});
        }
    } else {
        for (size_t i = 0; i < 4; ++i) {
            g.emplace_back();
            for (size_t j = 0; j < 4; ++j) {
                const auto& p = l.vlab.points[i * 4 + j];
                g.back().push_back({p[0], p[1], p[2]});
            }
        }
    }
    return g;
}

bool write(App& app, const Listed& l, const PatchGrid& g, std::uint64_t gesture) {
    if (l.lpy) {
        // The patch as the text has it now (the list is the one of the last frame).
        for (const LpyPatch& p : lpyPatches(app.state.text())) {
            if (p.name != l.patch.name) continue;
            auto rows = p.rows;
            for (size_t i = 0; i < rows.size() && i < g.size(); ++i)
                for (size_t j = 0; j < rows[i].size() && j < g[i].size(); ++j) rows[i][j] = {g[i][j][0], g[i][j][1], g[i][j][2], rows[i][j][3]};
            app.state.setText(setLpyPatchPoints(app.state.text(), p, rows), gesture);
            return true;
        }
        return false;
    }
    std::array<std::array<float, 3>, 16> pts{};
    for (size_t i = 0; i < 4 && i < g.size(); ++i)
        for (size_t j = 0; j < 4 && j < g[i].size(); ++j) pts[i * 4 + j] = {float(g[i][j][0]), float(g[i][j][1]), float(g[i][j][2])};
    std::string error;
    const auto text = vlabSurfaceText(l.vlab, pts, error);
    if (!text) return app.say(l.vlab.label + ": " + error), false;
    return writeObjectFile(app, l.vlab.path, *text, gesture);
}

EditedSurface edited(App& app, const Listed& l) {
    EditedSurface e;
    e.key = l.label;
    e.points = gridOf(l);
    if (l.lpy) {
        const auto rows = l.patch.rows;
        const int du = l.patch.udegree, dv = l.patch.vdegree;
        e.samples = [rows, du, dv](const PatchGrid& g) {
            auto r = rows;
            for (size_t i = 0; i < r.size() && i < g.size(); ++i)
                for (size_t j = 0; j < r[i].size() && j < g[i].size(); ++j) r[i][j] = {g[i][j][0], g[i][j][1], g[i][j][2], r[i][j][3]};
            return lpy::patchSamples(r, du, dv, 9);
        };
    } else {
        e.samples = [](const PatchGrid& g) {
            std::array<std::array<float, 3>, 16> pts{};
            for (size_t i = 0; i < 4 && i < g.size(); ++i)
                for (size_t j = 0; j < 4 && j < g[i].size(); ++j) pts[i * 4 + j] = {float(g[i][j][0]), float(g[i][j][1]), float(g[i][j][2])};
            return bezierPatchSamples(pts, 9);
        };
    }
    e.write = [&app, l](const PatchGrid& g, std::uint64_t gesture) { return write(app, l, g, gesture); };
    return e;
}

size_t& openIndex() {
    static size_t open = 0;
    return open;
}

}  // namespace

bool hasSurfaces(App& app) { return !listed(app).empty(); }

void surfaceSection(App& app) {
    const std::vector<Listed> all = listed(app);  // a copy: a write lists them again
    size_t& open = openIndex();
    open = std::min(open, all.size() - 1);
    for (size_t i = 0; i < all.size(); ++i)
        if (ImGui::Selectable(all[i].label.c_str(), open == i)) open = i;
    ImGui::PushID(int(open));
    surfaceCanvas(app, edited(app, all[open]));
    ImGui::PopID();
    if (!all[open].lpy) {
        if (ImGui::SmallButton("undo##surfaces")) objectUndo(app, false);
        ImGui::SameLine();
        if (ImGui::SmallButton("redo##surfaces")) objectUndo(app, true);
    }
}

std::vector<std::string> surfaceLines(App& app) {
    std::vector<std::string> out;
    for (const Listed& l : listed(app)) {
        std::string line = "surface=" + l.label.substr(0, l.label.find("  (")) + " points=";
        const PatchGrid g = gridOf(l);
        for (size_t i = 0; i < g.size(); ++i)
            for (size_t j = 0; j < g[i].size(); ++j) {
                char buf[100];
                std::snprintf(buf, sizeof buf, "%s%.6g,%.6g,%.6g", i + j ? ";" : "", g[i][j][0], g[i][j][1], g[i][j][2]);
                line += buf;
            }
        out.push_back(line);
    }
    return out;
}

bool setSurfacePoint(App& app, size_t which, size_t u, size_t v, const std::array<double, 3>& p, std::uint64_t gesture) {
    const auto all = listed(app);
    if (which >= all.size()) return false;
    PatchGrid g = gridOf(all[which]);
    if (u >= g.size() || v >= g[u].size()) return false;
    g[u][v] = p;
    return write(app, all[which], g, gesture ? gesture : newGesture());
}

void openSurface(size_t which) { openIndex() = which; }

}  // namespace sprout::viewer::detail
