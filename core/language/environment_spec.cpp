// The environment as a grammar declares it: its `environment:` lines read into shapes and
// numbers (Environment::declare), and the shapes' own geometry (inside, distance, normal).
// What it answers a plant is core/environment/environment.cpp.
#include "core/language/environment_spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace sprout {

namespace {

// Möller-Trumbore: the distance along the ray to the triangle, or < 0 when it misses.
double rayTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-15) return -1;
    const glm::dvec3 t = o - a;
    const double u = glm::dot(t, p) / det;
    if (u < 0 || u > 1) return -1;
    const glm::dvec3 q = glm::cross(t, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0 || u + v > 1) return -1;
    return glm::dot(e2, q) / det;
}

// The distance from p to the triangle (Ericson, Real-Time Collision Detection 5.1.5).
double pointTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> environmentTokens(std::string_view text) {
    auto separator = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == ','; };
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && separator(text[i])) ++i;
        const std::size_t start = i;
        int depth = 0;
        while (i < text.size() && (depth > 0 || !separator(text[i]))) {
            depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
            ++i;
        }
        if (i > start) out.emplace_back(start, i);
    }
    return out;
}

bool isEnvironmentKeyword(std::string_view word) {
    static const char* keywords[] = {"obstacle", "ground", "sphere", "box", "ellipsoid", "cylinder", "light", "attraction",
                                     "influence", "kill", "mesh", "sun"};
    return std::any_of(std::begin(keywords), std::end(keywords), [&](const char* k) { return word == k; });
}

bool TriMesh::parse(std::string_view obj, std::string& error) {
    vertices.clear();
    triangles.clear();
    std::istringstream in{std::string(obj)};
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::istringstream words(line);
        std::string tag;
        if (!(words >> tag)) continue;
        if (tag == "v") {
            glm::dvec3 v;
            if (!(words >> v.x >> v.y >> v.z) || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                error = "line " + std::to_string(number) + ": a vertex needs three finite numbers";
                return false;
            }
            vertices.push_back(v);
        } else if (tag == "f") {
            std::vector<std::uint32_t> face;
            std::string ref;
            while (words >> ref) {
                const long i = std::strtol(ref.c_str(), nullptr, 10);  // "7", "7/1", "7//3", "-1"
                const long index = i < 0 ? long(vertices.size()) + i : i - 1;
                if (i == 0 || index < 0 || index >= long(vertices.size())) {
                    error = "line " + std::to_string(number) + ": the face names vertex " + ref + ", which is not there";
                    return false;
                }
                face.push_back(std::uint32_t(index));
            }
            for (size_t k = 2; k < face.size(); ++k) triangles.insert(triangles.end(), {face[0], face[k - 1], face[k]});
        }
    }
    if (triangles.empty()) {
        error = "it has no faces";
        return false;
    }
    // Closed: every edge is shared by exactly two triangles (inside and outside make sense).
    std::unordered_map<std::uint64_t, int> edges;
    for (size_t t = 0; t < triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = triangles[t + size_t(k)], b = triangles[t + size_t((k + 1) % 3)];
            ++edges[std::min(a, b) << 32 | std::max(a, b)];
        }
    size_t open = 0;
    for (const auto& [e, n] : edges) open += n != 2;
    if (open) {
        error = "it is not closed: " + std::to_string(open) + " of its edges do not belong to exactly two faces";
        return false;
    }
    return true;
}

