// What the turtle draws with an image (its palette entry's texture, or cpfg's @Tx): stems,
// predefined surfaces and polygons, as triangles with texture coordinates in the polygon mesh.
// The instances the renderer draws stems and surfaces from have no room for an image, so a
// textured stem or surface is noted as it is drawn and made triangles at the finish, when its
// radius and size are final, and taken out of the instances.
#include <algorithm>
#include <cmath>

#include "core/turtle/turtle_impl.hpp"
#include "core/turtle/unit_surfaces.hpp"

namespace sprout {
namespace turtle_impl {

namespace {

constexpr int kStemSides = 16;
// At most this many stems and surfaces are made textured triangles (a stem's are 3.5 KB, a
// leaf's 5.4 KB, against an instance's 40 or 48 bytes): the rest keep their colour, so that a
// textured plant of millions of stems costs no more memory than the instances predicted.
constexpr std::size_t kMaxTextured = 40'000;

// The instances not noted in `noted` (by index, increasing), kept in order; their modules too.
template <class Buffer, class Noted>
void dropNoted(Buffer& items, const std::vector<Noted>& noted, std::vector<std::uint32_t>* modules) {
    const bool withModules = modules && modules->size() == items.size();
    size_t kept = 0, k = 0;
    for (size_t i = 0; i < items.size(); ++i) {
        if (k < noted.size() && noted[k].index == i) {
            ++k;
            continue;
        }
        items[kept] = items[i];
        if (withModules) (*modules)[kept] = (*modules)[i];
        ++kept;
    }
    items.resizeUninitialized(kept);
    if (withModules) modules->resize(kept);
}

}  // namespace

// A stem of length `len` just drawn with an image: its v runs on from the stems drawn before
// it in the same colour (PlantGL's axial length, kept in pos[3]).
void Turtle::noteTexturedStem(State& t, float len) {
    const std::uint32_t image = textureOf(t);
    if (!image || m_level || !m_opt.meshes || m_opt.ages || !(len > 0) || textured() >= kMaxTextured) return;
    const float v0 = t.pos[3];
    t.pos[3] = v0 + len;
    m_texturedStems.push_back({std::uint32_t(m_seg->count() - 1), image, t.texture, v0, v0 + len, toGlm(t.L)});
}

void Turtle::noteTexturedSurface(const State& t) {
    const std::uint32_t image = textureOf(t);
    if (!image || m_level || !m_opt.meshes || m_opt.ages || textured() >= kMaxTextured) return;
    m_texturedSurfaces.push_back({std::uint32_t(m_out.surfaces.size() - 1), image, t.texture});
}

void Turtle::polygonTexcoords(const State& t, const Frame& at, std::uint32_t base) {
    const std::uint32_t image = textureOf(t);
    Mesh& m = m_out.polygons;
    if (!image || base >= m.positions.size()) return;
    const glm::vec3 sAxis = -at.l, tAxis = at.h;
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (size_t k = base; k < m.positions.size(); ++k) {
        const glm::vec2 st(glm::dot(m.positions[k], sAxis), glm::dot(m.positions[k], tAxis));
        lo = glm::min(lo, st), hi = glm::max(hi, st);
    }
    const glm::vec2 extent = hi - lo;
    const TexTransform& tx = m_texTransforms[size_t(t.texture)];
    m.texcoords.resize(base);
    for (size_t k = base; k < m.positions.size(); ++k) {
        const glm::vec2 st(glm::dot(m.positions[k], sAxis), glm::dot(m.positions[k], tAxis));
        const glm::vec2 uv((extent.x > 0 ? (st.x - lo.x) / extent.x : 0), (extent.y > 0 ? (st.y - lo.y) / extent.y : 0));
        const glm::vec2 q = tx(uv);
        m.texcoords.push_back({q.x, q.y, image});
    }
}

void Turtle::drawTextured() {
    if (m_out.planarCurve) m_texturedStems.clear();  // a flat curve's stems stay its ink
    if (m_texturedStems.empty() && m_texturedSurfaces.empty()) return;
    Mesh& m = m_out.polygons;
    // Stems: open tubes as PlantGL's cylinders are, u round from U towards -L, v along.
    for (const Textured& s : m_texturedStems) {
        if (s.index >= m_out.cylinders.size()) continue;
        const CylinderInstance& c = m_out.cylinders[s.index];
        const glm::vec3 axis = c.end - c.start;
        const float length = glm::length(axis);
        if (!(length > 0)) continue;
        const glm::vec3 d = axis / length;
        glm::vec3 l = s.left - glm::dot(s.left, d) * d;
        if (!(glm::length(l) > 1e-6f)) l = glm::cross(std::fabs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), d);
        l = glm::normalize(l);
        const glm::vec3 u = glm::cross(d, l);
        TexTransform x = m_texTransforms[size_t(s.transform)];
        if (x.along > 0) x.scale.y *= x.along / std::max(c.startRadius + c.endRadius, 1e-6f);  // cpfg's proportions
        const std::uint32_t base = std::uint32_t(m.positions.size());
        m.texcoords.resize(base);
        for (int end = 0; end < 2; ++end)
            for (int i = 0; i <= kStemSides; ++i) {
                const float a = 2 * kPi * float(i) / float(kStemSides);
                const glm::vec3 n = std::cos(a) * u - std::sin(a) * l;
                m.positions.push_back((end ? c.end : c.start) + (end ? c.endRadius : c.startRadius) * n);
                m.normals.push_back(n);
                m.colours.push_back(c.colour);
                glm::vec2 q = x(glm::vec2(float(i) / float(kStemSides), end ? s.v1 - s.v0 : 0.0f));
                q.y += s.v0 * x.scale.y;  // PlantGL's shift by the axial length
                m.texcoords.push_back({q.x, q.y, s.image});
            }
        const std::uint32_t ring = kStemSides + 1;
        for (std::uint32_t i = 0; i < std::uint32_t(kStemSides); ++i) {
            const std::uint32_t a0 = base + i, a1 = a0 + 1, b0 = a0 + ring, b1 = a1 + ring;
            m.indices.insert(m.indices.end(), {a0, a1, b1, a0, b1, b0});
        }
        // Flat ends, as PlantGL's solid cylinders have them (the image as a disc on each).
        for (int end = 0; end < 2; ++end) {
            const std::uint32_t centre = std::uint32_t(m.positions.size());
            const glm::vec3 n = end ? d : -d;
            for (int i = -1; i < kStemSides; ++i) {
                const float a = 2 * kPi * float(std::max(i, 0)) / float(kStemSides);
                const glm::vec2 disc = i < 0 ? glm::vec2(0.5f) : glm::vec2(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a));
                const glm::vec3 p = end ? c.end : c.start;
                m.positions.push_back(i < 0 ? p : p + (end ? c.endRadius : c.startRadius) * (std::cos(a) * u - std::sin(a) * l));
                m.normals.push_back(n);
                m.colours.push_back(c.colour);
                const glm::vec2 q = x(disc);
                m.texcoords.push_back({q.x, q.y, s.image});
            }
            for (std::uint32_t i = 0; i < std::uint32_t(kStemSides); ++i) {
                const std::uint32_t a = centre + 1 + i, b = centre + 1 + (i + 1) % std::uint32_t(kStemSides);
                if (end) m.indices.insert(m.indices.end(), {centre, a, b});
                else m.indices.insert(m.indices.end(), {centre, b, a});
            }
        }
    }
    // Surfaces: the unit meshes the renderer instances, placed as it places them.
    static const SurfaceMesh leaf = makeLeaf(), petal = makePetal(), sphere = makeSphere(16, 10);
    for (const Textured& t : m_texturedSurfaces) {
        if (t.index >= m_out.surfaces.size()) continue;
        const SurfaceInstance& s = m_out.surfaces[t.index];
        const SurfaceMesh& unit = s.kind == SurfaceKind::Leaf ? leaf : s.kind == SurfaceKind::Petal ? petal : sphere;
        const glm::vec3 H = glm::normalize(s.heading), U = glm::normalize(s.up), L = glm::cross(U, H);
        const TexTransform& x = m_texTransforms[size_t(t.transform)];
        const std::uint32_t base = std::uint32_t(m.positions.size());
        m.texcoords.resize(base);
        for (size_t k = 0; k < unit.positions.size(); ++k) {
            const glm::vec3& p = unit.positions[k];
            const glm::vec3& n = unit.normals[k];
            m.positions.push_back(s.position + s.size * (p.x * L + p.y * H + p.z * U));
            m.normals.push_back(n.x * L + n.y * H + n.z * U);
            m.colours.push_back(s.colour);
            const glm::vec2 q = x(unit.uvs[k]);
            m.texcoords.push_back({q.x, q.y, t.image});
        }
        for (std::uint32_t i : unit.indices) m.indices.push_back(base + i);
    }
    dropNoted(m_out.cylinders, m_texturedStems, m_opt.segmentModules);
    dropNoted(m_out.surfaces, m_texturedSurfaces, m_opt.surfaceModules);
    m_texturedStems.clear();
    m_texturedSurfaces.clear();
}

}  // namespace turtle_impl
}  // namespace sprout
