#include "core/turtle.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <glm/geometric.hpp>

#include "core/d0l.hpp"
#include "core/derive.hpp"
#include "core/generalized_cylinder.hpp"

namespace sprout {
namespace {

enum class Act : std::uint8_t {
    None, Draw, DrawNoVertex, Move, MoveNoVertex, Left, Right, Down, Up, RollLeft, RollRight,
    Around, Horizontal, Push, Pop, PolyBegin, PolyVertex, PolyEnd, WidthDec, WidthInc,
    ColourNext, ColourPrev, Leaf, Petal, Sphere, ScaleLength, ScaleAngle, ScaleWidth, Gravity,
    Query, MoveTo, SetHeading, Disc, CurveStart, CurvePoint, CurveEnd, CurveTangent,
};

Act actionOf(const std::string& name) {
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
        // step), move to a point, set the heading, roll L horizontal, a disc.
        {"?P", Act::Query}, {"?H", Act::Query}, {"?U", Act::Query}, {"?L", Act::Query},
        {"@M", Act::MoveTo}, {"@R", Act::SetHeading}, {"@v", Act::Horizontal}, {"@c", Act::Disc},
        // cpfg's generalized cylinders: start, control point, end, tangent length.
        {"@Gs", Act::CurveStart}, {"@Gc", Act::CurvePoint}, {"@Ge", Act::CurveEnd}, {"@Gt", Act::CurveTangent},
    };
    for (const auto& [n, a] : table)
        if (name == n) return a;
    return Act::None;
}

// ABOP's `'` steps through a colour map: index 0 is bark, 1..8 a ramp of greens from dark
// to light, then flower colours.
constexpr std::uint32_t kDefaultPalette[16] = {
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
    v4 pos{0, 0, 0, 0};
    v4 H{0, 1, 0, 0};
    v4 L{-1, 0, 0, 0};  // U is H x L, made when a pitch, roll or surface needs it
    float length = 1;
    float width = 1;  // diameter
    std::int32_t lastSegment = -1;  // the segment this branch's next segment continues
    std::uint16_t order = 0;
    std::int8_t colour = -1;  // palette index set by ; , ' (wrapped); -1: none set
    std::int16_t curve = -1;  // the generalized cylinder this branch draws into (@Gs); -1: none
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

std::uint32_t lerpColour(std::uint32_t a, std::uint32_t b, float t) {
    std::uint32_t out = 0;
    for (int shift = 24; shift >= 0; shift -= 8) {
        float x = float((a >> shift) & 0xFF), y = float((b >> shift) & 0xFF);
        out |= std::uint32_t(std::lround(x + (y - x) * t)) << shift;
    }
    return out;
}

// Parameters the turtle can use: finite, and small enough that float positions summed over
// millions of segments stay finite (beyond 1e30 is treated like infinity: not drawn).
bool finite(const double* p, int n) {
    for (int k = 0; k < n; ++k)
        if (!(std::fabs(p[k]) <= 1e30)) return false;
    return true;
}

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
TreeWorkspace& treeWorkspace() {
    thread_local TreeWorkspace w;
    return w;
}

class Turtle {
public:
    Turtle(const Grammar& g, const TurtleOptions& o, Geometry& out)
        : m_g(g), m_opt(o), m_out(out), m_segments(out.cylinders), m_rng(Rng::forStream(o.seed, 0x7077e)) {
        const auto& st = g.settings;
        m_actions.resize(g.alphabet.size());
        m_arity.resize(g.alphabet.size());
        for (size_t s = 0; s < g.alphabet.size(); ++s) {
            m_arity[s] = g.alphabet[SymbolId(s)].arity;
            m_actions[s] = actionOf(g.alphabet[SymbolId(s)].name);
            m_colourModules |= m_actions[s] == Act::ColourNext || m_actions[s] == Act::ColourPrev;
            m_hasCurves |= m_actions[s] == Act::CurveStart;
        }
        m_gradient = st.gradient == Toggle::On || (st.gradient == Toggle::Auto && !m_colourModules);
        m_autoWidth = st.width <= 0;
        m_angle = float(st.angle.mean) * kPi / 180.0f;
        m_cos = std::cos(m_angle);
        m_sin = std::sin(m_angle);
        m_angleSigma = float(st.angle.sigma) * kPi / 180.0f;
        m_stepSigma = float(st.step.sigma);
        m_tropism = glm::vec3(st.tropism[0], st.tropism[1], st.tropism[2]);
        if (glm::length(m_tropism) > 0) m_tropism = glm::normalize(m_tropism);
        m_tropismE = float(st.tropismStrength);
        m_widthFactor = float(st.widthFactor);
        m_branchLength = float(st.branchLength);
        // Automatic widths thin each branch order, as real stems do (da Vinci's rule keeps
        // the total cross-section roughly constant at a fork).
        m_branchWidth = m_autoWidth && st.branchWidth == 1 ? 0.75f : float(st.branchWidth);
        m_palette = st.palette;
        if (m_palette.empty()) m_palette.assign(std::begin(kDefaultPalette), std::end(kDefaultPalette));
        if (m_palette.size() > 127) m_palette.resize(127);  // the state keeps the index in a byte
        // Colour by branch order: bark at the trunk, approaching the tip colour with each
        // order (t = 1 - 0.55^order), so no pass is needed to find the deepest order first.
        float t = 0;
        for (int o = 0; o < kOrderColours; ++o, t = 1 - (1 - t) * 0.55f)
            m_byOrder[o] = lerpColour(st.barkColour, st.tipColour, t);
        m_state.length = float(st.step.mean * std::pow(st.stepScale, o.derivationSteps));
        m_state.width = m_autoWidth ? 1.0f : float(st.width);
        m_min = m_max = m_state.pos;
        m_state.stemColour = stemColour(m_state);
        // Runs of F can be batched when nothing changes from one segment to the next.
        m_plainRuns = m_stepSigma <= 0 && m_tropismE == 0 && !(o.ages && o.growStep >= 0);
    }

    void run(const ModuleString& s) {
        // Strings without parameters (most D0L plants) take a loop with no parameter walk.
        if (s.params.empty()) runLoop<false>(s);
        else runLoop<true>(s);
        finish();
    }

    // Draws step n of a D0L grammar from its derivation tree instead of its string (which
    // must be that step: see interpret). A subtree that occurs more than once is drawn once
    // in a frame of its own, as a block, and then placed wherever it occurs by transforming
    // its segments: no dispatch per module, and the string is never read.
    TurtleStats runTree(const D0LExpander& tree, const ModuleString& axiom, int n) {
        m_tree = &tree;
        m_alpha = m_actions.size();
        setLeaves();
        // Without a subtree to place, walking the tree module by module is slower than the string.
        if (!planBlocks(axiom, n)) return {};
        m_work.clear();
        State t = m_state;
        for (SymbolId s : axiom.symbols) walk(s, n, t);
        m_state = t;
        m_seg->finish();
        finish();
        m_work.trim();
        return {true, m_blocks.size()};
    }
    // Whether runTree can draw this grammar: nothing that depends on the absolute position
    // or on the module's index (jitter, tropism, growth), and interpretation rules (if any)
    // that map each symbol to one fixed string.
    bool treeApplicable() const {
        return m_stepSigma <= 0 && m_angleSigma <= 0 && m_tropismE == 0 && !m_opt.ages && !m_hasCurves &&
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
    void runLoop(const ModuleString& s) {
        const SymbolId* sym = s.symbols.data();
        const double* par = s.params.data();
        const size_t N = s.size();
        const Act* actions = m_actions.data();
        const std::uint8_t* arities = m_arity.data();
        // The state lives in a local for the loop so that the compiler keeps it in registers.
        State t = m_state;
        for (size_t i = 0; i < N; ++i) {
            const SymbolId id = sym[i];
            const double* p = nullptr;
            int arity = 0;
            if constexpr (Parametric) {
                arity = arities[id];
                p = par;
                par += arity;
            }
            const Act act = actions[id];
            if (act == Act::None) continue;
            if (act == Act::Draw && !arity && m_plainRuns && m_polygons.empty() && t.curve < 0) {
                // A run of plain F (F -> FF makes long ones): collinear segments in a tight loop.
                size_t j = i + 1;
                while (j < N && sym[j] == id) ++j;
                if (j - i > 1) {
                    segmentRun(t, j - i, i);
                    i = j - 1;
                    continue;
                }
            }
            if constexpr (Parametric) {
                if (arity && !finite(p, arity)) continue;  // NaN or infinity: skip, never draw garbage
            }
            apply(t, act, arity ? p : nullptr, i, arity);
        }
        m_state = t;
        m_seg->finish();
    }

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
    size_t planBlocks(const ModuleString& axiom, int n) {
        const size_t A = m_alpha, D = size_t(n) + 1;
        static constexpr std::uint64_t kSat = 1ull << 62;
        auto sat = [](std::uint64_t a) { return std::min(a, kSat); };
        std::vector<std::uint64_t> modules(D * A), occurs(D * A, 0);
        std::vector<std::uint8_t> ok(D * A);
        std::vector<std::int64_t> net(D * A), low(D * A);  // bracket depth change, lowest prefix
        for (size_t d = 0; d < D; ++d) {
            for (size_t s = 0; s < A; ++s) {
                const size_t k = d * A + s;
                const SymbolId id = SymbolId(s);
                if (d == 0 || m_tree->identity(id)) {
                    std::int64_t depth = 0, lowest = 0;
                    bool good = true;
                    for (std::uint32_t i = m_leafStart[s]; i < m_leafStart[s + 1]; ++i) {
                        const Act a = m_leafActs[i];
                        good = good && blockAction(a);
                        depth += a == Act::Push ? 1 : a == Act::Pop ? -1 : 0;
                        lowest = std::min(lowest, depth);
                    }
                    modules[k] = 1;
                    ok[k] = good;
                    net[k] = depth;
                    low[k] = lowest;
                    continue;
                }
                std::uint64_t m = 0;
                bool good = true;
                std::int64_t depth = 0, lowest = 0;
                for (const SymbolId* c = m_tree->successorBegin(id); c != m_tree->successorEnd(id); ++c) {
                    const size_t kc = (d - 1) * A + *c;
                    m = sat(m + modules[kc]);
                    good = good && ok[kc];
                    lowest = std::min(lowest, depth + low[kc]);
                    depth = std::clamp<std::int64_t>(depth + net[kc], -std::int64_t(kSat), std::int64_t(kSat));
                }
                modules[k] = m;
                ok[k] = good;
                net[k] = depth;
                low[k] = lowest;
            }
        }
        for (SymbolId s : axiom.symbols) occurs[size_t(n) * A + s] = sat(occurs[size_t(n) * A + s] + 1);
        for (size_t d = D - 1; d > 0; --d) {
            for (size_t s = 0; s < A; ++s) {
                const std::uint64_t o = occurs[d * A + s];
                if (!o || m_tree->identity(SymbolId(s))) continue;
                for (const SymbolId* c = m_tree->successorBegin(SymbolId(s)); c != m_tree->successorEnd(SymbolId(s)); ++c)
                    occurs[(d - 1) * A + *c] = sat(occurs[(d - 1) * A + *c] + o);
            }
        }
        m_blockState.assign(D * A, BlockState::No);
        m_blockIndex.assign(D * A, 0);
        size_t candidates = 0;
        for (size_t d = 1; d < D; ++d) {
            for (size_t s = 0; s < A; ++s) {
                const size_t k = d * A + s;
                if (occurs[k] >= 2 && ok[k] && net[k] == 0 && low[k] >= 0 && !m_tree->identity(SymbolId(s)) &&
                    modules[k] >= kMinBlockModules && modules[k] <= kMaxBlockModules)
                    m_blockState[k] = BlockState::Unbuilt, ++candidates;
            }
        }
        return candidates;
    }

    // What a symbol of the derived string draws: its own action, or the actions of its
    // interpretation rule's successor (cpfg's homomorphism, applied once at the leaves).
    void setLeaves() {
        m_leafStart.assign(m_alpha + 1, 0);
        m_leafActs.clear();
        for (size_t s = 0; s < m_alpha; ++s) {
            m_leafStart[s] = std::uint32_t(m_leafActs.size());
            const auto* list = s < m_g.interpretation.bySymbol.size() ? &m_g.interpretation.bySymbol[s] : nullptr;
            if (list && !list->empty()) {
                for (SymbolId c : m_g.interpretation.productions[list->front()].successor.symbols)
                    if (m_actions[c] != Act::None) m_leafActs.push_back(m_actions[c]);
            } else if (m_actions[s] != Act::None) {
                m_leafActs.push_back(m_actions[s]);
            }
        }
        m_leafStart[m_alpha] = std::uint32_t(m_leafActs.size());
    }

    void walk(SymbolId s, int d, State& t) {
        if (d == 0 || m_tree->identity(s)) {
            for (std::uint32_t i = m_leafStart[s]; i < m_leafStart[s + 1]; ++i) {
                const Act act = m_leafActs[i];
                if (m_level) {
                    // Inside a block being built: the segment before the block is not ours to taper.
                    if ((act == Act::WidthDec || act == Act::WidthInc || act == Act::ScaleWidth) && t.lastSegment == kEntrySegment) {
                        m_abort = true;
                        return;
                    }
                    apply(t, act, nullptr, 0);
                    if (act == Act::Move || act == Act::MoveNoVertex) m_scratch[m_level - 1].points.push_back(t.pos);
                    continue;
                }
                apply(t, act, nullptr, 0);
            }
            return;
        }
        const size_t k = size_t(d) * m_alpha + s;
        if (m_blockState[k] != BlockState::No && t.angleScale == 1.0f && m_polygons.empty()) {
            if (m_blockState[k] == BlockState::Unbuilt) build(s, d);
            if (m_blockState[k] == BlockState::Built) {
                const Block& b = m_blocks[m_blockIndex[k]];
                // A surface's size follows the turtle's length or width: not negative ones.
                if (!b.surfaces || (t.length > 0 && t.width > 0)) {
                    place(b, t);
                    return;
                }
            }
        }
        for (const SymbolId* c = m_tree->successorBegin(s); c != m_tree->successorEnd(s) && !m_abort; ++c) walk(*c, d - 1, t);
    }

    void build(SymbolId s, int d) {
        const size_t k = size_t(d) * m_alpha + s;
        m_blockState[k] = BlockState::No;  // unless it completes
        if (m_blockSegs.size() > kMaxBlockSegments) return;
        if (m_scratch.size() <= size_t(m_level)) m_scratch.emplace_back();
        TreeScratch& scratch = m_scratch[size_t(m_level)];
        scratch.segments.clear();
        scratch.surfaces.clear();
        scratch.points.clear();
        SegmentWriter& local = scratch.writer;
        SegmentWriter* outer = m_seg;
        const v4 outerMin = m_min, outerMax = m_max;
        const size_t stackBase = m_stack.size();
        const bool outerBrackets = m_usedBrackets;
        m_seg = &local;
        m_usedBrackets = false;
        ++m_level;
        State t;
        t.lastSegment = kEntrySegment;
        t.stemColour = stemColour(t);
        for (const SymbolId* c = m_tree->successorBegin(s); c != m_tree->successorEnd(s) && !m_abort; ++c) walk(*c, d - 1, t);
        local.finish();
        --m_level;
        m_seg = outer;
        m_min = outerMin;
        m_max = outerMax;
        const bool brackets = m_usedBrackets;
        m_usedBrackets = outerBrackets;
        if (m_abort || m_stack.size() != stackBase || t.order != 0) {
            m_abort = false;
            m_stack.resizeUninitialized(stackBase);
            return;  // walked instead, in the caller's frame
        }
        Block b;
        b.first = std::uint32_t(m_blockSegs.size());
        b.count = std::uint32_t(scratch.segments.size());
        b.firstPoint = std::uint32_t(m_blockPoints.size());
        b.points = std::uint32_t(scratch.points.size());
        b.pos = t.pos;
        b.H = t.H;
        b.L = t.L;
        b.length = t.length;
        b.width = t.width;
        b.lastSegment = t.lastSegment;
        b.colour = t.colour;
        b.brackets = brackets;
        b.colours = false;
        for (const auto& c : scratch.segments) b.colours |= c.colour != kInheritColour;
        b.firstSurface = std::uint32_t(m_blockSurfs.size());
        b.surfaces = std::uint32_t(scratch.surfaces.size());
        m_blockSurfs.append(scratch.surfaces.data(), scratch.surfaces.size());
        m_blockSegs.append(scratch.segments.data(), scratch.segments.size());
        m_blockPoints.insert(m_blockPoints.end(), scratch.points.begin(), scratch.points.end());
        m_blockIndex[k] = std::uint32_t(m_blocks.size());
        m_blocks.push_back(b);
        m_blockState[k] = BlockState::Built;
    }

    // Draws block b for turtle t and moves t to where the block leaves it.
    void place(const Block& b, State& t) {
        const v4 ax = -t.L, ay = t.H, az = up(t);  // the identity frame's x y z, turned
        const v4 sx = ax * t.length, sy = ay * t.length, sz = az * t.length;
        const v4 radius = v4{0, 0, 0, t.width};
        v4 origin = t.pos;
        origin[3] = 0;
        auto at = [&](v4 p) { return origin + sx * p[0] + sy * p[1] + sz * p[2] + p * radius; };
        // Colours: a segment that took no palette step has the turtle's colour (by branch order,
        // or its palette entry; inside a block being built, its step code); one that did is
        // that many steps from the turtle's palette entry.
        const bool byOrder = !m_level && t.colour < 0 && m_gradient;
        const std::uint32_t fixed = t.stemColour;
        const int order = t.order;
        const int palette = int(m_palette.size()), from = std::max<int>(t.colour, 0);
        auto stepped = [&](std::uint32_t code) {
            const int index = (from + int(code)) % palette;
            return m_level ? std::uint32_t(index) : m_palette[size_t(index)];
        };
        const std::size_t base = m_seg->count();
        const CylinderInstance* src = m_blockSegs.data() + b.first;
        const std::uint32_t count = b.count;
        v4 lo = m_min, hi = m_max;
        // Two copies of the loop: most blocks take no palette step, and the check costs there.
        auto segments = [&](auto colours) {
            v4 low = lo, high = hi;  // locals: in registers, not stored at every segment
            for (std::uint32_t i = 0; i < count; ++i) {
                v4 a, e;
                std::memcpy(&a, &src[i].start, 16);
                std::memcpy(&e, &src[i].end, 16);
                const v4 wa = at(a), we = at(e);
                CylinderInstance& c = m_seg->next();
                std::memcpy(&c.start, &wa, 16);
                std::memcpy(&c.end, &we, 16);
                const int o = std::min(order + src[i].order, 65535);
                c.order = std::uint16_t(o);
                c.colour = byOrder ? m_byOrder[std::min(o, kOrderColours - 1)] : fixed;
                if constexpr (decltype(colours)::value)
                    if (src[i].colour != kInheritColour) c.colour = stepped(src[i].colour);
                c.step = 0;
                low = __builtin_ia32_minps(low, we);
                high = __builtin_ia32_maxps(high, we);
            }
            lo = low;
            hi = high;
        };
        if (b.colours) segments(std::true_type{});
        else segments(std::false_type{});
        m_min = lo;
        m_max = hi;
        for (std::uint32_t i = 0; i < b.surfaces; ++i) {
            SurfaceInstance s = m_blockSurfs[b.firstSurface + i];
            const v4 p = at(fromGlm(s.position)), h = fromGlm(s.heading), u = fromGlm(s.up);
            s.position = toGlm(p);
            s.heading = toGlm(ax * h[0] + ay * h[1] + az * h[2]);
            s.up = toGlm(ax * u[0] + ay * u[1] + az * u[2]);
            s.size *= s.kind == SurfaceKind::Sphere ? t.width : t.length;
            if (s.colour != kInheritColour) s.colour = stepped(s.colour);
            else if (m_level) s.colour = t.colour >= 0 ? std::uint32_t(t.colour) : kInheritColour;
            else s.colour = surfaceColour(t, s.kind);
            if (m_level) {
                m_scratch[size_t(m_level) - 1].surfaces.push_back(s);
                continue;
            }
            m_out.surfaces.push_back(s);
            addBound(p);
            addBound(p + fromGlm(s.heading) * s.size);
        }
        for (std::uint32_t i = 0; i < b.points; ++i) {
            v4 p = at(m_blockPoints[b.firstPoint + i]);
            p[3] = 0;
            if (m_level) m_scratch[size_t(m_level) - 1].points.push_back(p);
            else addBound(p);
        }
        t.pos = at(b.pos);
        t.pos[3] = 0;
        const v4 H = ax * b.H[0] + ay * b.H[1] + az * b.H[2];
        const v4 L = ax * b.L[0] + ay * b.L[1] + az * b.L[2];
        t.H = H;
        t.L = L;
        t.length *= b.length;
        t.width *= b.width;
        if (b.colour >= 0) {
            t.colour = std::int8_t((from + b.colour) % palette);
            t.stemColour = stemColour(t);
        }
        if (b.lastSegment >= 0) t.lastSegment = std::int32_t(base) + b.lastSegment;
        else if (b.lastSegment == -1) t.lastSegment = -1;
        m_usedBrackets |= b.brackets;
    }


    [[gnu::always_inline]] inline void turn(const State& t, v4& a, v4& b, const double* p, float sign) {
        if (p) {
            // A negative angle scale (Fractint's '!') swaps the meaning of the turns.
            float r = float(*p) * kPi / 180.0f * (t.angleScale < 0 ? -sign : sign);
            rotate(a, b, std::cos(r), std::sin(r));
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
            case Act::Gravity: bendTowards(t, glm::vec3(0, -1, 0), p ? float(*p) : 0.2f); break;
            case Act::Leaf:
            case Act::Petal:
            case Act::Sphere: surface(t, act, p, growth(i)); break;
            case Act::Query:
                if (m_opt.queries) m_opt.queries->push_back({toGlm(t.pos), toGlm(t.H), toGlm(up(t)), toGlm(t.L)});
                break;
            case Act::MoveTo:
            case Act::SetHeading:
            case Act::Disc: cpfgCommand(t, act, p, arity); break;
            case Act::CurveStart:
            case Act::CurvePoint:
            case Act::CurveEnd:
            case Act::CurveTangent: curveCommand(t, act, p); break;
            default: break;
        }
    }

    // Generalized cylinders: @Gs starts one at the turtle, @Gc(n) adds a control point (and
    // makes n the pieces of each following span), @Ge(n) adds the last one, @Gt(s) sets the
    // tangents' length in chords. Every F in between is a control point too.
    [[gnu::noinline]] void curveCommand(State& t, Act act, const double* p) {
        if (act == Act::CurveStart) {
            if (m_curves.size() >= 32767) return;  // the state keeps the index in 16 bits
            m_curves.emplace_back();
            m_curves.back().curve.left = toGlm(t.L);
            t.curve = std::int16_t(m_curves.size() - 1);
            t.lastSegment = -1;
            curvePoint(t, 1);
            return;
        }
        if (t.curve < 0) return;
        auto& c = m_curves[size_t(t.curve)];
        const int n = p ? int(std::clamp(*p, 1.0, 64.0)) : c.subdivisions;
        if (act == Act::CurveTangent) {
            c.curve.tangentScale = p ? float(std::clamp(*p, 0.0, 10.0)) : 1.0f;
            return;
        }
        if (act == Act::CurvePoint) c.subdivisions = n;
        curvePoint(t, n);
        if (act == Act::CurveEnd) t.curve = -1;
    }
    void curvePoint(const State& t, int subdivisions) {
        auto& c = m_curves[size_t(t.curve)];
        const glm::vec3 p = toGlm(t.pos);
        if (!c.curve.points.empty() && glm::length(c.curve.points.back().position - p) < 1e-7f) {
            c.curve.points.back().radius = t.width * 0.5f;  // the same place: update, do not repeat
            c.curve.points.back().subdivisions = subdivisions;
            return;
        }
        c.curve.points.push_back({p, glm::normalize(toGlm(t.H)), t.width * 0.5f, t.stemColour, subdivisions});
    }

    // cpfg's @M(x,y,z), @R(hx,hy,hz[,ux,uy,uz]) and @c(r): rare, so out of the hot switch.
    [[gnu::noinline]] void cpfgCommand(State& t, Act act, const double* p, int arity) {
        if (act == Act::MoveTo) {
            if (!p || arity < 3) return;
            t.pos = v4{float(p[0]), float(p[1]), float(p[2]), 0};
            t.lastSegment = -1;  // the next segment starts a new stem there
            addBound(t.pos);
            if (!m_polygons.empty()) vertex(t);
            return;
        }
        if (act == Act::SetHeading) {
            if (!p || arity < 3) return;
            glm::vec3 h{float(p[0]), float(p[1]), float(p[2])};
            if (!(glm::length(h) > 1e-12f)) return;
            h = glm::normalize(h);
            glm::vec3 l = toGlm(t.L);
            if (arity >= 6) {  // with an up vector: L = U x H
                glm::vec3 u{float(p[3]), float(p[4]), float(p[5])};
                l = glm::cross(u, h);
            } else {           // keep the left vector as near as it was
                l -= glm::dot(l, h) * h;
            }
            if (!(glm::length(l) > 1e-6f)) {
                l = glm::cross(std::fabs(h.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), h);
            }
            t.H = fromGlm(h);
            t.L = fromGlm(glm::normalize(l));
            return;
        }
        // @c(r): a disc of radius r across the heading, as a 24-sided polygon.
        const float r = p ? float(p[0]) : t.width * 0.5f;
        if (!(r > 0)) return;
        const glm::vec3 c = toGlm(t.pos), l = toGlm(t.L), u = toGlm(up(t));
        std::vector<glm::vec3> pts;
        for (int k = 0; k < 24; ++k) {
            const float a = 2 * kPi * float(k) / 24;
            pts.push_back(c + r * (std::cos(a) * l + std::sin(a) * u));
            addBound(fromGlm(pts.back()));
        }
        emitPolygon(t, pts);
    }

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

    static glm::vec3 rodrigues(const glm::vec3& v, const glm::vec3& k, float a) {
        float c = std::cos(a), s = std::sin(a);
        return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
    }

    void vertex(const State& t) {
        auto& poly = m_polygons.back();
        glm::vec3 p = toGlm(t.pos);
        if (poly.empty() || glm::length(poly.back() - p) > 1e-6f) poly.push_back(p);
    }

    void emitPolygon(const State& t, std::vector<glm::vec3>& pts) {
        if (pts.size() > 1 && glm::length(pts.front() - pts.back()) < 1e-6f) pts.pop_back();
        if (pts.size() < 3) return;
        Mesh& m = m_out.polygons;
        // Newell's normal: robust for concave and slightly non-planar outlines.
        glm::vec3 n(0);
        for (size_t i = 0; i < pts.size(); ++i) {
            const glm::vec3& a = pts[i];
            const glm::vec3& b = pts[(i + 1) % pts.size()];
            n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        float len = glm::length(n);
        if (len < 1e-12f) return;
        n /= len;
        std::uint32_t base = std::uint32_t(m.positions.size());
        std::uint32_t col = t.colour >= 0 ? colour(t.colour) : colour(kLeafColour);
        for (const auto& p : pts) {
            m.positions.push_back(p);
            m.normals.push_back(n);
            m.colours.push_back(col);
            addBound(fromGlm(p));
        }
        triangulatePolygon(pts, base, m.indices);
    }

    void surface(const State& t, Act act, const double* p, float grow) {
        SurfaceInstance s;
        s.position = toGlm(t.pos);
        s.heading = toGlm(t.H);
        s.up = toGlm(up(t));
        if (act == Act::Sphere) {
            s.kind = SurfaceKind::Sphere;
            s.size = p ? float(*p) : t.width;  // radius
        } else {
            s.kind = act == Act::Leaf ? SurfaceKind::Leaf : SurfaceKind::Petal;
            s.size = p ? float(*p) : t.length;
        }
        s.colour = surfaceColour(t, s.kind);
        s.size *= grow;
        if (!(s.size > 0)) return;
        if (m_level) {  // a block being built: resolved when placed
            s.colour = t.colour >= 0 ? std::uint32_t(t.colour) : kInheritColour;
            m_scratch[size_t(m_level) - 1].surfaces.push_back(s);  // bounded when placed
            return;
        }
        m_out.surfaces.push_back(s);
        addBound(t.pos);
        addBound(t.pos + t.H * s.size);
    }

    void finish() {
        Geometry& out = m_out;
        out.bounds.empty = false;
        out.bounds.min = toGlm(m_min);
        out.bounds.max = toGlm(m_max);
        // Automatic width: stems in proportion to the plant, 1/80 of its size at the base.
        float k = 1.0f;
        if (m_autoWidth && !m_absoluteWidths) {
            glm::vec3 size = out.bounds.size();
            float extent = std::max({size.x, size.y, size.z});
            if (extent > 0) k = extent / 80.0f;
            for (auto& s : out.surfaces)
                if (s.kind == SurfaceKind::Sphere) s.size *= k;
        }
        if (k != 1.0f) {
            for (auto& c : out.cylinders) {
                c.startRadius *= k;
                c.endRadius *= k;
            }
        }
        for (const auto& c : m_curves) appendTube(c.curve, k, out.polygons);
        // A planar curve: every point in the z = 0 plane and no branches or surfaces.
        const float tol = 1e-4f * (1 + glm::length(out.bounds.size()));
        bool flat = std::fabs(out.bounds.min.z) < tol && std::fabs(out.bounds.max.z) < tol;
        auto view = m_g.settings.view;
        out.planarCurve = flat && view != ViewHint::Solid &&
                          (view == ViewHint::Flat || (!m_usedBrackets && out.surfaces.empty()));
    }

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
    struct OpenCurve {
        GeneralizedCylinder curve;
        int subdivisions = 4;  // pieces of each span, until an @Gc(n) says otherwise
    };
    std::vector<OpenCurve> m_curves;
    bool m_absoluteWidths = false;
    // Drawing from the derivation tree
    const D0LExpander* m_tree = nullptr;
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
    bool m_abort = false;            // the block being built cannot be one
};

}  // namespace

void Bounds::add(const glm::vec3& p) {
    if (empty) {
        min = max = p;
        empty = false;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::add(const Bounds& b) {
    if (b.empty) return;
    add(b.min);
    add(b.max);
}

void Geometry::clear() {
    cylinders.clear();
    surfaces.clear();
    polygons.clear();
    bounds = {};
    planarCurve = false;
}

std::uint32_t defaultPaletteColour(int index) { return kDefaultPalette[((index % 16) + 16) % 16]; }

constexpr int kTreeMaxDepth = 1024;  // the tree walk recurses once per step
constexpr size_t kTreeMaxTable = 1 << 22;

TurtleStats interpret(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out) {
    out.clear();
    {
        Turtle turtle(g, options, out);
        // A big D0L string is drawn from its derivation tree when it is exactly step n of the
        // grammar (checked: comparing costs a small part of interpreting). Interpretation
        // rules, if simple, are applied at the tree's leaves.
        const int n = options.derivationSteps;
        if (options.fromTree && s.size() >= options.treeMinModules && n > 0 && n <= kTreeMaxDepth &&
            turtle.treeApplicable() && D0LExpander::applicable(g) && (size_t(n) + 1) * g.alphabet.size() <= kTreeMaxTable) {
            D0LExpander tree(g);
            if (tree.matches(g.axiom, n, s))
                if (TurtleStats stats = turtle.runTree(tree, g.axiom, n); stats.fromTree) return stats;
        }
        if (g.interpretation.productions.empty()) {
            turtle.run(s);
            return {};
        }
    }
    ModuleString drawn = applyInterpretation(g, s, options.seed);
    TurtleOptions o = options;
    o.ages = nullptr;  // the interpretation changes positions: ages no longer line up
    Turtle(g, o, out).run(drawn);
    return {};
}

}  // namespace sprout
