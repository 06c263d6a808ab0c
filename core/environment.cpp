#include "core/environment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace sprout {

bool EnvShape::contains(const glm::dvec3& p) const {
    switch (kind) {
        case Kind::Sphere: return glm::length(p - a) <= b.x;
        case Kind::Box: return p.x >= a.x && p.y >= a.y && p.z >= a.z && p.x <= b.x && p.y <= b.y && p.z <= b.z;
        case Kind::Ellipsoid: {
            const glm::dvec3 q = (p - a) / b;
            return glm::dot(q, q) <= 1.0;
        }
        case Kind::Cylinder: {
            const double dx = p.x - a.x, dz = p.z - a.z;
            return dx * dx + dz * dz <= b.x * b.x && p.y >= a.y && p.y <= a.y + b.y;
        }
    }
    return false;
}

double EnvShape::distanceToSurface(const glm::dvec3& p) const {
    switch (kind) {
        case Kind::Sphere: return std::fabs(glm::length(p - a) - b.x);
        case Kind::Box: {
            const glm::dvec3 c = (a + b) * 0.5, h = (b - a) * 0.5, q = glm::abs(p - c) - h;
            const glm::dvec3 outside = glm::max(q, glm::dvec3(0.0));
            const double inside = std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
            return std::fabs(glm::length(outside) + inside);
        }
        case Kind::Ellipsoid: {
            // The distance along the ray from the centre: exact on the axes, close elsewhere.
            const glm::dvec3 d = p - a;
            const double len = glm::length(d);
            if (len == 0) return std::min(b.x, std::min(b.y, b.z));
            const glm::dvec3 u = d / len, q = u / b;
            return std::fabs(len - 1.0 / std::sqrt(glm::dot(q, q)));
        }
        case Kind::Cylinder: {
            const double dx = p.x - a.x, dz = p.z - a.z;
            const double radial = std::sqrt(dx * dx + dz * dz) - b.x;
            const double axial = std::max(a.y - p.y, p.y - (a.y + b.y));
            const double outside = std::sqrt(std::max(radial, 0.0) * std::max(radial, 0.0) + std::max(axial, 0.0) * std::max(axial, 0.0));
            const double inside = std::min(std::max(radial, axial), 0.0);
            return std::fabs(outside + inside);
        }
    }
    return 0;
}

glm::dvec3 EnvShape::normal(const glm::dvec3& p) const {
    // The gradient of the distance, by central differences: one formula for every shape.
    const double e = 1e-6 * (1.0 + glm::length(b - a));
    auto signedDistance = [&](const glm::dvec3& q) { return contains(q) ? -distanceToSurface(q) : distanceToSurface(q); };
    glm::dvec3 g(signedDistance(p + glm::dvec3(e, 0, 0)) - signedDistance(p - glm::dvec3(e, 0, 0)),
                 signedDistance(p + glm::dvec3(0, e, 0)) - signedDistance(p - glm::dvec3(0, e, 0)),
                 signedDistance(p + glm::dvec3(0, 0, e)) - signedDistance(p - glm::dvec3(0, 0, e)));
    const double n = glm::length(g);
    return n > 0 ? g / n : glm::dvec3(0, 1, 0);
}

double LightGrid::lightAt(const glm::dvec3& p) const {
    const glm::dvec3 c = (p - origin) / voxel;
    const int i = int(std::floor(c.x)), j = int(std::floor(c.y)), k = int(std::floor(c.z));
    if (i < 0 || j < 0 || k < 0 || i >= nx || j >= ny || k >= nz) return 1.0;  // beyond the plant: open sky
    const double s = shadow[(std::size_t(j) * std::size_t(nz) + std::size_t(k)) * std::size_t(nx) + std::size_t(i)];
    return std::max(0.0, 1.0 - s);
}

