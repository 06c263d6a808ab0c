#pragma once
// cpfg's background scene (VLab's cpfg/background.c, ReadBackgroundSceneFile): the file a view
// file's `background scene: FILE` names, simple shapes cpfg draws with the plant. The file goes
// through the C preprocessor (preprocessor.hpp: comments, #define, #include), then each command
// is a word followed by its numbers, any number of them on any number of lines:
//
//   polygon x y z x y z x y z ...     a fan from the first point (3 points or more)
//   polygonuv x y z nx ny nz ...      the same, each point with its normal (3 or more)
//   rectangle w h [x y [e]]           w by h in the z = 0 plane from (x, y); e scales its emission
//   mesh a1 b1 a2 b2 ...              rows of two points (x y z each); a quad between two rows
//   prism x y z  (or box)             the box from the origin to (x, y, z)
//   cone r1 r2 h                      along y, radius r1 at 0 to r2 at h, closed by discs
//   cylinder r h                      along y from 0 to h, closed by discs
//   sphere r                          at the origin
//   material a a a a [d d d d [s s s s [e e e e [shininess]]]]
//                                     RGBA ambient, diffuse, specular, emission (0..1)
//   pushmatrix, popmatrix, translate x y z, rotate degrees x y z, scale x y z,
//   multmatrix m00 m01 ... m33        (the matrix row by row, IRIS GL's: the last row moves)
//
// A word that is no command, a command short of numbers, a file cut short: a message at the
// file, line and column, saying what was expected, and the command left out (cpfg skips what
// it cannot draw: "Unknown keyword", "not enough parameters"). Numbers beyond what a command
// uses are a warning, as are a `popmatrix` with nothing pushed and a 51st `pushmatrix` (cpfg
// keeps 50 matrices), which are left out as cpfg ignores them. Never throws; nothing in a file
// can make it loop or grow without bound (a million numbers at most). Core's turtle draws the
// scene (core/turtle/background_scene.hpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"
#include "core/language/vlab/colours.hpp"
#include "core/language/vlab/preprocessor.hpp"

namespace sprout::vlab {

enum class BackgroundCommand : std::uint8_t {
    Polygon, PolygonUV, Rectangle, Mesh, Prism, Cone, Cylinder, Sphere,
    Material, PushMatrix, PopMatrix, Translate, Rotate, Scale, MultMatrix
};

// A command as cpfg keeps it: its numbers, checked (at least as many as it uses; a polygon's
// and a mesh's cut to whole points and rows).
struct BackgroundItem {
    BackgroundCommand command = BackgroundCommand::Polygon;
    std::uint32_t first = 0, count = 0;  // its numbers: BackgroundScene::values[first, first + count)
    std::uint16_t file = 0;              // into BackgroundScene::files
    int line = 0;
};

struct BackgroundScene {
    std::vector<BackgroundItem> items;  // in the files' order
    std::vector<float> values;
    std::vector<std::string> files;     // the files read and those they include
    struct Problem {
        std::string file;
        Diagnostic diagnostic;
        std::string text() const { return formatDiagnostic(diagnostic, file); }  // FILE:line:col: ...
    };
    std::vector<Problem> problems;
    int pushed = 0;  // matrices pushed and not popped when the last file ended

    // How the object draws it, which cpfg takes from its colours and view file (app/plant):
    // the colour it starts with is colour index 0 of the reference set (cpfg's clp.colormap),
    // which each `material` changes.
    bool materials = true;               // a material set (-M); false: a colour map (-m)
    Material start;                      // material 0 of the reference set
    std::uint32_t startColour = 0xC8C8C8;  // colour 0 of the reference map, 0xRRGGBB
    int sides = 8;                       // `contour sides:`: cylinders, cones and spheres
    bool tapered = true;                 // `tapered lines:`; off, a cone is drawn as a cylinder

    bool ok() const;  // no errors (warnings allowed)
};

// The commands' names as a file writes them ("polygon" ... "multmatrix", "box").
const std::vector<std::string>& backgroundCommands();

// `text` (the file `file`) read as cpfg reads a background scene, its items appended to
// `scene` (cpfg reads the files of one `background scene:` line one after the other, its
// matrix stack going on from one to the next); `include` reads the files it #includes.
void readBackgroundScene(std::string_view text, const std::string& file, BackgroundScene& scene, const IncludeReader& include = {});

// The file at `path` read, its #includes beside it; a file that cannot be read is one error.
void loadBackgroundScene(const std::filesystem::path& path, BackgroundScene& scene);

}  // namespace sprout::vlab
