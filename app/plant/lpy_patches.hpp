#pragma once
// An L-Py model's NURBS patches as its INITIALISATION part holds them (issue 52), read and
// written in place like its curves (lpy_objects.hpp):
//     NAME = pgl.NurbsPatch(
//         pgl.Point4Matrix([[(x, y, z, w), ...], [...], ...]) ,
//         )
// with or without `pgl.`; `udegree = n` and `vdegree = m` after the matrix are read.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

struct LpyPatch {
    std::string name;
    std::vector<std::vector<std::array<double, 4>>> rows;  // PlantGL's [u][v] control points (x, y, z, w)
    int udegree = 3, vdegree = 3;                            // clamped to the points
    int line = 0;
    size_t begin = 0, end = 0;  // the matrix's bytes, its outer `[` to `]`
};
std::vector<LpyPatch> lpyPatches(std::string_view text);
// The text with the patch's matrix replaced (Studio's form: six significant digits); nothing
// else changes.
std::string setLpyPatchPoints(std::string_view text, const LpyPatch& patch, const std::vector<std::vector<std::array<double, 4>>>& rows);

}  // namespace sprout
