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

#include "core/geometry.hpp"
#include "core/grammar.hpp"

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
};

struct TurtleStats {
    bool fromTree = false;  // drawn from the derivation tree
    size_t blocks = 0;      // repeated subtrees drawn once and placed
};

// Interprets `s` (after the grammar's interpretation rules, if any) into `out`, reusing its
// buffers. Never fails: unknown modules are ignored, unbalanced ']' is harmless, non-finite
// parameters are skipped.
TurtleStats interpret(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out);

// Appends `g` turned by `yaw` degrees about +Y and moved to `at` (a plant of a forest).
void placeGeometry(const Geometry& g, float yaw, const glm::vec3& at, Geometry& out);

// Default palette (16 colours: 0 bark, 1..8 greens dark to light, 9.. flower colours).
std::uint32_t defaultPaletteColour(int index);

// Triangulates a simple polygon (concave allowed) by ear clipping in its best-fit plane;
// appends triangle indices (relative to `base`) to `indices`.
void triangulatePolygon(const std::vector<glm::vec3>& points, std::uint32_t base,
                        std::vector<std::uint32_t>& indices);

}  // namespace sprout
