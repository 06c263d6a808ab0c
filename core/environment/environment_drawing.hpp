#pragma once
// The environment drawn with the plant (the viewer, and `sprout render --show-environment`):
// regions to grow in and attraction shapes as translucent glass, obstacles as stone, the
// ground plane, the attraction points still free as small dots, and on demand a horizontal
// slice of the light grid (clear where the sky is open, deep blue in the plant's shade).
#include <cstdint>

#include "core/environment/environment.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout {

struct EnvironmentView {
    bool lightSlice = false;
    double sliceHeight = 0.5;  // 0 the plant's lowest point, 1 its top
};

// Appends the environment's triangles to `out` (colours 0xRRGGBBAA, alpha below 255 where
// translucent). `grown` is the plant as drawn (the light grid and used-up points come from it);
// `seed` the plant's seed (the attraction points). False with `error` when the light slice asks
// for a grid that is too big (the plant was refused the same way).
bool drawEnvironment(const Environment& env, const Geometry& grown, std::uint64_t seed, const EnvironmentView& view,
                     Mesh& out, std::string* error = nullptr);

}  // namespace sprout
