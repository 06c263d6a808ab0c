#pragma once
// An L-Py model's graphical objects as its text holds them (issue 52): the 2D curves of its
// INITIALISATION part, read and written in place so that the text stays the one source of
// truth (what the panel's curve editor moves is what is saved, and L-Py reads it back).
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

// A curve as L-Py Studio writes it in `__initialiseContext__`:
//     NAME = pgl.NurbsCurve2D(
//         ctrlPointList = pgl.Point3Array([(x, y, w),(x, y, w), ...]) ,
//         )
// or `pgl.BezierCurve2D(pgl.Point3Array([...]))`, `pgl.Polyline2D(pgl.Point2Array([(x, y), ...]))`,
// with or without the `pgl.` and the array's name; a `degree = n` after the list is read.
// `function`: the model's panel lists it as a function of x in [0, 1] (`('Function', NAME)`),
// not a curve (`('Curve2D', NAME)`).
struct LpyCurve {
    enum class Kind { Nurbs, Bezier, Polyline };
    std::string name;
    Kind kind = Kind::Nurbs;
    bool function = false;
    std::string panel;  // the name of the panel that lists it (L-Py Studio's `panel_N`), "" if none
    std::vector<std::array<double, 3>> points;  // x, y, weight (1 for a polyline's)
    int degree = 3;                             // as written (a NURBS's is clamped to the points)
    int line = 0;                               // 1-based, of the name
    size_t begin = 0, end = 0;                  // the point list's bytes, `[` to `]` included
};
std::vector<LpyCurve> lpyCurves(std::string_view text);
// The curve a name means: where several panels set it (L-Py Studio keeps each panel's version),
// the last, which the model's variable holds; null when none has it.
const LpyCurve* lastLpyCurve(const std::vector<LpyCurve>& curves, std::string_view name);
// The curve `key` names: "NAME", the last version (lastLpyCurve's), or "NAME#k", the k-th from
// 0 of the versions several panels set, in the text's order (an earlier one: what its panel
// shows in Studio, not what the model uses); null when there is none.
const LpyCurve* lpyCurveNamed(const std::vector<LpyCurve>& curves, std::string_view key);
// The key of curves[i]: its name, or NAME#k for a version before the last.
std::string lpyCurveKey(const std::vector<LpyCurve>& curves, size_t i);

// The text with the curve's point list replaced by `points` (as L-Py Studio writes them: six
// significant digits, `(x, y, w)` joined by `,`; `(x, y)` for a polyline); nothing else changes.
std::string setLpyCurvePoints(std::string_view text, const LpyCurve& curve, const std::vector<std::array<double, 3>>& points);

}  // namespace sprout
