#include "app/export/scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>

namespace sprout::exporter {

float srgbToLinear(std::uint8_t c) {
    float s = float(c) / 255.0f;
    return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

namespace {
constexpr int kAutoSides[3] = {10, 7, 5};
constexpr float kAutoThreshold[2] = {0.006f, 0.0015f};  // radius / plant size

bool continues(const CylinderInstance& a, const CylinderInstance& c) {
    if (a.colour != c.colour || a.endRadius != c.startRadius || a.order != c.order ||
        glm::length(c.start - a.end) > 1e-5f * (1 + glm::length(a.end)))
        return false;
    glm::vec3 da = a.end - a.start, dc = c.end - c.start;
    float la = glm::length(da), lc = glm::length(dc);
    return la > 0 && lc > 0 && glm::dot(da, dc) > 0.99999f * la * lc;
}
}  // namespace

ExportScene::ExportScene(const Geometry& g, int sides) : m_g(g) {
    for (int l = 0; l < 3; ++l) m_stem[l] = mesh::makeCylinder(sides > 0 ? sides : kAutoSides[l], 0);
    m_leaf = mesh::makeLeaf();
    m_petal = mesh::makePetal();
    m_sphere = mesh::makeSphere(16, 10);

    // Straight runs of equal stems become one tube: F -> FF plants shrink many times over.
    const float extent = std::max(glm::length(g.bounds.size()), 1e-6f);
    m_runs.reserve(g.cylinders.size() / 4 + 16);
    for (const auto& c : g.cylinders) {
        if (!m_runs.empty() && continues(m_runs.back(), c)) {
            m_runs.back().end = c.end;
            m_runs.back().endRadius = c.endRadius;
        } else {
            m_runs.push_back(c);
        }
    }
    m_runLevel.resize(m_runs.size());
    for (std::size_t i = 0; i < m_runs.size(); ++i) {
        float rel = std::max(m_runs[i].startRadius, m_runs[i].endRadius) / extent;
        m_runLevel[i] = rel >= kAutoThreshold[0] ? 0 : rel >= kAutoThreshold[1] ? 1 : 2;
    }

    // One primitive per part and colour, in a stable order.
    auto group = [&](const char* part, Source source, bool doubleSided, auto count, auto colourOf, auto accept,
                     auto textureOf) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> byColour;
        for (std::uint32_t i = 0; i < std::uint32_t(count); ++i)
            if (accept(i)) byColour[{colourOf(i), textureOf(i)}].push_back(i);
        for (auto& [key, items] : byColour) {
            Primitive p;
            p.part = part;
            p.colour = key.first;
            p.texture = key.second;
            p.doubleSided = doubleSided;
            p.source = source;
            p.items = std::move(items);
            primitives.push_back(std::move(p));
        }
    };
    auto all = [](std::uint32_t) { return true; };
    auto plain = [](std::uint32_t) { return 0u; };
    group("stems", Source::Stems, false, m_runs.size(), [&](std::uint32_t i) { return m_runs[i].colour; }, all, plain);
    const SurfaceKind kinds[3] = {SurfaceKind::Leaf, SurfaceKind::Petal, SurfaceKind::Sphere};
    const char* names[3] = {"leaves", "petals", "spheres"};
    for (int k = 0; k < 3; ++k)
        group(names[k], Source::Surfaces, k < 2, g.surfaces.size(), [&](std::uint32_t i) { return g.surfaces[i].colour; },
              [&](std::uint32_t i) { return g.surfaces[i].kind == kinds[k]; }, plain);
    mesh::bakePolygons(g.polygons, m_polygons);
    group("polygons", Source::Polygons, true, m_polygons.indices.size() / 3,
          [&](std::uint32_t t) { return m_polygons.vertices[m_polygons.indices[3 * t]].colour; }, all, [&](std::uint32_t t) {
              const std::uint32_t v = m_polygons.indices[3 * t];
              const std::uint32_t image = v < m_polygons.texcoords.size() ? m_polygons.texcoords[v].texture : 0;
              return image <= g.textures.size() ? image : 0u;
          });

    // Counts and exact bounds, which glTF wants before the data.
    for (Primitive& p : primitives) {
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
            p.vertices += chunk.vertices.size();
            p.indices += chunk.indices.size();
            for (const auto& v : chunk.vertices) {
                lo = glm::min(lo, v.position);
                hi = glm::max(hi, v.position);
            }
        });
        p.min = p.vertices ? lo : glm::vec3(0.0f);
        p.max = p.vertices ? hi : glm::vec3(0.0f);
    }
    std::erase_if(primitives, [](const Primitive& p) { return p.indices == 0; });
}

void ExportScene::emit(const Primitive& p, std::size_t begin, std::size_t end, mesh::BakedMesh& out) const {
    for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t i = p.items[k];
        switch (p.source) {
            case Source::Stems: mesh::bakeCylinder(m_runs[i], m_stem[m_runLevel[i]], out); break;
            case Source::Surfaces: {
                const SurfaceInstance& s = m_g.surfaces[i];
                mesh::bakeSurface(s, s.kind == SurfaceKind::Leaf ? m_leaf : s.kind == SurfaceKind::Petal ? m_petal : m_sphere, out);
                break;
            }
            case Source::Polygons: {
                const std::uint32_t base = std::uint32_t(out.vertices.size());
                for (int c = 0; c < 3; ++c) {
                    const std::uint32_t v = m_polygons.indices[3 * i + c];
                    out.vertices.push_back(m_polygons.vertices[v]);
                    if (p.texture) out.texcoords.push_back(v < m_polygons.texcoords.size() ? m_polygons.texcoords[v] : TexCoord{});
                    out.indices.push_back(base + c);
                }
                break;
            }
        }
    }
}

}  // namespace sprout::exporter