bool EnvShape::contains(const glm::dvec3& p) const {
    switch (kind) {
        case Kind::Mesh: {
            // Crossings of a ray: odd inside. A direction off the axes, so that it does not
            // run along the edges of an axis-aligned mesh.
            const glm::dvec3 d = glm::normalize(glm::dvec3(1.0, 0.000137, 0.000271));
            int crossings = 0;
            for (size_t t = 0; t < mesh->triangles.size(); t += 3)
                crossings += rayTriangle(p, d, mesh->vertices[mesh->triangles[t]], mesh->vertices[mesh->triangles[t + 1]],
                                         mesh->vertices[mesh->triangles[t + 2]]) > 0;
            return crossings % 2 == 1;
        }
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
        case Kind::Mesh: {
            double best = 1e300;
            for (size_t t = 0; t < mesh->triangles.size(); t += 3)
                best = std::min(best, pointTriangle(p, mesh->vertices[mesh->triangles[t]], mesh->vertices[mesh->triangles[t + 1]],
                                                    mesh->vertices[mesh->triangles[t + 2]]));
            return best;
        }
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

void EnvShape::box(glm::dvec3& lo, glm::dvec3& hi) const {
    switch (kind) {
        case Kind::Sphere: lo = a - glm::dvec3(b.x), hi = a + glm::dvec3(b.x); break;
        case Kind::Box: lo = a, hi = b; break;
        case Kind::Ellipsoid: lo = a - b, hi = a + b; break;
        case Kind::Cylinder: lo = a - glm::dvec3(b.x, 0, b.x), hi = a + glm::dvec3(b.x, b.y, b.x); break;
        case Kind::Mesh:
            lo = hi = mesh->vertices.front();
            for (const auto& v : mesh->vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
            break;
    }
}

glm::dvec3 Environment::sunDirection() const {
    const double az = glm::radians(sunAzimuth), el = glm::radians(sunElevation);
    if (sunElevation >= 90) return {0, 1, 0};  // exactly overhead: no rounding in the default
    return glm::normalize(glm::dvec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)));
}


bool Environment::declareMesh(std::shared_ptr<const TriMesh> mesh, std::string& error) {
    if (!obstacles.empty() || ground || isLight() || isAttraction()) {
        error = "one grammar has one kind of environment: a region to grow in, or obstacles and ground";
        return false;
    }
    EnvShape s;
    s.kind = EnvShape::Kind::Mesh;
    s.mesh = std::move(mesh);
    region.push_back(std::move(s));
    return true;
}

bool Environment::declare(const std::vector<std::string>& words, const std::vector<double>& v, std::string& error) {
    if (words.empty()) {
        error = "expected 'environment: sphere CX CY CZ R' (or box, ellipsoid, cylinder, obstacle ..., ground Y)";
        return false;
    }
    size_t w = 0;
    const bool obstacle = words[0] == "obstacle";
    if (obstacle) ++w;
    if (!obstacle && words[0] == "attraction") {
        // attraction N shape numbers... [influence R] [kill K]: the words after the shape's
        // numbers come as words too; their values follow at the end of `v`.
        if (words.size() < 2 || v.empty() || !(v[0] >= 1 && v[0] <= 1e6) || v[0] != std::floor(v[0])) {
            error = "expected 'environment: attraction N sphere CX CY CZ R [influence R] [kill K]', N a whole number of points "
                    "from 1 to 1000000";
            return false;
        }
        if (!region.empty() || !obstacles.empty() || ground || isLight() || attractionShape) {
            error = "one grammar has one kind of environment: attraction points, light, a region to grow in, or obstacles and ground";
            return false;
        }
        std::vector<double> rest(v.begin() + 1, v.end());
        size_t extra = words.size() - 2;  // influence / kill, each with one number at the end
        if (rest.size() < extra) {
            error = "'influence' and 'kill' each need a distance after them";
            return false;
        }
        std::vector<double> shapeNumbers(rest.begin(), rest.end() - std::ptrdiff_t(extra));
        // The points' shape is one of the region shapes (not ground, light, an obstacle, ...).
        if (words[1] != "sphere" && words[1] != "box" && words[1] != "ellipsoid" && words[1] != "cylinder") {
            error = "attraction points fill a shape: 'environment: attraction N sphere|box|ellipsoid|cylinder ...', not '" +
                    words[1] + "'";
            return false;
        }
        Environment probe;
        if (!probe.declare({words[1]}, shapeNumbers, error)) return false;
        if (probe.region.size() != 1) {
            error = "expected one shape for the attraction points";
            return false;
        }
        attractionShape = probe.region.front();
        attractionPoints = int(v[0]);
        for (size_t k = 0; k < extra; ++k) {
            const double value = rest[rest.size() - extra + k];
            if (!(value > 0)) {
                error = "'" + words[2 + k] + "' must be a distance above 0";
                return false;
            }
            if (value < kMinDistance) {
                error = "'" + words[2 + k] + "' must be a distance of at least 1e-6";
                return false;
            }
            if (words[2 + k] == "influence") influence = value;
            else if (words[2 + k] == "kill") kill = value;
            else {
                error = "unknown word '" + words[2 + k] + "': attraction points take 'influence R' and 'kill K'";
                return false;
            }
        }
        return true;
    }
    if (isAttraction()) {
        error = "one grammar has one kind of environment: attraction points, light, a region to grow in, or obstacles and ground";
        return false;
    }
    if (!obstacle && words[0] == "light") {
        // light VOXEL [SHADOW] [sun AZIMUTH ELEVATION]
        const bool sun = words.size() == 2 && words[1] == "sun";
        const size_t own = v.size() - (sun ? 2 : 0);
        if ((words.size() > 1 && !sun) || v.size() < (sun ? 3u : 1u) || own < 1 || own > 2 || !(v[0] > 0) ||
            (own == 2 && !(v[1] > 0))) {
            error = "expected 'environment: light VOXEL [SHADOW] [sun AZIMUTH ELEVATION]', with a voxel size above 0 (and a "
                    "shadow above 0)";
            return false;
        }
        if (v[0] < kMinDistance) {
            error = "the light's voxel size must be at least 1e-6 (a grid of smaller cells holds no plant)";
            return false;
        }
        if (sun && !(std::isfinite(v[own]) && v[own + 1] > 0 && v[own + 1] <= 90)) {
            error = "the sun's elevation must be above 0 and at most 90 degrees (90: overhead)";
            return false;
        }
        if (!region.empty() || !obstacles.empty() || ground) {
            error = "one grammar has one kind of environment: light, a region to grow in, or obstacles and ground";
            return false;
        }
        lightVoxel = v[0];
        if (own == 2) lightShadow = v[1];
        if (sun) sunAzimuth = v[own], sunElevation = v[own + 1];
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
        error = "unknown environment '" + kind + "': Sprout's are sphere, box, ellipsoid, cylinder, mesh (a region to grow "
                "in), obstacle sphere|box, ground, light and attraction";
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
