#include "core/turtle/background_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace sprout {
namespace {

using C = vlab::BackgroundCommand;
constexpr float kPi = 3.14159265358979f;

// One shape's triangles in world coordinates, before it joins the mesh.
struct Piece {
    std::vector<glm::vec3> positions, normals;
    std::vector<std::uint32_t> indices;
    void clear() {
        positions.clear();
        normals.clear();
        indices.clear();
    }
    std::uint32_t vertex(const glm::vec3& p, const glm::vec3& n) {
        positions.push_back(p);
        normals.push_back(n);
        return std::uint32_t(positions.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
};

class Painter {
public:
    Painter(const vlab::BackgroundScene& scene, Geometry& out) : m_scene(scene), m_out(out), m_material(scene.start) {
        m_map = glm::vec3(float(scene.startColour >> 16 & 0xFF), float(scene.startColour >> 8 & 0xFF), float(scene.startColour & 0xFF));
        m_sides = std::clamp(scene.sides, 3, 128);
        setMatrix(glm::mat4(1.0f));
    }
    void item(const vlab::BackgroundItem& it);
    std::size_t triangles() const { return m_triangles; }

private:
    void setMatrix(const glm::mat4& m) {
        m_matrix = m;
        const glm::mat3 l(m);
        const float det = glm::determinant(l);
        m_normals = std::isfinite(det) && std::fabs(det) > 1e-30f ? glm::transpose(glm::inverse(l)) : l;
    }
    // cpfg's Transform3Point: the point in the matrix, divided by w when w is neither 0 nor 1.
    glm::vec3 point(const glm::vec3& p) const {
        glm::vec4 q = m_matrix * glm::vec4(p, 1.0f);
        if (q.w != 0.0f && q.w != 1.0f) q /= q.w;
        return glm::vec3(q);
    }
    glm::vec3 direction(const glm::vec3& n) const { return unit(m_normals * n); }
    static glm::vec3 unit(const glm::vec3& v) {
        const float l = glm::length(v);
        return std::isfinite(l) && l > 1e-30f ? v / l : glm::vec3(0.0f);
    }
    std::uint32_t colour(float emission = 1.0f) const;
    void material(const float* v, std::uint32_t n);
    // Flat shapes: a fan of points (cpfg's normal from the first three unless given), a quad.
    void fan(const std::vector<glm::vec3>& world, const std::vector<glm::vec3>* normals);
    void quad(const float* p1, const float* p2, const float* p3, const float* p4);
    void prism(const float* v);
    void tube(float r1, float r2, float h);
    void sphere(float r);
    void commit(std::uint32_t colour);

    const vlab::BackgroundScene& m_scene;
    Geometry& m_out;
    vlab::Material m_material;
    glm::vec3 m_map;  // a colour map's entry, 0..255
    int m_sides = 8;
    glm::mat4 m_matrix{1.0f};
    glm::mat3 m_normals{1.0f};
    std::vector<glm::mat4> m_stack;
    Piece m_piece;
    std::size_t m_triangles = 0;
    bool m_full = false;  // kMaxBackgroundTriangles reached: the shapes after are left out
};

std::uint32_t Painter::colour(float emission) const {
    if (m_scene.materials) {
        vlab::Material m = m_material;
        for (float& e : m.emission) e *= emission;
        return vlab::materialColour(m);
    }
    auto channel = [&](float v) { return std::uint32_t(std::lround(std::clamp(v * emission, 0.0f, 255.0f))); };
    return channel(m_map.r) << 24 | channel(m_map.g) << 16 | channel(m_map.b) << 8 | 0xFFu;
}

// cpfg's `material`: RGBA ambient, diffuse, specular and emission, then shininess, each group
// given changing the material the scene draws with (a colour map takes the diffuse colour).
void Painter::material(const float* v, std::uint32_t n) {
    auto rgb = [&](std::array<float, 3>& into, std::uint32_t at) {
        for (int c = 0; c < 3; ++c) into[size_t(c)] = v[at + std::uint32_t(c)];
    };
    if (!m_scene.materials) {
        if (n >= 8) m_map = glm::vec3(v[4], v[5], v[6]) * 255.0f;
        return;
    }
    if (n >= 4) rgb(m_material.ambient, 0);
    if (n >= 8) {
        rgb(m_material.diffuse, 4);
        m_material.transparency = 1.0f - std::clamp(v[7], 0.0f, 1.0f);  // GL's alpha is the diffuse colour's
    }
    if (n >= 12) rgb(m_material.specular, 8);
    if (n >= 16) rgb(m_material.emission, 12);
    if (n >= 17) m_material.shininess = v[16];
}

void Painter::fan(const std::vector<glm::vec3>& world, const std::vector<glm::vec3>* normals) {
    glm::vec3 n(0.0f);
    if (!normals) {
        n = unit(glm::cross(world[0] - world[1], world[2] - world[1]));  // cpfg's (a - b) x (c - b)
        if (n == glm::vec3(0.0f)) {  // its first points in a line: the outline's own normal
            for (size_t i = 0; i < world.size(); ++i) n += glm::cross(world[i], world[(i + 1) % world.size()]);
            n = unit(n);
        }
    }
    for (size_t i = 0; i < world.size(); ++i) m_piece.vertex(world[i], normals ? (*normals)[i] : n);
    for (std::uint32_t i = 1; i + 1 < world.size(); ++i) m_piece.triangle(0, i, i + 1);
}

// cpfg's DrawRectangle: two triangles (p1 p2 p3, p1 p3 p4), the normal (p3 - p1) x (p2 - p1).
void Painter::quad(const float* p1, const float* p2, const float* p3, const float* p4) {
    const glm::vec3 a = point(glm::make_vec3(p1)), b = point(glm::make_vec3(p2)), c = point(glm::make_vec3(p3)),
                    d = point(glm::make_vec3(p4));
    const glm::vec3 n = unit(glm::cross(c - a, b - a));
    const std::uint32_t base = std::uint32_t(m_piece.positions.size());
    for (const glm::vec3& p : {a, b, c, d}) m_piece.vertex(p, n);
    m_piece.triangle(base, base + 1, base + 2);
    m_piece.triangle(base, base + 2, base + 3);
}

// cpfg's prism: the box from the origin to (x, y, z), its six faces as cpfg lists them.
void Painter::prism(const float* v) {
    float P[2][2][2][3];
    for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y)
            for (int z = 0; z < 2; ++z) {
                P[x][y][z][0] = float(x) * v[0];
                P[x][y][z][1] = float(y) * v[1];
                P[x][y][z][2] = float(z) * v[2];
            }
    quad(P[0][0][0], P[0][0][1], P[0][1][1], P[0][1][0]);
    quad(P[1][0][0], P[1][1][0], P[1][1][1], P[1][0][1]);
    quad(P[0][0][0], P[0][1][0], P[1][1][0], P[1][0][0]);
    quad(P[0][0][1], P[1][0][1], P[1][1][1], P[0][1][1]);
    quad(P[0][0][0], P[0][0][1], P[1][0][1], P[1][0][0]);
    quad(P[0][1][0], P[1][1][0], P[1][1][1], P[0][1][1]);
}

// A cylinder or cone along y from 0 (radius r1) to h (radius r2), its sides where cpfg's unit
// cylinder puts them in the turtle's frame (x along -left, z along -up), closed by discs.
void Painter::tube(float r1, float r2, float h) {
    const int n = m_sides;
    const float s = h < 0 ? -1.0f : 1.0f;
    auto around = [&](int k, float r, float y) {
        const float t = 2 * kPi * float(k % n) / float(n);
        return glm::vec3(-r * std::cos(t), y, -r * std::sin(t));
    };
    if (h != 0) {  // cpfg draws no side for a segment of length 0
        const std::uint32_t base = std::uint32_t(m_piece.positions.size());
        for (int k = 0; k < n; ++k) {
            const float t = 2 * kPi * float(k) / float(n);
            const glm::vec3 local(-std::cos(t) * std::fabs(h), (r1 - r2) * s, -std::sin(t) * std::fabs(h));
            m_piece.vertex(point(around(k, r1, 0)), direction(local));
            m_piece.vertex(point(around(k, r2, h)), direction(local));
        }
        for (std::uint32_t k = 0; k < std::uint32_t(n); ++k) {
            const std::uint32_t a = base + 2 * k, b = base + 2 * ((k + 1) % std::uint32_t(n));
            m_piece.triangle(a, b, b + 1);
            m_piece.triangle(a, b + 1, a + 1);
        }
    }
    for (const auto& [r, y, outwards] : {std::tuple{r1, 0.0f, -s}, std::tuple{r2, h, s}}) {
        if (r == 0) continue;  // gluDisk of radius 0
        const glm::vec3 normal = direction(glm::vec3(0, outwards, 0));
        const std::uint32_t centre = m_piece.vertex(point(glm::vec3(0, y, 0)), normal);
        for (int k = 0; k < n; ++k) m_piece.vertex(point(around(k, r, y)), normal);
        for (std::uint32_t k = 0; k < std::uint32_t(n); ++k) m_piece.triangle(centre, centre + 1 + k, centre + 1 + (k + 1) % std::uint32_t(n));
    }
}

// gluSphere(r, sides, sides / 2 + 1) in cpfg's frame for it (x along -left): poles on z.
void Painter::sphere(float r) {
    const int slices = m_sides, stacks = m_sides / 2 + 1;
    const std::uint32_t base = std::uint32_t(m_piece.positions.size());
    for (int i = 0; i <= stacks; ++i) {
        const float phi = kPi * float(i) / float(stacks);
        for (int k = 0; k <= slices; ++k) {
            const float t = 2 * kPi * float(k % slices) / float(slices);
            const glm::vec3 d(-std::sin(phi) * std::cos(t), std::sin(phi) * std::sin(t), std::cos(phi));
            m_piece.vertex(point(r * d), direction(d));
        }
    }
    const std::uint32_t row = std::uint32_t(slices + 1);
    for (std::uint32_t i = 0; i < std::uint32_t(stacks); ++i)
        for (std::uint32_t k = 0; k < std::uint32_t(slices); ++k) {
            const std::uint32_t a = base + i * row + k, b = a + row;
            if (i > 0) m_piece.triangle(a, b, a + 1);                       // none at the top pole
            if (i + 1 < std::uint32_t(stacks)) m_piece.triangle(a + 1, b, b + 1);  // nor at the bottom one
        }
}

// The piece joins the mesh, each triangle turned counter-clockwise about its normals; left out
// when a point is not finite or the scene has drawn its most triangles.
void Painter::commit(std::uint32_t colour) {
    Piece& p = m_piece;
    const std::size_t triangles = p.indices.size() / 3;
    const bool finite = std::all_of(p.positions.begin(), p.positions.end(),
                                    [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); });
    if (m_triangles + triangles > kMaxBackgroundTriangles) m_full = true;  // nothing more is drawn
    if (finite && triangles && !m_full) {
        Mesh& mesh = m_out.polygons;
        const std::uint32_t base = std::uint32_t(mesh.positions.size());
        for (size_t i = 0; i < p.positions.size(); ++i) {
            mesh.positions.push_back(p.positions[i]);
            mesh.normals.push_back(p.normals[i]);
            mesh.colours.push_back(colour);
            m_out.backdrop.add(p.positions[i]);
        }
        for (size_t t = 0; t < p.indices.size(); t += 3) {
            std::uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
            const glm::vec3 face = glm::cross(p.positions[b] - p.positions[a], p.positions[c] - p.positions[a]);
            if (glm::dot(face, p.normals[a] + p.normals[b] + p.normals[c]) < 0) std::swap(b, c);
            mesh.indices.insert(mesh.indices.end(), {base + a, base + b, base + c});
        }
        m_triangles += triangles;
    }
    p.clear();
}

void Painter::item(const vlab::BackgroundItem& it) {
    if (std::size_t(it.first) + it.count > m_scene.values.size()) return;
    const float* v = m_scene.values.data() + it.first;
    const std::uint32_t n = it.count;
    const bool shape = it.command != C::Material && it.command != C::PushMatrix && it.command != C::PopMatrix &&
                       it.command != C::Translate && it.command != C::Rotate && it.command != C::Scale && it.command != C::MultMatrix;
    if (shape && m_full) return;
    switch (it.command) {
        case C::Material: return material(v, n);
        case C::PushMatrix:
            if (m_stack.size() < 49) m_stack.push_back(m_matrix);
            return;
        case C::PopMatrix:
            if (!m_stack.empty()) setMatrix(m_stack.back()), m_stack.pop_back();
            return;
        case C::Translate: return n >= 3 ? setMatrix(glm::translate(m_matrix, glm::make_vec3(v))) : void();
        case C::Scale: return n >= 3 ? setMatrix(glm::scale(m_matrix, glm::make_vec3(v))) : void();
        case C::Rotate: {
            if (n < 4) return;
            const glm::vec3 axis = unit(glm::make_vec3(v + 1));
            if (axis != glm::vec3(0.0f)) setMatrix(glm::rotate(m_matrix, v[0] * kPi / 180.0f, axis));
            return;
        }
        case C::MultMatrix: return n >= 16 ? setMatrix(m_matrix * glm::make_mat4(v)) : void();  // rows of IRIS GL are glm's columns
        case C::Polygon:
        case C::PolygonUV: {
            const std::uint32_t stride = it.command == C::Polygon ? 3 : 6;
            if (n < 3 * stride) return;
            std::vector<glm::vec3> world, normals;
            for (std::uint32_t k = 0; k + stride <= n; k += stride) {
                world.push_back(point(glm::make_vec3(v + k)));
                if (stride == 6) normals.push_back(direction(glm::make_vec3(v + k + 3)));
            }
            fan(world, stride == 6 ? &normals : nullptr);
            break;
        }
        case C::Rectangle: {
            if (n < 2) return;
            const float x = n >= 4 ? v[2] : 0, y = n >= 4 ? v[3] : 0;
            const float p[4][3] = {{x, y, 0}, {x + v[0], y, 0}, {x + v[0], y + v[1], 0}, {x, y + v[1], 0}};
            quad(p[0], p[1], p[2], p[3]);
            return commit(colour(n >= 5 ? v[4] : 1.0f));
        }
        case C::Mesh:
            for (std::uint32_t j = 0; j + 12 <= n; j += 6) quad(v + j, v + j + 6, v + j + 9, v + j + 3);
            break;
        case C::Prism:
            if (n < 3) return;
            prism(v);
            break;
        case C::Cone:
        case C::Cylinder: {
            if (n < (it.command == C::Cone ? 3u : 2u)) return;
            const float r1 = std::fabs(v[0]);
            const float r2 = it.command == C::Cone && m_scene.tapered ? std::fabs(v[1]) : r1;
            tube(r1, r2, it.command == C::Cone ? v[2] : v[1]);
            break;
        }
        case C::Sphere:
            if (n < 1 || v[0] == 0) return;  // cpfg draws no sphere of radius 0
            sphere(std::fabs(v[0]));
            break;
    }
    commit(colour());
}

}  // namespace

std::size_t drawBackgroundScene(const vlab::BackgroundScene& scene, Geometry& out) {
    const std::size_t first = out.polygons.positions.size();
    Painter painter(scene, out);
    for (const vlab::BackgroundItem& it : scene.items) painter.item(it);
    out.backdropFirst = std::uint32_t(first);
    out.backdropCount = std::uint32_t(out.polygons.positions.size() - first);
    return painter.triangles();
}

}  // namespace sprout
