// The panel's 2D curve editor (app/viewer/window/curve_canvas.hpp): drawn with Dear ImGui's
// draw list; every change goes through app/plant/curve_edit and the curve's own writer.
#include "app/viewer/window/curve_canvas.hpp"

#include "app/render/gl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/image.hpp"
#include "app/viewer/window/panel_sections.hpp"

namespace sprout::viewer::detail {
namespace {

// What the editor keeps between frames: the curve shown, the point held or last held, and the
// view, which stays as it is while a point moves (fit again with the button or another curve).
struct CanvasState {
    std::string key;
    int held = -1, selected = -1;
    std::uint64_t gesture = 0;  // the drag's (one undo step)
    bool fitted = false, snap = false;
    int preset = 0;
    double cx = 0, cy = 0, scale = 100;  // the world point at the canvas's centre; pixels a unit
    double grabX = 0, grabY = 0;         // the held point less the mouse, when pressed
    std::vector<ImVec2> drawn;           // where the points were drawn last
    bool reveal = false;                 // scroll the panel to the canvas
};

CanvasState& state() {
    static CanvasState s;
    return s;
}

// An image under the curve to trace (a leaf's photo), over a rectangle of the curve's plane.
struct Trace {
    std::string path;
    unsigned texture = 0;
    int width = 0, height = 0;
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    float opacity = 0.6f;
    bool place = false;  // fit to the view on the next frame
    char input[512] = "";
};

Trace& trace() {
    static Trace t;
    return t;
}

void fit(CanvasState& v, const EditedCurve& c, ImVec2 size) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& p : c.points)
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[size_t(k)]), hi[k] = std::max(hi[k], p[size_t(k)]);
    if (c.rules.function) lo[0] = std::min(lo[0], 0.0), hi[0] = std::max(hi[0], 1.0);
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

// The grid (its axes brighter; a function's range of x in green), the control polygon, the
// curve and the points, `lit` brighter.
void draw(const CanvasState& v, const EditedCurve& c, ImVec2 origin, ImVec2 size, int lit) {
    auto screen = [&](double x, double y) {
        return ImVec2(origin.x + size.x / 2 + float((x - v.cx) * v.scale), origin.y + size.y / 2 - float((y - v.cy) * v.scale));
    };
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(28, 30, 34, 255));
    if (Trace& t = trace(); t.texture) {
        if (t.place) {  // the image fitted in the view's middle, its aspect kept
            const double w = size.x / v.scale * 0.8, h = w * t.height / std::max(t.width, 1);
            const double k = std::min(1.0, size.y / v.scale * 0.8 / h);
            t.x0 = v.cx - w * k / 2, t.x1 = v.cx + w * k / 2, t.y0 = v.cy - h * k / 2, t.y1 = v.cy + h * k / 2;
            t.place = false;
        }
        dl->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t.texture)), screen(t.x0, t.y1), screen(t.x1, t.y0), ImVec2(0, 0),
                     ImVec2(1, 1), IM_COL32(255, 255, 255, int(t.opacity * 255)));
    }
    const double step = gridStep(v.scale), halfW = size.x / 2 / v.scale, halfH = size.y / 2 / v.scale;
    for (double x = std::floor((v.cx - halfW) / step) * step; x <= v.cx + halfW; x += step)
        dl->AddLine(screen(x, v.cy - halfH), screen(x, v.cy + halfH), std::fabs(x) < step / 2 ? IM_COL32(110, 110, 120, 255) : IM_COL32(50, 52, 58, 255));
    for (double y = std::floor((v.cy - halfH) / step) * step; y <= v.cy + halfH; y += step)
        dl->AddLine(screen(v.cx - halfW, y), screen(v.cx + halfW, y), std::fabs(y) < step / 2 ? IM_COL32(110, 110, 120, 255) : IM_COL32(50, 52, 58, 255));
    if (c.rules.function) {
        dl->AddLine(screen(0, v.cy - halfH), screen(0, v.cy + halfH), IM_COL32(90, 140, 90, 255));
        dl->AddLine(screen(1, v.cy - halfH), screen(1, v.cy + halfH), IM_COL32(90, 140, 90, 255));
    }
    std::vector<ImVec2> poly;
    for (const auto& p : c.points) poly.push_back(screen(p[0], p[1]));
    state().drawn = poly;
    dl->AddPolyline(poly.data(), int(poly.size()), IM_COL32(120, 120, 140, 255), c.rules.closed ? ImDrawFlags_Closed : ImDrawFlags_None, 1.0f);
    std::vector<ImVec2> line;
    if (c.samples)
        for (const auto& p : c.samples(c.points)) line.push_back(screen(p[0], p[1]));
    if (line.size() >= 2) dl->AddPolyline(line.data(), int(line.size()), IM_COL32(120, 220, 120, 255), ImDrawFlags_None, 2.0f);
    for (size_t k = 0; k < poly.size(); ++k) {
        const bool on = int(k) == lit;
        dl->AddCircleFilled(poly[k], on ? 6.0f : 4.5f, on ? IM_COL32(255, 200, 80, 255) : IM_COL32(230, 230, 240, 255));
    }
    dl->PopClipRect();
}

