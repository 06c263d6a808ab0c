#pragma once
// A `.lsys` grammar's own functions and contours (issue 52: `function: NAME x,y ...`,
// `contour: ID [open|closed] x,y ...`, core/language/lsys_curves.cpp), as the panel's curve
// editor reads and writes them: each line's points replaced in place, nothing else changed.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

struct LsysCurve {
    std::string name;       // the function's name, the contour's id
    bool function = true;   // else a contour
    bool closed = true;     // a contour's
    std::vector<std::array<double, 3>> points;  // x, y, 1
    int line = 0;
    size_t begin = 0, end = 0;  // the points' bytes in the line
};
std::vector<LsysCurve> lsysCurves(std::string_view text);
std::string setLsysCurvePoints(std::string_view text, const LsysCurve& c, const std::vector<std::array<double, 3>>& points);

}  // namespace sprout
