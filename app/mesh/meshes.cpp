#include "app/mesh/meshes.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace sprout::mesh {
namespace {
constexpr float kPi = 3.14159265358979f;
}

CylinderMesh makeCylinder(int sides, int capRings) {
    CylinderMesh m;
    // Rings from the bottom of the start cap to the top of the end cap.
    struct Ring {
        float y, scale, end;
    };
    std::vector<Ring> rings;
    for (int r = capRings; r >= 1; --r) {
        float a = kPi / 2 * float(r) / float(capRings);
        rings.push_back({-std::sin(a), std::cos(a), 0});
    }
    rings.push_back({0, 1, 0});
    rings.push_back({0, 1, 1});
    for (int r = 1; r <= capRings; ++r) {
        float a = kPi / 2 * float(r) / float(capRings);
        rings.push_back({std::sin(a), std::cos(a), 1});
    }
    // Poles close the caps.
    std::uint32_t bottom = 0;
    m.vertices.push_back({0, -1, 0, 0});
    for (const Ring& ring : rings)
        for (int s = 0; s < sides; ++s) {
            float a = 2 * kPi * float(s) / float(sides);
            m.vertices.push_back({std::cos(a) * ring.scale, ring.y, std::sin(a) * ring.scale, ring.end});
        }
    std::uint32_t top = std::uint32_t(m.vertices.size());
    m.vertices.push_back({0, 1, 0, 1});
    auto at = [&](size_t ring, int s) { return std::uint32_t(1 + ring * size_t(sides) + size_t((s + sides) % sides)); };
    for (int s = 0; s < sides; ++s) m.indices.insert(m.indices.end(), {bottom, at(0, s + 1), at(0, s)});
    for (size_t r = 0; r + 1 < rings.size(); ++r)
        for (int s = 0; s < sides; ++s)
            m.indices.insert(m.indices.end(), {at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    size_t last = rings.size() - 1;
    for (int s = 0; s < sides; ++s) m.indices.insert(m.indices.end(), {at(last, s), at(last, s + 1), top});
    return m;
}

}  // namespace sprout::mesh

namespace sprout::mesh {

CylinderMesh makePrism(int sides) {
    CylinderMesh m;
    for (float end : {0.0f, 1.0f})
        for (int s = 0; s < sides; ++s) {
            float a = 2 * 3.14159265358979f * float(s) / float(sides);
            m.vertices.push_back({std::cos(a), 0, std::sin(a), end});
        }
    const std::uint32_t n = std::uint32_t(sides);
    for (std::uint32_t s = 0; s < n; ++s) {
        std::uint32_t a = s, b = (s + 1) % n;
        m.indices.insert(m.indices.end(), {a, b, n + b, a, n + b, n + a});
    }
    return m;
}

}  // namespace sprout::mesh
