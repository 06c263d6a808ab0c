#pragma once
// The parts of a plant as exporters see them: primitives (one per part and colour) whose
// triangles are produced on demand, a chunk at a time.
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "app/mesh/bake.hpp"
#include "app/mesh/meshes.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout::exporter {

enum class Source { Stems, Surfaces, Polygons };

struct Primitive {
    std::string part;  // "stems", "leaves", "petals", "spheres", "polygons"
    std::uint32_t colour = 0;  // 0xRRGGBBAA (sRGB)
    bool doubleSided = false;
    std::uint32_t texture = 0;  // its image, Geometry::textures[texture - 1] (polygons); 0: none
    Source source = Source::Stems;
    std::vector<std::uint32_t> items;  // stem runs, surfaces or polygon triangles
    std::size_t vertices = 0, indices = 0;
    glm::vec3 min{0.0f}, max{0.0f};
};

class ExportScene {
public:
    ExportScene(const Geometry& g, int sides);

    std::vector<Primitive> primitives;  // part order, then colour
    std::size_t stems() const { return m_runs.size(); }
    const Geometry& geometry() const { return m_g; }

    // Calls f(chunk) with the primitive's triangles a few thousand items at a time; the
    // chunk's indices count from the chunk's first vertex; a textured primitive's chunks have
    // their texcoords.
    template <class F>
    void forEachChunk(const Primitive& p, F&& f) const {
        mesh::BakedMesh chunk;
        constexpr std::size_t kItems = 4096;
        for (std::size_t i = 0; i < p.items.size(); i += kItems) {
            chunk.clear();
            emit(p, i, std::min(p.items.size(), i + kItems), chunk);
            f(chunk);
        }
    }
    void emit(const Primitive& p, std::size_t begin, std::size_t end, mesh::BakedMesh& out) const;

private:
    const Geometry& m_g;
    std::vector<CylinderInstance> m_runs;  // straight runs of stems merged
    std::vector<std::uint8_t> m_runLevel;
    mesh::CylinderMesh m_stem[3];
    mesh::SurfaceMesh m_leaf, m_petal, m_sphere;
    mesh::BakedMesh m_polygons;
};

// sRGB 0..255 -> linear 0..1 (glTF colour factors and MTL are linear).
float srgbToLinear(std::uint8_t c);

}  // namespace sprout::exporter
