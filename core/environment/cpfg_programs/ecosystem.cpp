// ecosystem (VLab's ENVIRO/ecosystem, a version of honda81): each ?E(radius[, group or vigor])
// is a disc (a sphere in 3d) where the turtle stands; it is answered 0 when it meets another
// of the same group that is at least as big (with `vigor: on`: one of higher vigor, or of the
// same vigor and bigger), else 1. The ecosystem object's plants die so. Specification:
// `grid size: X Y Z` (the cells the discs are sorted into), `3d case: on|yes`, `vigor: on`,
// `verbose`. The grid is ecosystem's own (grid.c), to the float, so that which discs are
// compared is the program's.
#include <cmath>
#include <limits>

#include "core/environment/cpfg_programs/spec_file.hpp"

namespace sprout::cpfgprog {
namespace {

constexpr std::int64_t kMaxCells = 16'000'000;

struct Ecosystem : EnvironmentProgram {
    int size[3] = {1, 1, 1};
    bool is3d = false, vigor = false;
    std::unique_ptr<ProgramRun> start() const override;
};

class EcosystemRun : public ProgramRun {
public:
    explicit EcosystemRun(const Ecosystem& p) : m_p(p) {
        for (int c = 0; c < 3; ++c) m_size[c] = c <= (p.is3d ? 2 : 1) ? std::max(p.size[c], 1) : 1;
        m_cells.resize(size_t(m_size[0]) * size_t(m_size[1]) * size_t(m_size[2]));
    }

    void pass(std::vector<ProgramQuery>& queries) override {
        struct Item {
            float pos[3], radius, vigor;
            int index;
            bool removed = false;
            int range[3][2];
            ProgramQuery* q;
        };
        std::vector<Item> items;
        const int dims = m_p.is3d ? 3 : 2;
        for (ProgramQuery& q : queries) {
            if (q.position.count < 3 || int(q.params.size()) < 1 + int(m_p.vigor)) continue;
            Item it{};
            it.pos[0] = q.position.v[0];
            if (m_p.is3d) {
                it.pos[1] = q.position.v[1];
                it.pos[2] = q.position.v[2];
            } else {
                it.pos[1] = q.position.v[2];
                it.pos[2] = 0;
            }
            it.radius = q.params[0];
            if (m_p.vigor) {
                it.vigor = q.params.size() > 1 ? q.params[1] : 1;
                it.index = 0;
            } else {
                it.vigor = 1;
                it.index = q.params.size() > 1 ? toInt(q.params[1]) : 0;
            }
            it.q = &q;
            // The grid's range: the first query's from the turtle's own coordinates (x and y,
            // even in 2d, where the others give x and z), as ecosystem.c does.
            for (int c = 0; c < dims; ++c) {
                const float lo = (items.empty() ? q.position.v[size_t(c)] : it.pos[c]) - it.radius;
                const float hi = (items.empty() ? q.position.v[size_t(c)] : it.pos[c]) + it.radius;
                if (items.empty() || m_min[c] > lo) m_min[c] = lo;
                if (items.empty() || m_max[c] < hi) m_max[c] = hi;
            }
            items.push_back(it);
        }
        // ResetGrid (its constants are doubles, its results floats).
        float pos[3] = {0, 0, 0}, range[3] = {1, 1, 1};
        for (int c = 0; c < dims; ++c) {
            pos[c] = float(double(m_min[c]) - 0.001);
            range[c] = float(double(m_max[c] - m_min[c]) + 0.002);
        }
        for (auto& cell : m_cells) cell.clear();
        // AddObject: each disc into the cells of its box, one cell more each way.
        for (size_t i = 0; i < items.size(); ++i) {
            Item& it = items[i];
            for (int c = 0; c < dims; ++c) {
                it.range[c][0] = toInt(std::floor((it.pos[c] - it.radius - pos[c]) / range[c] * float(m_size[c]))) - 1;
                if (it.range[c][0] < 0) it.range[c][0] = 0;
                it.range[c][1] = 1 + toInt(std::floor((it.pos[c] + it.radius - pos[c]) / range[c] * float(m_size[c])));
                if (it.range[c][1] >= m_size[c]) it.range[c][1] = m_size[c] - 1;
            }
            if (!m_p.is3d) it.range[2][0] = it.range[2][1] = 0;
            forCells(it.range, [&](std::vector<std::uint32_t>& cell) { cell.push_back(std::uint32_t(i)); });
        }
        // TestIntersection, in the order of the queries (a disc removed earlier dominates no one).
        for (size_t i = 0; i < items.size(); ++i) {
            Item& a = items[i];
            bool free = true;
            forCells(a.range, [&](std::vector<std::uint32_t>& cell) {
                for (std::uint32_t j : cell) {
                    const Item& b = items[j];
                    if (j == i || a.index != b.index) continue;
                    if (m_p.vigor && b.removed) continue;
                    if (!m_p.vigor && !(a.radius <= b.radius)) continue;
                    const float v0 = a.pos[0] - b.pos[0], v1 = a.pos[1] - b.pos[1], v2 = m_p.is3d ? a.pos[2] - b.pos[2] : 0.0f;
                    if (!(v0 * v0 + v1 * v1 + v2 * v2 <= (a.radius + b.radius) * (a.radius + b.radius))) continue;
                    if (!m_p.vigor) {
                        free = false;
                    } else if (a.vigor < b.vigor || (a.vigor == b.vigor && a.radius < b.radius)) {
                        free = false;
                        a.removed = true;
                    }
                }
            });
            a.q->reply({free ? 1.0f : 0.0f});
        }
    }

private:
    template <class F>
    void forCells(const int (&r)[3][2], F f) {
        for (int z = r[2][0]; z <= r[2][1]; ++z)
            for (int y = r[1][0]; y <= r[1][1]; ++y)
                for (int x = r[0][0]; x <= r[0][1]; ++x)
                    f(m_cells[size_t(z) * size_t(m_size[0]) * size_t(m_size[1]) + size_t(y) * size_t(m_size[0]) + size_t(x)]);
    }

