// What an environment answers (open L-systems): the light grid over the plant grown so far,
// the attraction points it has not used up, and the answer to each ?E.
#include "core/environment/environment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace sprout {

double LightGrid::lightAt(const glm::dvec3& p) const {
    const glm::dvec3 c = (p - origin) / voxel;
    // Compared as doubles before any cast: a turtle 1e30 away (or at NaN) is beyond the grid.
    if (!(c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < nx && c.y < ny && c.z < nz)) return 1.0;  // beyond the plant: open sky
    const int i = int(c.x), j = int(c.y), k = int(c.z);
    const double s = shadow[(std::size_t(j) * std::size_t(nz) + std::size_t(k)) * std::size_t(nx) + std::size_t(i)];
    return std::max(0.0, 1.0 - s);
}

std::uint64_t cellKey(const glm::dvec3& p, double cell) {
    // The environment's own numbers keep its points within 1e15 cells of the origin
    // (kMaxNumber / kMinDistance < 2^50), and so every cell a point looks in. A plant's node
    // farther than that (F(1e30), or NaN) goes to a bucket of its own that no point asks for:
    // no point is near it, and far nodes never crowd a near cell's bucket.
    const glm::dvec3 c = glm::floor(p / cell);
    constexpr double kFar = 0x1p50;
    if (!(std::fabs(c.x) < kFar && std::fabs(c.y) < kFar && std::fabs(c.z) < kFar)) return ~std::uint64_t(0);
    // 21 bits an axis (at most 2^63 - 1, never the far key): cells that alias share a bucket,
    // nothing more (distances are compared).
    const auto index = [](double v) { return std::uint64_t(std::int64_t(v)) & 0x1fffff; };
    return (index(c.x) << 42) | (index(c.y) << 21) | index(c.z);
}