// Under the canvas: the selected point's numbers and weight, taking it away, snapping,
// presets, fit.
void tools(CanvasState& v, const EditedCurve& c) {
    const size_t k = size_t(v.selected);
    if (v.selected >= 0 && k < c.points.size()) {
        ImGui::Text("point %d: %.4g, %.4g", v.selected, c.points[k][0], c.points[k][1]);
        if (c.weights) {
            float w = float(c.points[k][2]);
            ImGui::SetNextItemWidth(120);
            const bool changed = ImGui::DragFloat("weight", &w, 0.01f, 0.01f, 100.0f, "%.3g", ImGuiSliderFlags_AlwaysClamp);
            if (ImGui::IsItemActivated()) v.gesture = newGesture();  // a whole drag of it: one undo step
            if (changed)
                if (auto pts = weightedPoint(c.points, k, double(w))) c.write(*pts, v.gesture);
            ImGui::SameLine();
        }
        if (ImGui::SmallButton("delete point"))
            if (auto pts = removedPoint(c.points, c.rules, k)) c.write(*pts, newGesture()), v.selected = -1;
        ImGui::SameLine();
        if (ImGui::SmallButton("add after"))
            if (auto pts = insertedPoint(c.points, c.rules, k)) c.write(*pts, newGesture()), v.selected = int(k) + 1;
    } else {
        ImGui::TextColored(kDim, "drag a point; double-click adds one, right-click deletes");
    }
    ImGui::Checkbox("snap to grid", &v.snap);
    ImGui::SameLine();
    if (ImGui::SmallButton("fit")) v.fitted = false;
    static const char* names[] = {"line", "arc", "circle", "S"};
    ImGui::SetNextItemWidth(90);
    ImGui::Combo("##preset", &v.preset, names, c.rules.function ? 2 : 4);
    ImGui::SameLine();
    if (ImGui::SmallButton("set to preset"))
        if (auto pts = presetPoints(CurvePreset(v.preset), c.rules, c.points.size())) {
            c.write(*pts, newGesture());
            v.fitted = false, v.selected = -1;
        }
    // An image to trace under the curve: a PNG (a leaf's photo), fitted to the view.
    Trace& t = trace();
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - 140));
    ImGui::InputTextWithHint("##trace", "an image to trace (a PNG's path)", t.input, sizeof t.input);
    ImGui::SameLine();
    if (ImGui::SmallButton("trace"))
        if (std::string why = loadTraceImage(t.input); !why.empty()) ImGui::OpenPopup("trace error"), t.path = why;
    if (t.texture) {
        ImGui::SameLine();
        if (ImGui::SmallButton("clear")) glDeleteTextures(1, &t.texture), t.texture = 0;
        ImGui::SetNextItemWidth(120);
        ImGui::SliderFloat("image opacity", &t.opacity, 0.05f, 1.0f, "%.2f");
        ImGui::SameLine();
        if (ImGui::SmallButton("fit image")) t.place = true;
    }
    if (ImGui::BeginPopup("trace error")) {
        ImGui::TextColored(kError, "%s", t.path.c_str());
        ImGui::EndPopup();
    }
}

}  // namespace

void refitCurveCanvas() { state().fitted = false; }

bool curveRow(const char* label, bool selected, const std::vector<std::array<double, 2>>& samples) {
    const ImVec2 thumb(56, 32), at = ImGui::GetCursorScreenPos();
    ImGui::PushID(label);
    const bool clicked = ImGui::Selectable("##row", selected, 0, ImVec2(0, thumb.y));
    ImGui::PopID();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(at, ImVec2(at.x + thumb.x, at.y + thumb.y), IM_COL32(28, 30, 34, 255));
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& p : samples)
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[size_t(k)]), hi[k] = std::max(hi[k], p[size_t(k)]);
    const double scale = std::min((thumb.x - 6) / std::max(hi[0] - lo[0], 1e-9), (thumb.y - 6) / std::max(hi[1] - lo[1], 1e-9));
    std::vector<ImVec2> line;
    for (const auto& p : samples)
        line.push_back(ImVec2(at.x + thumb.x / 2 + float((p[0] - (lo[0] + hi[0]) / 2) * scale),
                              at.y + thumb.y / 2 - float((p[1] - (lo[1] + hi[1]) / 2) * scale)));
    if (line.size() >= 2) dl->AddPolyline(line.data(), int(line.size()), IM_COL32(120, 220, 120, 255), ImDrawFlags_None, 1.5f);
    dl->AddText(ImVec2(at.x + thumb.x + 8, at.y + (thumb.y - ImGui::GetTextLineHeight()) / 2), ImGui::GetColorU32(ImGuiCol_Text), label);
    return clicked;
}

