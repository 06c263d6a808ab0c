#pragma once
// Compares two drawings of the same string (from the derivation tree and from the string):
// the same segments in the same order, equal up to float rounding. Reports the first
// difference only, so a wrong plant does not print a million lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/turtle/geometry.hpp"

namespace sprout::test {

inline bool near(const glm::vec3& a, const glm::vec3& b, float tol) {
    return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol && std::fabs(a.z - b.z) <= tol;
}

inline void expectSameDrawing(const Geometry& a, const Geometry& b, const std::string& what) {
    const glm::vec3 size = b.bounds.size();
    const float extent = std::max({size.x, size.y, size.z});
    // Float rounding differs between the two (the tree composes frames, the string turtle
    // turns one module at a time) and grows along long chains: the Gosper curve's 117,649
    // segments in a row end 0.3 units from exact arithmetic either way. A misplaced subtree
    // is off by whole segments.
    const float chain = std::max(1.0f, std::sqrt(float(b.cylinders.size()) / 1e4f));
    const float tol = 2e-4f * (1 + extent) * chain;
    EXPECT_TRUE(near(a.bounds.min, b.bounds.min, tol) && near(a.bounds.max, b.bounds.max, tol)) << what << ": bounds";
    EXPECT_EQ(a.planarCurve, b.planarCurve) << what;
    EXPECT_EQ(a.surfaces.size(), b.surfaces.size()) << what;
    // Polygon outlines pass through placed blocks: a closing vertex 1e-6 from the first one
    // is dropped or kept by rounding, a triangle more or less.
    EXPECT_NEAR(double(a.polygons.indices.size()), double(b.polygons.indices.size()), 6 + b.polygons.indices.size() / 100.0)
        << what;
    for (size_t i = 0; i < a.surfaces.size() && i < b.surfaces.size(); ++i) {
        const SurfaceInstance &x = a.surfaces[i], &y = b.surfaces[i];
        if (!near(x.position, y.position, tol) || !near(x.heading, y.heading, 1e-3f) || !near(x.up, y.up, 1e-3f) ||
            std::fabs(x.size - y.size) > 1e-3f * (1e-3f + y.size) || x.colour != y.colour || x.kind != y.kind) {
            ADD_FAILURE() << what << ": surface " << i << " of " << a.surfaces.size() << " differs: size " << x.size << " vs "
                          << y.size << ", colour " << std::hex << x.colour << " vs " << y.colour << std::dec;
            break;
        }
    }
    ASSERT_EQ(a.cylinders.size(), b.cylinders.size()) << what;
    for (size_t i = 0; i < a.cylinders.size(); ++i) {
        const CylinderInstance &x = a.cylinders[i], &y = b.cylinders[i];
        const float rtol = 1e-3f * (1e-3f + std::max(y.startRadius, y.endRadius));  // automatic widths follow the size
        if (!near(x.start, y.start, tol) || !near(x.end, y.end, tol) || std::fabs(x.startRadius - y.startRadius) > rtol ||
            std::fabs(x.endRadius - y.endRadius) > rtol || x.colour != y.colour || x.order != y.order || x.step != y.step) {
            ADD_FAILURE() << what << ": segment " << i << " of " << a.cylinders.size() << " differs: start (" << x.start.x
                          << ", " << x.start.y << ", " << x.start.z << ") vs (" << y.start.x << ", " << y.start.y << ", "
                          << y.start.z << "), end (" << x.end.x << ", " << x.end.y << ", " << x.end.z << ") vs (" << y.end.x
                          << ", " << y.end.y << ", " << y.end.z << "), radii " << x.startRadius << "/" << x.endRadius
                          << " vs " << y.startRadius << "/" << y.endRadius << ", colour " << std::hex << x.colour << " vs "
                          << y.colour << std::dec << ", order " << x.order << " vs " << y.order;
            return;
        }
    }
}

}  // namespace sprout::test
