#pragma once
// The turtle's vocabulary, in one table: L-Py's predefined modules (src/cpp/predefinedmodules.cpp)
// with their aliases, in the order of L-Py's ids; the method of PglTurtle that puts each into
// the string from an interpretation rule (`turtle.left(60)`); and what Sprout's turtle does with
// each. The others read it: lstring.cpp's module classes (ModuleClasses), lpy/draw/draw.cpp's
// mapping of each module to Sprout's turtle, and lpy/api/lpy.py's interpretation turtle
// (through _sprout_lpy._turtle_methods, lpy/api/module.cpp). No Python: translate/ includes it.
#include <array>
#include <cstdint>

namespace sprout::lpy {

// What the drawing (lpy/draw/draw.cpp) does with a module.
enum class TurtleOp : std::uint8_t {
    LeftOut,  // not drawn by Sprout: said so (a warning)
    Silent,   // draws nothing in L-Py either: no warning
    Skip, Forward, Move, StepForward, Turn, Around, Vertical, SetHead, MoveTo, LineTo, IncWidth, DecWidth, SetWidth,
    IncColour, DecColour, SetColour, Sphere, Circle, Surface, PolyBegin, PolyVertex, PolyEnd, Push, Pop,
    Bare,  // the Sprout module, without parameters
    Tropism, Elasticity, SetGuide, EndGuide, PositionOnGuide, SetContour, Sweep,
    Point,  // the Sprout module with L-Py's x y z as Sprout's
    Frame, InterpolateColours, Shape, Label,
    Numbers,  // the Sprout module of the same name, with L-Py's numbers as they are
    TextureBaseColour,  // TextureBaseColor, InterpolateTextureBaseColors: a texture's tint
};

struct TurtleWord {
    std::array<const char*, 3> names;  // L-Py's name, then its aliases (null after them)
    const char* method;                // PglTurtle's method, or null
    TurtleOp op;
    const char* sprout = nullptr;      // the Sprout module, for ops that keep their name
};

// The first six keep the ids ModuleClasses names (kPush to kSurface).
inline constexpr TurtleWord kTurtleVocabulary[] = {
    {{"[", "SB"}, "push", TurtleOp::Push, "["},
    {{"]", "EB"}, "pop", TurtleOp::Pop, "]"},
    {{"%", "Cut"}, nullptr, TurtleOp::Silent},
    {{"*", "any"}, nullptr, TurtleOp::Silent},
    {{"", "None"}, nullptr, TurtleOp::Silent},  // L-Py's None module is named '' (printed as nothing)
    {{"~"}, nullptr, TurtleOp::Surface, "~l"},
    {{"surface"}, "surface", TurtleOp::Surface, "~l"},  // a class of its own in L-Py, as ~ is
    {{"F"}, "F", TurtleOp::Forward, "F"},
    {{"f"}, "f", TurtleOp::Move, "f"},
    {{"nF"}, "nF", TurtleOp::StepForward, "F"},
    {{"+", "Left"}, "left", TurtleOp::Turn, "+"},
    {{"-", "Right"}, "right", TurtleOp::Turn, "-"},
    {{"^", "Up"}, "up", TurtleOp::Turn, "^"},
    {{"&", "Down"}, "down", TurtleOp::Turn, "&"},
    // L-Py's / is RollL, about H by +angle (PlantGL: left towards up), which is Sprout's (ABOP's)
    // \ ; its \ is Sprout's /.
    {{"/", "RollL"}, "rollL", TurtleOp::Turn, "\\"},
    {{"\\", "RollR"}, "rollR", TurtleOp::Turn, "/"},
    {{"iRollL"}, "iRollL", TurtleOp::Turn, "\\"},
    {{"iRollR"}, "iRollR", TurtleOp::Turn, "/"},
    {{"|", "TurnAround"}, "turnAround", TurtleOp::Around, "|"},
    {{"@v", "RollToVert"}, "rollToVert", TurtleOp::Vertical, "$"},
    {{"@h", "RollToHorizontal"}, "rollToHorizontal", TurtleOp::LeftOut},
    {{"@R", "SetHead"}, "setHead", TurtleOp::SetHead, "@R"},
    {{"EulerAngles"}, nullptr, TurtleOp::LeftOut},
    {{"Pinpoint"}, "pinpoint", TurtleOp::Point, "Pinpoint"},
    {{"PinpointRel"}, "pinpointRel", TurtleOp::Point, "PinpointRel"},
    {{"@M", "MoveTo"}, "move", TurtleOp::MoveTo, "@M"},
    {{"MoveRel"}, "moveRel", TurtleOp::Point, "MoveRel"},
    {{"LineTo"}, "lineTo", TurtleOp::LineTo, "LineTo"},
    {{"LineRel"}, "lineRel", TurtleOp::LineTo, "LineRel"},
    {{"OLineTo"}, "oLineTo", TurtleOp::LineTo, "OLineTo"},
    {{"OLineRel"}, "oLineRel", TurtleOp::LineTo, "OLineRel"},
    {{"_", "IncWidth"}, "incWidth", TurtleOp::IncWidth},
    {{"!", "DecWidth"}, "decWidth", TurtleOp::DecWidth},
    {{"SetWidth"}, "setWidth", TurtleOp::SetWidth},
    {{";", "IncColor"}, "incColor", TurtleOp::IncColour},
    {{",", "DecColor"}, "decColor", TurtleOp::DecColour},
    {{"SetColor"}, "setColor", TurtleOp::SetColour},
    // A colour between two materials.
    {{"InterpolateColors"}, "interpolateColors", TurtleOp::InterpolateColours},
    // The colour a texture material's image is drawn times (PlantGL's texBaseColor).
    {{"TextureBaseColor"}, nullptr, TurtleOp::TextureBaseColour},
    {{"InterpolateTextureBaseColors"}, nullptr, TurtleOp::TextureBaseColour},
    {{"@O", "Sphere"}, "sphere", TurtleOp::Sphere, "@O"},
    {{"@o", "Circle"}, "circle", TurtleOp::Circle, "@c"},
    {{"@B", "Box"}, "box", TurtleOp::LeftOut},
    {{"@b", "Quad"}, "quad", TurtleOp::LeftOut},
    // A text at the turtle (@L(text[, size]): PlantGL's label, facing the viewer).
    {{"@L", "Label"}, "label", TurtleOp::Label},
    // Generalized cylinders: the stems between StartGC and EndGC are one smooth tube (Sprout's
    // cpfg @Gs ... @Ge: each F a control point).
    {{"@Gc", "StartGC"}, "startGC", TurtleOp::Bare, "@Gs"},
    {{"@Ge", "EndGC"}, "stopGC", TurtleOp::Bare, "@Ge"},
    {{"{", "BP"}, "startPolygon", TurtleOp::PolyBegin, "{"},
    {{".", "PP"}, "polygonPoint", TurtleOp::PolyVertex, "."},
    {{"}", "EP"}, "stopPolygon", TurtleOp::PolyEnd, "}"},
    // Cross-sections: the tubes after SetContour(curve) are swept with that curve's shape (an open
    // curve: a surface, such as a leaf blade); Sweep(path, section, length, dl, radius,
    // radiusFunction) is SetGuide, SetContour and nF together (PlantGL's sweep).
    {{"SetContour"}, nullptr, TurtleOp::SetContour},
    {{"SectionResolution"}, nullptr, TurtleOp::Silent},
    // Guides: the F and f that follow go along a curve (PlantGL's Turtle2DPath).
    {{"SetGuide"}, "setGuide", TurtleOp::SetGuide},
    {{"EndGuide"}, "endGuide", TurtleOp::EndGuide},
    {{"PositionOnGuide"}, nullptr, TurtleOp::PositionOnGuide},
    {{"Sweep"}, "sweep", TurtleOp::Sweep},
    // A PlantGL shape at the turtle (@g(shape[, scale])): its x along the turtle's up, its y to
    // the right, its z along the heading (so a shape's coordinates are L-Py's world ones for a
    // turtle that has not turned, as a guide's are).
    {{"@g", "PglShape"}, nullptr, TurtleOp::Shape},
    // The turtle's frame as three arrows (heading red, up blue, left green).
    {{"Frame"}, "frame", TurtleOp::Frame},
    {{"Arrow"}, "arrow", TurtleOp::LeftOut},
    {{"@D", "SetScale"}, "setScale", TurtleOp::Silent},
    {{"@Di", "MultScale"}, nullptr, TurtleOp::Silent},
    {{"@Dd", "DivScale"}, nullptr, TurtleOp::Silent},
    // Tropism: before each F and f, H turns towards the tropism vector by the elasticity times the
    // angle between them (Sprout's @T with a direction).
    {{"@Ts", "Elasticity"}, "setElasticity", TurtleOp::Elasticity},
    {{"@Tp", "Tropism"}, "setTropism", TurtleOp::Tropism},
    {{"LeftReflection"}, nullptr, TurtleOp::LeftOut},
    {{"UpReflection"}, nullptr, TurtleOp::LeftOut},
    {{"HeadingReflection"}, nullptr, TurtleOp::LeftOut},
    {{"@2D", "StartScreenProjection"}, nullptr, TurtleOp::Silent},
    {{"@3D", "EndScreenProjection"}, nullptr, TurtleOp::Silent},
    // How a texture lies on the textured surfaces after them (PlantGL's Texture2DTransformation).
    {{"TextureScale"}, nullptr, TurtleOp::Numbers, "TextureScale"},
    {{"TextureUScale"}, nullptr, TurtleOp::Numbers, "TextureUScale"},
    {{"TextureVScale", "TextureVCoeff"}, nullptr, TurtleOp::Numbers, "TextureVScale"},
    {{"TextureTranslation"}, nullptr, TurtleOp::Numbers, "TextureTranslation"},
    {{"TextureRotation"}, nullptr, TurtleOp::Numbers, "TextureRotation"},
    {{"TextureTransformation"}, nullptr, TurtleOp::Numbers, "TextureTransformation"},
    {{"?P", "GetPos"}, nullptr, TurtleOp::Silent},
    {{"?H", "GetHead"}, nullptr, TurtleOp::Silent},
    {{"?U", "GetUp"}, nullptr, TurtleOp::Silent},
    {{"?L", "GetLeft"}, nullptr, TurtleOp::Silent},
    {{"?R", "GetRight"}, nullptr, TurtleOp::Silent},
    {{"?F", "GetFrame"}, nullptr, TurtleOp::Silent},
    {{"X", "MouseIns"}, nullptr, TurtleOp::Silent},
    {{"x", "repexp", "all"}, nullptr, TurtleOp::Silent},
    {{"or", "||"}, nullptr, TurtleOp::Silent},
    {{"=]"}, nullptr, TurtleOp::Silent},
    {{"?I", "GetIterator"}, nullptr, TurtleOp::Silent},
    {{"new", "newmodule"}, nullptr, TurtleOp::Silent},
    // L-Py's GetModule: `$` alone (`$x` and `$A(a)` are read before any name).
    {{"$", "GetModule"}, nullptr, TurtleOp::Silent},
};

}  // namespace sprout::lpy
