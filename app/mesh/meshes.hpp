#pragma once
// The unit meshes the renderer instances: a capped cylinder, a leaf, a petal, a sphere.
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace sprout::mesh {

// Cylinder vertices: x, z on the unit circle (scaled by cos of the cap angle), y the offset
// along the axis in radii (negative below the start, positive past the end), w 0 at the
// start ring, 1 at the end ring. The hemispherical caps close the joints between segments.
struct CylinderMesh {
    std::vector<glm::vec4> vertices;
    std::vector<std::uint32_t> indices;
};
CylinderMesh makeCylinder(int sides, int capRings);

// Surfaces in the turtle frame: x along L (left), y along H (heading), z along U (up).
struct SurfaceMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
};
SurfaceMesh makeLeaf(int along = 12, int across = 6);
SurfaceMesh makePetal(int along = 10, int across = 6);
SurfaceMesh makeSphere(int slices, int stacks);

}  // namespace sprout::mesh

namespace sprout::mesh {

// An open tube (no caps) for stems a pixel or two wide: 2 rings of `sides` vertices.
CylinderMesh makePrism(int sides);

}  // namespace sprout::mesh
