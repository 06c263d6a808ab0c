#pragma once
// Picking: the stem or surface under a ray (a click in the 3D view). Brute force over the
// plant's instances with a test a few dozen operations long, so it needs no index built in
// advance and costs nothing until a click (tens of ms for 1.5 M segments on one core;
// bench/pick_bench).
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/turtle/geometry.hpp"

namespace sprout {

struct PickHit {
    enum class Kind { Segment, Surface } kind = Kind::Segment;
    std::uint32_t index = 0;  // into geometry.cylinders or geometry.surfaces
    float distance = 0;       // along the ray
};

// The nearest instance the ray from `origin` along `direction` (unit) passes through. A stem
// thinner than `slack` radians as seen from the origin is widened to it, so that a hairline
// stem (drawn as a line) can still be clicked; `minRadius` does the same in world units (an
// orthographic view, where a pixel is the same size at every depth).
std::optional<PickHit> pick(const Geometry& g, const glm::vec3& origin, const glm::vec3& direction, float slack = 0.003f,
                            float minRadius = 0.0f);

// Highlights for picked stems and leaves: each segment as a hexagonal tube a little wider than
// it, each surface as a diamond around it, in `colour` (0xRRGGBBAA). At most `limit` segments
// are drawn (the first ones); the rest are counted, not shown.
void highlightMesh(const Geometry& g, const std::vector<std::uint32_t>& segments, const std::vector<std::uint32_t>& surfaces,
                   std::uint32_t colour, Mesh& out, std::size_t limit = 300000);

}  // namespace sprout
