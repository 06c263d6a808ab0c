#include "core/turtle/unit_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace sprout {
namespace {

constexpr float kPi = 3.14159265358979f;

// sin(a) for a in [0, pi], never below 0: a float pi's sine is -8.7e-8, and its fractional
// power was NaN, which made every leaf's and petal's tip NaN (their last row of cells not
// drawn, NaN in the exports).
float sinAbove0(float a) { return std::max(0.0f, std::sin(a)); }

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
            m.uvs.emplace_back(1 - float(j) / float(across), t);  // x > 0 is left: u grows to the right
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
        along, across, [](float t) { return 0.32f * std::pow(sinAbove0(kPi * std::pow(t, 0.8f)), 0.9f); },
        [](float t, float u) { return 0.06f * u - 0.08f * t * t; });
}

SurfaceMesh makePetal(int along, int across) {
    // A rounded petal, narrow at the base, cupped upwards.
    return blade(
        along, across, [](float t) { return 0.42f * std::pow(sinAbove0(kPi * (0.15f + 0.85f * t)), 0.6f) * std::min(1.0f, t * 4 + 0.2f); },
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
            m.uvs.emplace_back(float(j) / float(slices) - 0.25f, 1 - float(i) / float(stacks));  // u 0 at U, as PlantGL's
        }
    }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            std::uint32_t a = std::uint32_t(i * (slices + 1) + j), b = a + std::uint32_t(slices + 1);
            m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    return m;
}

}  // namespace sprout
