#pragma once
// The predefined surfaces (~l leaves, ~p petals, @O spheres) as unit meshes in the turtle
// frame: x along L (left), y along H (heading), z along U (up). The renderer instances them;
// the turtle draws a textured one as triangles of its own (their `uvs` then).
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace sprout {

struct SurfaceMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    // Each position's place in an image: a blade's u runs across it, from its right edge
    // (seen from above) to its left, and v from its base (0) to its tip (1); a sphere's u runs
    // round it from U towards -L (PlantGL's) and v from the pole behind the heading (0) to the
    // one ahead (1).
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
};
SurfaceMesh makeLeaf(int along = 12, int across = 6);
SurfaceMesh makePetal(int along = 10, int across = 6);
SurfaceMesh makeSphere(int slices, int stacks);

}  // namespace sprout
