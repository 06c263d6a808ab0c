#include "app/mesh/bake.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace sprout::mesh {

void bakeCylinder(const CylinderInstance& c, const CylinderMesh& mesh, BakedMesh& out) {
    glm::vec3 axis = c.end - c.start;
    float len = glm::length(axis);
    glm::vec3 d = len > 1e-9f ? axis / len : glm::vec3(0, 1, 0);
    glm::vec3 helper = std::fabs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    glm::vec3 s1 = glm::normalize(glm::cross(d, helper));
    glm::vec3 s2 = glm::cross(d, s1);
    const std::uint32_t base = std::uint32_t(out.vertices.size());
    for (const glm::vec4& v : mesh.vertices) {
        float r = v.w > 0.5f ? c.endRadius : c.startRadius;
        glm::vec3 centre = v.w > 0.5f ? c.end : c.start;
        glm::vec3 offset = v.x * s1 + v.z * s2 + d * v.y;
        float ol = glm::length(offset);
        out.vertices.push_back({centre + r * offset, ol > 1e-9f ? offset / ol : d, c.colour});
    }
    for (std::uint32_t i : mesh.indices) out.indices.push_back(base + i);
}

void bakeSurface(const SurfaceInstance& s, const SurfaceMesh& mesh, BakedMesh& out) {
    glm::vec3 H = glm::normalize(s.heading), U = glm::normalize(s.up);
    glm::vec3 L = glm::cross(U, H);
    glm::mat3 frame(L, H, U);
    const std::uint32_t base = std::uint32_t(out.vertices.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        out.vertices.push_back({s.position + s.size * (frame * mesh.positions[i]), frame * mesh.normals[i], s.colour});
    for (std::uint32_t i : mesh.indices) out.indices.push_back(base + i);
}

void bakePolygons(const Mesh& p, BakedMesh& out) {
    const std::uint32_t base = std::uint32_t(out.vertices.size());
    for (size_t i = 0; i < p.positions.size(); ++i) out.vertices.push_back({p.positions[i], p.normals[i], p.colours[i]});
    for (std::uint32_t i : p.indices) out.indices.push_back(base + i);
    if (!p.texcoords.empty()) {
        out.texcoords.resize(base);
        out.texcoords.insert(out.texcoords.end(), p.texcoords.begin(), p.texcoords.end());
    }
}

std::vector<TextureRange> texturedLast(BakedMesh& m, std::size_t opaque) {
    std::vector<TextureRange> out;
    if (m.texcoords.empty()) return out;
    opaque = std::min(opaque, m.indices.size() / 3);
    auto image = [&](std::size_t t) { return m.indices[3 * t] < m.texcoords.size() ? m.texcoords[m.indices[3 * t]].texture : 0u; };
    std::vector<std::uint32_t> images;
    for (std::size_t t = 0; t < opaque; ++t)
        if (const std::uint32_t k = image(t); k && std::find(images.begin(), images.end(), k) == images.end()) images.push_back(k);
    if (images.empty()) return out;
    std::vector<std::vector<std::uint32_t>> groups(images.size() + 1);  // 0: untextured
    for (std::size_t t = 0; t < opaque; ++t) {
        const std::uint32_t k = image(t);
        auto& g = groups[k ? std::size_t(std::find(images.begin(), images.end(), k) - images.begin()) + 1 : 0];
        g.insert(g.end(), m.indices.begin() + std::ptrdiff_t(3 * t), m.indices.begin() + std::ptrdiff_t(3 * t + 3));
    }
    std::size_t at = 0;
    for (std::size_t k = 0; k < groups.size(); ++k) {
        std::copy(groups[k].begin(), groups[k].end(), m.indices.begin() + std::ptrdiff_t(3 * at));
        if (k > 0) out.push_back({at, groups[k].size() / 3, images[k - 1]});
        at += groups[k].size() / 3;
    }
    return out;
}

std::size_t translucentLast(BakedMesh& m) {
    auto seeThrough = [&](std::size_t t) {
        for (std::size_t k = 0; k < 3; ++k)
            if ((m.vertices[m.indices[t + k]].colour & 0xFFu) != 0xFFu) return true;
        return false;
    };
    std::vector<std::uint32_t> opaque, translucent;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
        if (seeThrough(t)) translucent.insert(translucent.end(), m.indices.begin() + std::ptrdiff_t(t), m.indices.begin() + std::ptrdiff_t(t + 3));
    if (translucent.empty()) return 0;
    opaque.reserve(m.indices.size() - translucent.size());
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
        if (!seeThrough(t)) opaque.insert(opaque.end(), m.indices.begin() + std::ptrdiff_t(t), m.indices.begin() + std::ptrdiff_t(t + 3));
    opaque.insert(opaque.end(), translucent.begin(), translucent.end());
    m.indices = std::move(opaque);
    return translucent.size() / 3;
}

std::vector<ShineRange> groupShines(BakedMesh& m, std::size_t opaque, const std::vector<std::pair<std::uint32_t, Shine>>& shines) {
    std::vector<ShineRange> out;
    if (shines.empty()) return out;
    std::vector<std::uint32_t> colours;  // the shining colours, the first of each
    for (const auto& [c, s] : shines)
        if (std::find(colours.begin(), colours.end(), c) == colours.end()) colours.push_back(c), out.push_back({0, 0, s});
    std::vector<std::vector<std::uint32_t>> groups(colours.size() + 1);  // 0: plain
    opaque = std::min(opaque, m.indices.size() / 3);
    for (std::size_t t = 0; t < opaque; ++t) {
        const std::uint32_t c = m.vertices[m.indices[3 * t]].colour;
        const auto at = std::find(colours.begin(), colours.end(), c);
        auto& g = groups[at == colours.end() ? 0 : std::size_t(at - colours.begin()) + 1];
        g.insert(g.end(), m.indices.begin() + std::ptrdiff_t(3 * t), m.indices.begin() + std::ptrdiff_t(3 * t + 3));
    }
    std::size_t at = 0;
    for (std::size_t k = 0; k < groups.size(); ++k) {
        std::copy(groups[k].begin(), groups[k].end(), m.indices.begin() + std::ptrdiff_t(3 * at));
        if (k > 0) out[k - 1].first = at, out[k - 1].count = groups[k].size() / 3;
        at += groups[k].size() / 3;
    }
    out.erase(std::remove_if(out.begin(), out.end(), [](const ShineRange& r) { return r.count == 0; }), out.end());
    return out;
}

}  // namespace sprout::mesh
