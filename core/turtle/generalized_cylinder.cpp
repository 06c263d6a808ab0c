#include "core/turtle/generalized_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace sprout {
namespace {

constexpr int kSides = 12;
constexpr float kPi = 3.14159265358979f;

glm::vec3 hermite(const glm::vec3& p0, const glm::vec3& t0, const glm::vec3& p1, const glm::vec3& t1, float s) {
    const float s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * t0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * t1;
}

glm::vec3 hermiteTangent(const glm::vec3& p0, const glm::vec3& t0, const glm::vec3& p1, const glm::vec3& t1, float s) {
    const float s2 = s * s;
    return (6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * t0 + (-6 * s2 + 6 * s) * p1 + (3 * s2 - 2 * s) * t1;
}

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float n = glm::length(v);
    return n > 1e-12f ? v / n : fallback;
}

// A textured tube's coordinates (PlantGL's Extrusion): at ring point j (of `per`: a closed
// ring's first point again at its end) u is the share of the section's length so far, v the
// length along the axis; then the curve's texture transform.
struct TubeTexture {
    const GeneralizedCylinder& curve;
    std::vector<float> around;
    float ca, sa;
    TubeTexture(const GeneralizedCylinder& c, const std::vector<glm::vec2>& ring, std::uint32_t per)
        : curve(c), around(per, 0.0f), ca(std::cos(c.texAngle)), sa(std::sin(c.texAngle)) {
        for (std::uint32_t k = 1; k < per; ++k) around[k] = around[k - 1] + glm::length(ring[k % ring.size()] - ring[k - 1]);
        if (!around.empty() && around.back() > 0)
            for (float& a : around) a /= around.back();
    }
    TexCoord at(std::size_t j, float along) const {
        const glm::vec2 q = glm::vec2(around[j], along) * curve.texScale - curve.texCentre;
        const glm::vec2 r = glm::vec2(ca * q.x - sa * q.y, sa * q.x + ca * q.y) + curve.texCentre + curve.texTranslation;
        return TexCoord{r.x, r.y, curve.image};
    }
};

}  // namespace

