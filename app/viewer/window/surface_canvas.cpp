// The panel's surface editor (surface_canvas.hpp): an orthographic view turned by yaw and
// pitch, the control net, iso lines of the surface, the points; a point dragged moves along
// the view's right and up.
#include "app/viewer/window/surface_canvas.hpp"

#include <algorithm>
#include <cmath>

#include "app/viewer/window/panel_sections.hpp"

namespace sprout::viewer::detail {
namespace {

struct SurfaceView {
    std::string key;
    float yaw = 35, pitch = 25;  // degrees
    double cx = 0, cy = 0, cz = 0, scale = 100;
    bool fitted = false, reveal = false;
    int heldU = -1, heldV = -1;
    int selU = -1, selV = -1;  // the point last taken hold of (the row, column and weight tools')
    std::uint64_t gesture = 0;
    std::vector<std::vector<ImVec2>> drawn;
};

SurfaceView& view() {
    static SurfaceView v;
    return v;
}

// The view's axes in the world: right, up (z up at pitch 0), and depth.
std::array<std::array<double, 3>, 2> axes(const SurfaceView& v) {
    const double y = v.yaw * M_PI / 180, p = v.pitch * M_PI / 180;
    const std::array<double, 3> right{std::cos(y), std::sin(y), 0};
    const std::array<double, 3> up{-std::sin(p) * -std::sin(y), -std::sin(p) * std::cos(y), std::cos(p)};
    return {right, up};
}

ImVec2 project(const SurfaceView& v, const std::array<double, 3>& q, ImVec2 origin, ImVec2 size) {
    const auto [r, u] = axes(v);
    const double d[3] = {q[0] - v.cx, q[1] - v.cy, q[2] - v.cz};
    const double x = d[0] * r[0] + d[1] * r[1] + d[2] * r[2], y = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    return ImVec2(origin.x + size.x / 2 + float(x * v.scale), origin.y + size.y / 2 - float(y * v.scale));
}

void fit(SurfaceView& v, const PatchGrid& g, ImVec2 size) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& row : g)
        for (const auto& p : row)
            for (size_t c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
    v.cx = (lo[0] + hi[0]) / 2, v.cy = (lo[1] + hi[1]) / 2, v.cz = (lo[2] + hi[2]) / 2;
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-6});
    v.scale = std::min(size.x, size.y) / (extent * 1.4);
    v.fitted = true;
}

}  // namespace

std::optional<std::array<std::size_t, 2>> selectedSurfacePoint(const std::string& key) {
    const SurfaceView& v = view();
    if (v.key != key || v.selU < 0) return std::nullopt;
    return std::array<std::size_t, 2>{std::size_t(v.selU), std::size_t(v.selV)};
}

void selectSurfacePoint(std::size_t u, std::size_t w) { view().selU = int(u), view().selV = int(w); }

std::optional<std::array<float, 2>> surfacePointOnScreen(std::size_t u, std::size_t w) {
    SurfaceView& v = view();
    v.reveal = true;
    if (u >= v.drawn.size() || w >= v.drawn[u].size()) return std::nullopt;
    return std::array<float, 2>{v.drawn[u][w].x, v.drawn[u][w].y};
}

