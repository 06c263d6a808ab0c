#include "core/environment/environment_drawing.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/base/bounded.hpp"

namespace sprout {
namespace {

constexpr std::uint32_t kGlass = 0x8cc8f050;     // regions and attraction shapes
constexpr std::uint32_t kStone = 0x9a9084ff;     // obstacles: solid
constexpr std::uint32_t kGroundSheet = 0x7a6a4a60;
constexpr std::uint32_t kPoint = 0xf0a030ff;     // attraction points still free

struct Builder {
    Mesh& m;
    std::uint32_t colour;
    std::uint32_t vertex(const glm::dvec3& p, const glm::dvec3& n) {
        m.positions.emplace_back(p);
        m.normals.emplace_back(n);
        m.colours.push_back(colour);
        return std::uint32_t(m.positions.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { m.indices.insert(m.indices.end(), {a, b, c}); }
    void quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, d - a));
        const std::uint32_t i = vertex(a, n), j = vertex(b, n), k = vertex(c, n), l = vertex(d, n);
        triangle(i, j, k);
        triangle(i, k, l);
    }
    // A unit sphere scaled by `radii` about `centre` (an ellipsoid).
    void ellipsoid(const glm::dvec3& centre, const glm::dvec3& radii, int slices = 32, int stacks = 16) {
        const std::uint32_t base = std::uint32_t(m.positions.size());
        for (int i = 0; i <= stacks; ++i) {
            const double v = 3.14159265358979 * i / stacks;
            for (int j = 0; j <= slices; ++j) {
                const double u = 2 * 3.14159265358979 * j / slices;
                const glm::dvec3 unit(std::sin(v) * std::cos(u), std::cos(v), std::sin(v) * std::sin(u));
                vertex(centre + unit * radii, glm::normalize(unit / radii));
            }
        }
        for (int i = 0; i < stacks; ++i)
            for (int j = 0; j < slices; ++j) {
                const std::uint32_t a = base + std::uint32_t(i * (slices + 1) + j), b = a + std::uint32_t(slices + 1);
                triangle(a, b, a + 1);
                triangle(a + 1, b, b + 1);
            }
    }
    void box(const glm::dvec3& lo, const glm::dvec3& hi) {
        const glm::dvec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                                 {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
        quad(c[0], c[3], c[2], c[1]);  // -z
        quad(c[4], c[5], c[6], c[7]);  // +z
        quad(c[0], c[4], c[7], c[3]);  // -x
        quad(c[1], c[2], c[6], c[5]);  // +x
        quad(c[0], c[1], c[5], c[4]);  // -y
        quad(c[3], c[7], c[6], c[2]);  // +y
    }
    void cylinder(const glm::dvec3& base, double r, double h, int slices = 40) {
        const std::uint32_t first = std::uint32_t(m.positions.size());
        for (int j = 0; j <= slices; ++j) {
            const double u = 2 * 3.14159265358979 * j / slices;
            const glm::dvec3 n(std::cos(u), 0, std::sin(u));
            vertex(base + n * r, n);
            vertex(base + n * r + glm::dvec3(0, h, 0), n);
        }
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = first + std::uint32_t(2 * j);
            triangle(a, a + 1, a + 2);
            triangle(a + 2, a + 1, a + 3);
        }
        for (double y : {0.0, h}) {  // the caps
            const glm::dvec3 n(0, y > 0 ? 1 : -1, 0);
            const std::uint32_t centre = vertex(base + glm::dvec3(0, y, 0), n), ring = std::uint32_t(m.positions.size());
            for (int j = 0; j <= slices; ++j) {
                const double u = 2 * 3.14159265358979 * j / slices;
                vertex(base + glm::dvec3(std::cos(u) * r, y, std::sin(u) * r), n);
            }
            for (int j = 0; j < slices; ++j) triangle(centre, ring + std::uint32_t(j), ring + std::uint32_t(j + 1));
        }
    }
    void mesh(const TriMesh& t) {
        for (size_t k = 0; k + 2 < t.triangles.size(); k += 3) {
            const glm::dvec3 &a = t.vertices[t.triangles[k]], &b = t.vertices[t.triangles[k + 1]], &c = t.vertices[t.triangles[k + 2]];
            glm::dvec3 n = glm::cross(b - a, c - a);
            n = glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0, 1, 0);
            triangle(vertex(a, n), vertex(b, n), vertex(c, n));
        }
    }
    void shape(const EnvShape& s) {
        switch (s.kind) {
            case EnvShape::Kind::Sphere: ellipsoid(s.a, glm::dvec3(s.b.x)); break;
            case EnvShape::Kind::Ellipsoid: ellipsoid(s.a, s.b); break;
            case EnvShape::Kind::Box: box(s.a, s.b); break;
            case EnvShape::Kind::Cylinder: cylinder(s.a, s.b.x, s.b.y); break;
            case EnvShape::Kind::Mesh: mesh(*s.mesh); break;
        }
    }
};

