// The panel's curve editor (issue 52): an L-Py model's 2D curves (app/plant/lpy_objects.hpp),
// each drawn as PlantGL evaluates it (lpy::curveSamples) over a grid, with its control polygon.
// A control point dragged with the mouse moves in the model's text (its INITIALISATION part,
// as L-Py Studio writes it), and the worker derives the model again while the point moves.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/plant/lpy_objects.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "lpy/lpy.hpp"

namespace sprout::viewer::detail {
namespace {

// What the editor keeps between frames: the curve shown, the point held, and the view, which
// stays as it is while a point moves (fit again with the button or another curve).
struct CurveView {
    std::string open;
    int held = -1;
    std::uint64_t gesture = 0;  // the drag's (one undo step)
    bool fitted = false;
    double cx = 0, cy = 0, scale = 100;  // the world point at the canvas's centre; pixels a unit
};

CurveView& view() {
    static CurveView v;
    return v;
}

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

void fit(CurveView& v, const LpyCurve& c, ImVec2 size) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& p : c.points)
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[size_t(k)]), hi[k] = std::max(hi[k], p[size_t(k)]);
    if (c.function) lo[0] = std::min(lo[0], 0.0), hi[0] = std::max(hi[0], 1.0);
    const double w = std::max(hi[0] - lo[0], 1e-6), h = std::max(hi[1] - lo[1], 1e-6);
    v.cx = (lo[0] + hi[0]) / 2;
    v.cy = (lo[1] + hi[1]) / 2;
    v.scale = std::min(size.x / (w * 1.25), size.y / (h * 1.25));
    v.fitted = true;
}

// A grid step of about 40 pixels: 1, 2 or 5 times a power of ten.
double gridStep(double scale) {
    const double raw = 40 / std::max(scale, 1e-12), p = std::pow(10.0, std::floor(std::log10(raw)));
    return raw <= p ? p : raw <= 2 * p ? 2 * p : raw <= 5 * p ? 5 * p : 10 * p;
}

// Point k at (x, y): a function's points keep their order along x, its ends at 0 and 1.
std::vector<std::array<double, 3>> moved(const LpyCurve& c, size_t k, double x, double y) {
    std::vector<std::array<double, 3>> pts = c.points;
    if (c.function) {
        const double left = k == 0 ? 0 : pts[k - 1][0], right = k + 1 == pts.size() ? 1 : pts[k + 1][0];
        x = k == 0 ? 0 : k + 1 == pts.size() ? 1 : std::clamp(x, left, right);
    }
    pts[k][0] = x;
    pts[k][1] = y;
    return pts;
}