void surfaceCanvas(App& app, const EditedSurface& s) {
    (void)app;
    SurfaceView& v = view();
    if (v.key != s.key) {
        const bool reveal = v.reveal;
        v = SurfaceView{};
        v.key = s.key, v.reveal = reveal;
    }
    const float width = std::max(160.0f, ImGui::GetContentRegionAvail().x);
    const ImVec2 size(width, std::round(width * 0.75f)), origin = ImGui::GetCursorScreenPos();
    if (!v.fitted) fit(v, s.points, size);
    if (v.reveal) ImGui::SetScrollHereY(0.1f), v.reveal = false;
    ImGui::InvisibleButton("##surface", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool pressed = ImGui::IsItemActivated(), active = ImGui::IsItemActive();
    const ImGuiIO& io = ImGui::GetIO();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(28, 30, 34, 255));
    // The surface's iso lines, then the control net, then the points.
    const PatchGrid surface = s.samples ? s.samples(s.points) : PatchGrid{};
    for (size_t i = 0; i < surface.size(); ++i) {
        std::vector<ImVec2> a, b;
        for (size_t j = 0; j < surface[i].size(); ++j) a.push_back(project(v, surface[i][j], origin, size));
        for (size_t j = 0; j < surface.size() && i < surface[j].size(); ++j) b.push_back(project(v, surface[j][i], origin, size));
        dl->AddPolyline(a.data(), int(a.size()), IM_COL32(100, 190, 100, 200), ImDrawFlags_None, 1.0f);
        dl->AddPolyline(b.data(), int(b.size()), IM_COL32(100, 190, 100, 200), ImDrawFlags_None, 1.0f);
    }
    v.drawn.assign(s.points.size(), {});
    for (size_t i = 0; i < s.points.size(); ++i)
        for (const auto& p : s.points[i]) v.drawn[i].push_back(project(v, p, origin, size));
    for (size_t i = 0; i < v.drawn.size(); ++i) {
        dl->AddPolyline(v.drawn[i].data(), int(v.drawn[i].size()), IM_COL32(130, 130, 150, 255), ImDrawFlags_None, 1.0f);
        if (i + 1 < v.drawn.size())
            for (size_t j = 0; j < v.drawn[i].size() && j < v.drawn[i + 1].size(); ++j)
                dl->AddLine(v.drawn[i][j], v.drawn[i + 1][j], IM_COL32(130, 130, 150, 255));
    }
    int nu = -1, nv = -1;
    float best = 9.0f * 9.0f;
    for (size_t i = 0; i < v.drawn.size(); ++i)
        for (size_t j = 0; j < v.drawn[i].size(); ++j) {
            const float dx = v.drawn[i][j].x - io.MousePos.x, dy = v.drawn[i][j].y - io.MousePos.y;
            if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, nu = int(i), nv = int(j);
        }
    for (size_t i = 0; i < v.drawn.size(); ++i)
        for (size_t j = 0; j < v.drawn[i].size(); ++j) {
            const bool lit = (int(i) == v.heldU && int(j) == v.heldV) || (v.heldU < 0 && int(i) == nu && int(j) == nv);
            dl->AddCircleFilled(v.drawn[i][j], lit ? 6.0f : 4.0f, lit ? IM_COL32(255, 200, 80, 255) : IM_COL32(230, 230, 240, 255));
            if (int(i) == v.selU && int(j) == v.selV) dl->AddCircle(v.drawn[i][j], 8.0f, IM_COL32(255, 200, 80, 255), 0, 1.5f);
        }
    dl->PopClipRect();
    if (pressed) {
        v.heldU = ImGui::IsMouseDown(ImGuiMouseButton_Left) ? nu : -1;
        v.heldV = v.heldU >= 0 ? nv : -1;
        if (v.heldU >= 0) v.selU = v.heldU, v.selV = v.heldV;
        v.gesture = newGesture();
    }
    if (!active) v.heldU = v.heldV = -1;
    if (active && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        if (v.heldU >= 0 && size_t(v.heldU) < s.points.size() && size_t(v.heldV) < s.points[size_t(v.heldU)].size()) {
            const auto [r, u] = axes(v);
            PatchGrid g = s.points;
            auto& p = g[size_t(v.heldU)][size_t(v.heldV)];
            for (size_t c = 0; c < 3; ++c) p[c] += (io.MouseDelta.x * r[c] - io.MouseDelta.y * u[c]) / v.scale;
            s.write(g, v.gesture);
        } else {  // turning the view
            v.yaw -= io.MouseDelta.x * 0.5f;
            v.pitch = std::clamp(v.pitch + io.MouseDelta.y * 0.5f, -89.0f, 89.0f);
        }
    }
    if (v.heldU >= 0) {
        const auto& p = s.points[size_t(v.heldU)][size_t(v.heldV)];
        ImGui::Text("point %d,%d: %.4g, %.4g, %.4g", v.heldU, v.heldV, p[0], p[1], p[2]);
    } else {
        ImGui::TextColored(kDim, "drag a point to move it; drag elsewhere to turn the view");
    }
    if (ImGui::SmallButton("fit##surface")) v.fitted = false;
}

}  // namespace sprout::viewer::detail
