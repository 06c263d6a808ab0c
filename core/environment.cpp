#include "core/environment.hpp"

#include <algorithm>
#include <cmath>

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

void Environment::answer(const glm::dvec3& p, const glm::dvec3& heading, double* params, int arity) const {
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
