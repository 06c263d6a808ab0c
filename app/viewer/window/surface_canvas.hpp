#pragma once
// Private to app/viewer: the panel's surface editor (issue 52): a patch's control net and the
// surface as its tool evaluates it, in a small 3D view drawn with Dear ImGui's draw list. The
// left button drags a control point in the view's plane (a whole drag is one undo step); the
// right button (or the left away from the points) turns the view.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/window/app.hpp"

namespace sprout::viewer::detail {

using PatchGrid = std::vector<std::vector<std::array<double, 3>>>;  // [u][v]

struct EditedSurface {
    std::string key;
    PatchGrid points;
    std::function<PatchGrid(const PatchGrid&)> samples;  // the surface through `points`, [u][v]
    std::function<bool(const PatchGrid&, std::uint64_t gesture)> write;
};

void surfaceCanvas(App& app, const EditedSurface& surface);
// Where control point (u, v) of the surface open was drawn last frame, in window pixels; the
// panel scrolls to the editor on the next frame. Null: none.
std::optional<std::array<float, 2>> surfacePointOnScreen(std::size_t u, std::size_t v);
// The control point (u, v) last taken hold of in the editor of the surface `key`, ringed: the
// one the row, column and weight tools act on; none before one is. Scripts choose one.
std::optional<std::array<std::size_t, 2>> selectedSurfacePoint(const std::string& key);
void selectSurfacePoint(std::size_t u, std::size_t v);

}  // namespace sprout::viewer::detail
