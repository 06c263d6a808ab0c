#pragma once
// The turtle's per-module step (Turtle::apply) and what it inlines: turns, segments and
// stems, tropism. The hot code of the turtle: both readers (the string's loop in turtle.cpp,
// the tree's walk in turtle_tree.cpp) inline it, so it is defined here, inline, after the
// class it belongs to (turtle_class.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>

#include "core/turtle/turtle_class.hpp"
#include "core/turtle/turtle_state.hpp"

namespace sprout::turtle_impl {

// cos and sin of an angle in degrees, exact for a quarter turn: a float pi/2 has a cosine
// of -4.4e-8, and a 90-degree curve turned 5 M times drifted 12 degrees round (a square
// drawn as a smeared band).
inline void Turtle::cosSinDegrees(double degrees, float& c, float& s) {
    const double r = std::remainder(degrees, 360.0);  // -180 .. 180
    // Only the quarter turns are snapped; every other angle is turned as before, in float
    // (a polygon turned back exactly on itself triangulates by rounding, and the tree
    // turtle's placed blocks reproduce the float values: the fuzzer compares the two).
    if (r == 90) c = 0, s = 1;
    else if (r == -90) c = 0, s = -1;
    else {
        const float a = float(degrees) * kPi / 180.0f;
        c = std::cos(a), s = std::sin(a);
    }
}

[[gnu::always_inline]] inline void Turtle::turn(const State& t, v4& a, v4& b, const double* p, float sign) {
    if (p) {
        // A negative angle scale (Fractint's '!') swaps the meaning of the turns.
        float c, s;
        cosSinDegrees(std::isfinite(*p) ? *p * double(t.angleScale < 0 ? -sign : sign) : 0.0, c, s);
        rotate(a, b, c, s);
    } else if (m_angleSigma > 0) {
        float r = (m_angle + jitter(m_angleSigma)) * sign;
        rotate(a, b, std::cos(r), std::sin(r));
    } else if (t.angleScale != 1.0f) {
        float r = m_angle * t.angleScale * sign;
        rotate(a, b, std::cos(r), std::sin(r));
    } else {
        rotate(a, b, m_cos, m_sin * sign);
    }
}

// F and its kin: a segment ahead, or inside { } a polygon's edge, or in a generalized cylinder a
// control point. One if-else chain: GCC predicts an early return unlikely (the loop ran 2% slower).
[[gnu::always_inline]] inline void Turtle::drawForward(State& t, Act act, const double* p, size_t i) {
    if (m_moves) movementAdjust(t);  // cpfg: the tropisms bend the heading before each step
    float len = p ? float(*p) * scaleOf(t) : m_stepSigma > 0 ? t.length + jitter(m_stepSigma) : t.length;
    len *= growth(i);
    if (!m_polygons.empty()) {  // inside { }, F outlines the polygon (cpfg)
        if (m_polygonEdgesDrawn) segment(t, len, i);  // and draws its segment (PlantGL)
        else t.pos += t.H * len;
        if (act == Act::Draw) vertex(t);
    } else if (t.curve >= 0) {  // a generalized cylinder: a control point, no cylinder
        t.pos += t.H * len;
        addBound(t.pos);
        if (m_tropismE != 0) bend(t);
        curvePoint(t, m_curves[size_t(t.curve)].subdivisions);
    } else {
        segment(t, len, i);
    }
}

// f and its kin: a step ahead that draws nothing (a polygon's vertex inside { }).
[[gnu::always_inline]] inline void Turtle::moveForward(State& t, Act act, const double* p, size_t i) {
    if (m_moves) movementAdjust(t);
    float len = (p ? float(*p) * scaleOf(t) : t.length) * growth(i);
    t.pos += t.H * len;
    t.lastSegment = -1;
    addBound(t.pos);
    if (act == Act::Move && !m_polygons.empty()) vertex(t);
}

// $ and @v: L turned horizontal about H.
[[gnu::always_inline]] inline void Turtle::levelLeft(State& t) {
    glm::vec3 h = toGlm(t.H);
    glm::vec3 l = glm::cross(glm::vec3(0, 1, 0), h);
    float n = glm::length(l);
    if (n > 1e-6f) {
        t.L = fromGlm(l / n);
    }
}

// [ and ]: the turtle kept and taken back.
[[gnu::always_inline]] inline void Turtle::pushBranch(State& t) {
    m_usedBrackets = true;
    m_stack.push_back(t);  // PodBuffer: no per-push construction
    if (m_moves) m_elasticStack.push_back(m_elastic);
    const std::int16_t parentCurve = t.curve;
    t.curve = -1;  // a branch draws its own stem (or starts its own @Gs)
    if (parentCurve >= 0 && m_cpfg) forkCurve(t, parentCurve);  // cpfg: it goes on from the last control point
    t.order = std::uint16_t(std::min<int>(t.order + 1, 65535));
    if (m_gradient && t.colour < 0) t.stemColour = stemColour(t);
    t.length *= m_branchLength;
    t.width *= m_branchWidth;
    t.lastSegment = -1;  // a branch does not continue its parent's taper
}
[[gnu::always_inline]] inline void Turtle::popBranch(State& t) {
    if (!m_stack.empty()) {  // an unbalanced ']' is harmless
        t = m_stack.back();
        m_stack.pop_back();
        if (m_moves && !m_elasticStack.empty()) {
            m_elastic = m_elasticStack.back();
            m_elasticStack.pop_back();
        }
    }
}

// Polygons: { opens one, . adds a vertex (or a contour's point), } closes it, }(name) keeps it.
[[gnu::always_inline]] inline void Turtle::beginPolygon(const State& t) {
    m_polygons.emplace_back();
    m_polygons.back().push_back(toGlm(t.pos));
    m_polygonFrames.push_back({toGlm(t.pos), toGlm(t.H), toGlm(t.L), toGlm(up(t))});
}
[[gnu::always_inline]] inline void Turtle::polygonVertex(const State& t) {
    if (!m_polygons.empty()) vertex(t);
    else if (m_capturing && m_contour.size() < 4096) m_contour.push_back(glm::vec2(float(t.pos[0]), float(t.pos[1])));
}
[[gnu::always_inline]] inline void Turtle::endPolygon(State& t) {
    if (!m_polygons.empty()) {
        emitPolygon(t, m_polygons.back(), nullptr, &m_polygonFrames.back());
        m_polygons.pop_back();
        m_polygonFrames.pop_back();
    } else if (t.curve >= 0 && m_g.settings.bracePaths) {  // the end of an L-system Explorer path
        curveCommand(t, Act::CurveEnd, nullptr);
    }
}
[[gnu::always_inline]] inline void Turtle::endPolygonKept(State& t, const double* p) {
    if (!m_polygons.empty()) {
        if (p && *p != m_emptyName) keepPolygon(t, m_polygons.back(), m_polygonFrames.back(), *p);
        else emitPolygon(t, m_polygons.back(), nullptr, &m_polygonFrames.back());
        m_polygons.pop_back();
        m_polygonFrames.pop_back();
    } else if (t.curve >= 0) {  // a path's end, kept by that name
        const std::int16_t c = t.curve;
        curveCommand(t, Act::CurveEnd, nullptr);
        if (p && *p != m_emptyName) keepTube(size_t(c), *p);
    }
}

// ! and #: the width set, or narrowed or widened by the grammar's factor.
[[gnu::always_inline]] inline void Turtle::stepWidth(State& t, Act act, const double* p) {
    // A width given as a number is absolute: no automatic scaling then (ABOP 2.8).
    if (p) m_absoluteWidths = true;
    // cpfg: a width set or stepped by number is times the turtle's scale (@D).
    if (m_widthSteps && !p) t.width = std::max(0.0f, t.width + (act == Act::WidthDec ? -m_widthStep : m_widthStep) * scaleOf(t));
    else t.width = p ? float(*p) * scaleOf(t) : act == Act::WidthDec ? t.width * m_widthFactor : t.width / m_widthFactor;
    // Taper: the segment before ends as thick as the next one starts.
    if (t.lastSegment >= 0) m_seg->at(size_t(t.lastSegment)).endRadius = t.width * 0.5f;
}

// ; ' and ,: the palette entry set, or the next one (; ') or the previous one (,).
[[gnu::always_inline]] inline void Turtle::stepColour(State& t, Act act, const double* p) {
    int index = p ? int(std::clamp(*p, -1e6, 1e6))
                  : act == Act::ColourNext ? std::max<int>(t.colour, 0) + m_colourStep : std::max<int>(t.colour, 0) - m_colourStep;
    const int n = int(m_palette.size());
    t.colour = std::int16_t(((index % n) + n) % n);
    t.stemColour = stemColour(t);
    t.pos[3] = 0;  // a new colour: its image starts afresh along the stems (PlantGL's axial length)
}

// A label at the turtle: text number p[0], in size p[1] (13 unless given).
[[gnu::always_inline]] inline void Turtle::addLabel(const State& t, const double* p, int arity) {
    if (p && *p >= 0 && *p < double(m_g.settings.labels.size()) && m_out.labels.size() < 100000)
        m_out.labels.push_back({toGlm(t.pos), m_g.settings.labels[size_t(*p)],
                                arity >= 2 && p[1] > 0 && p[1] < 200 ? float(p[1]) : 13.0f, t.stemColour});
}

[[gnu::always_inline]] inline void Turtle::apply(State& t, Act act, const double* p, size_t i, int arity) {
    switch (act) {
        case Act::Draw:
        case Act::DrawNoVertex: drawForward(t, act, p, i); break;
        case Act::Move:
        case Act::MoveNoVertex: moveForward(t, act, p, i); break;
        case Act::Left: turn(t, t.H, t.L, p, 1.0f); break;
        case Act::Right: turn(t, t.H, t.L, p, -1.0f); break;
        case Act::Down:
        case Act::Up: {
            v4 u = up(t);
            turn(t, t.H, u, p, act == Act::Up ? 1.0f : -1.0f);
            break;
        }
        case Act::RollLeft:
        case Act::RollRight: {
            v4 u = up(t);
            turn(t, t.L, u, p, act == Act::RollLeft ? 1.0f : -1.0f);
            break;
        }
        case Act::Around:
            t.H = -t.H;
            t.L = -t.L;
            break;
        case Act::Horizontal: levelLeft(t); break;
        case Act::Push: pushBranch(t); break;
        case Act::Pop: popBranch(t); break;
        case Act::PolyBegin: beginPolygon(t); break;
        case Act::PolyVertex: polygonVertex(t); break;
        case Act::ContourStart:
        case Act::ContourEnd:
        case Act::ContourUse:
        case Act::ContourSides: contourCommand(t, act, p); break;
        case Act::PolyEnd: endPolygon(t); break;
        case Act::PolyEndSave: endPolygonKept(t, p); break;
        case Act::InsertSaved:
            insertKept(t, p, arity);
            break;
        case Act::WidthDec:
        case Act::WidthInc: stepWidth(t, act, p); break;
        case Act::ColourNext:
        case Act::ColourPrev: stepColour(t, act, p); break;
        case Act::ScaleLength: t.length *= p ? float(*p) : 1.0f; break;
        case Act::ScaleAngle: t.angleScale *= p ? float(*p) : 1.0f; break;
        case Act::ScaleWidth:
            t.width *= p ? float(*p) : 1.0f;
            if (t.lastSegment >= 0) m_seg->at(size_t(t.lastSegment)).endRadius = t.width * 0.5f;
            break;
        case Act::Gravity:
            // @T(e): Lparser's bend towards gravity now; @T(e, x, y, z, 1): L-Py's tropism
            // before a step, H turned towards (x, y, z) by e times the angle between them.
            if (p && arity >= 5 && p[4] != 0) bendByFraction(t, glm::vec3(float(p[1]), float(p[2]), float(p[3])), float(p[0]));
            else bendTowards(t, glm::vec3(0, -1, 0), p ? float(*p) : 0.2f);
            break;
        case Act::Leaf:
        case Act::Petal:
        case Act::Sphere:
            m_surfaceModule = i;
            surface(t, act, p, growth(i));
            break;
        case Act::Query:
            if (m_opt.queries) m_opt.queries->push_back({toGlm(t.pos), toGlm(t.H), toGlm(up(t)), toGlm(t.L)});
            break;
        case Act::MoveTo:
        case Act::MoveRel:
        case Act::Pinpoint:
        case Act::PinpointRel:
        case Act::SetHeading:
        case Act::Disc: cpfgCommand(t, act, p, arity); break;
        case Act::LineTo:
        case Act::OLineTo:
        case Act::LineRel:
        case Act::OLineRel: lineTo(t, act, p, arity, i); break;
        case Act::CurveStart:
        case Act::CurvePoint:
        case Act::CurveEnd:
        case Act::CurveTangent:
        case Act::CurveEndKeep: curveCommand(t, act, p, arity); break;
        case Act::Label: addLabel(t, p, arity); break;
        case Act::CpfgLabel: cpfgLabel(t, p, arity); break;
        case Act::RadiusTangents: radiusTangents(p, arity); break;
        case Act::ElasticSet:
        case Act::ElasticInc:
        case Act::ElasticDec: elasticity(act, p, arity); break;
        case Act::PatchStart:
        case Act::PatchPoint:
        case Act::PatchDraw: patchCommand(t, act, p, arity); break;
        case Act::ScaleSet:
            if (p && std::isfinite(*p)) t.length = float(*p) / m_invStep;
            break;
        case Act::ScaleMul:
        case Act::ScaleDiv: {
            // blackbox.c: a factor of 0 is refused; without one, the view file's multiplier
            const float f = p ? (std::isfinite(*p) && *p != 0 ? float(*p) : 1.0f) : m_scaleMultiplier;
            t.length = act == Act::ScaleMul ? t.length * f : t.length / f;
            break;
        }
        case Act::Section:
            t.section = p && *p >= 0 && *p < double(m_g.settings.sections.size()) ? std::int16_t(*p) : std::int16_t(-1);
            break;
        case Act::TextureScale: case Act::TextureUScale: case Act::TextureVScale:
        case Act::TextureTranslation: case Act::TextureRotation: case Act::TextureTransformation:
        case Act::TextureSet: textureCommand(t, act, p, arity); break;
        default: break;
    }
}

// A stem from the turtle to (x, y, z), or by it (LineRel, OLineRel); OLineTo and OLineRel
// also turn the heading towards it.
inline void Turtle::lineTo(State& t, Act act, const double* p, int arity, size_t i) {
    if (!p || arity < 3) return;
    v4 target{float(p[0]), float(p[1]), float(p[2]), 0};
    if (act == Act::LineRel || act == Act::OLineRel) target += t.pos, target[3] = 0;
    const v4 d = target - t.pos;
    const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0)) return;
    // The heading turned towards it by the least rotation (PlantGL's _tendTo), which turns
    // left and up with it (projecting left onto the new normal plane failed for a point
    // straight to the left).
    if (act == Act::OLineTo || act == Act::OLineRel) tendTo(t, toGlm(d));
    t.lastSegment = std::int32_t(m_seg->count());
    stem(t, t.pos, target, i);
    t.pos = target;
    addBound(t.pos);
    if (!m_polygons.empty()) vertex(t);
}

