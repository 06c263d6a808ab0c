// The panel's Surfaces section (issue 52): an L-Py model's NurbsPatch objects (written in its
// text as L-Py Studio writes them) and a VLab object's Bezier patches (its `.s` files, written
// as bezieredit writes them), each opened in the 3D surface editor (surface_canvas.hpp).
#include <algorithm>
#include <cmath>
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
    e.key = l.label.substr(0, l.label.find("  ("));  // the same editor while rows come and go
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

// An L-Py patch's text with its points `rows` (another shape, a weight), one undo step.
std::string writeRows(App& app, const Listed& l, const std::vector<std::vector<std::array<double, 4>>>& rows) {
    for (const LpyPatch& p : lpyPatches(app.state.text()))
        if (p.name == l.patch.name) {
            app.state.setText(setLpyPatchPoints(app.state.text(), p, rows), newGesture());
            return "";
        }
    return "no patch " + l.patch.name;
}

std::string editRows(App& app, const Listed& l, PatchEdit what, size_t k) {
    std::string error;
    const auto rows = editedPatch(l.patch, what, k, error);
    return rows ? writeRows(app, l, *rows) : error;
}

// Below an L-Py patch's editor: rows and columns added after, or taken away at, the chosen
// point's (the last ones before a point is chosen), and the chosen point's weight.
void patchTools(App& app, const Listed& l) {
    const auto chosen = selectedSurfacePoint(l.label.substr(0, l.label.find("  (")));
    const size_t u = chosen ? (*chosen)[0] : l.patch.rows.size() - 1, v = chosen ? (*chosen)[1] : l.patch.rows.front().size() - 1;
    std::string why;
    if (ImGui::SmallButton("+ row")) why = editRows(app, l, PatchEdit::AddRow, u);
    ImGui::SameLine();
    if (ImGui::SmallButton("- row")) why = editRows(app, l, PatchEdit::DeleteRow, u);
    ImGui::SameLine();
    if (ImGui::SmallButton("+ column")) why = editRows(app, l, PatchEdit::AddColumn, v);
    ImGui::SameLine();
    if (ImGui::SmallButton("- column")) why = editRows(app, l, PatchEdit::DeleteColumn, v);
    if (chosen && u < l.patch.rows.size() && v < l.patch.rows[u].size()) {
        float w = float(l.patch.rows[u][v][3]);
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
        if (ImGui::DragFloat("weight of the point", &w, 0.01f, 0.01f, 100.0f, "%.3g") && w > 0) {
            auto rows = l.patch.rows;
            rows[u][v][3] = w;
            why = writeRows(app, l, rows);
        }
    } else {
        ImGui::TextColored(kDim, "take hold of a point to add or delete its row or column, or weigh it");
    }
    if (!why.empty()) app.say(l.patch.name + ": " + why);
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
    if (all[open].lpy) patchTools(app, all[open]);
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

std::string editSurface(App& app, size_t which, const std::string& what, size_t k, double weight, size_t v) {
    const auto all = listed(app);
    if (which >= all.size()) return "no surface " + std::to_string(which);
    if (!all[which].lpy) return "a VLab Bezier patch keeps its 4 x 4 points";
    if (what == "weight") {
        auto rows = all[which].patch.rows;
        if (k >= rows.size() || v >= rows[k].size()) return "no point " + std::to_string(k) + "," + std::to_string(v);
        if (!(weight > 0) || !std::isfinite(weight)) return "a weight is above 0";
        rows[k][v][3] = weight;
        return writeRows(app, all[which], rows);
    }
    const PatchEdit e = what == "add-row"      ? PatchEdit::AddRow
                        : what == "delete-row" ? PatchEdit::DeleteRow
                        : what == "add-column" ? PatchEdit::AddColumn
                                               : PatchEdit::DeleteColumn;
    return editRows(app, all[which], e, k);
}

}  // namespace sprout::viewer::detail