bool Environment::buildLight(const Geometry& g, LightGrid& grid, std::string& error) const {
    grid = LightGrid();
    grid.voxel = lightVoxel;
    if (g.bounds.empty) return true;
    // Shadow reaches kDepth cells down and as many sideways: the grid is the plant's box,
    // widened by that much on the sides and below.
    constexpr int kDepth = 8;
    const glm::dvec3 lo = glm::dvec3(g.bounds.min) - glm::dvec3(kDepth + 1, kDepth + 1, kDepth + 1) * lightVoxel;
    const glm::dvec3 hi = glm::dvec3(g.bounds.max) + glm::dvec3(kDepth + 1, 1, kDepth + 1) * lightVoxel;
    const glm::dvec3 cells = glm::ceil((hi - lo) / lightVoxel);
    const double total = cells.x * cells.y * cells.z;
    if (!(total <= double(kMaxLightCells))) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "the light grid would have %.0f x %.0f x %.0f = %.3g cells (%.1f GB at 4 bytes each), over the limit of "
                      "32 million: make the voxels larger ('environment: light VOXEL')",
                      cells.x, cells.y, cells.z, total, total * 4 / 1e9);
        error = msg;
        return false;
    }
    grid.origin = lo;
    grid.nx = int(cells.x), grid.ny = int(cells.y), grid.nz = int(cells.z);
    grid.shadow.assign(std::size_t(total), 0.0f);
    auto at = [&](int i, int j, int k) -> float& {
        return grid.shadow[(std::size_t(j) * std::size_t(grid.nz) + std::size_t(k)) * std::size_t(grid.nx) + std::size_t(i)];
    };
    // Each leaf (and a quarter for each segment's end) shades a pyramid of cells below it.
    auto cast = [&](const glm::vec3& p, double weight) {
        const glm::dvec3 c = (glm::dvec3(p) - lo) / lightVoxel;
        const int i0 = int(std::floor(c.x)), j0 = int(std::floor(c.y)), k0 = int(std::floor(c.z));
        for (int q = 1; q <= kDepth; ++q) {
            const int j = j0 - q;
            if (j < 0) break;
            const float s = float(weight * lightShadow * std::pow(2.0, -(q - 1)));
            for (int dk = -(q - 1); dk <= q - 1; ++dk)
                for (int di = -(q - 1); di <= q - 1; ++di) {
                    const int i = i0 + di, k = k0 + dk;
                    if (i >= 0 && k >= 0 && i < grid.nx && k < grid.nz) at(i, j, k) += s;
                }
        }
    };
    for (const SurfaceInstance& s : g.surfaces)
        if (s.kind != SurfaceKind::Sphere) cast(s.position, 1.0);
    for (const CylinderInstance& c : g.cylinders) cast(c.end, 0.25);
    for (const glm::vec3& p : g.polygons.positions) cast(p, 0.05);
    return true;
}

void Environment::answer(const glm::dvec3& p, const glm::dvec3& heading, double* params, int arity,
                         const LightGrid* light) const {
    if (isLight()) {
        if (arity > 0) params[0] = light ? std::round(light->lightAt(p) * 1e5) / 1e5 : 1.0;
        return;
    }
    if (isRegion()) {
        bool inside = false;
        double distance = 1e300;
        for (const EnvShape& s : region) {
            inside |= s.contains(p);
            distance = std::min(distance, s.distanceToSurface(p));
        }
        if (arity > 0) params[0] = inside ? 1 : 0;
        if (arity > 1) params[1] = distance;
        return;
    }
    // Obstacles: march the segment ahead in small steps (exact enough for boxes and spheres at
    // plant scale: 64 steps of the segment, then the first hit refined by bisection).
    const double length = arity > 0 && std::isfinite(params[0]) && params[0] > 0 ? params[0] : 1.0;
    auto blocked = [&](const glm::dvec3& q, const EnvShape** by) {
        if (ground && q.y < *ground) {
            *by = nullptr;
            return true;
        }
        for (const EnvShape& s : obstacles)
            if (s.contains(q)) {
                *by = &s;
                return true;
            }
        return false;
    };
    const EnvShape* hitShape = nullptr;
    bool hit = false;
    double tHit = length;
    double lo = 0;
    constexpr int kSteps = 64;
    for (int k = 1; k <= kSteps && !hit; ++k) {
        const double t = length * k / kSteps;
        if (blocked(p + heading * t, &hitShape)) {
            hit = true;
            double hi = t;
            for (int i = 0; i < 30; ++i) {  // the entry point
                const double mid = (lo + hi) / 2;
                const EnvShape* ignored = nullptr;
                (blocked(p + heading * mid, &ignored) ? hi : lo) = mid;
            }
            tHit = hi;
        }
        lo = t;
    }
    glm::dvec3 free = heading;
    if (hit) {
        const glm::dvec3 q = p + heading * tHit;
        const glm::dvec3 n = hitShape ? hitShape->normal(q) : glm::dvec3(0, 1, 0);
        glm::dvec3 slid = heading - glm::dot(heading, n) * n;  // along the surface
        if (!(glm::length(slid) > 1e-6)) {
            // Head-on: any way along the surface is as good; a fixed one, so the answer is
            // the same on every machine.
            slid = glm::cross(n, std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1));
        }
        free = glm::normalize(slid);
    }
    if (arity > 1) params[1] = hit ? 1 : 0;
    for (int k = 0; k < 3 && 2 + k < arity; ++k) params[2 + k] = std::round(free[k] * 1e5) / 1e5 + 0.0;
}

