#pragma once
// The turtle's machinery, shared by the three files that make it:
//   core/turtle/turtle.cpp           the string turtle: reads a module string, one module at a time
//   core/turtle/turtle_tree.cpp      the tree-drawing optimizer: draws a D0L string from its derivation
//                                    tree, each repeated subtree once, placed by a transform
//   core/turtle/turtle_geometry.cpp  the geometry they emit beyond stems: polygons, surfaces, discs,
//                                    generalized cylinders, automatic widths and bounds
// Here: the segment writer, the tree turtle's workspace, and the Turtle class with its
// per-module step (apply), which both readers inline; the actions, the frame (SIMD vectors)
// and the state pushed at brackets are in turtle_state.hpp.
#include "core/turtle/turtle.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <glm/geometric.hpp>

#include "core/language/successor_table.hpp"
#include "core/turtle/generalized_cylinder.hpp"
#include "core/turtle/turtle_state.hpp"

namespace sprout::turtle_impl {

// Segments go through a small staging buffer that is flushed with non-temporal stores: the
// 40-byte instances of a big plant are far more than the caches hold, and plain stores would
// first read every destination line (measured: 63 MB of instances for the fractal plant n=10).
class SegmentWriter {
public:
    // `stream`: non-temporal stores, for output that is not read again soon.
    explicit SegmentWriter(PodBuffer<CylinderInstance>& out, bool stream = true) : m_out(out), m_stream(stream) {}
    ~SegmentWriter() { flush(); }
    CylinderInstance& next() {
        if (m_staged == kStage) flush();
        return m_stage[m_staged++];
    }
    std::size_t count() const { return m_out.size() + m_staged; }
    CylinderInstance& at(std::size_t i) { return i >= m_out.size() ? m_stage[i - m_out.size()] : m_out[i]; }
    void flush() {
        if (!m_staged) return;
        const std::size_t size = m_out.size();
        if (size + m_staged > m_out.capacity()) m_out.reserve(std::max<std::size_t>(2 * m_out.capacity(), size + kStage * 64));
        m_out.resizeUninitialized(size + m_staged);
        char* dst = reinterpret_cast<char*>(m_out.data() + size);
        const char* src = reinterpret_cast<const char*>(m_stage);
        const std::size_t bytes = m_staged * sizeof(CylinderInstance);
#if defined(__SSE2__)
        if (m_stream && (reinterpret_cast<std::uintptr_t>(dst) & 15) == 0 && bytes % 16 == 0) {
            for (std::size_t o = 0; o < bytes; o += 16)
                _mm_stream_si128(reinterpret_cast<__m128i*>(dst + o), _mm_load_si128(reinterpret_cast<const __m128i*>(src + o)));
        } else {
            std::memcpy(dst, src, bytes);
        }
#else
        std::memcpy(dst, src, bytes);
#endif
        m_staged = 0;
    }
    void finish() {
        flush();
#if defined(__SSE2__)
        _mm_sfence();
#endif
    }

private:
    static constexpr std::size_t kStage = 128;  // 5 KB: 128 x 40 bytes, a multiple of 16
    PodBuffer<CylinderInstance>& m_out;
    bool m_stream;
    alignas(16) CylinderInstance m_stage[kStage];
    std::size_t m_staged = 0;
};

// What drawing from the derivation tree works in: blocks being built (on the heap: builds
// nest as deep as the derivation, and a writer holds 5 KB) and the blocks made. Kept per
// thread between interpretations: fresh buffers each time cost more in page faults (the
// kernel zeroing new pages) than placing the blocks.
struct TreeScratch {
    PodBuffer<CylinderInstance> segments;
    PodBuffer<SurfaceInstance> surfaces;
    std::vector<v4> points;
    SegmentWriter writer{segments, false};
};
struct TreeWorkspace {
    PodBuffer<CylinderInstance> blockSegments;
    PodBuffer<SurfaceInstance> blockSurfaces;
    std::vector<v4> blockPoints;
    std::deque<TreeScratch> scratch;  // one per block being built, nested (stable addresses)
    void clear() {
        blockSegments.clear();
        blockSurfaces.clear();
        blockPoints.clear();
    }
    // A pathological grammar's 80 MB is not kept for the rest of the thread's life.
    void trim() {
        if (blockSegments.capacity() > (4u << 20) / sizeof(CylinderInstance)) *this = TreeWorkspace{};
    }
};
inline TreeWorkspace& treeWorkspace() {
    thread_local TreeWorkspace w;
    return w;
}

class Turtle {
public:
    Turtle(const Grammar& g, const TurtleOptions& o, Geometry& out);

