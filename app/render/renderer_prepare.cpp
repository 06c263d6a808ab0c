// Baking a plant for drawing on the CPU (no GL, any thread): Renderer::prepare, and what a
// moving frame draws instead (prepareMoving: a sketch, a coarser bake or a clustered mesh).
#include "app/render/renderer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>
#include <glm/geometric.hpp>

#include "app/mesh/bake.hpp"
#include "app/mesh/texture_images.hpp"
#include "app/mesh/meshes.hpp"
#include "core/base/bounded.hpp"

namespace sprout::render {
namespace {

// A line from a to b in its colour, as the line programs read it: x y z and the colour's
// 0xRRGGBBAA bits as a float, for each end.
void appendLine(std::vector<float>& out, const glm::vec3& a, const glm::vec3& b, std::uint32_t colour) {
    float cf;
    std::memcpy(&cf, &colour, 4);
    out.insert(out.end(), {a.x, a.y, a.z, cf, b.x, b.y, b.z, cf});
}

// Levels of detail for stems, chosen by the stem's radius relative to the plant's size (the
// plant is framed whole, so that says how many pixels it covers at 720p): a round mesh with
// caps that close the joints, a coarser one, an open three-sided prism, and plain lines for
// stems under about a pixel. Measured on llvmpipe (2 cores): 98 k segments drawn as lines
// take 6 ms, as prisms baked on the CPU ~40 ms, as instanced cylinders read from a buffer
// texture 1 s; so everything is baked into one mesh and drawn with the simplest shader.
constexpr float kLevelThreshold[3] = {1.0f / 100, 1.0f / 300, 1.0f / 900};  // fine, medium, prism; below: line
// Interactive detail (the window while editing a big plant) trades roundness for speed:
// every triangle costs llvmpipe ~0.2 us of single-threaded setup.
constexpr float kInteractiveScale = 3.0f;
constexpr std::size_t kVertexBudget = 6'000'000;
// Planar curves with more segments than this are rasterised on the CPU (curve_raster.hpp) on a
// software rasteriser (a GPU draws them as ribbons: Renderer::bigCurveRibbons):
// below it every preset keeps its ribbons, pixel for pixel; above it a ribbon per segment
// costs far more than the picture (the quadratic Gosper curve n=5: 9.8 M ribbons, 5.6 s).
constexpr std::size_t kRasterCurveSegments = 200'000;  // ~170 MB baked; past it, thresholds rise

// The unit meshes baking uses, made once (thread-safe: prepare() runs on worker threads).
struct UnitMeshes {
    mesh::CylinderMesh stems[3] = {mesh::makeCylinder(10, 2), mesh::makeCylinder(6, 0), mesh::makePrism(3)};
    mesh::SurfaceMesh leaf = mesh::makeLeaf(), petal = mesh::makePetal(), sphere = mesh::makeSphere(16, 10), smallSphere = mesh::makeSphere(6, 3);
    // A moving frame's, by coarseness (144, 120 and 320 triangles above; 12, 12 and 48, then
    // 6, 6 and 24 here, the outline of six points: llvmpipe pays for each triangle).
    mesh::SurfaceMesh coarseLeaf[2] = {mesh::makeLeaf(3, 2), mesh::makeLeaf(3, 1)}, coarsePetal[2] = {mesh::makePetal(3, 2), mesh::makePetal(3, 1)},
                coarseSphere[2] = {mesh::makeSphere(8, 3), mesh::makeSphere(6, 2)};
};
const UnitMeshes& unitMeshes() {
    static const UnitMeshes m;
    return m;
}

}  // namespace

void Renderer::prepare(const Geometry& g, Quality detail, PreparedScene& out, std::shared_ptr<const Geometry> owner,
                       int coarseness) {
    const UnitMeshes& meshes = unitMeshes();
    out = PreparedScene();
    out.detail = detail;
    out.bounds = g.extent();  // the plant and a VLab object's background scene: the clip planes hold both
    out.planarCurve = g.planarCurve;
    out.cylinders = g.cylinders.size();
    out.surfaces = g.surfaces.size();
    mesh::BakedMesh& b = out.baked;
    const glm::vec3 size = g.bounds.empty ? glm::vec3(1) : g.bounds.size();
    const float extent = std::max({size.x, size.y, size.z, 1e-6f});
    if (g.planarCurve && g.cylinders.size() > kRasterCurveSegments) {
        // A big curve: rasterised from its segments at the size of the picture when drawn,
        // never copied (9.8 M segments are 390 MB).
        out.curveGeometry = owner ? std::move(owner) : std::shared_ptr<const Geometry>(&g, [](const Geometry*) {});
    } else if (g.planarCurve) {
        // A curve: every segment a screen-space ribbon.
        out.curve.assign(g.cylinders.begin(), g.cylinders.end());
    } else {
        // Pick the levels: the finest the vertex budget allows.
        float scale = detail == Quality::Interactive ? kInteractiveScale : 1.0f;
        auto levelOf = [&](const CylinderInstance& c) {
            float rel = std::max(c.startRadius, c.endRadius) / extent;
            for (int l = 0; l < 3; ++l)
                if (rel >= kLevelThreshold[l] * scale) return l;
            return 3;
        };
        for (;; scale *= 2) {
            std::size_t verts = 0;
            for (const auto& c : g.cylinders) {
                int l = levelOf(c);
                verts += l < 3 ? meshes.stems[l].vertices.size() : 0;
            }
            if (verts <= kVertexBudget || scale > 1e6f) break;
        }
        std::size_t reserve = 0;
        for (const auto& c : g.cylinders) {
            int l = levelOf(c);
            ++out.levels[l];
            reserve += l < 3 ? meshes.stems[l].vertices.size() : 0;
        }
        b.vertices.reserve(reserve);
        out.lines.reserve(out.levels[3] * 8);
        // Stems that continue straight on with the same radius and colour (F -> FF makes long
        // runs) are drawn as one tube or line: the same picture from a fraction of the primitives.
        auto continues = [](const CylinderInstance& a, const CylinderInstance& c) {
            if (a.colour != c.colour || a.endRadius != c.startRadius || glm::length(c.start - a.end) > 1e-5f * (1 + glm::length(a.end)))
                return false;
            glm::vec3 da = a.end - a.start, dc = c.end - c.start;
            float la = glm::length(da), lc = glm::length(dc);
            return la > 0 && lc > 0 && glm::dot(da, dc) > 0.99999f * la * lc;
        };
        CylinderInstance run{};
        int runLevel = -1;
        mesh::BakedMesh open;  // the prisms (open tubes), after the closed stems
        auto emit = [&] {
            if (runLevel < 0) return;
            if (runLevel < 3) {
                mesh::bakeCylinder(run, meshes.stems[runLevel], runLevel == 2 ? open : b);
            } else {
                appendLine(out.lines, run.start, run.end, run.colour);
            }
            runLevel = -1;
        };
        for (const auto& c : g.cylinders) {
            int l = levelOf(c);
            if (runLevel == l && continues(run, c)) {
                run.end = c.end;
                run.endRadius = c.endRadius;
                continue;
            }
            emit();
            run = c;
            runLevel = l;
        }
        emit();
        out.closedStems = b.indices.size() / 3;
        const std::uint32_t base = std::uint32_t(b.vertices.size());
        b.vertices.insert(b.vertices.end(), open.vertices.begin(), open.vertices.end());
        for (std::uint32_t i : open.indices) b.indices.push_back(base + i);
    }
    // Small spheres (seeds, buds) get a coarse mesh; they cover a few pixels.
    const int c = std::clamp(coarseness, 0, 2) - 1;  // the coarse meshes' index; -1: full
    for (const auto& x : g.surfaces) {
        const mesh::SurfaceMesh& mesh = x.kind == SurfaceKind::Leaf    ? (c >= 0 ? meshes.coarseLeaf[c] : meshes.leaf)
                                  : x.kind == SurfaceKind::Petal ? (c >= 0 ? meshes.coarsePetal[c] : meshes.petal)
                                  : x.size < extent / 60         ? meshes.smallSphere
                                  : c >= 0                       ? meshes.coarseSphere[c]
                                                                 : meshes.sphere;
        mesh::bakeSurface(x, mesh, b);
    }
    mesh::bakePolygons(g.polygons, b);
    out.translucent = mesh::translucentLast(b);
    std::size_t plain = b.indices.size() / 3 - out.translucent;
    out.textured = mesh::texturedLast(b, plain);
    for (const mesh::TextureRange& r : out.textured) plain -= r.count;
    out.textures = g.textures;
    out.shines = mesh::groupShines(b, plain, g.shines);
    // The closed stems stay the first triangles unless translucent or shining ones were moved
    // (stems among them): else none are culled.
    if (out.translucent || !out.shines.empty()) out.closedStems = 0;
}

namespace {

// Vertex clustering (Rossignac and Borrel): the vertices in one cell of a grid become one
// (their normals averaged), and triangles that collapse are dropped, so a mesh of any size
// becomes one bounded by the grid's cells on its surface.
mesh::BakedMesh clusterMesh(const mesh::BakedMesh& in, const Bounds& bounds, float cell) {
    mesh::BakedMesh out;
    std::unordered_map<std::uint64_t, std::uint32_t> cells;
    cells.reserve(in.vertices.size() / 4 + 16);
    std::vector<std::uint32_t> remap(in.vertices.size());
    std::vector<glm::vec3> normals;
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        const mesh::BakedVertex& v = in.vertices[i];
        const glm::vec3 q = glm::floor((v.position - bounds.min) / cell);
        auto axis = [](float x) { return std::uint64_t(std::clamp(saturate<int>(x), 0, (1 << 21) - 1)); };  // NaN: cell 0
        const std::uint64_t key = axis(q.x) | axis(q.y) << 21 | axis(q.z) << 42;
        const auto [at, fresh] = cells.try_emplace(key, std::uint32_t(out.vertices.size()));
        if (fresh) {
            out.vertices.push_back(v);
            normals.push_back(v.normal);
        } else {
            normals[at->second] += v.normal;
        }
        remap[i] = at->second;
    }
    for (std::size_t i = 0; i < out.vertices.size(); ++i) {
        const float l = glm::length(normals[i]);
        if (l > 1e-12f) out.vertices[i].normal = normals[i] / l;
    }
    for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3) {
        const std::uint32_t a = remap[in.indices[t]], b = remap[in.indices[t + 1]], c = remap[in.indices[t + 2]];
        if (a != b && b != c && a != c) out.indices.insert(out.indices.end(), {a, b, c});
    }
    return out;
}

}  // namespace

