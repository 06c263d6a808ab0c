#include "lpy/plantgl/asymmetric_hull.hpp"

#include <algorithm>
#include <cmath>

namespace sprout {

HullMesh meshOf(const AsymmetricHull& h) {
    using P = std::array<double, 3>;
    const int slices = std::clamp(h.slices, 1, 64), stacks = std::clamp(h.stacks, 1, 64);
    const double shapeBottom = std::max(1e-6, h.bottomShape), shapeTop = std::max(1e-6, h.topShape);
    // The quadrants in PlantGL's order, each with its x and y radius and height.
    const double rx[4] = {h.posXRadius, h.negXRadius, h.negXRadius, h.posXRadius};
    const double ry[4] = {h.posYRadius, h.posYRadius, h.negYRadius, h.negYRadius};
    const double hx[4] = {h.posXHeight, h.negXHeight, h.negXHeight, h.posXHeight};
    const double hy[4] = {h.posYHeight, h.posYHeight, h.negYHeight, h.negYHeight};
    const int around = 4 * slices, ring = 2 * stacks - 1;
    auto towards = [](const P& end, const P& p, double t, double shape) {
        return P{end[0] + (p[0] - end[0]) * t, end[1] + (p[1] - end[1]) * t, end[2] + (p[2] - end[2]) * std::pow(t, shape)};
    };
    HullMesh out;
    out.points.reserve(size_t(around * ring + 2));
    for (int q = 0; q < 4; ++q)
        for (int i = 0; i < slices; ++i) {
            const double a = 2 * M_PI * double(q * slices + i) / double(around);
            const double c = std::cos(a), s = std::sin(a);
            const P p{c * rx[q], s * ry[q], hx[q] * c * c + hy[q] * s * s};
            for (int j = 1; j < stacks; ++j) out.points.push_back(towards(h.bottom, p, double(j) / stacks, shapeBottom));
            out.points.push_back(p);
            for (int j = 1; j < stacks; ++j) out.points.push_back(towards(h.top, p, 1 - double(j) / stacks, shapeTop));
        }
    const auto b = std::uint32_t(out.points.size()), t = b + 1;
    out.points.push_back(h.bottom);
    out.points.push_back(h.top);
    for (int k = 0; k < around; ++k) {
        const auto cur = std::uint32_t(k * ring), nxt = std::uint32_t((k + 1) % around * ring);
        out.triangles.push_back({cur, b, nxt});
        for (std::uint32_t j = 0; j + 1 < std::uint32_t(ring); ++j) {
            out.triangles.push_back({cur + j, nxt + j, nxt + j + 1});
            out.triangles.push_back({cur + j, nxt + j + 1, cur + j + 1});
        }
        out.triangles.push_back({cur + std::uint32_t(ring) - 1, nxt + std::uint32_t(ring) - 1, t});
    }
    return out;
}

}  // namespace sprout