    void run(const ModuleString& s);

    // Draws step n of a D0L grammar from its derivation tree instead of its string (which
    // must be that step: see drawTree). A subtree that occurs more than once is drawn once
    // in a frame of its own, as a block, and then placed wherever it occurs by transforming
    // its segments: no dispatch per module, and the string is never read.
    TurtleStats runTree(const SuccessorTable& tree, const ModuleString& axiom, int n);
    // Whether runTree can draw this grammar: nothing that depends on the absolute position
    // or on the module's index (jitter, tropism, growth), and interpretation rules (if any)
    // that map each symbol to one fixed string.
    bool treeApplicable() const {
        return m_stepSigma <= 0 && m_angleSigma <= 0 && m_tropismE == 0 && !m_opt.ages && !m_hasCurves &&
               !m_opt.segmentModules && !m_opt.surfaceModules &&
               m_surfaceFiles.empty() &&
               simpleInterpretation(m_g);
    }
    static bool simpleInterpretation(const Grammar& g) {
        for (const auto& list : g.interpretation.bySymbol) {
            if (list.size() > 1) return false;
            for (auto idx : list) {
                const Production& p = g.interpretation.productions[idx];
                if (p.hasContext() || p.stochastic() || p.condition || p.slotCount || !p.successor.args.empty()) return false;
                for (SymbolId c : p.successor.symbols)
                    if (c == Alphabet::kCut) return false;
            }
        }
        return true;
    }

private:
    template <bool Parametric>
    void runLoop(const ModuleString& s);

    static constexpr int kOrderColours = 32;

    // ---- Drawing from the derivation tree (D0L) ----
    //
    // A block is the drawing of S(s, d) (symbol s after d steps) by a turtle that starts at
    // the origin in the identity frame with length 1 and width 1. Placing it for a turtle t
    // maps the identity frame's axes (-L, H, U) to t's, scales positions by t.length and
    // radii by t.width, and adds t's branch order. This is exact because nothing a block may
    // contain depends on where the turtle is: only F G f g, turns, pitches, rolls, |, [ ],
    // ! # @L @W, leaves, petals, spheres, and ; , ' as palette steps from the colour the
    // turtle brings (no $, polygons or gravity).

    static constexpr std::int32_t kEntrySegment = -2;  // lastSegment: the one before the block
    static constexpr std::uint32_t kInheritColour = 0xFFFFFFFF;  // in a block: the turtle's colour
    static constexpr std::uint64_t kMinBlockModules = 16;      // smaller: walking is as fast
    static constexpr std::uint64_t kMaxBlockModules = 1 << 16;  // larger: occurs too rarely to pay
    static constexpr std::size_t kMaxBlockSegments = 1 << 21;   // all blocks: 80 MB at most

    struct Block {
        std::uint32_t first, count;        // segments in m_blockSegs, in the identity frame
        std::uint32_t firstPoint, points;  // places moved to (f g), for the bounds
        v4 pos, H, L;                      // the turtle after the block, in the identity frame
        float length, width;               // factors on the turtle's length and width
        std::uint32_t firstSurface, surfaces;  // in m_blockSurfs, in the identity frame
        std::int32_t lastSegment;          // index in the block, kEntrySegment or -1
        std::int8_t colour;                // palette steps at the end, -1: none taken
        bool brackets;
        bool colours;                      // some segment takes palette steps
    };
    enum class BlockState : std::uint8_t { No, Unbuilt, Built };


