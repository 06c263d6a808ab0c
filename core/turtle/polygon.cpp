// Polygon triangulation for the turtle's { . } polygons: ear clipping in the plane that best
// fits the outline, so concave leaves (ABOP fig. 5.5) fill correctly.
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "core/turtle/turtle.hpp"

namespace sprout {
namespace {

struct P2 {
    double x, y;
};

double cross(const P2& o, const P2& a, const P2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool inside(const P2& p, const P2& a, const P2& b, const P2& c) {
    double d1 = cross(p, a, b), d2 = cross(p, b, c), d3 = cross(p, c, a);
    bool neg = d1 < 0 || d2 < 0 || d3 < 0, pos = d1 > 0 || d2 > 0 || d3 > 0;
    return !(neg && pos);
}

}  // namespace

void triangulatePolygon(const std::vector<glm::vec3>& points, std::uint32_t base,
                        std::vector<std::uint32_t>& indices) {
    const size_t n = points.size();
    if (n < 3) return;
    glm::dvec3 normal(0);
    for (size_t i = 0; i < n; ++i) {
        glm::dvec3 a(points[i]), b(points[(i + 1) % n]);
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    // Project on the plane of the dominant normal axis.
    glm::dvec3 an = glm::abs(normal);
    int drop = an.x > an.y ? (an.x > an.z ? 0 : 2) : (an.y > an.z ? 1 : 2);
    std::vector<P2> p(n);
    for (size_t i = 0; i < n; ++i) {
        glm::dvec3 v(points[i]);
        p[i] = drop == 0 ? P2{v.y, v.z} : drop == 1 ? P2{v.z, v.x} : P2{v.x, v.y};
    }
    double area = 0;
    for (size_t i = 0; i < n; ++i) area += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    std::vector<std::uint32_t> idx(n);
    for (size_t i = 0; i < n; ++i) idx[i] = std::uint32_t(area >= 0 ? i : n - 1 - i);  // counter-clockwise

    // Ear clipping, O(n^2); huge outlines fall back to a fan so no input can stall the turtle.
    if (n > 2000) {
        for (size_t i = 1; i + 1 < n; ++i) indices.insert(indices.end(), {base, base + std::uint32_t(i), base + std::uint32_t(i + 1)});
        return;
    }
    // The work is bounded (in corner-inside-triangle tests): a degenerate outline (points
    // repeated, every corner blocked) would otherwise cost n^3, 12 s for 2,000 points
    // (found by the fuzzers). 4 n^2 tests, and at most 2^22 (4 M, about 0.1 s: a degenerate
    // 1,800-point outline took 0.43 s a drawing under 4 n^2 alone, a fuzz timeout under ASan).
    // What is left when the budget runs out is closed with a fan.
    std::uint64_t budget = std::min<std::uint64_t>(4ull * n * n, 1ull << 22);
    size_t start = 0;  // scanning on from the last ear finds the next one sooner
    while (idx.size() > 3 && budget > 0) {
        bool clipped = false;
        const size_t m = idx.size();
        for (size_t j = 0; j < m && budget > 0; ++j) {
            const size_t i = (start + j) % m;
            std::uint32_t a = idx[(i + m - 1) % m], b = idx[i], c = idx[(i + 1) % m];
            if (cross(p[a], p[b], p[c]) <= 0) {  // reflex or degenerate corner
                --budget;
                continue;
            }
            bool ear = true;
            for (std::uint32_t k : idx) {
                if (budget) --budget;
                if (k == a || k == b || k == c) continue;
                if (inside(p[k], p[a], p[b], p[c])) {
                    ear = false;
                    break;
                }
            }
            if (!ear) continue;
            indices.insert(indices.end(), {base + a, base + b, base + c});
            idx.erase(idx.begin() + std::ptrdiff_t(i));
            start = i;
            clipped = true;
            break;
        }
        if (!clipped) break;  // self-intersecting outline: finish with a fan below
    }
    for (size_t i = 1; i + 1 < idx.size(); ++i) indices.insert(indices.end(), {base + idx[0], base + idx[i], base + idx[i + 1]});
}

}  // namespace sprout
