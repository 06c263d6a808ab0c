#include "core/turtle/pick.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace sprout {

std::optional<PickHit> pick(const Geometry& g, const glm::vec3& o, const glm::vec3& d, float slack, float minRadius) {
    std::optional<PickHit> best;
    float bestT = INFINITY;
    // In the ray's frame (e1, e2 across it, d along it) a stem is a 2D segment with a depth:
    // most are thrown out by their 2D box before any division.
    const glm::vec3 e1 = glm::normalize(glm::cross(d, std::fabs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 e2 = glm::cross(d, e1);
    auto test = [&](const glm::vec3& a, const glm::vec3& b, float ra, float rb) -> std::optional<float> {
        const glm::vec3 pa = a - o, pb = b - o;
        const float ta = glm::dot(pa, d), tb = glm::dot(pb, d);
        if (ta < 0 && tb < 0) return std::nullopt;  // behind the eye
        const float ax = glm::dot(pa, e1), ay = glm::dot(pa, e2), bx = glm::dot(pb, e1), by = glm::dot(pb, e2);
        const float reach = std::max(std::max(ra, rb), minRadius + slack * std::max(ta, tb));
        if (std::min(ax, bx) > reach || std::max(ax, bx) < -reach || std::min(ay, by) > reach || std::max(ay, by) < -reach)
            return std::nullopt;
        const float ux = bx - ax, uy = by - ay, uu = ux * ux + uy * uy;
        const float s = uu > 0 ? std::clamp(-(ax * ux + ay * uy) / uu, 0.0f, 1.0f) : 0.0f;
        const float px = ax + ux * s, py = ay + uy * s, t = ta + (tb - ta) * s;
        if (t < 0 || t >= bestT) return std::nullopt;
        const float r = std::max(ra + (rb - ra) * s, minRadius + slack * t);
        if (px * px + py * py > r * r) return std::nullopt;
        return t;
    };
    const CylinderInstance* c = g.cylinders.data();
    for (std::size_t i = 0, n = g.cylinders.size(); i < n; ++i)
        if (auto t = test(c[i].start, c[i].end, c[i].startRadius, c[i].endRadius)) {
            bestT = *t;
            best = PickHit{PickHit::Kind::Segment, std::uint32_t(i), *t};
        }
    // Leaves and petals as their midrib with a third of their size around it; spheres as spheres.
    for (std::size_t i = 0; i < g.surfaces.size(); ++i) {
        const SurfaceInstance& s = g.surfaces[i];
        const bool sphere = s.kind == SurfaceKind::Sphere;
        const float r = sphere ? s.size : s.size * 0.3f;
        if (auto t = test(s.position, sphere ? s.position : s.position + s.heading * s.size, r, r)) {
            bestT = *t;
            best = PickHit{PickHit::Kind::Surface, std::uint32_t(i), *t};
        }
    }
    return best;
}

void highlightMesh(const Geometry& g, const std::vector<std::uint32_t>& segments, const std::vector<std::uint32_t>& surfaces,
                   std::uint32_t colour, Mesh& out, std::size_t limit) {
    auto tube = [&](const glm::vec3& a, const glm::vec3& b, float r) {
        glm::vec3 h = b - a;
        const float len = glm::length(h);
        h = len > 0 ? h / len : glm::vec3(0, 1, 0);
        const glm::vec3 u = glm::normalize(glm::cross(h, std::fabs(h.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
        const glm::vec3 v = glm::cross(h, u);
        const std::uint32_t base = std::uint32_t(out.positions.size());
        for (int k = 0; k < 6; ++k) {
            const float angle = float(k) * 1.0471976f;
            const glm::vec3 n = u * std::cos(angle) + v * std::sin(angle);
            for (const glm::vec3& p : {a - h * r, b + h * r}) {
                out.positions.push_back(p + n * r);
                out.normals.push_back(n);
                out.colours.push_back(colour);
            }
        }
        for (std::uint32_t k = 0; k < 6; ++k) {
            const std::uint32_t i = base + 2 * k, j = base + 2 * ((k + 1) % 6);
            out.indices.insert(out.indices.end(), {i, j, i + 1, i + 1, j, j + 1});
        }
    };
    std::size_t drawn = 0;
    for (std::uint32_t s : segments) {
        if (s >= g.cylinders.size() || drawn++ >= limit) continue;
        const CylinderInstance& c = g.cylinders[s];
        const float r = std::max(c.startRadius, c.endRadius);
        tube(c.start, c.end, r * 1.35f + 0.02f * glm::length(c.end - c.start) + 1e-4f);
    }
    for (std::uint32_t s : surfaces) {
        if (s >= g.surfaces.size()) continue;
        const SurfaceInstance& f = g.surfaces[s];
        const bool sphere = f.kind == SurfaceKind::Sphere;
        tube(sphere ? f.position - f.heading * f.size : f.position, f.position + f.heading * f.size, f.size * (sphere ? 1.1f : 0.35f));
    }
}

}  // namespace sprout