    static bool blockAction(Act a) {
        switch (a) {
            case Act::None: case Act::Draw: case Act::DrawNoVertex: case Act::Move: case Act::MoveNoVertex:
            case Act::Left: case Act::Right: case Act::Down: case Act::Up: case Act::RollLeft:
            case Act::RollRight: case Act::Around: case Act::Push: case Act::Pop: case Act::WidthDec:
            case Act::WidthInc: case Act::ScaleLength: case Act::ScaleWidth: case Act::ColourNext:
            case Act::ColourPrev: case Act::Leaf: case Act::Petal: case Act::Sphere:
                return true;
            default:
                return false;
        }
    }

    // Which (s, d) become blocks: those that occur at least twice in the tree, are of a
    // useful size, contain only block actions and close every bracket they open.
    // Returns how many there are.
    size_t planBlocks(const ModuleString& axiom, int n);

    // What a symbol of the derived string draws: its own action, or the actions of its
    // interpretation rule's successor (cpfg's homomorphism, applied once at the leaves).
    void setLeaves();

    [[gnu::noinline]] void walkLeaves(SymbolId s, State& t);
    void walk(SymbolId s, int d, State& t);

    void build(SymbolId s, int d);

    // Draws block b for turtle t and moves t to where the block leaves it.
    void place(const Block& b, State& t);


