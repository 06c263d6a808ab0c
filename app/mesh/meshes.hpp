#pragma once
// The unit meshes the renderer instances: a capped cylinder, a prism, and (from core) a leaf,
// a petal, a sphere.
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "core/turtle/unit_surfaces.hpp"

namespace sprout::mesh {

// Cylinder vertices: x, z on the unit circle (scaled by cos of the cap angle), y the offset
// along the axis in radii (negative below the start, positive past the end), w 0 at the
// start ring, 1 at the end ring. The hemispherical caps close the joints between segments.
struct CylinderMesh {
    std::vector<glm::vec4> vertices;
    std::vector<std::uint32_t> indices;
};
CylinderMesh makeCylinder(int sides, int capRings);

// The leaf, petal and sphere: core/turtle/unit_surfaces.hpp (the turtle draws textured ones).
using sprout::SurfaceMesh;
using sprout::makeLeaf;
using sprout::makePetal;
using sprout::makeSphere;

}  // namespace sprout::mesh

namespace sprout::mesh {

// An open tube (no caps) for stems a pixel or two wide: 2 rings of `sides` vertices.
CylinderMesh makePrism(int sides);

}  // namespace sprout::mesh
