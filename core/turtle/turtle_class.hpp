#pragma once
// The Turtle class: what it holds (its options, the frame, the stack, the output, the tree
// turtle's blocks) and what its files define. Its small members are here; the per-module
// step and the stems it draws are defined inline in turtle_step.hpp, where both readers
// (turtle.cpp, turtle_tree.cpp) inline them: see turtle_impl.hpp for the whole.
#include <cmath>
#include <cstdint>
#include <deque>
#include <array>
#include <map>
#include <unordered_map>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/language/successor_table.hpp"
#include "core/turtle/generalized_cylinder.hpp"
#include "core/turtle/turtle.hpp"
#include "core/turtle/turtle_buffers.hpp"
#include "core/turtle/turtle_state.hpp"

namespace sprout::turtle_impl {

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
        return m_stepSigma <= 0 && m_angleSigma <= 0 && m_tropismE == 0 && !m_opt.ages && !m_hasCurves && !m_scaled && !m_moves &&
               !m_opt.segmentModules && !m_opt.surfaceModules &&
               m_surfaceFiles.empty() && m_palette.size() <= 127 && m_colourStep == 1 && !m_widthSteps && !m_texturing &&
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

    // ---- The per-module step and what it inlines: defined inline in turtle_step.hpp ----

    // cos and sin of an angle in degrees, exact for a quarter turn.
    static inline void cosSinDegrees(double degrees, float& c, float& s);
    // Frame axes a and b turned by the module's angle (p), else the grammar's.
    [[gnu::always_inline]] inline void turn(const State& t, v4& a, v4& b, const double* p, float sign);
    // What module i (action act, parameters p) does to turtle t: the switch both readers inline.
    [[gnu::always_inline]] inline void apply(State& t, Act act, const double* p, size_t i, int arity = 1);
    // What apply's longer cases do, one helper each, inlined into its switch as they were
    // written in it: F and f, $ and @v, [ and ], { . } and }(name), ! and #, ; ' and ,, a label.
    [[gnu::always_inline]] inline void drawForward(State& t, Act act, const double* p, size_t i);
    [[gnu::always_inline]] inline void moveForward(State& t, Act act, const double* p, size_t i);
    [[gnu::always_inline]] inline void levelLeft(State& t);
    [[gnu::always_inline]] inline void pushBranch(State& t);
    [[gnu::always_inline]] inline void popBranch(State& t);
    [[gnu::always_inline]] inline void beginPolygon(const State& t);
    [[gnu::always_inline]] inline void polygonVertex(const State& t);
    [[gnu::always_inline]] inline void endPolygon(State& t);
    [[gnu::always_inline]] inline void endPolygonKept(State& t, const double* p);
    [[gnu::always_inline]] inline void stepWidth(State& t, Act act, const double* p);
    [[gnu::always_inline]] inline void stepColour(State& t, Act act, const double* p);
    [[gnu::always_inline]] inline void addLabel(const State& t, const double* p, int arity);
    // Stems: to a point (LineTo and its kin), from a to b, one segment ahead, a run of them.
    inline void lineTo(State& t, Act act, const double* p, int arity, size_t i);
    inline void stem(const State& t, v4 a, v4 b, size_t i);
    [[gnu::always_inline]] inline void segment(State& t, float len, size_t i);
    inline void segmentRun(State& t, size_t count, size_t first);
    // The heading bent: by tropism (ABOP 2.2), towards a vector, by a share of the angle to it
    // (L-Py's elasticity), or turned onto it.
    inline void bend(State& t);
    inline void bendTowards(State& t, const glm::vec3& towards, float e);
    inline void bendByFraction(State& t, glm::vec3 towards, float e);
    inline void tendTo(State& t, glm::vec3 to);
    static inline glm::vec3 rodrigues(const glm::vec3& v, const glm::vec3& k, float a);

    // ---- What the step calls: small helpers here, the rest in turtle_geometry.cpp ----

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