    // cos and sin of an angle in degrees, exact for a quarter turn: a float pi/2 has a cosine
    // of -4.4e-8, and a 90-degree curve turned 5 M times drifted 12 degrees round (a square
    // drawn as a smeared band).
    static void cosSinDegrees(double degrees, float& c, float& s) {
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

    [[gnu::always_inline]] inline void turn(const State& t, v4& a, v4& b, const double* p, float sign) {
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
    // The length factor of module i while its creation step is growing.
    float growth(size_t i) const {
        return m_opt.ages && m_opt.growStep >= 0 && m_opt.ages[i] == m_opt.growStep ? m_opt.growFraction : 1.0f;
    }
    // Seeded normal jitter truncated at 3 sigma.
    float jitter(float sigma) {
        for (;;) {
            float v = float(m_rng.normal(0.0, 1.0));
            if (std::fabs(v) <= 3.0f) return v * sigma;
        }
    }
    void addBound(v4 p) {
        m_min = __builtin_ia32_minps(m_min, p);
        m_max = __builtin_ia32_maxps(m_max, p);
    }

    [[gnu::always_inline]] inline void apply(State& t, Act act, const double* p, size_t i, int arity = 1) {
        switch (act) {
            case Act::Draw:
            case Act::DrawNoVertex: {
                float len = p ? float(*p) : m_stepSigma > 0 ? t.length + jitter(m_stepSigma) : t.length;
                len *= growth(i);
                if (!m_polygons.empty()) {  // inside { }, F outlines the polygon (cpfg)
                    t.pos += t.H * len;
                    if (act == Act::Draw) vertex(t);
                    break;
                }
                if (t.curve >= 0) {  // a generalized cylinder: a control point, no cylinder
                    t.pos += t.H * len;
                    addBound(t.pos);
                    if (m_tropismE != 0) bend(t);
                    curvePoint(t, m_curves[size_t(t.curve)].subdivisions);
                    break;
                }
                segment(t, len, i);
                break;
            }
            case Act::Move:
            case Act::MoveNoVertex: {
                float len = (p ? float(*p) : t.length) * growth(i);
                t.pos += t.H * len;
                t.lastSegment = -1;
                addBound(t.pos);
                if (act == Act::Move && !m_polygons.empty()) vertex(t);
                break;
            }
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
            case Act::Horizontal: {
                glm::vec3 h = toGlm(t.H);
                glm::vec3 l = glm::cross(glm::vec3(0, 1, 0), h);
                float n = glm::length(l);
                if (n > 1e-6f) {
                    t.L = fromGlm(l / n);
                }
                break;
            }
            case Act::Push:
                m_usedBrackets = true;
                m_stack.push_back(t);  // PodBuffer: no per-push construction
                t.curve = -1;  // a branch draws its own stem (or starts its own @Gs)
                t.order = std::uint16_t(std::min<int>(t.order + 1, 65535));
                if (m_gradient && t.colour < 0) t.stemColour = stemColour(t);
                t.length *= m_branchLength;
                t.width *= m_branchWidth;
                t.lastSegment = -1;  // a branch does not continue its parent's taper
                break;
            case Act::Pop:
                if (!m_stack.empty()) {  // an unbalanced ']' is harmless
                    t = m_stack.back();
                    m_stack.pop_back();
                }
                break;
            case Act::PolyBegin:
                m_polygons.emplace_back();
                m_polygons.back().push_back(toGlm(t.pos));
                break;
            case Act::PolyVertex:
                if (!m_polygons.empty()) vertex(t);
                break;
            case Act::PolyEnd:
                if (!m_polygons.empty()) {
                    emitPolygon(t, m_polygons.back());
                    m_polygons.pop_back();
                }
                break;
            case Act::WidthDec:
            case Act::WidthInc:
                // A width given as a number is absolute: no automatic scaling then (ABOP 2.8).
                if (p) m_absoluteWidths = true;
                t.width = p ? float(*p) : act == Act::WidthDec ? t.width * m_widthFactor : t.width / m_widthFactor;
                // Taper: the segment before ends as thick as the next one starts.
                if (t.lastSegment >= 0) m_seg->at(size_t(t.lastSegment)).endRadius = t.width * 0.5f;
                break;
            case Act::ColourNext:
            case Act::ColourPrev:
            {
                int index = p ? int(std::clamp(*p, -1e6, 1e6)) : act == Act::ColourNext ? std::max<int>(t.colour, 0) + 1 : std::max<int>(t.colour, 0) - 1;
                const int n = int(m_palette.size());
                t.colour = std::int8_t(((index % n) + n) % n);
                t.stemColour = stemColour(t);
            }
                break;
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
            case Act::CurveTangent: curveCommand(t, act, p); break;
            case Act::Label:
                if (p && *p >= 0 && *p < double(m_g.settings.labels.size()) && m_out.labels.size() < 100000)
                    m_out.labels.push_back({toGlm(t.pos), m_g.settings.labels[size_t(*p)],
                                            arity >= 2 && p[1] > 0 && p[1] < 200 ? float(p[1]) : 13.0f, t.stemColour});
                break;
            case Act::Section:
                t.section = p && *p >= 0 && *p < double(m_g.settings.sections.size()) ? std::int16_t(*p) : std::int16_t(-1);
                break;
            default: break;
        }
    }

    // Generalized cylinders: @Gs starts one at the turtle, @Gc(n) adds a control point (and
    // makes n the pieces of each following span), @Ge(n) adds the last one, @Gt(s) sets the
    // tangents' length in chords. Every F in between is a control point too.
    [[gnu::noinline]] void curveCommand(State& t, Act act, const double* p);
    void curvePoint(const State& t, int subdivisions);
    void placeSurfaceFile(const State& t, SymbolId id, const double* p);

    // cpfg's @M(x,y,z), @R(hx,hy,hz[,ux,uy,uz]) and @c(r): rare, so out of the hot switch.
    [[gnu::noinline]] void cpfgCommand(State& t, Act act, const double* p, int arity);

    // The colour of a stem: the palette entry set by ; , ', else the branch order's gradient
    // colour (or the bark colour).
    std::uint32_t stemColour(const State& t) const {
        // Inside a block being built, colours stay palette steps until the block is placed.
        if (m_level) return t.colour >= 0 ? std::uint32_t(t.colour) : kInheritColour;
        return t.colour >= 0 ? m_palette[size_t(t.colour)]
                             : m_gradient ? m_byOrder[std::min<int>(t.order, kOrderColours - 1)] : m_palette[0];
    }
    // A surface's colour: the palette entry set by ; , ', else its kind's own.
    std::uint32_t surfaceColour(const State& t, SurfaceKind kind) const {
        return colour(t.colour >= 0 ? t.colour
                      : kind == SurfaceKind::Sphere ? kSphereColour
                      : kind == SurfaceKind::Leaf   ? kLeafColour
                                                    : kPetalColour);
    }
    std::uint32_t colour(int index) const {
        int n = int(m_palette.size());
        return m_palette[size_t(((index % n) + n) % n)];
    }

    // A stem from the turtle to (x, y, z), or by it (LineRel, OLineRel); OLineTo and OLineRel
    // also turn the heading towards it.
    void lineTo(State& t, Act act, const double* p, int arity, size_t i) {
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
    void stem(const State& t, v4 a, v4 b, size_t i) {
        a[3] = b[3] = t.width * 0.5f;
        CylinderInstance& c = m_seg->next();
        std::memcpy(&c.start, &a, 16);
        std::memcpy(&c.end, &b, 16);
        c.colour = t.stemColour;
        c.order = t.order;
        c.step = m_opt.ages ? m_opt.ages[i] : 0;
        if (m_opt.segmentModules) m_opt.segmentModules->push_back(std::uint32_t(i));
    }

    [[gnu::always_inline]] inline void segment(State& t, float len, size_t i) {
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
        addBound(t.pos);
        if (m_tropismE != 0) bend(t);
    }

    // `count` segments of the default length straight ahead (no jitter, tropism or growth).
    void segmentRun(State& t, size_t count, size_t first) {
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
    void bend(State& t) { bendTowards(t, m_tropism, m_tropismE); }
    void bendTowards(State& t, const glm::vec3& towards, float e) {
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
    void bendByFraction(State& t, glm::vec3 towards, float e) {
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
    void tendTo(State& t, glm::vec3 to) {
        const glm::vec3 h = toGlm(t.H);
        if (glm::dot(to, h) < 0 && glm::length(glm::cross(to, h)) < 1e-6f * glm::length(to)) rotate(t.H, t.L, -1.0f, 0.0f);
        else bendByFraction(t, to, 1.0f);
    }

    static glm::vec3 rodrigues(const glm::vec3& v, const glm::vec3& k, float a) {
        float c = std::cos(a), s = std::sin(a);
        return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
    }

    void vertex(const State& t);

    void emitPolygon(const State& t, std::vector<glm::vec3>& pts);

    void surface(const State& t, Act act, const double* p, float grow);

    void finish();

    const Grammar& m_g;
    const TurtleOptions& m_opt;
    Geometry& m_out;
    SegmentWriter m_segments;
    SegmentWriter* m_seg = &m_segments;  // where segments go: the output, or a block being built
    Rng m_rng;
    std::vector<Act> m_actions;
    std::vector<std::uint8_t> m_arity;
    PodBuffer<State> m_stack;
    std::vector<std::vector<glm::vec3>> m_polygons;
    std::vector<std::uint32_t> m_palette;
    std::uint32_t m_byOrder[kOrderColours];
    State m_state;
    v4 m_min, m_max;
    float m_angle, m_cos, m_sin, m_angleSigma, m_stepSigma;
    glm::vec3 m_tropism;
    float m_tropismE, m_widthFactor, m_branchLength, m_branchWidth;
    bool m_gradient, m_autoWidth, m_usedBrackets = false, m_colourModules = false, m_plainRuns = false;
    bool m_hasCurves = false;
    std::vector<const SurfaceFile*> m_surfaceFiles;  // per symbol, for Act::SurfaceFile
    struct OpenCurve {
        GeneralizedCylinder curve;
        int subdivisions = 4;  // pieces of each span, until an @Gc(n) says otherwise
    };
    std::vector<OpenCurve> m_curves;
    bool m_absoluteWidths = false;
    // Drawing from the derivation tree
    const SuccessorTable* m_tree = nullptr;
    size_t m_alpha = 0;
    std::vector<std::uint32_t> m_leafStart;  // per symbol, into m_leafActs
    std::vector<Act> m_leafActs;
    std::vector<BlockState> m_blockState;  // [d * alphabet + s]
    std::vector<std::uint32_t> m_blockIndex;
    std::vector<Block> m_blocks;
    TreeWorkspace& m_work = treeWorkspace();
    PodBuffer<CylinderInstance>& m_blockSegs = m_work.blockSegments;
    PodBuffer<SurfaceInstance>& m_blockSurfs = m_work.blockSurfaces;
    std::vector<v4>& m_blockPoints = m_work.blockPoints;
    std::deque<TreeScratch>& m_scratch = m_work.scratch;
    int m_level = 0;                 // blocks being built
    size_t m_surfaceModule = 0;      // the module drawing the surface being made (picking)
    bool m_abort = false;            // the block being built cannot be one
};

}  // namespace sprout::turtle_impl