bool buildLight(const Environment& env, const Geometry& g, LightGrid& grid, std::string& error) {
    grid = LightGrid();
    grid.voxel = env.lightVoxel;
    if (g.bounds.empty) return true;
    // Shadow reaches kDepth cells away from the sun and as many sideways: the grid is the
    // plant's box, widened by that much on the sides and below (and above, for a sun below).
    constexpr int kDepth = 8;
    const glm::dvec3 sun = env.sunDirection(), away = -sun;
    const double up = sun.y >= 0 ? 1 : kDepth + 1;
    const glm::dvec3 lo = glm::dvec3(g.bounds.min) - glm::dvec3(kDepth + 1, kDepth + 1, kDepth + 1) * env.lightVoxel;
    const glm::dvec3 hi = glm::dvec3(g.bounds.max) + glm::dvec3(kDepth + 1, up, kDepth + 1) * env.lightVoxel;
    const glm::dvec3 cells = glm::ceil((hi - lo) / env.lightVoxel);
    const double total = cells.x * cells.y * cells.z;
    // Each side checked on its own too: a plant 1e12 from the origin loses its width in float
    // (lo == hi on an axis), and a product with a zero side says nothing of the others.
    const auto side = [](double c) { return c >= 1 && c <= double(Environment::kMaxLightCells); };
    if (!(total <= double(Environment::kMaxLightCells)) || !side(cells.x) || !side(cells.y) || !side(cells.z)) {
        // Whole counts in full while they are short; a plant 1e30 tall in powers of ten.
        const auto count = [](double c, const char* whole) {
            char b[40];
            std::snprintf(b, sizeof b, c < 1e12 ? whole : "%.3g", c);
            return std::string(b);
        };
        char msg[400];
        std::snprintf(msg, sizeof msg,
                      "the light grid would have %s x %s x %s = %.3g cells (%s GB at 4 bytes each), over the limit of "
                      "32 million: make the voxels larger ('environment: light VOXEL')",
                      count(cells.x, "%.0f").c_str(), count(cells.y, "%.0f").c_str(), count(cells.z, "%.0f").c_str(), total,
                      count(total * 4 / 1e9, "%.1f").c_str());
        error = msg;
        return false;
    }
    grid.origin = lo;
    grid.nx = int(cells.x), grid.ny = int(cells.y), grid.nz = int(cells.z);
    grid.shadow.assign(std::size_t(total), 0.0f);
    // The pyramid's axis steps one cell along the shadow's main axis each time, and spreads
    // over the other two.
    const glm::dvec3 mag = glm::abs(away);
    const int axis = mag.y >= mag.x && mag.y >= mag.z ? 1 : mag.x >= mag.z ? 0 : 2;
    const glm::dvec3 stride = away / mag[axis];  // one cell along the main axis per step
    const int spreadA = axis == 0 ? 1 : 0, spreadB = axis == 2 ? 1 : 2;
    const int n[3] = {grid.nx, grid.ny, grid.nz};
    // Each leaf (and a quarter for each segment's end) shades a pyramid of cells away from the
    // sun. Shadow adds up, so the casters are first summed per cell (a crown puts many in one)
    // and each cell casts once, from its centre.
    std::vector<std::pair<std::uint64_t, float>> casters;
    casters.reserve(g.surfaces.size() + g.cylinders.size() + g.polygons.positions.size());
    auto deposit = [&](const glm::vec3& p, float weight) {
        const glm::dvec3 c = glm::floor((glm::dvec3(p) - lo) / env.lightVoxel);
        if (!(c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < grid.nx && c.y < grid.ny && c.z < grid.nz)) return;
        casters.emplace_back((std::uint64_t(c.y) * std::uint64_t(grid.nz) + std::uint64_t(c.z)) * std::uint64_t(grid.nx) +
                                 std::uint64_t(c.x),
                             weight);
    };
    for (const SurfaceInstance& s : g.surfaces)
        if (s.kind != SurfaceKind::Sphere) deposit(s.position, 1.0f);
    for (const CylinderInstance& c : g.cylinders) deposit(c.end, 0.25f);
    for (const glm::vec3& p : g.polygons.positions) deposit(p, 0.05f);
    std::stable_sort(casters.begin(), casters.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    float level[kDepth + 1];
    for (int q = 1; q <= kDepth; ++q) level[q] = float(env.lightShadow * std::pow(2.0, -(q - 1)));
    for (size_t k = 0; k < casters.size();) {
        const std::uint64_t index = casters[k].first;
        double weight = 0;  // summed in the order of the geometry (a stable sort): the same on every machine
        for (; k < casters.size() && casters[k].first == index; ++k) weight += casters[k].second;
        const int i0 = int(index % std::uint64_t(grid.nx)), k0 = int(index / std::uint64_t(grid.nx) % std::uint64_t(grid.nz)),
                  j0 = int(index / (std::uint64_t(grid.nx) * std::uint64_t(grid.nz)));
        const glm::dvec3 c(i0 + 0.5, j0 + 0.5, k0 + 0.5);
        for (int q = 1; q <= kDepth; ++q) {
            const glm::dvec3 centre = c + stride * double(q);
            int cell[3] = {int(std::floor(centre.x)), int(std::floor(centre.y)), int(std::floor(centre.z))};
            if (cell[axis] < 0 || cell[axis] >= n[axis]) break;
            const float s = float(weight) * level[q];
            const int a0 = cell[spreadA], b0 = cell[spreadB];
            const int aLo = std::max(0, a0 - (q - 1)), aHi = std::min(n[spreadA] - 1, a0 + (q - 1));
            const int bLo = std::max(0, b0 - (q - 1)), bHi = std::min(n[spreadB] - 1, b0 + (q - 1));
            for (int bb = bLo; bb <= bHi; ++bb)
                for (int aa = aLo; aa <= aHi; ++aa) {
                    cell[spreadA] = aa, cell[spreadB] = bb;
                    grid.shadow[(std::size_t(cell[1]) * std::size_t(grid.nz) + std::size_t(cell[2])) * std::size_t(grid.nx) +
                                std::size_t(cell[0])] += s;
                }
        }
    }
    return true;
}

std::vector<glm::dvec3> freePoints(const Environment& env, const Geometry& grown, std::uint64_t seed) {
    std::vector<glm::dvec3> points;
    if (!env.attractionShape) return points;
    const EnvShape& shape = *env.attractionShape;
    // The shape's box, for rejection sampling.
    glm::dvec3 lo, hi;
    shape.box(lo, hi);
    // SplitMix64, as the grammar's randomness: the same points on every machine.
    std::uint64_t state = seed ^ 0xa77ac7104e5ull;
    auto next = [&] {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    };
    for (int tries = 0; int(points.size()) < env.attractionPoints && tries < env.attractionPoints * 20; ++tries) {
        const glm::dvec3 p(lo.x + (hi.x - lo.x) * next(), lo.y + (hi.y - lo.y) * next(), lo.z + (hi.z - lo.z) * next());
        if (shape.contains(p)) points.push_back(p);
    }
    // Used up: within the kill distance of a node of the plant (a segment's ends), found
    // through a hash of the nodes in cells the kill distance wide.
    std::unordered_map<std::uint64_t, std::vector<glm::dvec3>> cells;
    auto key = [&](const glm::dvec3& p) { return cellKey(p, env.kill); };
    for (const CylinderInstance& c : grown.cylinders)
        for (const glm::vec3& e : {c.start, c.end}) cells[key(glm::dvec3(e))].push_back(glm::dvec3(e));
    std::vector<glm::dvec3> free;
    for (const glm::dvec3& p : points) {
        bool used = false;
        for (int dz = -1; dz <= 1 && !used; ++dz)
            for (int dy = -1; dy <= 1 && !used; ++dy)
                for (int dx = -1; dx <= 1 && !used; ++dx) {
                    auto it = cells.find(key(p + glm::dvec3(dx, dy, dz) * env.kill));
                    if (it == cells.end()) continue;
                    for (const glm::dvec3& n : it->second)
                        if (glm::length(n - p) <= env.kill) used = true;
                }
        if (!used) free.push_back(p);
    }
    return free;
}

void answerAttraction(const Environment& env, const std::vector<glm::dvec3>& buds, const std::vector<glm::dvec3>& points,
                      const std::vector<double*>& params, const std::vector<int>& arities) {
    std::vector<glm::dvec3> pull(buds.size(), glm::dvec3(0.0));
    std::vector<int> count(buds.size(), 0);
    // Buds in cells the influence radius wide: each point looks at its own and the next cells.
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
    auto key = [&](const glm::dvec3& p) { return cellKey(p, env.influence); };
    for (std::uint32_t b = 0; b < buds.size(); ++b) cells[key(buds[b])].push_back(b);
    for (const glm::dvec3& p : points) {
        double best = env.influence;
        std::int64_t nearest = -1;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto it = cells.find(key(p + glm::dvec3(dx, dy, dz) * env.influence));
                    if (it == cells.end()) continue;
                    for (std::uint32_t b : it->second) {
                        const double d = glm::length(p - buds[b]);
                        if (d <= best && (d < best || std::int64_t(b) < nearest)) best = d, nearest = b;
                    }
                }
        if (nearest < 0 || best <= 0) continue;
        pull[size_t(nearest)] += (p - buds[size_t(nearest)]) / best;
        ++count[size_t(nearest)];
    }
    for (size_t b = 0; b < buds.size(); ++b) {
        const double n = glm::length(pull[b]);
        const glm::dvec3 dir = n > 0 ? pull[b] / n : glm::dvec3(0.0);
        double* out = params[b];
        for (int k = 0; k < 3 && k < arities[b]; ++k) out[k] = std::round(dir[k] * 1e5) / 1e5 + 0.0;
        if (arities[b] > 3) out[3] = count[b];
    }
}

