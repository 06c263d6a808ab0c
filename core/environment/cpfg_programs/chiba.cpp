// chiba (VLab's ENVIRO/chiba, after Chiba et al.): the light reaching spheres (leaf clusters)
// from a sky of sample directions or from given sources, each sphere on a ray's way taking
// some of it. ?E(radius) or ?E(radius, x, y, z) (0: the file's radius) is answered, after the
// whole pass, the light its centre receives (0 to 1) and, with four parameters, the brightest
// direction. Specification: `grid size: X Y Z`, `number of samples: N`, `lower to upper ratio:
// U` (0.7), `use CIE formula: yes`, `source direction: X Y Z INTENSITY` (any number),
// `transmittance: T` (0.6), `radius: R` (25), `beam radius: B`, `estimate intersection area:
// on`, `verbose`. Ported to the float, grid walk and all (chiba.c, sphere.c), so that the
// answers are chiba's.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/environment/cpfg_programs/spec_file.hpp"

namespace sprout::cpfgprog {
namespace {

constexpr std::int64_t kMaxCells = 16'000'000;
constexpr double kPi = 3.14159265358979323846;

struct Sample {
    float dir[3];
    float intensity;
};

struct Chiba : EnvironmentProgram {
    int size[3] = {1, 1, 1};
    float LtoU = 0.7f, transmittance = 0.6f, radius = 25, beamRadius = 0;
    bool estimateArea = false;
    std::vector<Sample> samples;  // the sky's, or the sources
    std::unique_ptr<ProgramRun> start() const override;
};

void normalize(float* v) {
    const float len = float(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    if (len > 0)
        for (int i = 0; i < 3; ++i) v[i] /= len;
}

struct Leaf {
    float pos[3], radius, area;
    int params;
    std::uint64_t signature = 0;
    ProgramQuery* q;
};

class ChibaRun : public ProgramRun {
public:
    explicit ChibaRun(const Chiba& p) : m_p(p) {}

    void pass(std::vector<ProgramQuery>& queries) override {
        m_leaves.clear();
        for (ProgramQuery& q : queries) store(q);
        if (m_leaves.empty()) return;
        buildGrid();
        m_signature = 0;
        for (Leaf& leaf : m_leaves) {
            float sum = 0, br[3] = {0, 0, 0};
            for (const Sample& s : m_p.samples) {
                const float a = intensity(leaf, s);
                sum += a;
                for (int c = 0; c < 3; ++c) br[c] += a * s.dir[c];
            }
            std::vector<float> answer(size_t(leaf.params), 0.0f);
            answer[0] = sum;
            if (leaf.params >= 4) {
                normalize(br);
                for (int c = 0; c < 3; ++c) answer[size_t(1 + c)] = br[c];
            }
            leaf.q->answer = answer;
            leaf.q->set.assign(answer.size(), false);
            for (size_t k = 0; k < answer.size() && k < 4; ++k) leaf.q->set[k] = true;
        }
    }

private:
    void store(ProgramQuery& q) {
        const int n = int(q.params.size());
        if (n != 1 && n < 4) return;
        if (q.position.count < 3) return;
        Leaf leaf{};
        leaf.params = n;
        leaf.q = &q;
        leaf.radius = q.params[0] > 0 ? q.params[0] : m_p.radius;
        leaf.area = float(kPi * leaf.radius * leaf.radius);
        for (int i = 0; i < 3; ++i) leaf.pos[i] = q.position.v[size_t(i)];
        if (m_leaves.empty()) {
            for (int i = 0; i < 3; ++i) m_pos[i] = leaf.pos[i] - leaf.radius, m_range[i] = 2 * leaf.radius;
            m_maxRadius = leaf.radius;
        } else {
            for (int i = 0; i < 3; ++i) {
                float aux = m_pos[i] - (leaf.pos[i] - leaf.radius);
                if (aux > 0) m_pos[i] -= aux, m_range[i] += aux;
                aux = (leaf.pos[i] + leaf.radius) - (m_pos[i] + m_range[i]);
                if (aux > 0) m_range[i] += aux;
            }
            if (leaf.radius > m_maxRadius) m_maxRadius = leaf.radius;
        }
        m_leaves.push_back(leaf);
    }

    // InitializeGrid: each sphere in the voxels whose centre is near enough.
    void buildGrid() {
        const int* s = m_p.size;
        m_cells.assign(size_t(s[0]) * size_t(s[1]) * size_t(s[2]), {});
        float half = 0;
        for (int c = 0; c < 3; ++c) {
            const float aux = m_range[c] / float(s[c]);
            half += aux * aux;
        }
        half = float(0.5 * std::sqrt(half));
        const float reach = m_maxRadius * m_p.beamRadius;
        for (std::uint32_t lv = 0; lv < m_leaves.size(); ++lv) {
            const Leaf& l = m_leaves[lv];
            float range[3][2];
            for (int c = 0; c < 3; ++c) {
                range[c][0] = float(std::floor((l.pos[c] - l.radius - reach - m_pos[c]) / m_range[c] * float(s[c])) - 1);
                if (range[c][0] < 0) range[c][0] = 0;
                range[c][1] = float(1 + std::floor((l.pos[c] + l.radius + reach - m_pos[c]) / m_range[c] * float(s[c])));
                if (range[c][1] >= float(s[c])) range[c][1] = float(s[c] - 1);
            }
            const float limit = (l.radius + reach + half) * (l.radius + reach + half);
            // Kept in the grid whatever the bounds: a position that is not finite gives NaN ones.
            int lo[3], hi[3];
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::max(toInt(range[c][0]), 0);
                hi[c] = std::min(toInt(range[c][1]), s[c] - 1);
            }
            float pt[3];
            for (int z = lo[2]; z <= hi[2]; ++z) {
                pt[2] = float(double(m_pos[2]) + (double(float(z)) + 0.5) / double(float(s[2])) * double(m_range[2]));
                for (int y = lo[1]; y <= hi[1]; ++y) {
                    pt[1] = float(double(m_pos[1]) + (double(float(y)) + 0.5) / double(float(s[1])) * double(m_range[1]));
                    for (int x = lo[0]; x <= hi[0]; ++x) {
                        pt[0] = float(double(m_pos[0]) + (double(float(x)) + 0.5) / double(float(s[0])) * double(m_range[0]));
                        float v[3] = {l.pos[0] - pt[0], l.pos[1] - pt[1], l.pos[2] - pt[2]};
                        if (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= limit)
                            m_cells[size_t(z) * size_t(s[1]) * size_t(s[0]) + size_t(y) * size_t(s[0]) + size_t(x)].push_back(lv);
                    }
                }
            }
        }
        // chiba.c prepends to each cell's list: the last sphere added is met first.
        for (auto& cell : m_cells) std::reverse(cell.begin(), cell.end());
    }

    float coveredArea(const float* pt, const float* dir, const Leaf& l, float original) const {
        float vec[3];
        for (int c = 0; c < 3; ++c) vec[c] = pt[c] - l.pos[c];
        const float aux = dir[0] * vec[0] + dir[1] * vec[1] + dir[2] * vec[2];
        if (aux > 0) return 0;
        float d = vec[0] * vec[0] + vec[1] * vec[1] + vec[2] * vec[2] - aux * aux;
        if (!(d < (l.radius + original) * (l.radius + original))) return 0;
        const float r1 = l.radius < original ? original : l.radius, r2 = l.radius < original ? l.radius : original;
        const float r2s = r2 * r2, r1s = r1 * r1;
        d = float(std::sqrt(d));
        if (d + r2 <= r1) return float(kPi * r2s);
        const float x1 = (r1s + d * d - r2s) / (2 * d), x2 = (r2s + d * d - r1s) / (2 * d);
        const float y = float(std::sqrt(r2s - x2 * x2));
        return float(r1s * std::acos(double(x1 / r1)) + r2s * std::acos(double(x2 / r2)) - double(y * d));
    }

    float clusterIntersection(const float* pt, const float* dir, const Leaf& l, float oradius) const {
        float vec[3];
        for (int c = 0; c < 3; ++c) vec[c] = pt[c] - l.pos[c];
        const float aux = dir[0] * vec[0] + dir[1] * vec[1] + dir[2] * vec[2];
        const float r = l.radius + oradius * m_p.beamRadius;
        float d = aux * aux - (vec[0] * vec[0] + vec[1] * vec[1] + vec[2] * vec[2]) + r * r;
        if (d >= 0 && -aux + (d = float(std::sqrt(d))) > 0) return -aux - d >= 0 ? 2 * d : -aux + d;
        return 0;
    }

    // IntensityFromSample: the sample's ray from the sphere's centre, voxel after voxel.
    float intensity(Leaf& leaf, const Sample& sample) {
        if (sample.intensity == 0) return 0.0f;
        const int* s = m_p.size;
        std::int64_t step[3] = {1, s[0], std::int64_t(s[0]) * s[1]};
        float pt[3], nodeSize[3], middle[3];
        int node[3];
        for (int c = 0; c < 3; ++c) {
            pt[c] = leaf.pos[c];
            nodeSize[c] = float(0.5 * m_range[c] / float(s[c]));
            if (sample.dir[c] < 0) nodeSize[c] = -nodeSize[c], step[c] = -step[c];
        }
        int clamped[3];
        for (int c = 0; c < 3; ++c) {
            node[c] = toInt(std::floor((pt[c] - m_pos[c]) / m_range[c] * float(s[c])));
            middle[c] = float((double(float(node[c])) + 0.5) / double(float(s[c])) * double(m_range[c]));
            clamped[c] = std::min(std::max(node[c], 0), s[c] - 1);
        }
        std::int64_t cell = std::int64_t(clamped[2]) * s[1] * s[0] + std::int64_t(clamped[1]) * s[0] + clamped[0];
        float reduction = 1;
        const float red = m_p.transmittance;
        if (++m_signature == 0) {
            m_signature = 1;
            for (Leaf& l : m_leaves) l.signature = 0;
        }
        leaf.signature = m_signature;
        const std::int64_t cells = std::int64_t(m_cells.size());
        for (std::int64_t guard = 0; cell >= 0 && cell < cells && guard < 3 * cells + 3; ++guard) {
            for (std::uint32_t k : m_cells[size_t(cell)]) {
                Leaf& other = m_leaves[k];
                if (other.signature == m_signature) continue;
                if (m_p.estimateArea) {
                    const float aux = coveredArea(pt, sample.dir, other, leaf.radius);
                    if (aux > 0) {
                        other.signature = m_signature;
                        reduction *= 1 - (1 - red) * aux / leaf.area;
                    }
                } else {
                    const float aux = clusterIntersection(pt, sample.dir, other, leaf.radius);
                    if (aux > 0) {
                        other.signature = m_signature;
                        reduction = float(double(reduction) *
                                          std::pow(double(red), double(aux) / (2.0 * double(other.radius + m_p.beamRadius * leaf.radius))));
                    }
                }
            }
            // The face the ray leaves the voxel by (measured from the sphere's centre, as chiba does).
            float smallest = float(std::fabs(middle[0] + nodeSize[0] - pt[0]));
            int ind = 0;
            for (int c = 1; c < 3; ++c) {
                const float aux = middle[c] + nodeSize[c] - pt[c];
                if (std::fabs(aux * sample.dir[ind]) < std::fabs(smallest * sample.dir[c])) smallest = aux, ind = c;
            }
            middle[ind] += 2 * nodeSize[ind];
            cell += step[ind];
            node[ind] += sample.dir[ind] > 0 ? 1 : -1;
            if (node[ind] < 0 || node[ind] >= s[ind]) return sample.intensity * reduction;
        }
        return sample.intensity * reduction;  // a walk off the grid's array (chiba reads past it): stopped
    }

    const Chiba& m_p;
    std::vector<Leaf> m_leaves;
    std::vector<std::vector<std::uint32_t>> m_cells;
    float m_pos[3] = {0, 0, 0}, m_range[3] = {0, 0, 0}, m_maxRadius = 0;
    std::uint64_t m_signature = 0;
};

std::unique_ptr<ProgramRun> Chiba::start() const { return std::make_unique<ChibaRun>(*this); }

// sphere.c: an octahedron's triangles, subdivided `level - 1` times onto the unit sphere.
std::vector<std::array<std::array<double, 3>, 3>> polySphere(int level) {
    using P = std::array<double, 3>;
    const P xp{1, 0, 0}, xm{-1, 0, 0}, yp{0, 1, 0}, ym{0, -1, 0}, zp{0, 0, 1}, zm{0, 0, -1};
    std::vector<std::array<P, 3>> tris{{xp, zp, yp}, {yp, zp, xm}, {xm, zp, ym}, {ym, zp, xp},
                                       {xp, yp, zm}, {yp, xm, zm}, {xm, ym, zm}, {ym, xp, zm}};
    for (auto& t : tris) std::swap(t[0], t[2]);  // counter-clockwise
    auto mid = [](const P& a, const P& b) {
        P r{(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5};
        double mag = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        if (mag != 0.0) {
            mag = 1.0 / std::sqrt(mag);
            for (double& v : r) v *= mag;
        }
        return r;
    };
    for (int l = 1; l < level; ++l) {
        std::vector<std::array<P, 3>> next;
        next.reserve(tris.size() * 4);
        for (const auto& t : tris) {
            const P a = mid(t[0], t[2]), b = mid(t[0], t[1]), c = mid(t[1], t[2]);
            next.push_back({t[0], b, a});
            next.push_back({b, t[1], c});
            next.push_back({a, b, c});
            next.push_back({a, c, t[2]});
        }
        tris = std::move(next);
    }
    return tris;
}

void skySamples(Chiba& p, int wanted, bool cie, const Sink& sink, int line) {
    int level = wanted > 8 ? int(std::ceil(std::log(double(wanted) / 8.0) / std::log(4.0))) + 1 : 1;
    if (wanted < 8) sink.warning(line, "'number of samples': " + std::to_string(wanted) + " is below chiba's 8 (it takes 8)");
    if (level > 8) {
        sink.warning(line, "'number of samples': Sprout's chiba takes 131072 at most");
        level = 8;
    }
    for (const auto& t : polySphere(level)) {
        Sample s{};
        for (int c = 0; c < 3; ++c) {
            const float sum = float(t[0][size_t(c)]) + float(t[1][size_t(c)]) + float(t[2][size_t(c)]);
            s.dir[c] = float(double(sum) / 3.0);
        }
        normalize(s.dir);
        p.samples.push_back(s);
    }
    if (cie) {
        float total = 0;
        for (Sample& s : p.samples) {
            if (s.dir[1] <= 0) {
                s.intensity = 0;
                continue;
            }
            const double cosangle = double(s.dir[1]) / std::sqrt(double(s.dir[0] * s.dir[0] + s.dir[1] * s.dir[1]));
            s.intensity = float((1 + cosangle) / 3.0 * (8.6 * cosangle + 0.123) / 0.203);
            total += s.intensity;
        }
        for (Sample& s : p.samples) s.intensity /= total;
        return;
    }
    int up = 0;
    for (const Sample& s : p.samples) up += s.dir[1] >= 0;
    const int n = int(p.samples.size());
    for (Sample& s : p.samples)
        s.intensity = s.dir[1] >= 0 ? float(1.0 / double(float(up)) / (1.0 + p.LtoU))
                                    : float(double(p.LtoU) / double(float(n - up)) / (1.0 + p.LtoU));
}

}  // namespace

std::shared_ptr<EnvironmentProgram> makeChiba(const std::string&, const std::string& text, const Sink& sink) {
    auto p = std::make_shared<Chiba>();
    const std::vector<std::string> keywords{"grid size", "verbose", "lower to upper ratio", "transmittance", "number of samples",
                                            "radius", "beam radius", "source direction", "estimate intersection area",
                                            "use CIE formula"};
    int wanted = 20, sizeLine = 0, samplesLine = 0;
    bool cie = false;
    std::vector<Sample> sources;
    for (const SpecLine& line : specLines(text)) {
        const std::vector<Token> x = tokensOf(line, "x,; \t:\n"), t = tokensOf(line, ",; \t:\n");
        const std::string& k = line.keyword;
        if (k == "grid size") {
            sizeLine = line.number;
            for (size_t c = 0; c < 3 && c < x.size(); ++c) p->size[c] = toInt(numberOf(x[c], line, sink, "a whole number of voxels"));
        } else if (k == "lower to upper ratio" && !t.empty()) {
            p->LtoU = float(numberOf(t[0], line, sink, "a number from 0 to 1"));
        } else if (k == "transmittance" && !t.empty()) {
            p->transmittance = float(numberOf(t[0], line, sink, "a number from 0 to 1"));
        } else if (k == "number of samples" && !x.empty()) {
            samplesLine = line.number;
            wanted = toInt(numberOf(x[0], line, sink, "a whole number"));
        } else if (k == "radius" && !t.empty()) {
            p->radius = float(numberOf(t[0], line, sink, "a number"));
        } else if (k == "beam radius" && !t.empty()) {
            p->beamRadius = float(numberOf(t[0], line, sink, "a number from 0 to 1"));
        } else if (k == "source direction") {
            if (sources.size() >= 100) {
                sink.warning(line.number, "chiba takes 100 light sources at most: this one is left out");
                continue;
            }
            Sample s{{0, 0, 0}, 1};
            for (size_t c = 0; c < 3 && c < t.size(); ++c) s.dir[c] = float(numberOf(t[c], line, sink, "a direction's x y z and an intensity"));
            if (t.size() >= 4) s.intensity = float(numberOf(t[3], line, sink, "an intensity"));
            if (t.size() < 4) sink.warning(line.number, "'source direction': expected X Y Z INTENSITY");
            sources.push_back(s);
        } else if (k == "estimate intersection area") {
            if (!x.empty()) p->estimateArea = x[0].text == "on";
        } else if (k == "use CIE formula") {
            if (!x.empty()) cie = x[0].text == "yes";
        } else if (k != "verbose" && std::find(keywords.begin(), keywords.end(), k) == keywords.end()) {
            unknownKeyword(line, keywords, "chiba", sink);
        }
    }
    const std::int64_t cells = gridCells({p->size[0], p->size[1], p->size[2]}, kMaxCells);
    if (cells < 1 || cells > kMaxCells) {
        sink.error(sizeLine, "'grid size': expected three whole numbers of voxels, at least 1 each and " +
                                 std::to_string(kMaxCells) + " in all at most");
        return nullptr;
    }
    if (!sources.empty()) {
        float total = 0;
        for (const Sample& s : sources) total += s.intensity;
        for (Sample& s : sources) {
            s.intensity /= total;
            normalize(s.dir);
        }
        p->samples = std::move(sources);
    } else {
        skySamples(*p, wanted, cie, sink, samplesLine);
    }
    if (p->estimateArea) p->beamRadius = 1;
    return p;
}

}  // namespace sprout::cpfgprog
