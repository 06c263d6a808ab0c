#pragma once
// A VLab object's functions, curves, contours and surfaces: the files its view file names
// (`function:`, `function set:`, `curve:`, `contour:`, `contour sides:`, `surface:`, `texture:`), read
// (core/language/vlab/curve_files.hpp) into what the parse of its L-system takes
// (ParseOptions::curves, ::surfaces and ::viewTextures). openText calls it for an L-system inside an object.
#include <string>
#include <vector>

#include "core/language/diagnostic.hpp"
#include "core/language/grammar.hpp"

namespace sprout {

struct VlabCurves {
    bool object = false;  // the L-system is the one an object's cpfg line runs
    // Problems in the files, each naming its file and line ("calyx.con:3:1: ...").
    std::vector<std::string> problems;
};

// Fills `options.curves` and `options.surfaces` from the object around `lsystemPath`, when
// there is one whose cpfg line runs that L-system with a view file.
VlabCurves readVlabCurves(const std::string& lsystemPath, ParseOptions& options);

}  // namespace sprout
