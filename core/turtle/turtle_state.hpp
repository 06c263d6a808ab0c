#pragma once
// The turtle's vocabulary and state, shared by the files that make the turtle (see
// turtle_impl.hpp): the action of each module name, the default palette, the frame as SIMD
// vectors, the state pushed at brackets, and the small vector helpers.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <glm/geometric.hpp>

#include "core/turtle/turtle.hpp"

namespace sprout::turtle_impl {

enum class Act : std::uint8_t {
    None, Draw, DrawNoVertex, Move, MoveNoVertex, Left, Right, Down, Up, RollLeft, RollRight,
    Around, Horizontal, Push, Pop, PolyBegin, PolyVertex, PolyEnd, WidthDec, WidthInc,
    ColourNext, ColourPrev, Leaf, Petal, Sphere, ScaleLength, ScaleAngle, ScaleWidth, Gravity,
    Query, MoveTo, SetHeading, Disc, CurveStart, CurvePoint, CurveEnd, CurveTangent,
    LineTo, OLineTo, LineRel, OLineRel, MoveRel, Pinpoint, PinpointRel, Section, Label,
    SurfaceFile,  // a cpfg .s surface (per symbol, from the grammar; not in the name table)
    // L-system Explorer (Settings::bracePaths): `}(name)` keeps the polygon as a surface
    // instead of drawing it, `~(name[, scale])` draws it at the turtle.
    PolyEndSave, InsertSaved, CurveEndKeep,
    // Its contours: @Cs (@Ds) starts one, each '.' adds the turtle's point, @Ce(id) (@De) ends
    // and names it, @#(id) makes it the cross-section of the paths started after it.
    ContourStart, ContourEnd, ContourUse,
    ContourSides,  // cpfg's @!(n): the sides of the view file's contours chosen after it
    // cpfg's turtle scale: @D(s) sets it, @Di(s) multiplies it by s (the view file's scale
    // multiplier without one), @Dd(s) divides it; and @L("format", x...), a label.
    ScaleSet, ScaleMul, ScaleDiv, CpfgLabel,
    RadiusTangents,  // cpfg's @Gr(a1, l1, a2, l2) and @Gr(flag): the tubes' radius along a span
    ElasticSet, ElasticInc, ElasticDec,  // cpfg's @Ts, @Ti, @Td(id, value): a tropism's elasticity
    PatchStart, PatchPoint, PatchDraw,   // cpfg's @PS(id, basis), @PC(id, row, col), @PD(id, s, t)
    // L-Py's texture transforms (PlantGL's turtle): how the image lies on the textured surfaces
    // drawn after them.
    TextureScale, TextureUScale, TextureVScale, TextureTranslation, TextureRotation, TextureTransformation,
    TextureSet,  // cpfg's @Tx(n): the view file's n-th texture on the surfaces after it (@Tx: none)
};

inline Act actionOf(const std::string& name) {
    static const std::pair<const char*, Act> table[] = {
        {"F", Act::Draw}, {"G", Act::DrawNoVertex}, {"f", Act::Move}, {"g", Act::MoveNoVertex},
        {"+", Act::Left}, {"-", Act::Right}, {"&", Act::Down}, {"^", Act::Up},
        {"\\", Act::RollLeft}, {"/", Act::RollRight}, {"|", Act::Around}, {"$", Act::Horizontal},
        {"[", Act::Push}, {"]", Act::Pop}, {"{", Act::PolyBegin}, {".", Act::PolyVertex},
        {"}", Act::PolyEnd}, {"!", Act::WidthDec}, {"#", Act::WidthInc}, {";", Act::ColourNext},
        {"'", Act::ColourNext}, {",", Act::ColourPrev}, {"~leaf", Act::Leaf}, {"~l", Act::Leaf},
        {"~L", Act::Leaf}, {"~petal", Act::Petal}, {"~p", Act::Petal}, {"~P", Act::Petal},
        {"@O", Act::Sphere}, {"@o", Act::Sphere},
        // Extensions for imported grammars (Lparser): scale the step, the angle, the width
        // by a factor; bend towards gravity now (Lparser's t).
        {"@L", Act::ScaleLength}, {"@A", Act::ScaleAngle}, {"@W", Act::ScaleWidth}, {"@T", Act::Gravity},
        // cpfg: query modules (the turtle's frame is written back into them after each
        // step), move to a point (L-system Explorer's @m too), set the heading, roll L
        // horizontal, a disc.
        {"?P", Act::Query}, {"?H", Act::Query}, {"?U", Act::Query}, {"?L", Act::Query}, {"?E", Act::Query},
        {"@M", Act::MoveTo}, {"@m", Act::MoveTo}, {"@R", Act::SetHeading}, {"@v", Act::Horizontal}, {"@c", Act::Disc},
        // L-Py's (PlantGL's turtle): a stem straight to a point, the heading kept (LineTo) or
        // turned towards it (OLineTo).
        {"LineTo", Act::LineTo}, {"OLineTo", Act::OLineTo},
        // And the same by a vector from the turtle (LineRel, OLineRel), a move by one
        // (MoveRel), and the heading turned towards a point or along a vector (Pinpoint,
        // PinpointRel: the least rotation, PlantGL's _tendTo).
        {"LineRel", Act::LineRel}, {"OLineRel", Act::OLineRel}, {"MoveRel", Act::MoveRel},
        {"Pinpoint", Act::Pinpoint}, {"PinpointRel", Act::PinpointRel},
        // cpfg's generalized cylinders: start, control point, end, tangent length.
        {"@Gs", Act::CurveStart}, {"@Gc", Act::CurvePoint}, {"@Ge", Act::CurveEnd}, {"@Gt", Act::CurveTangent},
        // The cross-section of the generalized cylinders started after it (Settings::sections;
        // none or -1: round).
        {"SetContour", Act::Section},
        // A text at the turtle (Settings::labels; its size in pixels, 13 by default).
        {"Label", Act::Label},
        // The texture transforms: TextureScale(su[, sv]), TextureUScale(su), TextureVScale(sv),
        // TextureTranslation(tu, tv), TextureRotation(degrees[, cu, cv]),
        // TextureTransformation(su, sv, tu, tv, degrees, cu, cv) (PlantGL's Texture2DTransformation).
        {"TextureScale", Act::TextureScale}, {"TextureUScale", Act::TextureUScale}, {"TextureVScale", Act::TextureVScale},
        {"TextureVCoeff", Act::TextureVScale}, {"TextureTranslation", Act::TextureTranslation},
        {"TextureRotation", Act::TextureRotation}, {"TextureTransformation", Act::TextureTransformation},
    };
    for (const auto& [n, a] : table)
        if (name == n) return a;
    return Act::None;
}

// ABOP's `'` steps through a colour map: index 0 is bark, 1..8 a ramp of greens from dark
// to light, then flower colours.
inline constexpr std::uint32_t kDefaultPalette[16] = {
    0x6B4A2EFF, 0x3F6B25FF, 0x4A7A2AFF, 0x558A30FF, 0x629936FF, 0x70A73DFF, 0x80B448FF, 0x92C056FF,
    0xA6CB66FF, 0xF2D43DFF, 0xF7F4EAFF, 0xE58FB6FF, 0xD9442EFF, 0x9C6ADEFF, 0xFF9F1CFF, 0x3D7DD8FF,
};
constexpr int kLeafColour = 5, kPetalColour = 10, kSphereColour = 12;

constexpr float kPi = 3.14159265358979f;

// Four-float SIMD vectors (GCC vector extension): a frame rotation is four multiplies and
// two adds, and a segment's start or end with its radius is one 16-byte store. glm::vec3
// compiled to scalar code with shuffles and ran the turtle 3x slower.
typedef float v4 __attribute__((vector_size(16)));
inline v4 splat(float x) { return v4{x, x, x, x}; }
inline glm::vec3 toGlm(v4 v) { return {v[0], v[1], v[2]}; }
inline v4 fromGlm(const glm::vec3& v) { return v4{v.x, v.y, v.z, 0}; }

// Pushed and popped at every bracket.
struct State {
    v4 pos{0, 0, 0, 0};  // pos[3]: the length drawn textured since the colour was set (PlantGL's axial length)
    v4 H{0, 1, 0, 0};
    v4 L{-1, 0, 0, 0};  // U is H x L, made when a pitch, roll or surface needs it
    float length = 1;
    float width = 1;  // diameter
    std::int32_t lastSegment = -1;  // the segment this branch's next segment continues
    std::uint16_t order = 0;
    std::int16_t colour = -1;  // palette index set by ; , ' (wrapped); -1: none set
    std::int16_t curve = -1;  // the generalized cylinder this branch draws into (@Gs); -1: none
    std::int16_t section = -1;  // Settings::sections index of the next @Gs's cross-section; -1: round
    std::int16_t sides = 0;     // cpfg's @!(n) for the view file's contours; 0: `contour sides:`
    std::int16_t texture = 0;   // Turtle::m_texTransforms' entry the textured surfaces take; 0: none
    float angleScale = 1;     // @A: factor on the default turning angle
    // Resolved when the colour or the branch order changes: measured faster than looking it
    // up at every segment, even though it makes the state 80 bytes instead of 64.
    std::uint32_t stemColour = 0;
};

inline v4 cross(v4 a, v4 b) {
    return v4{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0], 0};
}
// U is made unit length: with U = H x L as it is, float rounding in |H| and |L| feeds back
// through pitches and rolls (|H'|^2 = |H|^2 (c^2 + |L|^2 s^2)) and grows exponentially: a rule
// with a hundred '&' made stems 10^13 long after 5 steps (found by the fuzzers). With a unit U
// a pitch or roll pulls |H| and |L| back towards 1 instead.
inline v4 up(const State& t) {
    v4 u = cross(t.H, t.L);
    const float n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    return n2 > 0 ? u * (1.0f / std::sqrt(n2)) : u;
}

// Rotation of the frame about one of its axes (ABOP 1.5) mixes the other two.
inline void rotate(v4& a, v4& b, float c, float s) {
    v4 na = a * c + b * s;
    b = b * c - a * s;
    a = na;
}

inline std::uint32_t lerpColour(std::uint32_t a, std::uint32_t b, float t) {
    std::uint32_t out = 0;
    for (int shift = 24; shift >= 0; shift -= 8) {
        float x = float((a >> shift) & 0xFF), y = float((b >> shift) & 0xFF);
        out |= std::uint32_t(std::lround(x + (y - x) * t)) << shift;
    }
    return out;
}

// Parameters the turtle can use: finite, and small enough that float positions summed over
// millions of segments stay finite (beyond 1e30 is treated like infinity: not drawn).
inline bool finite(const double* p, int n) {
    for (int k = 0; k < n; ++k)
        if (!(std::fabs(p[k]) <= 1e30)) return false;
    return true;
}

}  // namespace sprout::turtle_impl