    const Ecosystem& m_p;
    int m_size[3];
    float m_min[3] = {0, 0, 0}, m_max[3] = {0, 0, 0};  // kept from pass to pass, as ecosystem's are
    std::vector<std::vector<std::uint32_t>> m_cells;
};

std::unique_ptr<ProgramRun> Ecosystem::start() const { return std::make_unique<EcosystemRun>(*this); }

}  // namespace

std::shared_ptr<EnvironmentProgram> makeEcosystem(const std::string&, const std::string& text, const Sink& sink) {
    auto p = std::make_shared<Ecosystem>();
    const std::vector<std::string> keywords{"verbose", "grid size", "3d case", "vigor"};
    int gridLine = 0;
    for (const SpecLine& line : specLines(text)) {
        const std::vector<Token> t = tokensOf(line, "x,; \t:\n");
        if (line.keyword == "verbose") {
        } else if (line.keyword == "grid size") {
            gridLine = line.number;
            for (size_t c = 0; c < 3 && c < t.size(); ++c) {
                const int v = toInt(numberOf(t[c], line, sink, "a whole number of cells"));
                p->size[c] = v < 1 ? 1 : v;
            }
            if (t.size() < 3) sink.warning(line.number, "'grid size': expected three numbers of cells (x y z); the others are 1");
        } else if (line.keyword == "3d case") {
            if (!t.empty()) p->is3d = t[0].text == "on" || t[0].text == "yes";
        } else if (line.keyword == "vigor") {
            if (!t.empty()) p->vigor = t[0].text == "on";
        } else {
            unknownKeyword(line, keywords, "ecosystem", sink);
        }
    }
    if (gridCells({p->size[0], p->size[1], p->is3d ? p->size[2] : 1}, kMaxCells) > kMaxCells) {
        sink.error(gridLine, "'grid size': " + std::to_string(p->size[0]) + " x " + std::to_string(p->size[1]) +
                                 (p->is3d ? " x " + std::to_string(p->size[2]) : std::string()) + " cells is over Sprout's " +
                                 std::to_string(kMaxCells) + " for ecosystem's grid");
        return nullptr;
    }
    return p;
}

}  // namespace sprout::cpfgprog
