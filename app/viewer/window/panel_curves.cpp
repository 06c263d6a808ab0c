// The panel's Curves section (issue 52): an L-Py model's 2D curves (app/plant/lpy_objects.hpp),
// each opened in the curve editor (curve_canvas.hpp), drawn as PlantGL evaluates it
// (lpy::curveSamples). What the editor changes is written in the model's text (its
// INITIALISATION part, as L-Py Studio writes it), and the worker derives the model again.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "app/plant/lpy_objects.hpp"
#include "app/plant/lsys_curves.hpp"
#include "app/plant/vlab_edit.hpp"
#include "app/viewer/window/curve_canvas.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "lpy/lpy.hpp"

namespace sprout::viewer::detail {
namespace {

// The text's curves, read again only when the text changes (the panel asks every frame).
const std::vector<LpyCurve>& curvesOf(const std::string& text) {
    static std::string read;
    static std::vector<LpyCurve> curves;
    if (text != read) read = text, curves = lpyCurves(text);
    return curves;
}

const char* kindName(const LpyCurve& c) {
    switch (c.kind) {
        case LpyCurve::Kind::Bezier: return "Bezier";
        case LpyCurve::Kind::Polyline: return "polyline";
        default: return "NURBS";
    }
}

CurveRules rulesOf(const LpyCurve& c) {
    CurveRules r;
    r.function = c.function;
    // PlantGL reads a NURBS of fewer points than its degree + 1 no more.
    r.fewest = c.kind == LpyCurve::Kind::Nurbs ? size_t(std::max(c.degree, 1)) + 1 : 2;
    return r;
}

// Writes points into the curve `name` names (lpyCurveNamed: NAME, or NAME#k an earlier
// version) in the text the app has now.
bool writeCurve(App& app, const std::string& name, const CurvePoints& pts, std::uint64_t gesture) {
    const LpyCurve* c = lpyCurveNamed(curvesOf(app.state.text()), name);
    if (!c) return false;
    app.state.setText(setLpyCurvePoints(app.state.text(), *c, pts), gesture);
    return true;
}

EditedCurve edited(App& app, const LpyCurve& c, const std::string& key) {
    EditedCurve e;
    e.key = "lpy:" + key;
    e.points = c.points;
    e.rules = rulesOf(c);
    e.weights = c.kind == LpyCurve::Kind::Nurbs;
    const int kind = int(c.kind), degree = c.degree;
    e.samples = [kind, degree](const CurvePoints& pts) { return lpy::curveSamples(kind, degree, pts, 120); };
    e.write = [&app, key](const CurvePoints& pts, std::uint64_t g) { return writeCurve(app, key, pts, g); };
    return e;
}

// A VLab object's functions and contours, read again when the file or what the editor wrote
// changes (`version`), and the history of the editor's writes.
struct VlabCurves {
    std::string path;
    std::uint64_t version = 0, readAt = ~std::uint64_t(0);
    std::vector<VlabCurveFile> files;
    FileEdits edits;
    std::string open;
};

VlabCurves& vlab() {
    static VlabCurves v;
    return v;
}

const std::vector<VlabCurveFile>& vlabFilesOf(App& app) {
    VlabCurves& v = vlab();
    const std::string path = app.state.path().string();
    if (path != v.path || v.readAt != v.version) {
        if (path != v.path) v.edits = FileEdits{};  // another model: its own history
        v.path = path, v.readAt = v.version;
        v.files = path.empty() ? std::vector<VlabCurveFile>{} : vlabCurveFiles(path);
    }
    return v.files;
}

// Writes new points into file `f` (by the editor or the script), one undo step a gesture.
bool writeVlabCurve(App& app, const VlabCurveFile& f, const CurvePoints& pts, std::uint64_t gesture) {
    std::string error;
    const std::optional<std::string> text = vlabCurveText(f, pts, error);
    if (!text) {
        app.say(f.label + ": " + error);
        return false;
    }
    return writeObjectFile(app, f.path, *text, gesture);
}

EditedCurve edited(App& app, const VlabCurveFile& f) {
    EditedCurve e;
    e.key = "vlab:" + f.path + ":" + std::to_string(f.item);
    e.points = f.points;
    e.rules = f.rules;
    e.samples = [f](const CurvePoints& pts) { return vlabCurveSamples(f, pts); };
    e.write = [&app, f](const CurvePoints& pts, std::uint64_t g) { return writeVlabCurve(app, f, pts, g); };
    return e;
}

// A .lsys grammar's functions and contours (app/plant/lsys_curves.hpp), drawn as the parser
// makes them (a function's ends repeated three times, cpfg's B-spline; a contour resampled).
const LsysCurve* lsysCurveNamed(const std::vector<LsysCurve>& all, const std::string& name) {
    for (const LsysCurve& c : all)
        if (c.name == name) return &c;
    return nullptr;
}

CurveRules rulesOf(const LsysCurve& c) {
    CurveRules r;
    r.function = c.function, r.closed = !c.function && c.closed;
    r.fewest = c.function ? 2 : c.closed ? 3 : 4;
    r.newWeight = 1;
    return r;
}

bool writeLsysCurve(App& app, const std::string& name, const CurvePoints& pts, std::uint64_t gesture) {
    const auto all = lsysCurves(app.state.text());
    const LsysCurve* c = lsysCurveNamed(all, name);
    if (!c) return false;
    app.state.setText(setLsysCurvePoints(app.state.text(), *c, pts), gesture);
    return true;
}

EditedCurve edited(App& app, const LsysCurve& c) {
    EditedCurve e;
    e.key = "lsys:" + c.name + (c.function ? "f" : "c");
    e.points = c.points;
    e.rules = rulesOf(c);
    VlabCurveFile f;
    f.kind = c.function ? VlabCurveFile::Kind::Function : VlabCurveFile::Kind::Contour;
    f.rules = e.rules, f.samples = 64;
    e.samples = [f](const CurvePoints& pts) {
        CurvePoints m = pts;
        if (f.kind == VlabCurveFile::Kind::Function && !m.empty()) m.front()[2] = m.back()[2] = 3;  // as the parser repeats the ends
        return vlabCurveSamples(f, m);
    };
    e.write = [&app, name = c.name](const CurvePoints& pts, std::uint64_t g) { return writeLsysCurve(app, name, pts, g); };
    return e;
}

}  // namespace

bool hasLsysCurves(App& app) { return !lsysCurves(app.state.text()).empty(); }

void lsysCurveSection(App& app) {
    static std::string open;
    const auto all = lsysCurves(app.state.text());
    if (!lsysCurveNamed(all, open)) open = all.front().name;
    for (const LsysCurve& c : all) {
        char label[160];
        std::snprintf(label, sizeof label, "%s  (%s, %zu points)", c.name.c_str(),
                      c.function ? "function" : c.closed ? "closed contour" : "open contour", c.points.size());
        if (curveRow(label, open == c.name, edited(app, c).samples(c.points))) open = c.name;
    }
    if (const LsysCurve* c = lsysCurveNamed(all, open)) {
        ImGui::PushID(c->name.c_str());
        curveCanvas(app, edited(app, *c));
        ImGui::PopID();
    }
}

bool writeObjectFile(App& app, const std::string& path, const std::string& bytes, std::uint64_t gesture) {
    vlabFilesOf(app);  // another model: its own history first
    std::string error;
    if (!vlab().edits.write(path, bytes, gesture, error)) {
        app.say(path + ": " + error);
        return false;
    }
    ++vlab().version;
    app.state.filesChanged();
    return true;
}

std::uint64_t objectFilesVersion() { return vlab().version; }

bool hasVlabCurves(App& app) { return !vlabFilesOf(app).empty(); }

void vlabCurveSection(App& app) {
    VlabCurves& v = vlab();
    const auto files = vlabFilesOf(app);  // a copy: a write reads them again
    if (std::none_of(files.begin(), files.end(), [&](const VlabCurveFile& f) { return f.label == v.open; })) v.open = files.front().label;
    const VlabCurveFile* shown = nullptr;
    for (const VlabCurveFile& f : files) {
        char label[200];
        std::snprintf(label, sizeof label, "%s  (%s, %zu points)", f.label.c_str(),
                      f.kind == VlabCurveFile::Kind::Function ? "function" : f.rules.closed ? "closed contour" : "open contour", f.points.size());
        if (curveRow(label, v.open == f.label, vlabCurveSamples(f, f.points))) v.open = f.label;
        if (v.open == f.label) shown = &f;
    }
    if (ImGui::SmallButton("undo##files")) objectUndo(app, false);
    ImGui::SameLine();
    if (ImGui::SmallButton("redo##files")) objectUndo(app, true);
    ImGui::SameLine();
    ImGui::TextColored(kDim, "saved in the object's files as VLab's editors write them");
    if (!shown) return;
    ImGui::PushID(shown->label.c_str());
    curveCanvas(app, edited(app, *shown));
    if (shown->kind == VlabCurveFile::Kind::Function) {  // funcedit's table of samples (0: the curve itself)
        int samples = shown->samples;
        ImGui::SetNextItemWidth(120);
        if (ImGui::InputInt("samples", &samples, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue)) {
            std::string error;
            if (auto text = vlabFunctionSamplesText(*shown, std::clamp(samples, 0, 10000), error)) writeObjectFile(app, shown->path, *text, newGesture());
            else app.say(error);
        }
        ImGui::SameLine();
        ImGui::TextColored(kDim, "(funcedit's table; 0: the curve)");
    }
    ImGui::PopID();
}

std::vector<std::string> objectCurves(App& app) {
    std::vector<std::string> out;
    for (const VlabCurveFile& f : vlabFilesOf(app)) {
        std::string line = "object-curve=" + f.label + " points=";
        for (size_t i = 0; i < f.points.size(); ++i) {
            char buf[100];
            std::snprintf(buf, sizeof buf, "%s%.9g,%.9g,%g", i ? ";" : "", f.points[i][0], f.points[i][1], f.points[i][2]);
            line += buf;
        }
        out.push_back(line);
    }
    return out;
}

bool moveObjectPoint(App& app, size_t which, size_t k, double x, double y, std::uint64_t gesture) {
    const auto files = vlabFilesOf(app);
    if (which >= files.size() || k >= files[which].points.size()) return false;
    const VlabCurveFile& f = files[which];
    return writeVlabCurve(app, f, movedPoint(f.points, f.rules, k, x, y), gesture ? gesture : newGesture());
}

bool objectUndo(App& app, bool redo) {
    std::string error;
    const bool done = redo ? vlab().edits.redo(error) : vlab().edits.undo(error);
    if (!error.empty()) app.say(error);
    if (done) {
        ++vlab().version;
        app.state.filesChanged();
    }
    return done;
}

std::uint64_t newGesture() {
    static std::uint64_t last = 0;
    return ++last;
}

bool moveCurvePoint(App& app, const std::string& name, size_t k, double x, double y, std::uint64_t gesture) {
    const LpyCurve* c = lpyCurveNamed(curvesOf(app.state.text()), name);
    if (!c) {  // a .lsys grammar's function or contour
        const auto all = lsysCurves(app.state.text());
        const LsysCurve* l = lsysCurveNamed(all, name);
        return l && k < l->points.size() && writeLsysCurve(app, name, movedPoint(l->points, rulesOf(*l), k, x, y), gesture);
    }
    if (k >= c->points.size()) return false;
    return writeCurve(app, name, movedPoint(c->points, rulesOf(*c), k, x, y), gesture);
}

bool nudgeCurvePoint(App& app, const std::string& name, size_t k, double dx, double dy, std::uint64_t gesture) {
    const LpyCurve* c = lpyCurveNamed(curvesOf(app.state.text()), name);
    if (!c || k >= c->points.size()) return false;
    const double x = c->points[k][0] + dx, y = c->points[k][1] + dy;  // (c is the cache's: read before it moves)
    return moveCurvePoint(app, name, k, x, y, gesture);
}

std::string editCurve(App& app, const std::string& name, const std::string& op, double a, double b) {
    const LpyCurve* c = lpyCurveNamed(curvesOf(app.state.text()), name);
    if (!c) return "no curve " + name;
    const CurveRules rules = rulesOf(*c);
    std::optional<CurvePoints> pts;
    if (op == "add") pts = insertedPoint(c->points, rules, size_t(a));
    else if (op == "delete") pts = removedPoint(c->points, rules, size_t(a));
    else if (op == "weight") pts = c->kind == LpyCurve::Kind::Nurbs ? weightedPoint(c->points, size_t(a), b) : std::nullopt;
    else return "no edit " + op;
    if (!pts) return op + " refused: the curve would not be one L-Py reads";
    writeCurve(app, name, *pts, newGesture());
    return "";
}

std::string presetCurve(App& app, const std::string& name, const std::string& preset) {
    const LpyCurve* c = lpyCurveNamed(curvesOf(app.state.text()), name);
    if (!c) return "no curve " + name;
    const auto p = curvePresetNamed(preset);
    if (!p) return "no preset " + preset + " (line, arc, circle, s)";
    const auto pts = presetPoints(*p, rulesOf(*c), c->points.size());
    if (!pts) return "no " + preset + " for a function";
    writeCurve(app, name, *pts, newGesture());
    return "";
}

bool hasLpyCurves(App& app) { return !curvesOf(app.state.text()).empty(); }

namespace {
std::string& openLpyCurve() {
    static std::string open;
    return open;
}
}  // namespace

void openCurve(App& app, const std::string& name) {
    if (name.rfind("object:", 0) == 0) {
        const size_t i = size_t(std::atoi(name.c_str() + 7));
        if (i < vlabFilesOf(app).size()) vlab().open = vlabFilesOf(app)[i].label;
    } else {
        openLpyCurve() = name;
    }
}

void curveSection(App& app) {
    std::string& open = openLpyCurve();
    // Every version of a name several panels set, each by its key (NAME for the last, which
    // the model uses; NAME#k for an earlier one, which only its panel shows in Studio).
    const std::vector<LpyCurve> curves = curvesOf(app.state.text());  // a copy: a write reads them again
    std::vector<std::string> keys;
    for (size_t i = 0; i < curves.size(); ++i) keys.push_back(lpyCurveKey(curves, i));
    if (!keys.empty() && std::find(keys.begin(), keys.end(), open) == keys.end())
        open = keys.front();  // the first curve open at first (and when the one open is gone)
    size_t shown = curves.size();
    std::string panel = "\x01";
    for (size_t i = 0; i < curves.size(); ++i) {  // grouped by the model's panels, as L-Py Studio shows them
        const LpyCurve& c = curves[i];
        if (c.panel != panel) {
            panel = c.panel;
            ImGui::TextColored(kDim, "%s", panel.empty() ? "(in no panel)" : panel.c_str());
        }
        char label[200];
        std::snprintf(label, sizeof label, "%s  (%s%s, %zu points%s)", c.name.c_str(), kindName(c), c.function ? " function" : "",
                      c.points.size(), keys[i] == c.name ? "" : "; an earlier version: the model uses the last");
        if (curveRow(label, open == keys[i], lpy::curveSamples(int(c.kind), c.degree, c.points, 40))) open = keys[i];
        if (open == keys[i]) shown = i;
    }
    if (shown == curves.size()) return;
    ImGui::PushID(keys[shown].c_str());
    curveCanvas(app, edited(app, curves[shown], keys[shown]));
    ImGui::PopID();
}

}  // namespace sprout::viewer::detail
