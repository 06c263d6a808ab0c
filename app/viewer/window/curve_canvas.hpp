#pragma once
// Private to app/viewer: the panel's 2D curve editor (issue 52), one canvas for every kind of
// curve a model keeps (an L-Py model's curves and functions, a VLab object's functions and
// contours): the curve as its tool evaluates it over a grid, its control polygon and points.
// The mouse drags a point (a whole drag is one undo step), a double click adds one on the
// nearest segment, a right click takes one away; below the canvas: snapping to the grid, the
// held point's numbers and weight, presets and fit.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/plant/curve_edit.hpp"
#include "app/viewer/window/app.hpp"

namespace sprout::viewer::detail {

struct EditedCurve {
    std::string key;  // names the curve across frames (its view stays while it is shown)
    CurvePoints points;
    CurveRules rules;
    bool weights = false;  // a NURBS: each point's weight can be set
    // The curve as its tool draws it, through `points`.
    std::function<std::vector<std::array<double, 2>>(const CurvePoints&)> samples;
    // Writes new points where the curve lives (the model's text, its file); `gesture` joins
    // the writes of one drag into one undo step. False when it could not be written.
    std::function<bool(const CurvePoints&, std::uint64_t gesture)> write;
};

// A row of a list of curves: a thumbnail of the curve (its samples, fitted) and its label;
// true when clicked.
bool curveRow(const char* label, bool selected, const std::vector<std::array<double, 2>>& samples);

// The canvas and its tools for `curve`.
void curveCanvas(App& app, const EditedCurve& curve);
// Where point k of the curve open in the canvas was drawn last frame, in window pixels; the
// panel scrolls to the canvas on the next frame (the script's mouse drag). Null: none.
std::optional<std::array<float, 2>> curvePointOnScreen(std::size_t k);
// An image under the curve to trace (a PNG), fitted to the view: "" when loaded, else why not;
// its size once loaded.
std::string loadTraceImage(const std::string& path);
std::array<int, 2> traceImageSize();
// Makes the canvas fit its curve again on the next frame (another curve opened).
void refitCurveCanvas();

}  // namespace sprout::viewer::detail