void appendTube(const GeneralizedCylinder& curve, float radiusScale, Mesh& mesh) {
    const auto& pts = curve.points;
    if (pts.size() < 2) return;
    // Samples along the curve: position, tangent, radius, colour.
    struct Sample {
        glm::vec3 p, t;
        float r;
        std::uint32_t colour;
    };
    std::vector<Sample> samples;
    // Tangent directions: the turtle's heading at the two ends; between, the mean of the
    // chords in and out (Catmull-Rom style), so the tube bends at the control points as the
    // turtle does between them, without the wiggle a heading taken before a turn would give.
    std::vector<glm::vec3> dir(pts.size());
    dir.front() = pts.front().heading;
    dir.back() = pts.back().heading;
    for (size_t i = 1; i + 1 < pts.size(); ++i) {
        const glm::vec3 in = safeNormalize(pts[i].position - pts[i - 1].position, pts[i].heading);
        const glm::vec3 out = safeNormalize(pts[i + 1].position - pts[i].position, pts[i].heading);
        dir[i] = safeNormalize(in + out, pts[i].heading);
    }
    // A span takes the colour the turtle had when it drew it (the point at its end).
    samples.push_back({pts[0].position, dir[0], pts[0].radius, pts[1].colour});
    for (size_t i = 1; i < pts.size(); ++i) {
        const CurvePoint& a = pts[i - 1];
        const CurvePoint& b = pts[i];
        const float chord = glm::length(b.position - a.position);
        if (chord < 1e-9f) continue;
        const glm::vec3 t0 = dir[i - 1] * chord * curve.tangentScale, t1 = dir[i] * chord * curve.tangentScale;
        // The pieces @Gc(n) asks for; by default, one per 4 degrees the span's ends turn from
        // its chord, up to 4: a span that goes straight is one piece (a tube of a hundred short
        // steps along a guide, as L-Py models make them, is not cut in four hundred).
        int n = b.subdivisions;
        if (n < 0) {
            const glm::vec3 along = (b.position - a.position) / chord;
            const float bend = std::max(std::acos(std::clamp(glm::dot(dir[i - 1], along), -1.0f, 1.0f)),
                                        std::acos(std::clamp(glm::dot(dir[i], along), -1.0f, 1.0f)));
            n = std::min(-n, 1 + int(bend / (4 * kPi / 180)));
        }
        n = std::clamp(n, 1, 64);
        // The radius along the span (cpfg's radius tangents; linear by default).
        const glm::vec2 linear(1, b.radius - a.radius);
        glm::vec2 r0 = a.radiusOut, r1 = b.radiusIn;
        if (b.scaleRadius) r0.y *= chord, r1.y *= chord;
        if (r0 == glm::vec2(0)) r0 = linear;
        if (r1 == glm::vec2(0)) r1 = linear;
        const glm::vec2 c2 = 3.0f * linear - 2.0f * r0 - r1, c3 = -2.0f * linear + r0 + r1;
        for (int k = 1; k <= n; ++k) {
            const float q = float(k) / float(n);
            const float s = std::clamp(((c3.x * q + c2.x) * q + r0.x) * q, 0.0f, 1.0f);
            const float radius = k == n ? b.radius : ((c3.y * q + c2.y) * q + r0.y) * q + a.radius;
            samples.push_back({hermite(a.position, t0, b.position, t1, s),
                               safeNormalize(hermiteTangent(a.position, t0, b.position, t1, s), dir[i]), radius, b.colour});
        }
    }
    if (samples.size() < 2) return;
    // Rotation-minimising frame (double reflection, Wang et al. 2008), from the turtle's left.
    glm::vec3 t = safeNormalize(samples[0].t, glm::vec3(0, 1, 0));
    glm::vec3 u = curve.left - glm::dot(curve.left, t) * t;
    u = safeNormalize(u, glm::normalize(glm::cross(std::fabs(t.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), t)));
    // The section: a circle, or the given one (a closed one without its repeated last point).
    std::vector<glm::vec2> ring = curve.section;
    bool closed = ring.empty() || (ring.size() > 2 && glm::length(ring.front() - ring.back()) < 1e-6f);
    if (ring.empty())
        for (int k = 0; k < kSides; ++k) ring.emplace_back(std::cos(2 * kPi * float(k) / kSides), std::sin(2 * kPi * float(k) / kSides));
    else if (closed) ring.pop_back();
    if (ring.size() < 2) return;
    const std::uint32_t sides = std::uint32_t(ring.size());
    // Each point's normal in the section's plane: across the section's outline there (for a
    // circle, the point itself).
    std::vector<glm::vec2> across(sides);
    for (std::uint32_t k = 0; k < sides; ++k) {
        const glm::vec2 prev = ring[k > 0 ? k - 1 : closed ? sides - 1 : 0], next = ring[k + 1 < sides ? k + 1 : closed ? 0 : sides - 1];
        const glm::vec2 d = next - prev;
        const float n = glm::length(d);
        across[k] = n > 1e-12f ? glm::vec2(d.y, -d.x) / n : glm::vec2(0, 1);
        if (curve.section.empty()) across[k] = ring[k];
    }
    const std::uint32_t base = std::uint32_t(mesh.positions.size());
    // A textured tube: each ring with its first point again at its end (u = 1), u the share of
    // the section's length, v the length along the axis so far (PlantGL's Extrusion).
    const bool textured = curve.image != 0;
    const std::uint32_t per = textured && closed ? sides + 1 : sides;
    const TubeTexture texture(curve, ring, per);
    if (textured) mesh.texcoords.resize(base);
    float along = 0;
    for (size_t i = 0; i < samples.size(); ++i) {
        const Sample& s = samples[i];
        if (i > 0) along += glm::length(s.p - samples[i - 1].p);
        if (i > 0) {
            const glm::vec3 v1 = s.p - samples[i - 1].p;
            const float c1 = glm::dot(v1, v1);
            if (c1 > 1e-18f) {
                const glm::vec3 uL = u - (2 / c1) * glm::dot(v1, u) * v1;
                const glm::vec3 tL = t - (2 / c1) * glm::dot(v1, t) * v1;
                const glm::vec3 v2 = s.t - tL;
                const float c2 = glm::dot(v2, v2);
                u = c2 > 1e-18f ? uL - (2 / c2) * glm::dot(v2, uL) * v2 : uL;
            }
            t = s.t;
            u = safeNormalize(u - glm::dot(u, t) * t, u);
        }
        const glm::vec3 w = glm::cross(t, u);
        const float r = s.r * radiusScale;
        for (std::uint32_t j = 0; j < per; ++j) {
            const std::uint32_t k = j % sides;
            mesh.positions.push_back(s.p + r * (ring[k].x * u + ring[k].y * w));
            // A negative radius (cpfg's radius tangents can take it through 0) turns the section over.
            mesh.normals.push_back((r < 0 ? -1.0f : 1.0f) * safeNormalize(across[k].x * u + across[k].y * w, w));
            mesh.colours.push_back(s.colour);
            if (textured) mesh.texcoords.push_back(texture.at(j, along));
        }
    }
    const std::uint32_t rings = std::uint32_t(samples.size());
    for (std::uint32_t i = 0; i + 1 < rings; ++i)
        for (std::uint32_t k = 0; k < (closed && per == sides ? sides : per - 1); ++k) {
            const std::uint32_t a = base + i * per + k, b = base + i * per + (k + 1) % per;
            const std::uint32_t c = a + per, d = b + per;
            mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
        }
    if (!closed) return;  // an open surface has no ends to cap
    // Caps: a fan at each end, facing out along the curve.
    for (int end = 0; end < 2; ++end) {
        const Sample& s = end == 0 ? samples.front() : samples.back();
        const glm::vec3 n = end == 0 ? -safeNormalize(s.t, glm::vec3(0, 1, 0)) : safeNormalize(s.t, glm::vec3(0, 1, 0));
        const std::uint32_t centre = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(s.p);
        mesh.normals.push_back(n);
        mesh.colours.push_back(s.colour);
        const std::uint32_t ringStart = base + (end == 0 ? 0 : (rings - 1) * per);
        const std::uint32_t first = std::uint32_t(mesh.positions.size());
        for (std::uint32_t k = 0; k < sides; ++k) {
            mesh.positions.push_back(mesh.positions[ringStart + k]);
            mesh.normals.push_back(n);
            mesh.colours.push_back(s.colour);
        }
        for (std::uint32_t k = 0; k < sides; ++k) {
            const std::uint32_t a = first + k, b = first + (k + 1) % sides;
            if (end == 0) mesh.indices.insert(mesh.indices.end(), {centre, b, a});
            else mesh.indices.insert(mesh.indices.end(), {centre, a, b});
        }
    }
}

}  // namespace sprout
