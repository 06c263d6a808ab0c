#pragma once
// An L-Py model's NURBS patches as its INITIALISATION part holds them (issue 52), read and
// written in place like its curves (lpy_objects.hpp):
//     NAME = pgl.NurbsPatch(
//         pgl.Point4Matrix([[(x, y, z, w), ...], [...], ...]) ,
//         )
// with or without `pgl.`; `udegree = n` and `vdegree = m` after the matrix are read.
#include <array>
#include <optional>
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

// The patch's points with a row (along u) or a column (along v) added after row or column k
// (midway to the next one; after the last, as far again beyond it) or row or column k taken
// away, as PlantGL's patch editor adds and removes them; nothing, and `error`, where the patch
// would keep fewer than its degree + 1 rows or columns, or k is not one of them.
enum class PatchEdit { AddRow, DeleteRow, AddColumn, DeleteColumn };
std::optional<std::vector<std::vector<std::array<double, 4>>>> editedPatch(const LpyPatch& patch, PatchEdit edit, size_t k, std::string& error);

}  // namespace sprout
