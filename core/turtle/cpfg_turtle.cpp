// cpfg's own turtle modules (blackbox.c, movements.c, patches.c) for `.l` files: the tropisms
// and torques and their elasticities (@Ts, @Ti, @Td), the radius tangents of generalized
// cylinders (@Gr), labels (@L) and L-system defined surfaces (@PS, @PC, @PD).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>

#include "core/turtle/turtle_impl.hpp"

namespace sprout::turtle_impl {

// blackbox.c's @Ts(id, e) sets tropism id's elasticity (0 without e), @Ti adds e (the view
// file's S: step without it), @Td takes it; id counts the view file's tropism: and torque:
// lines from 1 (the first without one).
void Turtle::elasticity(Act act, const double* p, int arity) {
    const auto& ms = m_g.settings.movements;
    const double id = p && arity >= 1 ? p[0] - 1 : 0;
    if (!(id >= 0 && id < double(std::min<size_t>(ms.size(), m_elastic.size())))) return;
    const size_t k = size_t(id);
    const bool given = p && arity >= 2 && std::isfinite(p[1]);
    float& e = m_elastic[k];
    if (act == Act::ElasticSet) e = given ? float(p[1]) : 0.0f;
    else if (act == Act::ElasticInc) e += given ? float(p[1]) : float(ms[k].step);
    else e -= given ? float(p[1]) : float(ms[k].step);
}

// movements.c's movement_adjust: the heading turned towards the tropisms' sum (each one's
// direction times its elasticity; one at an angle g to it adds sin(g) e T x (H x T) / |H x T|)
// by |H x D| radians, at most 1, the left vector with it; then the up vector turned towards the
// torques' sum, as it lies across the heading. (cpfg then also undoes any roll since the last
// segment unless @Tf; Sprout keeps the roll.)
void Turtle::movementAdjust(State& t) {
    auto turnAbout = [](v4& v, const glm::vec3& axis, float angle) {
        const glm::vec3 x = toGlm(v);
        const float c = std::cos(angle), s = std::sin(angle);
        v = fromGlm(x * c + glm::cross(axis, x) * s + axis * glm::dot(axis, x) * (1 - c));
    };
    const auto& ms = m_g.settings.movements;
    const glm::vec3 H = toGlm(t.H);
    glm::vec3 D(0), torque(0);
    for (size_t i = 0; i < ms.size() && i < m_elastic.size(); ++i) {
        const glm::vec3 T(float(ms[i].direction[0]), float(ms[i].direction[1]), float(ms[i].direction[2]));
        const float e = m_elastic[i];
        if (ms[i].torque) {
            torque += e * T;
            continue;
        }
        const double g = ms[i].angle * 3.14159265358979 / 180;
        D += float(std::cos(g)) * e * T;
        if (const float sg = float(std::sin(g)); sg != 0 && e != 0) {
            glm::vec3 v = glm::cross(H, T);
            float len = glm::length(v);
            if (len < 1e-7f) v = toGlm(t.L), len = 1;
            D += (sg * e / len) * glm::cross(T, v);
        }
    }
    const glm::vec3 rot = glm::cross(H, D);
    if (const float a = glm::length(rot); a >= 1e-6f && std::isfinite(a)) {
        turnAbout(t.H, rot / a, std::min(a, 1.0f));
        turnAbout(t.L, rot / a, std::min(a, 1.0f));
    }
    const float strength = glm::length(torque);
    if (!(strength > 0) || !std::isfinite(strength)) return;
    const glm::vec3 h = glm::normalize(toGlm(t.H)), across = glm::cross(h, torque / strength);
    if (glm::dot(across, across) <= 1e-8f) return;
    const glm::vec3 want = glm::cross(across, h) * strength, u = toGlm(up(t)), w = glm::cross(u, want);
    if (const float l = glm::length(w); l >= 1e-7f) {
        v4 U = up(t);
        turnAbout(U, w / l, std::min(l, 1.0f));
        t.L = cross(U, t.H);
    }
}

// blackbox.c's @Gr: one number switches the scaling of the tangents by the span's length; two
// (an angle in degrees and a length) set both tangents, four set the one ending the span and
// the one starting the next.
void Turtle::radiusTangents(const double* p, int arity) {
    if (!p || arity < 1 || !finite(p, std::min(arity, 4))) return;
    if (arity == 1) {
        m_scaleRadius = *p != 0;
        return;
    }
    auto tangent = [](double degrees, double length) {
        return glm::vec2(float(std::cos(degrees * kPi / 180) * length), float(std::sin(degrees * kPi / 180) * length));
    };
    m_radiusIn = m_radiusOut = tangent(p[0], p[1]);
    if (arity >= 4) m_radiusOut = tangent(p[2], p[3]);
}

// cpfg's @L("format", x, ...): the format printed with the numbers after it (blackbox.c's
// Label: %f, %g, %e, %d take the next number; %% is a percent sign), at the turtle.
void Turtle::cpfgLabel(const State& t, const double* p, int arity) {
    const auto& strings = m_g.alphabet.strings();
    if (!p || arity < 1 || !(*p >= 0 && *p < double(strings.size())) || m_out.labels.size() >= 100000) return;
    const std::string& format = strings[size_t(*p)];
    std::string text;
    int next = 1;
    for (size_t k = 0; k < format.size() && text.size() < 1000; ++k) {
        if (format[k] != '%' || k + 1 >= format.size()) {
            text += format[k];
            continue;
        }
        size_t j = k + 1;
        while (j < format.size() && std::strchr("-+ #0123456789.l", format[j]) && format[j] != '\0') ++j;
        if (j >= format.size() || format[j] == '\0' || !std::strchr("fgeEGd%", format[j])) {
            text += format[k];
            continue;
        }
        if (format[j] == '%') {
            text += '%';
        } else if (next < arity) {
            // The conversion as written (flags, width up to 2 digits, precision), without 'l'.
            std::string spec;
            for (size_t c = k; c <= j; ++c)
                if (format[c] != 'l') spec += format[c];
            if (spec.size() > 8) spec = std::string("%") + format[j];
            char buf[128];
            if (format[j] == 'd') std::snprintf(buf, sizeof buf, spec.c_str(), int(std::clamp(p[next], -2e9, 2e9)));
            else std::snprintf(buf, sizeof buf, spec.c_str(), p[next]);
            ++next;
            text += buf;
        }
        k = j;
    }
    m_out.labels.push_back({toGlm(t.pos), std::move(text), 13.0f, t.stemColour});
}

// patches.c: @PS(id, basis) starts patch id with every control point at the origin, @PC(id,
// row, col) puts control point (row, col) where the turtle is, @PD(id, s, t) draws the bicubic
// surface through them (Bezier, B-spline or Cardinal basis) as s x t quads (5 x 5 without
// numbers, at most 10 x 10), in the turtle's colour; a patch with a point not set is not drawn.
void Turtle::patchCommand(const State& t, Act act, const double* p, int arity) {
    if (!p || arity < 1 || !std::isfinite(p[0])) return;
    if (act == Act::PatchStart) {
        if (m_patches.size() >= 4096 && !m_patches.count(p[0])) return;
        Patch& patch = m_patches[p[0]];
        patch = Patch{};
        if (arity >= 2 && p[1] >= 1 && p[1] <= 3) patch.basis = int(p[1]);
        return;
    }
    if (act == Act::PatchPoint) {
        if (arity < 3 || !(p[1] >= 0 && p[1] < 4 && p[2] >= 0 && p[2] < 4)) return;
        if (m_patches.size() >= 4096 && !m_patches.count(p[0])) return;
        Patch& patch = m_patches[p[0]];
        const int k = int(p[1]) * 4 + int(p[2]);
        patch.points[size_t(k)] = toGlm(t.pos);
        patch.assigned = std::uint16_t(patch.assigned | (1u << k));
        return;
    }
    auto it = m_patches.find(p[0]);
    if (it == m_patches.end() || it->second.assigned != 0xFFFF || !m_opt.meshes) return;
    const Patch& patch = it->second;
    const int ns = arity >= 3 && p[1] >= 1 ? int(std::min(p[1], 10.0)) : 5;
    const int nt = arity >= 3 && p[2] >= 1 ? int(std::min(p[2], 10.0)) : 5;
    static const float kBasis[3][4][4] = {
        {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}},
        {{-1 / 6.f, 3 / 6.f, -3 / 6.f, 1 / 6.f}, {3 / 6.f, -6 / 6.f, 3 / 6.f, 0}, {-3 / 6.f, 0, 3 / 6.f, 0}, {1 / 6.f, 4 / 6.f, 1 / 6.f, 0}},
        {{-0.5f, 1.5f, -1.5f, 0.5f}, {1, -2.5f, 2, -0.5f}, {-0.5f, 0, 0.5f, 0}, {0, 1, 0, 0}}};
    const auto& M = kBasis[patch.basis - 1];
    // The weights of the 4 control points of a row (or column) at u: [u^3 u^2 u 1] M.
    auto weights = [&](float u, bool derivative) {
        const float pw[4] = {derivative ? 3 * u * u : u * u * u, derivative ? 2 * u : u * u, derivative ? 1.0f : u, derivative ? 0.0f : 1.0f};
        std::array<float, 4> w{};
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) w[size_t(j)] += pw[k] * M[k][j];
        return w;
    };
    Mesh& mesh = m_out.polygons;
    const std::uint32_t base = std::uint32_t(mesh.positions.size());
    for (int i = 0; i <= ns; ++i) {
        const float s = float(i) / float(ns);
        const auto ws = weights(s, false), dws = weights(s, true);
        for (int j = 0; j <= nt; ++j) {
            const float u = float(j) / float(nt);
            const auto wt = weights(u, false), dwt = weights(u, true);
            glm::vec3 pos(0), ds(0), dt(0);
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) {
                    const glm::vec3& q = patch.points[size_t(r * 4 + c)];
                    pos += ws[size_t(r)] * wt[size_t(c)] * q;
                    ds += dws[size_t(r)] * wt[size_t(c)] * q;
                    dt += ws[size_t(r)] * dwt[size_t(c)] * q;
                }
            const glm::vec3 n = glm::cross(ds, dt);
            const float len = glm::length(n);
            mesh.positions.push_back(pos);
            mesh.normals.push_back(len > 1e-12f ? n / len : toGlm(up(t)));
            mesh.colours.push_back(t.stemColour);
            addBound(fromGlm(pos));
        }
    }
    const std::uint32_t row = std::uint32_t(nt + 1);
    for (std::uint32_t i = 0; i < std::uint32_t(ns); ++i)
        for (std::uint32_t j = 0; j < std::uint32_t(nt); ++j) {
            const std::uint32_t a = base + i * row + j, b = a + 1, c = a + row, d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
        }
}

}  // namespace sprout::turtle_impl
