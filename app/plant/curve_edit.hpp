#pragma once
// Editing a 2D curve's control points (issue 52), whatever file keeps it: an L-Py model's
// NurbsCurve2D / BezierCurve2D / Polyline2D (app/plant/lpy_objects.hpp), a VLab function
// (`.func`) or contour (`.con`). Each operation gives the new points, or nothing when the
// curve would no longer be one its tool reads; the caller writes them in the curve's format.
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace sprout {

using CurvePoints = std::vector<std::array<double, 3>>;  // x, y, weight

// What a curve's file asks of its points.
struct CurveRules {
    bool function = false;  // y = f(x) on [0, 1]: x in order, the first at 0 and the last at 1
    bool closed = false;    // the last point joins the first (a contour)
    size_t fewest = 2;      // fewer points are not a curve its tool reads (a NURBS: degree + 1)
    double newWeight = 0;   // an added point's weight; 0: its neighbours' mean
};

// Point k at (x, y); a function's points keep their order along x, its ends at 0 and 1.
CurvePoints movedPoint(const CurvePoints& pts, const CurveRules& rules, size_t k, double x, double y);
// A point put halfway between points k and k + 1 (a closed curve's last and first; an open
// curve's last: beyond it, as far as the segment before it), with their mean weight (or the
// rules' newWeight: a VLab point's multiplicity is 1).
std::optional<CurvePoints> insertedPoint(const CurvePoints& pts, const CurveRules& rules, size_t k);
// Point k taken away: nothing when the curve would have fewer than `fewest`, or for a
// function's end.
std::optional<CurvePoints> removedPoint(const CurvePoints& pts, const CurveRules& rules, size_t k);
// Point k's weight set (a NURBS's rational weight: more than 0).
std::optional<CurvePoints> weightedPoint(const CurvePoints& pts, size_t k, double w);
// The segment of the control polygon (k to k + 1; a closed curve's last wraps) nearest (x, y).
size_t nearestSegment(const CurvePoints& pts, const CurveRules& rules, double x, double y);
// (x, y) to the nearest multiple of `step`.
std::array<double, 2> snapped(double x, double y, double step);

// Shapes to start from, as L-Py's and PlantGL's curve editors offer them: a straight line,
// an arc, a circle (not for a function) and an S. A function's span x from 0 to 1, a curve's
// about the unit square round the origin. `count`: how many points, at least `fewest` and
// enough for the shape (an arc 5, an S 7, a circle 9: its last point is its first again
// unless the curve is closed).
enum class CurvePreset { Line, Arc, Circle, S };
std::optional<CurvePreset> curvePresetNamed(std::string_view name);  // line, arc, circle, s
std::optional<CurvePoints> presetPoints(CurvePreset preset, const CurveRules& rules, size_t count);

}  // namespace sprout
