#pragma once
// Instances baked into world-space triangles on the CPU. A software rasteriser runs complex
// vertex shaders slowly (llvmpipe: ~0.5 us per vertex for a cylinder that reads its segment
// from a buffer texture, ~0.06 us for a plain transformed vertex), so the renderer draws
// stems, leaves and spheres as one prebuilt mesh with the simplest shader. Exports reuse it.
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "app/mesh/meshes.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout::mesh {

struct BakedVertex {
    glm::vec3 position;
    glm::vec3 normal;
    std::uint32_t colour;  // 0xRRGGBBAA
};
static_assert(sizeof(BakedVertex) == 28);

struct BakedMesh {
    std::vector<BakedVertex> vertices;
    std::vector<std::uint32_t> indices;
    // Empty when nothing is textured; else texture coordinates for the first vertices (the
    // others: none), as Mesh::texcoords.
    std::vector<TexCoord> texcoords;
    void clear() {
        vertices.clear();
        indices.clear();
        texcoords.clear();
    }
};

// A tapered cylinder from a unit CylinderMesh (x, z ring, y cap offset in radii, w end).
void bakeCylinder(const CylinderInstance& c, const CylinderMesh& mesh, BakedMesh& out);
// A leaf, petal or sphere from its unit mesh in the turtle frame.
void bakeSurface(const SurfaceInstance& s, const SurfaceMesh& mesh, BakedMesh& out);
// The turtle's polygons as they are.
void bakePolygons(const Mesh& polygons, BakedMesh& out);
// The translucent triangles (one of whose vertices has an alpha below 255) moved after the
// others, each part in its order; how many they are.
std::size_t translucentLast(BakedMesh& m);
// The first `opaque` triangles' textured ones (their first vertex names an image) moved after
// the others, grouped by image: the groups, in order (their first triangle, how many, the image).
struct TextureRange {
    std::size_t first = 0, count = 0;
    std::uint32_t texture = 0;  // Geometry::textures[texture - 1]
};
std::vector<TextureRange> texturedLast(BakedMesh& m, std::size_t opaque);
// The first `opaque` triangles regrouped: those of colours that do not shine first, then those
// of each shining colour together (`shines`: by colour, the first listed for one counts).
// The groups of shining triangles, in order: their first triangle, how many, how they shine.
struct ShineRange {
    std::size_t first = 0, count = 0;
    Shine shine;
};
std::vector<ShineRange> groupShines(BakedMesh& m, std::size_t opaque, const std::vector<std::pair<std::uint32_t, Shine>>& shines);

}  // namespace sprout::mesh