std::string loadTraceImage(const std::string& path) {
    Trace& t = trace();
    Image img;
    std::string error;
    if (!readPng(path, img, error)) return path + ": " + error;
    if (!t.texture) glGenTextures(1, &t.texture);
    glBindTexture(GL_TEXTURE_2D, t.texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    t.path = path, t.width = img.width, t.height = img.height, t.place = true;
    return "";
}

std::array<int, 2> traceImageSize() { return {trace().width, trace().height}; }

std::optional<std::array<float, 2>> curvePointOnScreen(std::size_t k) {
    CanvasState& v = state();
    v.reveal = true;
    if (v.key.empty() || k >= v.drawn.size()) return std::nullopt;
    return std::array<float, 2>{v.drawn[k].x, v.drawn[k].y};
}

void curveCanvas(App& app, const EditedCurve& c) {
    (void)app;
    CanvasState& v = state();
    if (v.key != c.key) v = CanvasState{c.key, -1, -1, 0, false, v.snap, v.preset, 0, 0, 100, 0, 0, {}, v.reveal};
    const float width = std::max(160.0f, ImGui::GetContentRegionAvail().x);
    const ImVec2 size(width, std::round(width * 0.7f)), origin = ImGui::GetCursorScreenPos();
    auto outside = [&](const std::array<double, 3>& p) {  // more than the canvas's half from its centre
        return std::fabs(p[0] - v.cx) * v.scale > size.x / 2 || std::fabs(p[1] - v.cy) * v.scale > size.y / 2;
    };
    // Fit when first shown, and, while no point is held, when one is out of the view (moved by
    // the text or a script).
    if (!v.fitted || (v.held < 0 && std::any_of(c.points.begin(), c.points.end(), outside))) fit(v, c, size);
    if (v.reveal) ImGui::SetScrollHereY(0.1f), v.reveal = false;
    ImGui::InvisibleButton("##curve", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool pressed = ImGui::IsItemActivated(), active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
    const ImGuiIO& io = ImGui::GetIO();
    const double mx = v.cx + (io.MousePos.x - origin.x - size.x / 2) / v.scale;
    const double my = v.cy - (io.MousePos.y - origin.y - size.y / 2) / v.scale;
    int nearest = -1;
    float best = 9.0f * 9.0f;
    for (size_t k = 0; k < c.points.size(); ++k) {
        const float dx = float((c.points[k][0] - mx) * v.scale), dy = float((c.points[k][1] - my) * v.scale);
        if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, nearest = int(k);
    }
    draw(v, c, origin, size, v.held >= 0 ? v.held : nearest >= 0 ? nearest : v.selected);
    auto at = v.snap ? snapped(mx, my, gridStep(v.scale) / 2) : std::array<double, 2>{mx, my};
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right) && nearest >= 0) {  // right click: take the point away
        if (auto pts = removedPoint(c.points, c.rules, size_t(nearest))) c.write(*pts, newGesture());
        v.selected = v.held = -1;
        return tools(v, c);
    }
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && nearest < 0) {  // a point added where clicked
        const size_t seg = nearestSegment(c.points, c.rules, mx, my);
        if (auto pts = insertedPoint(c.points, c.rules, seg)) {
            c.write(movedPoint(*pts, c.rules, seg + 1, at[0], at[1]), newGesture());
            v.selected = int(seg) + 1;
        }
        return tools(v, c);
    }
    // A press on a point holds it; the point follows the mouse until the button is let go.
    if (pressed && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        v.held = nearest, v.gesture = newGesture();
        if (nearest >= 0) v.grabX = c.points[size_t(nearest)][0] - mx, v.grabY = c.points[size_t(nearest)][1] - my;
    }
    if (v.held >= 0 && !v.snap) at = {mx + v.grabX, my + v.grabY};  // the point keeps where it was taken
    if (v.held >= 0) v.selected = v.held;
    if (!active) v.held = -1;
    if (active && v.held >= 0 && size_t(v.held) < c.points.size() && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0))
        c.write(movedPoint(c.points, c.rules, size_t(v.held), at[0], at[1]), v.gesture);
    tools(v, c);
}

}  // namespace sprout::viewer::detail
