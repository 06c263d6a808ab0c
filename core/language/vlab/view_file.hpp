#pragma once
// A VLab object's view file (`.v`), read as cpfg reads it (VLab's cpfg/interpret.c,
// ReadViewData): each `name: value` command cpfg accepts, into a ViewFile. What concerns the
// turtle (angle, colour, width, tropism), the camera (viewpoint, projection, scale), the lights
// and the background is kept as values; the commands that name other files (surfaces,
// contours, functions, textures, a background scene) as data, for whoever reads those files.
// An unknown command is a warning at its line, as cpfg's "Unknown label"; a command whose
// values cpfg would refuse is an error naming what was expected. Never throws.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout::vlab {

using Vec3 = std::array<double, 3>;

// cpfg's `line style:` (and the word after `initial line width:`).
enum class LineStyle { Pixel, Polygon, Cylinder };

// A command that names another file: `surface: l leaf.s 6 6 10`, `contour: 1 calyx.con`,
// `function: growth.func 20`, `function set: functions.fset`, `texture: F: bark.png ...`,
// `background scene: scene.dat`, `blob: field.dat 1 1 1`, `curve: c.crv`, `tsurface:`, `line:`.
struct FileReference {
    std::string command;           // as cpfg names it, without the ':' ("surface", "function set")
    char id = 0;                   // surfaces, lines, tsurfaces: the module's letter (~l)
    std::string file;              // as written, relative to the object's folder
    std::vector<double> numbers;   // the numbers after the file (size, precisions, samples ...)
    std::string options;           // a texture's other options as written
    int line = 0;
};

// A `light:` command (cpfg's read_light): a direction (V:) or a position (O:), and colours.
struct Light {
    bool directional = true;
    Vec3 vector{0, 0, 1};          // V: towards the light, or O: where it is
    Vec3 ambient{1, 1, 1}, diffuse{1, 1, 1}, specular{1, 1, 1};
    int line = 0;
};

// A command kept as written: cpfg reads it but Sprout does not use it (font, shadow map ...).
struct OtherCommand {
    std::string command, value;
    int line = 0;
};

// cpfg's `tropism: T: x y z [I: intensity] [A: angle] [E: elasticity] [S: step]` and
// `torque: T: ...` (movements.c's read_movement): the direction times the intensity, the
// angle it tends to make with the heading (90: plagiotropism), the elasticity, and the step
// that @Ti and @Td add and take without a value.
struct Movement {
    bool torque = false;
    Vec3 direction{0, 0, 0};
    double angle = 0, elasticity = 0, step = 0;
    int line = 0;
};

struct ViewFile {
    // The turtle (cpfg's DRAWPARAM), with cpfg's defaults (InitializeParameters).
    std::optional<double> angleIncrement;  // degrees; `angle factor: n` gives 360 / n (default 45)
    std::optional<int> initialColour;      // `initial color: front [back]` (default 128)
    std::optional<int> initialColourBack;
    int colourIncrement = 1, colourIncrementBack = 1;
    std::optional<double> lineWidth;       // `initial line width:` (default 1)
    double widthIncrement = 0;             // `line width increment:`: ! and # without a value
    LineStyle lineStyle = LineStyle::Pixel;
    bool lineStyleSet = false;
    std::optional<Vec3> tropismDirection;  // unit length
    double elasticity = 0, elasticityIncrement = 0;
    std::vector<Movement> movements;       // `tropism:` and `torque:` lines, at most 10 (cpfg's MAXMOVEMENTS)
    bool twistOfCylinders = false;         // `twist of cylinders: on`
    bool taperedLines = true;
    int contourSides = 8;                  // `contour sides:`, or 2^(level+1) by `polygonization level:`
    double initialScale = 1, scaleMultiplier = 1;
    int interpretationStep = -1;
    bool interpretationPastCut = true;
    std::string renderMode = "filled";     // wireframe, filled, flat, interpolated, shaded, fast, shadows
    int shadeMode = 1;
    // The camera (cpfg's VIEWPARAM).
    Vec3 viewpoint{0, 0, 1}, reference{0, 0, 0};  // `viewpoint:`, `view reference point:`
    double twist = 0;                      // `twist:`, in tenths of a degree about the viewing direction (IRIS GL's unit)
    bool perspective = false;              // `projection: perspective` (default parallel)
    double viewingAngle = 45;              // degrees (perspective)
    double front = -100000, back = 100000; // `front distance:`, `back distance:`
    double scale = 1;                      // `scale factor:` (0 reads as 1)
    bool zBuffer = true;
    int cueRange = 0;
    std::optional<std::array<Vec3, 2>> box;  // `box: x: a,b y: c,d z: e,f`: min and max
    double minZoom = 0.05, maxZoom = 50;
    bool antialiasing = false;
    // Lights and colours.
    Vec3 lightDirection{1, 0, 0};          // `light direction:`, unit length
    bool lightDirectionSet = false;
    std::vector<Light> lights;             // `light:` commands, in order
    int diffuseReflection = 10;
    double surfaceAmbient = 0.15, surfaceDiffuse = 0.75;
    std::optional<Vec3> backgroundColour;  // `background color:` (cpfg reads it, its GL ignores it)
    std::optional<Vec3> ambientLight;
    // What names other files, and what is read but not used.
    std::vector<FileReference> files;
    std::vector<OtherCommand> others;
    std::vector<Diagnostic> diagnostics;   // at the file's lines
    bool ok() const { return !hasErrors(diagnostics); }
};

// The view file's text read. Comments (/* */ and //) are skipped as cpfg's preprocessor does.
ViewFile readViewFile(std::string_view text);

// Every command name cpfg's view-file reader accepts, with its ':' ("angle factor:").
const std::vector<std::string>& viewFileCommands();

}  // namespace sprout::vlab