// A colour for light in [0, 1]: deep blue in full shade to pale yellow in the open.
std::uint32_t lightColour(double light) {
    const double t = std::clamp(light, 0.0, 1.0);
    const auto mix = [&](double a, double b) { return std::uint32_t(std::lround(a + (b - a) * t)); };
    return mix(30, 255) << 24 | mix(40, 240) << 16 | mix(120, 150) << 8 | mix(230, 40);
}

}  // namespace

bool drawEnvironment(const Environment& env, const Geometry& grown, std::uint64_t seed, const EnvironmentView& view, Mesh& out,
                     std::string* error) {
    Builder b{out, kGlass};
    for (const EnvShape& s : env.region) b.shape(s);
    if (env.attractionShape) {
        b.shape(*env.attractionShape);
        // The points still free, as small diamonds (at most 20,000 of them).
        const std::vector<glm::dvec3> points = freePoints(env, grown, seed);
        const double r = std::max(0.04, env.kill * 0.12);
        b.colour = kPoint;
        const size_t stride = std::max<size_t>(1, points.size() / 20000);
        for (size_t k = 0; k < points.size(); k += stride) {
            const glm::dvec3& p = points[k];
            const glm::dvec3 axes[6] = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
            const std::uint32_t base = std::uint32_t(out.positions.size());
            for (const glm::dvec3& a : axes) b.vertex(p + a, glm::normalize(a));
            static const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
            for (const auto& f : faces) b.triangle(base + std::uint32_t(f[0]), base + std::uint32_t(f[1]), base + std::uint32_t(f[2]));
        }
    }
    b.colour = kStone;
    // A hair larger than they are: a plant that draws its own boulder where the obstacle is
    // (env_climber) shows the environment's, instead of the two fighting for each pixel.
    for (EnvShape s : env.obstacles) {
        if (s.kind == EnvShape::Kind::Sphere) s.b.x *= 1.004;
        else if (s.kind == EnvShape::Kind::Box) {
            const glm::dvec3 grow = (s.b - s.a) * 0.002 + 1e-4;
            s.a -= grow, s.b += grow;
        }
        b.shape(s);
    }
    if (env.ground) {
        // A sheet at the ground's height, wider than the plant and its obstacles.
        Bounds box = grown.bounds;
        for (const EnvShape& s : env.obstacles) {
            box.add(glm::vec3(s.a));
            box.add(glm::vec3(s.kind == EnvShape::Kind::Sphere ? s.a + s.b.x : s.b));
        }
        const glm::dvec3 c = box.empty ? glm::dvec3(0.0) : glm::dvec3(box.centre());
        const double half = std::max(5.0, 0.75 * double(std::max(box.size().x, box.size().z)) + 2.0);
        const double y = *env.ground;
        b.colour = kGroundSheet;
        b.quad({c.x - half, y, c.z - half}, {c.x - half, y, c.z + half}, {c.x + half, y, c.z + half}, {c.x + half, y, c.z - half});
    }
    if (view.lightSlice && env.isLight()) {
        LightGrid grid;
        std::string why;
        if (!buildLight(env, grown, grid, why)) {
            if (error) *error = why;
            return false;
        }
        if (grid.nx > 0 && grid.ny > 0 && grid.nz > 0) {
            // The height runs over the plant, from its lowest point to its top.
            const double want = grown.bounds.min.y + view.sliceHeight * (grown.bounds.max.y - grown.bounds.min.y);
            // The slice's height comes from the view (a script may say 'nan'): clamped as a double.
            const int j = std::clamp(floorCell<int>((want - grid.origin.y) / grid.voxel), 0, grid.ny - 1);
            const double y = grid.origin.y + (j + 0.5) * grid.voxel;
            // At most 256 x 256 quads: a larger grid is sampled.
            const int step = std::max(1, std::max(grid.nx, grid.nz) / 256);
            for (int k = 0; k < grid.nz; k += step)
                for (int i = 0; i < grid.nx; i += step) {
                    const glm::dvec3 lo = grid.origin + glm::dvec3(i, 0, k) * grid.voxel;
                    const double w = grid.voxel * step;
                    b.colour = lightColour(grid.lightAt({lo.x + 0.5 * grid.voxel, y, lo.z + 0.5 * grid.voxel}));
                    b.quad({lo.x, y, lo.z}, {lo.x, y, lo.z + w}, {lo.x + w, y, lo.z + w}, {lo.x + w, y, lo.z});
                }
        }
    }
    return true;
}

}  // namespace sprout