// A stem from a to b as thick as the turtle's width, drawn by module i (LineTo, an @g curve).
inline void Turtle::stem(const State& t, v4 a, v4 b, size_t i) {
    a[3] = b[3] = t.width * 0.5f;
    CylinderInstance& c = m_seg->next();
    std::memcpy(&c.start, &a, 16);
    std::memcpy(&c.end, &b, 16);
    c.colour = t.stemColour;
    c.order = t.order;
    c.step = m_opt.ages ? m_opt.ages[i] : 0;
    if (m_opt.segmentModules) m_opt.segmentModules->push_back(std::uint32_t(i));
}

[[gnu::always_inline]] inline void Turtle::segment(State& t, float len, size_t i) {
    t.lastSegment = std::int32_t(m_seg->count());
    CylinderInstance& c = m_seg->next();
    const float r = t.width * 0.5f;
    v4 a = t.pos;
    a[3] = r;
    t.pos += t.H * len;
    v4 b = t.pos;
    b[3] = r;
    std::memcpy(&c.start, &a, 16);  // start + startRadius
    std::memcpy(&c.end, &b, 16);    // end + endRadius
    c.colour = t.stemColour;
    c.order = t.order;
    c.step = m_opt.ages ? m_opt.ages[i] : 0;
    if (m_opt.segmentModules) m_opt.segmentModules->push_back(std::uint32_t(i));
    if (m_texturing) [[unlikely]] noteTexturedStem(t, len);
    addBound(t.pos);
    if (m_tropismE != 0) bend(t);
}