void Renderer::prepareForViewer(const Geometry& g, PreparedScene& out, std::shared_ptr<const Geometry> owner) {
    prepare(g, viewerDetail(g.cylinders.size()), out, std::move(owner));
    prepareMoving(g, out);
}

void Renderer::prepareMoving(const Geometry& g, PreparedScene& out) {
    out.proxy.clear();
    out.proxyBaked = mesh::BakedMesh();
    if (g.planarCurve) {  // a big curve moves its raster; one of many ribbons moves as lines
        if (out.curve.size() > PreparedScene::kCurveSketch) {
            out.proxy.reserve(out.curve.size() * 8);
            for (const CylinderInstance& c : out.curve) appendLine(out.proxy, c.start, c.end, c.colour);
        }
        return;
    }
    const std::size_t budget = PreparedScene::kProxyLines;
    const std::size_t triangles = out.baked.indices.size() / 3, primitives = triangles + out.lines.size() / 8;
    // A sketch: every stem of the lowest branch orders (up to half the budget: the trunk and
    // main branches whole), then an even share of the others and of the leaves, as lines.
    auto sketch = [&] {
        const std::size_t count = g.cylinders.size() + g.surfaces.size();
        std::vector<std::size_t> perOrder(65536 + 1, 0);
        for (const auto& c : g.cylinders) ++perOrder[c.order];
        int whole = -1;  // orders 0..whole are drawn whole
        for (std::size_t sum = 0; whole + 1 < 65536 && sum + perOrder[size_t(whole + 1)] <= budget / 2;) sum += perOrder[size_t(++whole)];
        std::size_t main = 0;
        for (int k = 0; k <= whole; ++k) main += perOrder[size_t(k)];
        const std::size_t stride = count > budget ? (count - main) / (budget - main) + 1 : 1;
        out.proxy.reserve(std::min(count, budget) * 8 + 64);
        std::size_t k = 0;
        for (const auto& c : g.cylinders)
            if (int(c.order) <= whole || ++k % stride == 0) appendLine(out.proxy, c.start, c.end, c.colour);
        for (const auto& x : g.surfaces)
            if (++k % stride == 0) appendLine(out.proxy, x.position, x.position + x.heading * x.size, x.colour);
    };
    if (g.polygons.indices.size() / 3 > budget / 2 && triangles > budget) {
        // Mostly polygons (generalized cylinders, surfaces): no stems to sketch, so the mesh
        // is clustered on a grid of 1/200 of the scene (about two pixels of a framed view at
        // half size), or coarser while that leaves more than kMovingTriangles (down to 1/50),
        // with the stems' lines.
        const Bounds all = g.extent();
        const glm::vec3 size = all.empty ? glm::vec3(1) : all.size();
        const float extent = std::max({size.x, size.y, size.z, 1e-6f});
        mesh::BakedMesh tinted;  // textured triangles in their images' average colour
        if (!out.textured.empty()) tinted = out.baked, mesh::tintTextured(tinted, out.textures);
        for (float cells : {200.0f, 140.0f, 100.0f, 70.0f, 50.0f}) {
            out.proxyBaked = clusterMesh(out.textured.empty() ? out.baked : tinted, all, extent / cells);
            if (out.proxyBaked.indices.size() / 3 <= PreparedScene::kMovingTriangles) break;
        }
        out.proxy = out.lines;
    } else if (out.detail == Quality::Interactive && primitives > budget) {
        sketch();
    } else if (triangles > PreparedScene::kProxyTriangles || primitives > budget) {
        // The interactive bake with coarse leaves, petals and spheres, if it has far fewer
        // triangles or fits the budget (else its sketch). Leafy plants move with a tenth of
        // their triangles: the L-Py flowering plant's 23 k had held its moving frames at 12-13
        // ms on llvmpipe at the smallest resolution, 8 of them drawing.
        // Leaves of 6 triangles where those of 12 leave more than kMovingTriangles
        // (`lpy_stochastic_shrub`: 15.8 k triangles instead of 22.6 k, moving at 303x258 to
        // 364x310 instead of the smallest resolution, 252x215, as far from the still picture).
        PreparedScene coarse;
        prepare(g, Quality::Interactive, coarse, {}, 1);
        if (coarse.baked.indices.size() / 3 > PreparedScene::kMovingTriangles) prepare(g, Quality::Interactive, coarse, {}, 2);
        const std::size_t coarseTriangles = coarse.baked.indices.size() / 3;
        if (coarseTriangles + coarse.lines.size() / 8 > budget) {
            sketch();
        } else if (2 * coarseTriangles < triangles || primitives > budget) {
            mesh::tintTextured(coarse.baked, coarse.textures);
            out.proxyBaked = std::move(coarse.baked);
            out.proxy = std::move(coarse.lines);
        }
    }
}

}  // namespace sprout::render