void answer(const Environment& env, const glm::dvec3& p, const glm::dvec3& heading, double* params, int arity,
            const LightGrid* light) {
    if (env.isLight()) {
        if (arity > 0) params[0] = light ? std::round(light->lightAt(p) * 1e5) / 1e5 : 1.0;
        return;
    }
    if (env.isRegion()) {
        bool inside = false;
        double distance = 1e300;
        for (const EnvShape& s : env.region) {
            inside |= s.contains(p);
            distance = std::min(distance, s.distanceToSurface(p));
        }
        if (arity > 0) params[0] = inside ? 1 : 0;
        // Rounded to 1e-5 as the other answers: the turtle's float positions show otherwise.
        if (arity > 1) params[1] = std::round(distance * 1e5) / 1e5 + 0.0;
        return;
    }
    // Obstacles: march the segment ahead in small steps (exact enough for boxes and spheres at
    // plant scale: 64 steps of the segment, then the first hit refined by bisection).
    const double length = arity > 0 && std::isfinite(params[0]) && params[0] > 0 ? params[0] : 1.0;
    // Only the obstacles whose boxes meet the segment's box are marched against (a grammar may
    // declare hundreds, and a plant ask tens of thousands of questions).
    const glm::dvec3 end = p + heading * length, segLo = glm::min(p, end), segHi = glm::max(p, end);
    std::vector<const EnvShape*> near;
    for (const EnvShape& s : env.obstacles) {
        glm::dvec3 lo, hi;
        s.box(lo, hi);
        if (lo.x <= segHi.x && lo.y <= segHi.y && lo.z <= segHi.z && hi.x >= segLo.x && hi.y >= segLo.y && hi.z >= segLo.z)
            near.push_back(&s);
    }
    auto blocked = [&](const glm::dvec3& q, const EnvShape** by) {
        if (env.ground && q.y < *env.ground) {
            *by = nullptr;
            return true;
        }
        for (const EnvShape* sp : near)
            if (const EnvShape& s = *sp; s.contains(q)) {
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

}  // namespace sprout