// `count` segments of the default length straight ahead (no jitter, tropism or growth).
inline void Turtle::segmentRun(State& t, size_t count, size_t first) {
    const float r = t.width * 0.5f;
    const std::uint32_t colour = t.stemColour;
    const v4 step = t.H * t.length;
    v4 a = t.pos;
    for (size_t k = 0; k < count; ++k) {
        CylinderInstance& c = m_seg->next();
        v4 b = a + step;
        v4 sa = a, sb = b;
        sa[3] = r;
        sb[3] = r;
        std::memcpy(&c.start, &sa, 16);
        std::memcpy(&c.end, &sb, 16);
        c.colour = colour;
        c.order = t.order;
        c.step = m_opt.ages ? m_opt.ages[first + k] : 0;
        if (m_opt.segmentModules) m_opt.segmentModules->push_back(std::uint32_t(first + k));
        a = b;
    }
    t.pos = a;
    t.lastSegment = std::int32_t(m_seg->count() - 1);
    addBound(t.pos);
}

// ABOP 2.2: after each segment, bend H towards T by e |H x T|.
inline void Turtle::bend(State& t) { bendTowards(t, m_tropism, m_tropismE); }
inline void Turtle::bendTowards(State& t, const glm::vec3& towards, float e) {
    glm::vec3 h = toGlm(t.H);
    glm::vec3 axis = glm::cross(h, towards);
    float mag = glm::length(axis);
    if (mag < 1e-6f) return;
    axis /= mag;
    float a = e * mag;
    t.H = fromGlm(rodrigues(h, axis, a));
    t.L = fromGlm(rodrigues(toGlm(t.L), axis, a));
}

