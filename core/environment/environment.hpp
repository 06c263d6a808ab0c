#pragma once
// What an environment answers (core/language/environment_spec.hpp says what each one is and
// what its ?E modules receive): the light grid over the plant grown so far, the attraction
// points still free, and the answer to each ?E. The derivation asks these between steps.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/language/environment_spec.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout {

// The light grid of one step: shadow per voxel, made from the geometry grown so far.
struct LightGrid {
    glm::dvec3 origin{0.0};
    double voxel = 1;
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> shadow;
    double lightAt(const glm::dvec3& p) const;
};

// The key of the cell `cell` wide that holds p (a hash key: 21 bits an axis), defined for any p:
// a point beyond 2^50 cells, or NaN, has the far key, which no cell of an environment's points
// has.
std::uint64_t cellKey(const glm::dvec3& p, double cell);

// The light grid for the plant drawn so far; false with `error` when it would be too big
// (over Environment::kMaxLightCells).
bool buildLight(const Environment& env, const Geometry& grown, LightGrid& grid, std::string& error);

// The attraction points still free after the plant drawn so far used up those near it (seeded
// by `seed`, the same points every step, so the answer depends on the plant only).
std::vector<glm::dvec3> freePoints(const Environment& env, const Geometry& grown, std::uint64_t seed);

// Space colonisation answers all buds at once: each free point pulls its nearest bud.
// `params[b]` points at bud b's parameters (arity `arities[b]`).
void answerAttraction(const Environment& env, const std::vector<glm::dvec3>& buds, const std::vector<glm::dvec3>& points,
                      const std::vector<double*>& params, const std::vector<int>& arities);

// The answer to one ?E at `position` heading `heading` (unit): writes `arity` parameters.
// `light` is the step's light grid (light environments only).
void answer(const Environment& env, const glm::dvec3& position, const glm::dvec3& heading, double* params, int arity,
            const LightGrid* light = nullptr);

}  // namespace sprout
