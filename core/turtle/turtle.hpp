#pragma once
// The 3D turtle (ABOP chapter 1.5 and cpfg conventions): interprets a module string into a
// Geometry. Starts at the origin heading +Y (the renderer is Y-up), left -X, up +Z, so
// `+` turns counter-clockwise as seen from the front.
//
// F(l) G(l) draw forward (G adds no polygon vertex); f(l) g(l) move; + - turn about U;
// & ^ pitch about L; \ / roll about H; | turn around; $ roll L horizontal; [ ] push/pop;
// { . } polygon; ! # width; ; , ' colour; ~leaf ~petal (~l ~p) surfaces; @O(r) sphere.
#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

#include "core/turtle/geometry.hpp"
#include "core/language/grammar.hpp"
#include "core/language/successor_table.hpp"

namespace sprout {

// The turtle's frame where it met a query module (?P ?H ?U ?L), in drawing order.
struct QueryFrame {
    glm::vec3 position, heading, up, left;
};

struct TurtleOptions {
    int derivationSteps = 0;            // n of the drawn string, for step_scale
    std::uint64_t seed = 1;             // jitter
    const std::uint16_t* ages = nullptr;  // per module: the step that created it (optional)
    // Smooth growth (ABOP's developmental animation): modules created at `growStep` are drawn
    // at `growFraction` of their length and size, so they grow from nothing while that step
    // plays instead of popping in.
    int growStep = -1;
    float growFraction = 1.0f;
    // A big D0L string that is exactly step `derivationSteps` of the grammar is drawn from
    // its derivation tree: each repeated subtree is drawn once and then placed by a
    // transform (the same geometry up to float rounding, several times faster). False
    // always reads the string (tests compare the two).
    bool fromTree = true;
    std::size_t treeMinModules = 1 << 15;  // shorter strings are read: blocks would not pay
    std::vector<QueryFrame>* queries = nullptr;  // when set, receives the frame at each query module
    // When set (picking): the index in the drawn string of the module that drew each segment
    // and each leaf, petal or sphere, in the order they are written. The string is read, not
    // the derivation tree.
    std::vector<std::uint32_t>* segmentModules = nullptr;
    std::vector<std::uint32_t>* surfaceModules = nullptr;
    // False: no meshes are made (generalized cylinders' tubes, surface files): a walk for its
    // query frames (L-Py's query modules, filled at each step).
    bool meshes = true;
};

struct TurtleStats {
    bool fromTree = false;  // drawn from the derivation tree
    size_t blocks = 0;      // repeated subtrees drawn once and placed
};

// What the derivation hands the turtle for a big D0L string that is exactly step n of its
// grammar: the grammar's rules as a table, the axiom and n. The turtle may draw it from this
// tree instead of the string (core/derive/draw.hpp decides; the turtle includes no
// derivation header).
struct DerivationTree {
    const SuccessorTable& successors;
    const ModuleString& axiom;
    int n = 0;
};

// Draws `s` as it is into `out`, reusing its buffers: the caller has applied the grammar's
// interpretation rules (core/derive/draw.hpp: interpret does both). Never fails: unknown
// modules are ignored, unbalanced ']' is harmless, non-finite parameters are skipped.
void drawString(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out);
// Draws step `tree.n` from its derivation tree: each repeated subtree once, then placed (the
// same geometry as the string up to float rounding, several times faster). Returns fromTree
// false, having drawn nothing, when no subtree is worth placing.
TurtleStats drawTree(const DerivationTree& tree, const Grammar& g, const TurtleOptions& options, Geometry& out);
// Whether drawTree can draw this grammar with these options: nothing that depends on the
// absolute position or on the module's index (jitter, tropism, growth, picking), and
// interpretation rules (if any) that map each symbol to one fixed string.
bool treeDrawable(const Grammar& g, const TurtleOptions& options);

// Whether a module of this name draws a segment (F, G, LineTo...): what a drawing's memory is
// predicted from (core/derive/draw.hpp: checkDrawing).
bool drawsSegment(const std::string& name);

// Appends `g` turned by `yaw` degrees about +Y and moved to `at` (a plant of a forest).
void placeGeometry(const Geometry& g, float yaw, const glm::vec3& at, Geometry& out);

// Default palette (16 colours: 0 bark, 1..8 greens dark to light, 9.. flower colours).
std::uint32_t defaultPaletteColour(int index);

// Triangulates a simple polygon (concave allowed) by ear clipping in its best-fit plane;
// appends triangle indices (relative to `base`) to `indices`.
void triangulatePolygon(const std::vector<glm::vec3>& points, std::uint32_t base,
                        std::vector<std::uint32_t>& indices);

}  // namespace sprout
