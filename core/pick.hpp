#pragma once
// Picking: the stem or surface under a ray (a click in the 3D view). Brute force over the
// plant's instances with a test a few dozen operations long, so it needs no index built in
// advance and costs nothing until a click (tens of ms for 1.5 M segments on one core;
// bench/pick_bench).
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "core/geometry.hpp"

namespace sprout {

struct PickHit {
    enum class Kind { Segment, Surface } kind = Kind::Segment;
    std::uint32_t index = 0;  // into geometry.cylinders or geometry.surfaces
    float distance = 0;       // along the ray
};

// The nearest instance the ray from `origin` along `direction` (unit) passes through. A stem
// thinner than `slack` radians as seen from the origin is widened to it, so that a hairline
// stem (drawn as a line) can still be clicked.
std::optional<PickHit> pick(const Geometry& g, const glm::vec3& origin, const glm::vec3& direction, float slack = 0.003f);

}  // namespace sprout
