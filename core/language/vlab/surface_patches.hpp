#pragma once
// A cpfg surface file (`.s`) as bezieredit keeps it (issue 52): its frame (contact point, end
// point, heading, up, size) and its bicubic Bezier patches, each with its name, colours and
// neighbours and its 16 control points, read in the order cpfg's patches.c reads it and written
// as bezieredit writes it (bezieredit/model.cpp, Model::save), so the two read it back alike.
// Drawing a surface is core/language/surface_file.hpp's; this is what its editor changes.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/vlab/curve_files.hpp"

namespace sprout {

struct SurfacePatch {
    std::string name;
    unsigned topColour = 0, bottomColour = 0;
    float topDiffuse = 0, bottomDiffuse = 0;
    // AL, A, AR, L, R, BL, B, BR: a neighbour's name, "~" for none.
    std::array<std::string, 8> neighbours{"~", "~", "~", "~", "~", "~", "~", "~"};
    std::array<std::array<float, 3>, 16> points{};  // row by row, as the file lists them
};

struct SurfacePatches {
    std::array<float, 3> contact{0, 0, 0}, end{0, 0, 0}, heading{0, 0, 1}, up{0, 1, 0};
    float size = 1;
    std::optional<std::array<int, 2>> precision;  // `PRECISION S: s T: t`, when given
    std::vector<SurfacePatch> patches;
};

struct SurfacePatchesRead {
    std::optional<SurfacePatches> surface;
    std::vector<CurveFileDiagnostic> diagnostics;
    bool ok() const;
};

// cpfg's reading: the bounding box (six numbers, not used), [PRECISION S: s T: t], CONTACT
// POINT X: Y: Z:, END POINT, HEADING, UP, SIZE:, then patches to the end: a name, [TOP COLOR: c
// DIFFUSE: d BOTTOM COLOR: c DIFFUSE: d], AL: A: AR:, L: R:, BL: B: BR:, 16 points. A problem
// is at its line and column with what was expected; a neighbour no patch is named is one too.
SurfacePatchesRead readSurfacePatches(std::string_view text, const std::string& fileName);
SurfacePatchesRead loadSurfacePatches(const std::filesystem::path& path);

// bezieredit's text: the bounding box of the points and the origin, the header lines, and per
// patch its name, colour line, neighbour lines (by name: bezieredit writes `Patch_<index>`,
// which breaks the links of patches named otherwise) and 4 rows of 4 `x y z` each ended by a
// tab. Numbers as C++ streams print them (6 significant digits; 7 for points), with more
// where that would change the float read back.
std::string writeSurfacePatches(const SurfacePatches& s);

}  // namespace sprout