bool Environment::declare(const std::vector<std::string>& words, const std::vector<double>& v, std::string& error) {
    if (words.empty()) {
        error = "expected 'environment: sphere CX CY CZ R' (or box, ellipsoid, cylinder, obstacle ..., ground Y)";
        return false;
    }
    size_t w = 0;
    const bool obstacle = words[0] == "obstacle";
    if (obstacle) ++w;
    if (!obstacle && words[0] == "light") {
        if (v.empty() || v.size() > 2 || !(v[0] > 0) || (v.size() == 2 && !(v[1] > 0))) {
            error = "expected 'environment: light VOXEL [SHADOW]', with a voxel size above 0 (and a shadow above 0)";
            return false;
        }
        if (!region.empty() || !obstacles.empty() || ground) {
            error = "one grammar has one kind of environment: light, a region to grow in, or obstacles and ground";
            return false;
        }
        lightVoxel = v[0];
        if (v.size() == 2) lightShadow = v[1];
        return true;
    }
    if (isLight()) {
        error = "one grammar has one kind of environment: light, a region to grow in, or obstacles and ground";
        return false;
    }
    if (!obstacle && words[0] == "ground") {
        if (v.size() != 1) {
            error = "expected 'environment: ground Y', the height of the ground";
            return false;
        }
        ground = v[0];
        if (!region.empty()) {
            error = "one grammar has one kind of environment: a region to grow in, or obstacles and ground (their ?E answers differ)";
            return false;
        }
        return true;
    }
    if (w >= words.size()) {
        error = "expected the shape of the obstacle: 'environment: obstacle sphere CX CY CZ R' or 'obstacle box X0 Y0 Z0 X1 Y1 Z1'";
        return false;
    }
    const std::string& kind = words[w];
    EnvShape s;
    auto need = [&](size_t n, const char* form) {
        if (v.size() == n) return true;
        error = std::string("expected ") + std::to_string(n) + " numbers: 'environment: " + (obstacle ? "obstacle " : "") + form + "'";
        return false;
    };
    if (kind == "sphere") {
        if (!need(4, "sphere CX CY CZ R")) return false;
        s.kind = EnvShape::Kind::Sphere, s.a = {v[0], v[1], v[2]}, s.b = {v[3], 0, 0};
        if (!(v[3] > 0)) return error = "a sphere's radius must be above 0", false;
    } else if (kind == "box") {
        if (!need(6, "box X0 Y0 Z0 X1 Y1 Z1")) return false;
        s.kind = EnvShape::Kind::Box, s.a = glm::min(glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]));
        s.b = glm::max(glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]));
    } else if (kind == "ellipsoid") {
        if (!need(6, "ellipsoid CX CY CZ RX RY RZ")) return false;
        s.kind = EnvShape::Kind::Ellipsoid, s.a = {v[0], v[1], v[2]}, s.b = {v[3], v[4], v[5]};
        if (!(v[3] > 0 && v[4] > 0 && v[5] > 0)) return error = "an ellipsoid's radii must be above 0", false;
    } else if (kind == "cylinder") {
        if (!need(5, "cylinder CX CY CZ R H")) return false;
        s.kind = EnvShape::Kind::Cylinder, s.a = {v[0], v[1], v[2]}, s.b = {v[3], v[4], 0};
        if (!(v[3] > 0 && v[4] > 0)) return error = "a cylinder's radius and height must be above 0", false;
    } else {
        error = "unknown environment '" + kind + "': Sprout's are sphere, box, ellipsoid, cylinder (a region to grow in), "
                "obstacle sphere|box and ground";
        return false;
    }
    (obstacle ? obstacles : region).push_back(s);
    if (!region.empty() && (!obstacles.empty() || ground)) {
        error = "one grammar has one kind of environment: a region to grow in, or obstacles and ground (their ?E answers differ)";
        return false;
    }
    return true;
}

}  // namespace sprout