void canvas(App& app, const LpyCurve& c) {
    CurveView& v = view();
    const float width = std::max(160.0f, ImGui::GetContentRegionAvail().x);
    const ImVec2 size(width, std::round(width * 0.7f)), origin = ImGui::GetCursorScreenPos();
    auto outside = [&](const std::array<double, 3>& p) {  // more than the canvas's half from its centre
        return std::fabs(p[0] - v.cx) * v.scale > size.x / 2 || std::fabs(p[1] - v.cy) * v.scale > size.y / 2;
    };
    // Fit when first shown, and, while no point is held, when one is out of the view (moved by
    // the text or a script).
    if (!v.fitted || (v.held < 0 && std::any_of(c.points.begin(), c.points.end(), outside))) fit(v, c, size);
    ImGui::InvisibleButton("##curve", size);
    const bool pressed = ImGui::IsItemActivated(), active = ImGui::IsItemActive();
    auto screen = [&](double x, double y) {
        return ImVec2(origin.x + size.x / 2 + float((x - v.cx) * v.scale), origin.y + size.y / 2 - float((y - v.cy) * v.scale));
    };
    const ImGuiIO& io = ImGui::GetIO();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(28, 30, 34, 255));
    // The grid, its axes brighter.
    const double step = gridStep(v.scale), halfW = size.x / 2 / v.scale, halfH = size.y / 2 / v.scale;
    for (double x = std::floor((v.cx - halfW) / step) * step; x <= v.cx + halfW; x += step)
        dl->AddLine(screen(x, v.cy - halfH), screen(x, v.cy + halfH), std::fabs(x) < step / 2 ? IM_COL32(110, 110, 120, 255) : IM_COL32(50, 52, 58, 255));
    for (double y = std::floor((v.cy - halfH) / step) * step; y <= v.cy + halfH; y += step)
        dl->AddLine(screen(v.cx - halfW, y), screen(v.cx + halfW, y), std::fabs(y) < step / 2 ? IM_COL32(110, 110, 120, 255) : IM_COL32(50, 52, 58, 255));
    if (c.function) {  // the function's range of x
        dl->AddLine(screen(0, v.cy - halfH), screen(0, v.cy + halfH), IM_COL32(90, 140, 90, 255));
        dl->AddLine(screen(1, v.cy - halfH), screen(1, v.cy + halfH), IM_COL32(90, 140, 90, 255));
    }
    // The control polygon, the curve, the points.
    std::vector<ImVec2> poly;
    for (const auto& p : c.points) poly.push_back(screen(p[0], p[1]));
    dl->AddPolyline(poly.data(), int(poly.size()), IM_COL32(120, 120, 140, 255), ImDrawFlags_None, 1.0f);
    std::vector<ImVec2> line;
    for (const auto& p : lpy::curveSamples(int(c.kind), c.degree, c.points, 120)) line.push_back(screen(p[0], p[1]));
    if (line.size() >= 2) dl->AddPolyline(line.data(), int(line.size()), IM_COL32(120, 220, 120, 255), ImDrawFlags_None, 2.0f);
    int nearest = -1;
    float best = 9.0f * 9.0f;
    for (size_t k = 0; k < poly.size(); ++k) {
        const float dx = poly[k].x - io.MousePos.x, dy = poly[k].y - io.MousePos.y;
        if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, nearest = int(k);
    }
    for (size_t k = 0; k < poly.size(); ++k) {
        const bool lit = int(k) == (v.held >= 0 ? v.held : nearest);
        dl->AddCircleFilled(poly[k], lit ? 6.0f : 4.5f, lit ? IM_COL32(255, 200, 80, 255) : IM_COL32(230, 230, 240, 255));
    }
    dl->PopClipRect();
    // A press on a point holds it; the point follows the mouse until the button is let go.
    if (pressed) v.held = nearest, v.gesture = newGesture();
    if (!active) v.held = -1;
    if (active && v.held >= 0 && size_t(v.held) < c.points.size() && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        const double x = v.cx + (io.MousePos.x - origin.x - size.x / 2) / v.scale;
        const double y = v.cy - (io.MousePos.y - origin.y - size.y / 2) / v.scale;
        app.state.setText(setLpyCurvePoints(app.state.text(), c, moved(c, size_t(v.held), x, y)), v.gesture);
    }
    if (v.held >= 0 && size_t(v.held) < c.points.size())
        ImGui::Text("point %d: %.4g, %.4g", v.held, c.points[size_t(v.held)][0], c.points[size_t(v.held)][1]);
    else
        ImGui::TextColored(kDim, "drag a point: the model grows again as it moves");
}

}  // namespace

std::uint64_t newGesture() {
    static std::uint64_t last = 0;
    return ++last;
}

bool moveCurvePoint(App& app, const std::string& name, size_t k, double x, double y, std::uint64_t gesture) {
    const LpyCurve* c = lastLpyCurve(curvesOf(app.state.text()), name);
    if (!c || k >= c->points.size()) return false;
    const std::string text = setLpyCurvePoints(app.state.text(), *c, moved(*c, k, x, y));
    app.state.setText(text, gesture);
    return true;
}

bool nudgeCurvePoint(App& app, const std::string& name, size_t k, double dx, double dy, std::uint64_t gesture) {
    const LpyCurve* c = lastLpyCurve(curvesOf(app.state.text()), name);
    if (!c || k >= c->points.size()) return false;
    const double x = c->points[k][0] + dx, y = c->points[k][1] + dy;  // (c is the cache's: read before it moves)
    return moveCurvePoint(app, name, k, x, y, gesture);
}

bool hasLpyCurves(App& app) { return !curvesOf(app.state.text()).empty(); }

void curveSection(App& app) {
    // A name several panels set: only the version lastLpyCurve names is listed and edited.
    std::vector<LpyCurve> curves;
    for (const LpyCurve& c : curvesOf(app.state.text()))
        if (lastLpyCurve(curvesOf(app.state.text()), c.name) == &c) curves.push_back(c);
    CurveView& v = view();
    const LpyCurve* shown = nullptr;
    if (!curves.empty() && std::none_of(curves.begin(), curves.end(), [&](const LpyCurve& c) { return c.name == v.open; })) {
        v.open = curves.front().name;  // the first curve open at first (and when the one open is gone)
        v.fitted = false;
        v.held = -1;
    }
    for (const LpyCurve& c : curves) {
        char label[160];
        std::snprintf(label, sizeof label, "%s  (%s%s, %zu points)", c.name.c_str(), kindName(c), c.function ? " function" : "",
                      c.points.size());
        if (ImGui::Selectable(label, v.open == c.name) && v.open != c.name) {
            v.open = c.name;
            v.fitted = false;
            v.held = -1;
        }
        if (v.open == c.name) shown = &c;
    }
    if (!shown) return;
    if (ImGui::SmallButton("fit")) v.fitted = false;
    ImGui::PushID(shown->name.c_str());
    canvas(app, *shown);
    ImGui::PopID();
}

}  // namespace sprout::viewer::detail