// L-Py's elasticity (PlantGL's turtle): H turns towards `towards` by e times the angle
// between them.
inline void Turtle::bendByFraction(State& t, glm::vec3 towards, float e) {
    const float n = glm::length(towards);
    if (!(n > 1e-9f) || !(e > 0)) return;
    towards /= n;
    glm::vec3 h = toGlm(t.H);
    glm::vec3 axis = glm::cross(h, towards);
    const float mag = glm::length(axis);
    if (mag < 1e-6f) return;
    axis /= mag;
    const float a = std::min(e, 1.0f) * std::atan2(mag, glm::dot(h, towards));
    t.H = fromGlm(rodrigues(h, axis, a));
    t.L = fromGlm(rodrigues(toGlm(t.L), axis, a));
}

// H turned to `to` by the least rotation; straight behind, half a turn about up (PlantGL).
inline void Turtle::tendTo(State& t, glm::vec3 to) {
    const glm::vec3 h = toGlm(t.H);
    if (glm::dot(to, h) < 0 && glm::length(glm::cross(to, h)) < 1e-6f * glm::length(to)) rotate(t.H, t.L, -1.0f, 0.0f);
    else bendByFraction(t, to, 1.0f);
}

inline glm::vec3 Turtle::rodrigues(const glm::vec3& v, const glm::vec3& k, float a) {
    float c = std::cos(a), s = std::sin(a);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
}

}  // namespace sprout::turtle_impl