    // Generalized cylinders: @Gs starts one at the turtle, @Gc(n) adds a control point (and
    // makes n the pieces of each following span), @Ge(n) adds the last one, @Gt(s) sets the
    // tangents' length in chords. Every F in between is a control point too.
    [[gnu::noinline]] void curveCommand(State& t, Act act, const double* p, int arity = 1);
    [[gnu::noinline]] void forkCurve(State& t, std::int16_t parent);
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


    void vertex(const State& t);

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
    // Where each open polygon started (the frame a kept surface is stored in), and the
    // surfaces kept by name (L-system Explorer's `}(name)`), in that frame: x along L, y along
    // H, z along U.
    struct Frame { glm::vec3 origin, h, l, u; };
    // A polygon drawn (or into `into`), textured in the frame `at` (its '{'; none: the turtle's).
    void emitPolygon(const State& t, std::vector<glm::vec3>& pts, Mesh* into = nullptr, const Frame* at = nullptr);
    std::vector<Frame> m_polygonFrames;
    std::unordered_map<double, Mesh> m_saved;
    double m_emptyName = -1;
    void keepPolygon(const State& t, std::vector<glm::vec3>& pts, const Frame& at, double name);
    void insertKept(const State& t, const double* p, int arity);
    void keepMesh(Mesh&& world, const Frame& at, double name);
    // L-system Explorer's contours: the one being captured (its points' x and y), and those
    // named, as cross-sections after Settings::sections (State::section counts on from there).
    bool m_capturing = false;
    std::vector<glm::vec2> m_contour;
    std::vector<std::vector<glm::vec2>> m_contours;
    std::unordered_map<double, std::int16_t> m_contourIds;
    // The view file's contours (Grammar::curves), by id and sides, sampled when first chosen.
    std::map<std::pair<int, int>, std::int16_t> m_fileContours;
    void contourCommand(State& t, Act act, const double* p);
    void keepTube(std::size_t curve, double name);
    std::vector<std::uint32_t> m_palette;
    std::uint32_t m_byOrder[kOrderColours];
    State m_state;
    v4 m_min, m_max;
    float m_angle, m_cos, m_sin, m_angleSigma, m_stepSigma;
    bool m_polygonEdgesDrawn = false;  // Settings::polygonEdgesDrawn
    glm::vec3 m_tropism;
    float m_tropismE, m_widthFactor, m_branchLength, m_branchWidth;
    int m_colourStep = 1;           // what ; and , add and take (cpfg's color increment)
    float m_widthStep = 0;          // cpfg's line width increment: ! and # take and add it
    bool m_widthSteps = false;      // ! and # add m_widthStep instead of multiplying by m_widthFactor
    bool m_gradient, m_autoWidth, m_usedBrackets = false, m_colourModules = false, m_plainRuns = false;
    bool m_hasCurves = false;
    // cpfg's files (Grammar::dialect "cpfg"): @O, @c take diameters; with a scale (m_scaled:
    // @D modules or an initial scale), the scale is t.length over the step, m_invStep.
    bool m_cpfg = false, m_scaled = false;
    float m_invStep = 1, m_scaleMultiplier = 1;
    float scaleOf(const State& t) const { return m_scaled ? t.length * m_invStep : 1.0f; }
    void cpfgLabel(const State& t, const double* p, int arity);
    // cpfg's @Gr: the radius tangents the next control points take (turtle-wide, not per branch).
    glm::vec2 m_radiusIn{0, 0}, m_radiusOut{0, 0};
    bool m_scaleRadius = false;
    void radiusTangents(const double* p, int arity);
    // cpfg's tropisms and torques (Settings::movements): the turtle's elasticities, kept with
    // its state at '[' and ']'.
    bool m_moves = false;
    std::array<float, 10> m_elastic{};
    std::vector<std::array<float, 10>> m_elasticStack;
    [[gnu::noinline]] void movementAdjust(State& t);
    void elasticity(Act act, const double* p, int arity);
    // cpfg's L-system defined surfaces (patches.c): 4 x 4 control points where the turtle stood.
    struct Patch {
        int basis = 1;  // 1 Bezier, 2 B-spline, 3 Cardinal
        std::array<glm::vec3, 16> points{};
        std::uint16_t assigned = 0;  // a bit per point
    };
    std::map<double, Patch> m_patches;
    [[gnu::noinline]] void patchCommand(const State& t, Act act, const double* p, int arity);
    std::vector<const SurfaceFile*> m_surfaceFiles;  // per symbol, for Act::SurfaceFile
    // Textures (Settings::textures): per palette index, its image's id in Geometry::textures
    // (1-based; 0: none); the view file's (Settings::viewTextures) ids; and the texture
    // transforms the turtle's State::texture names (PlantGL's Texture2DTransformation: u, v
    // scaled, turned about a centre, then moved), the first none, with cpfg's @Tx choice.
    std::vector<std::uint32_t> m_paletteTexture, m_viewTexture;
    struct TexTransform {
        glm::vec2 scale{1, 1}, translation{0, 0}, centre{0.5f, 0.5f};
        float angle = 0;  // radians
        std::int32_t image = -1;  // @Tx's image id (0: none); -1: the palette entry's
        bool perSurface = false;  // @Tx's texture spans the surface (SurfaceFile::surfaceUvs)
        float along = 0;          // @Tx's: a tube's v a unit of length, times its width (cpfg's); 0: PlantGL's, 1
        glm::vec2 operator()(glm::vec2 uv) const {
            uv = uv * scale - centre;
            const float c = std::cos(angle), s = std::sin(angle);
            return glm::vec2(c * uv.x - s * uv.y, s * uv.x + c * uv.y) + centre + translation;
        }
    };
    std::vector<TexTransform> m_texTransforms{TexTransform{}};
    [[gnu::noinline]] void textureCommand(State& t, Act act, const double* p, int arity);
    // The image id of the surfaces turtle t draws now (its palette entry's), 0: none.
    std::uint32_t textureOf(const State& t) const {
        if (const std::int32_t chosen = m_texTransforms[size_t(t.texture)].image; chosen >= 0) return std::uint32_t(chosen);
        if (m_paletteTexture.empty() || t.colour < 0) return 0;
        const int n = int(m_paletteTexture.size());
        return t.colour < n ? m_paletteTexture[size_t(t.colour)] : 0;
    }
    // Stems and surfaces drawn with an image (turtle_textured.cpp): noted as they are drawn,
    // made triangles with texture coordinates at the finish (the instances have no room for
    // an image), and taken out of the instances. Only when an image is in the drawing.
    bool m_texturing = false;
    struct Textured {
        std::uint32_t index;      // into m_out.cylinders or m_out.surfaces
        std::uint32_t image;      // Geometry::textures id
        std::int16_t transform;   // m_texTransforms entry
        float v0 = 0, v1 = 0;     // a stem's v at its start and end (PlantGL's axial length)
        glm::vec3 left{0};        // a stem's turtle L: where u starts round it
    };
    std::vector<Textured> m_texturedStems, m_texturedSurfaces;
    std::size_t textured() const { return m_texturedStems.size() + m_texturedSurfaces.size(); }
    [[gnu::noinline]] void noteTexturedStem(State& t, float len);
    [[gnu::noinline]] void noteTexturedSurface(const State& t);
    void drawTextured();
    // A textured polygon's texture coordinates (cpfg's: s along -L, t along H of the frame at
    // its '{', over the outline's extent), from vertex `base` of the polygon mesh.
    void polygonTexcoords(const State& t, const Frame& at, std::uint32_t base);
    struct OpenCurve {
        GeneralizedCylinder curve;
        int subdivisions = -4;  // pieces of each span (-4: up to 4, as it bends), until an @Gc(n) says
        Frame start{};         // the turtle's frame at @Gs (a kept tube is stored in it)
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
