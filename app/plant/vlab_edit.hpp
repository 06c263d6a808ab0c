#pragma once
// A VLab object's functions and contours as the panel's curve editor edits them (issue 52):
// the files its view file names (`function:`, the items of `function set:`, `contour:`), each
// one curve whose points are written back in its editor's format (funcedit's `fver 1 1`,
// gallery's set, cuspy's `cver 1 3`: core/language/vlab/curve_files.hpp), so VLab's editors
// and cpfg read them; and the undo history of those writes.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/plant/curve_edit.hpp"
#include "core/language/vlab/colours.hpp"

namespace sprout {

struct VlabCurveFile {
    enum class Kind { Function, Contour };
    Kind kind = Kind::Function;
    std::string label;  // "leaf-length.func", "functions.fset: length", "calyx.con"
    std::string path;
    int item = -1;      // the function's place in its set; -1: a file of its own
    CurvePoints points;  // x, y, multiplicity
    CurveRules rules;
    int samples = 0;     // a function's `samples:` (the first format: the view file's count, 0 for none);
                         // a contour: the view file's `contour sides:`
};

// The functions and contours of the object whose L-system is `lsystemPath`, in its view
// file's order; files that cannot be read are left out (the object's notes say why).
std::vector<VlabCurveFile> vlabCurveFiles(const std::string& lsystemPath);
// The curve as cpfg evaluates it through `pts`: a function over x in [0, 1], a contour
// resampled as cpfg samples it.
std::vector<std::array<double, 2>> vlabCurveSamples(const VlabCurveFile& f, const CurvePoints& pts);
// The file's text with `pts` (everything else as the file has it now); nothing, and `error`,
// when the file cannot be read again or the points would not be a curve cpfg reads.
std::optional<std::string> vlabCurveText(const VlabCurveFile& f, const CurvePoints& pts, std::string& error);

// The Bezier patches of the object's surfaces (the view file's `surface: ID FILE` lines), one
// entry a patch, and the file's text with one patch's 16 control points replaced (bezieredit's
// format: core/language/vlab/surface_patches.hpp).
struct VlabSurfacePatch {
    std::string label, path;  // "leaf.s: Patch_1"
    size_t patch = 0;
    std::array<std::array<float, 3>, 16> points{};
};
std::vector<VlabSurfacePatch> vlabSurfacePatches(const std::string& lsystemPath);
std::optional<std::string> vlabSurfaceText(const VlabSurfacePatch& p, const std::array<std::array<float, 3>, 16>& points, std::string& error);
// A bicubic Bezier patch's points, `samples` x `samples`, [u][v] (u down the file's rows).
std::vector<std::vector<std::array<double, 3>>> bezierPatchSamples(const std::array<std::array<float, 3>, 16>& points, int samples);

// The object's material sets (`-M[n] FILE`, medit's) and colour maps (`-m[n] FILE`,
// palette's), as its cpfg line names them; cpfg reads the kind named last (vlab_view.cpp).
struct VlabColourFile {
    std::string label, path;  // "plant.mat (materials, set 1)"
    bool material = false;
    int set = 1;
};
std::vector<VlabColourFile> vlabColourFiles(const std::string& lsystemPath);
// A colour map's bytes with entry k set to `rgb` (0xRRGGBB); with entries from..to the colours
// between the two ends, as palette's interpolation makes them (a byte of the linear mix,
// truncated). Nothing, and `error`, for a map that cannot be read.
std::optional<std::string> colourMapWith(const std::string& bytes, int k, std::uint32_t rgb, std::string& error);
std::optional<std::string> colourMapInterpolated(const std::string& bytes, int from, int to, std::string& error);

// A function's file with its `samples:` (funcedit's table size; 0: cpfg evaluates the curve
// itself) set, in funcedit's format; nothing, and `error`, for a contour or a count out of
// 0..10000.
std::optional<std::string> vlabFunctionSamplesText(const VlabCurveFile& f, int samples, std::string& error);

// Writes to files beside a model, undone and redone a whole gesture at a time.
// A material set's bytes with material k set to `m` (medit's record, every value truncated to a
// byte as medit writes it). Nothing, and `error`, for a set that cannot be read.
std::optional<std::string> materialsWith(const std::string& bytes, int k, const vlab::Material& m, std::string& error);

class FileEdits {
public:
    // Writes `text` to `path` atomically and records it; writes of the same gesture (not 0)
    // are one step. False, with `error`, when it could not be written.
    bool write(const std::string& path, const std::string& text, std::uint64_t gesture, std::string& error);
    // The last step taken back (the files as before it) or done again; false: none.
    bool undo(std::string& error);
    bool redo(std::string& error);

private:
    struct Step {
        std::uint64_t gesture = 0;
        std::vector<std::array<std::string, 3>> files;  // path, before, after
    };
    std::vector<Step> m_done, m_undone;
};

}  // namespace sprout
