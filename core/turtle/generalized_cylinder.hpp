#pragma once
// cpfg's generalized cylinders (@Gs ... @Gc(n) ... @Ge(n)): a stem drawn as one smooth tube
// through the turtle's positions instead of a chain of cylinders. The turtle records control
// points (position, heading, radius, colour); the tube is a cubic Hermite curve through them,
// its tangents the turtle's headings scaled by the chord, the radius interpolated along it,
// swept with a rotation-minimising frame (no twist) into a triangle mesh.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/turtle/geometry.hpp"

namespace sprout {

struct CurvePoint {
    glm::vec3 position;
    glm::vec3 heading;  // unit
    float radius;
    std::uint32_t colour;
    int subdivisions;   // pieces of the span that ends here; -n: up to n, as the span bends
    // cpfg's @Gr radius tangents (general.c): the span is a Hermite curve in (t, radius) from
    // (0, r0) to (1, r1), its tangents `radiusIn` (at this point, ending the span before) and
    // the previous point's `radiusOut`; (0, 0): linear. `scaleRadius`: their radius parts are
    // times the span's length (@Gr(1)).
    glm::vec2 radiusIn{0, 0}, radiusOut{0, 0};
    bool scaleRadius = false;
};

struct GeneralizedCylinder {
    std::vector<CurvePoint> points;
    glm::vec3 left{-1, 0, 0};   // the turtle's left at the start: the frame's first axis
    float tangentScale = 1.0f;  // @Gt: the Hermite tangents' length, in chords
    // The cross-section (SetContour), the radius one unit, x along the frame's left and y
    // along its up; empty: a circle of 12 sides. Closed when its last point is its first
    // (then capped), else an open surface (a leaf blade swept along its midrib).
    std::vector<glm::vec2> section;
    // Its image (Geometry::textures id; 0: none) and how it lies: PlantGL's Extrusion gives u the
    // share of the section's length around it, v the length along the axis, then the
    // turtle's texture transform (scaled, turned by `texAngle` radians about `texCentre`, moved).
    std::uint32_t image = 0;
    glm::vec2 texScale{1, 1}, texTranslation{0, 0}, texCentre{0.5f, 0.5f};
    float texAngle = 0;
};

// Appends the tube (open ends capped) to `mesh`; radii are multiplied by `radiusScale` (the
// turtle's automatic width). Curves of fewer than 2 points add nothing.
void appendTube(const GeneralizedCylinder& curve, float radiusScale, Mesh& mesh);

}  // namespace sprout
