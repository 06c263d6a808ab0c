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

namespace {

// A blade along +y (0..1) whose half-width follows `width(t)`, lifted by `lift(t, u)` with u
// the distance from the midrib (0..1); normals from the surface's partial derivatives.
template <class Width, class Lift>
SurfaceMesh blade(int along, int across, Width width, Lift lift) {
    SurfaceMesh m;
    auto point = [&](float t, float u) {  // u in -1..1 across the blade
        return glm::vec3(u * width(t), t, lift(t, std::fabs(u)));
    };
    for (int i = 0; i <= along; ++i) {
        float t = float(i) / float(along);
        for (int j = 0; j <= across; ++j) {
            float u = -1 + 2 * float(j) / float(across);
            glm::vec3 p = point(t, u);
            const float e = 1e-3f;
            glm::vec3 dt = point(std::min(t + e, 1.0f), u) - point(std::max(t - e, 0.0f), u);
            glm::vec3 du = point(t, std::min(u + e, 1.0f)) - point(t, std::max(u - e, -1.0f));
            glm::vec3 n = glm::cross(du, dt);
            float len = glm::length(n);
            m.positions.push_back(p);
            m.normals.push_back(len > 1e-9f ? n / len : glm::vec3(0, 0, 1));
        }
    }
    auto at = [&](int i, int j) { return std::uint32_t(i * (across + 1) + j); };
    for (int i = 0; i < along; ++i)
        for (int j = 0; j < across; ++j)
            m.indices.insert(m.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    return m;
}

}  // namespace

SurfaceMesh makeLeaf(int along, int across) {
    // An ovate leaf, widest below the middle, with a V-fold along the midrib and a tip that
    // curls slightly down.
    return blade(
        along, across, [](float t) { return 0.32f * std::pow(std::sin(kPi * std::pow(t, 0.8f)), 0.9f); },
        [](float t, float u) { return 0.06f * u - 0.08f * t * t; });
}

SurfaceMesh makePetal(int along, int across) {
    // A rounded petal, narrow at the base, cupped upwards.
    return blade(
        along, across, [](float t) { return 0.42f * std::pow(std::sin(kPi * (0.15f + 0.85f * t)), 0.6f) * std::min(1.0f, t * 4 + 0.2f); },
        [](float t, float u) { return 0.18f * t * t + 0.08f * u * u; });
}

SurfaceMesh makeSphere(int slices, int stacks) {
    SurfaceMesh m;
    for (int i = 0; i <= stacks; ++i) {
        float v = kPi * float(i) / float(stacks);
        for (int j = 0; j <= slices; ++j) {
            float u = 2 * kPi * float(j) / float(slices);
            glm::vec3 n(std::sin(v) * std::cos(u), std::cos(v), std::sin(v) * std::sin(u));
            m.positions.push_back(n);
            m.normals.push_back(n);
        }
    }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            std::uint32_t a = std::uint32_t(i * (slices + 1) + j), b = a + std::uint32_t(slices + 1);
            m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
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
