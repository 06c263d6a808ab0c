#include "core/turtle.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/derive.hpp"

namespace sprout {
namespace {

enum class Act : std::uint8_t {
    None, Draw, DrawNoVertex, Move, MoveNoVertex, Left, Right, Down, Up, RollLeft, RollRight,
    Around, Horizontal, Push, Pop, PolyBegin, PolyVertex, PolyEnd, WidthDec, WidthInc,
    ColourNext, ColourPrev, Leaf, Petal, Sphere,
};

Act actionOf(const std::string& name) {
    static const std::pair<const char*, Act> table[] = {
        {"F", Act::Draw}, {"G", Act::DrawNoVertex}, {"f", Act::Move}, {"g", Act::MoveNoVertex},
        {"+", Act::Left}, {"-", Act::Right}, {"&", Act::Down}, {"^", Act::Up},
        {"\\", Act::RollLeft}, {"/", Act::RollRight}, {"|", Act::Around}, {"$", Act::Horizontal},
        {"[", Act::Push}, {"]", Act::Pop}, {"{", Act::PolyBegin}, {".", Act::PolyVertex},
        {"}", Act::PolyEnd}, {"!", Act::WidthDec}, {"#", Act::WidthInc}, {";", Act::ColourNext},
        {"'", Act::ColourNext}, {",", Act::ColourPrev}, {"~leaf", Act::Leaf}, {"~l", Act::Leaf},
        {"~L", Act::Leaf}, {"~petal", Act::Petal}, {"~p", Act::Petal}, {"~P", Act::Petal},
        {"@O", Act::Sphere}, {"@o", Act::Sphere},
    };
    for (const auto& [n, a] : table)
        if (name == n) return a;
    return Act::None;
}

constexpr std::uint32_t kDefaultPalette[16] = {
    0x6B4A2EFF, 0x4E8F2EFF, 0x7DB344FF, 0xF2D43DFF, 0xD9442EFF, 0xF5F1E6FF, 0xE58FB6FF, 0x9C6ADEFF,
    0x3D7DD8FF, 0x2E5E2EFF, 0xA0522DFF, 0xC8A165FF, 0xFF9F1CFF, 0x8A8A8AFF, 0x2B2B2BFF, 0xFFFFFFFF,
};

constexpr float kPi = 3.14159265358979f;

struct State {
    glm::vec3 pos{0, 0, 0};
    glm::vec3 H{0, 1, 0};
    glm::vec3 L{-1, 0, 0};
    glm::vec3 U{0, 0, 1};
    float length = 1;
    float width = 1;  // diameter
    std::int32_t colour = 0;
    std::uint32_t stemColour = 0;   // resolved once when the colour or branch order changes
    std::int32_t lastSegment = -1;  // the segment this branch's next segment continues
    std::uint16_t order = 0;
    bool explicitColour = false;
};

// Rotations of the frame about its own axes (ABOP 1.5): each mixes two axes.
inline void rotate(glm::vec3& a, glm::vec3& b, float c, float s) {
    glm::vec3 na = a * c + b * s;
    b = b * c - a * s;
    a = na;
}

std::uint32_t lerpColour(std::uint32_t a, std::uint32_t b, float t) {
    std::uint32_t out = 0;
    for (int shift = 24; shift >= 0; shift -= 8) {
        float x = float((a >> shift) & 0xFF), y = float((b >> shift) & 0xFF);
        out |= std::uint32_t(std::lround(x + (y - x) * t)) << shift;
    }
    return out;
}

bool finite(const double* p, int n) {
    for (int k = 0; k < n; ++k)
        if (!std::isfinite(p[k])) return false;
    return true;
}

class Turtle {
public:
    Turtle(const Grammar& g, const TurtleOptions& o, Geometry& out)
        : m_g(g), m_opt(o), m_out(out), m_rng(Rng::forStream(o.seed, 0x7077e)) {
        const auto& st = g.settings;
        m_actions.resize(g.alphabet.size());
        m_arity.resize(g.alphabet.size());
        for (size_t s = 0; s < g.alphabet.size(); ++s) {
            m_arity[s] = g.alphabet[SymbolId(s)].arity;
            m_actions[s] = actionOf(g.alphabet[SymbolId(s)].name);
            m_colourModules |= m_actions[s] == Act::ColourNext || m_actions[s] == Act::ColourPrev;
        }
        m_gradient = st.gradient == Toggle::On || (st.gradient == Toggle::Auto && !m_colourModules);
        m_autoWidth = st.width <= 0;
        m_angle = float(st.angle.mean) * kPi / 180.0f;
        m_cos = std::cos(m_angle);
        m_sin = std::sin(m_angle);
        m_angleSigma = float(st.angle.sigma) * kPi / 180.0f;
        m_stepSigma = float(st.step.sigma);
        m_tropism = glm::vec3(st.tropism[0], st.tropism[1], st.tropism[2]);
        if (glm::length(m_tropism) > 0) m_tropism = glm::normalize(m_tropism);
        m_tropismE = float(st.tropismStrength);
        m_widthFactor = float(st.widthFactor);
        m_branchLength = float(st.branchLength);
        // Automatic widths thin each branch order, as real stems do (da Vinci's rule keeps
        // the total cross-section roughly constant at a fork).
        m_branchWidth = m_autoWidth && st.branchWidth == 1 ? 0.75f : float(st.branchWidth);
        m_palette = st.palette;
        if (m_palette.empty()) m_palette.assign(std::begin(kDefaultPalette), std::end(kDefaultPalette));
        m_state.stemColour = m_palette[0];
        m_state.length = float(st.step.mean * std::pow(st.stepScale, o.derivationSteps));
        m_state.width = m_autoWidth ? 1.0f : float(st.width);
        m_maxWidth = m_state.width;
    }

    void run(const ModuleString& s) {
        const SymbolId* sym = s.symbols.data();
        const double* par = s.params.data();
        const size_t N = s.size();
        m_usedBrackets = false;
        m_out.bounds.add(m_state.pos);
        if (m_gradient) {
            // Colour by branch order needs the deepest order first: one cheap pass.
            int depth = 0;
            for (size_t i = 0; i < N; ++i) {
                depth += (sym[i] == Alphabet::kPush) - (sym[i] == Alphabet::kPop && depth > 0);
                m_maxOrder = std::max(m_maxOrder, depth);
            }
            const auto& st = m_g.settings;
            for (int o = 0; o <= std::min(m_maxOrder, 65535); ++o)
                m_byOrder.push_back(lerpColour(st.barkColour, st.tipColour, float(o) / float(std::max(1, m_maxOrder))));
            m_state.stemColour = m_byOrder[0];
        }
        for (size_t i = 0; i < N; ++i) {
            const SymbolId id = sym[i];
            const int arity = m_arity[id];
            const double* p = par;
            par += arity;
            const Act act = m_actions[id];
            if (act == Act::None) continue;
            if (arity && !finite(p, arity)) continue;  // NaN or infinity: skip, never draw garbage
            m_step = m_opt.ages ? m_opt.ages[i] : 0;
            apply(act, arity ? p : nullptr);
        }
        finish();
    }

private:
    void turn(glm::vec3& a, glm::vec3& b, const double* p, float sign) {
        if (p) {
            float r = float(*p) * kPi / 180.0f * sign;
            rotate(a, b, std::cos(r), std::sin(r));
        } else if (m_angleSigma > 0) {
            float r = (m_angle + jitter(m_angleSigma)) * sign;
            rotate(a, b, std::cos(r), std::sin(r));
        } else {
            rotate(a, b, m_cos, m_sin * sign);
        }
    }
    // Seeded normal jitter truncated at 3 sigma.
    float jitter(float sigma) {
        for (;;) {
            float v = float(m_rng.normal(0.0, 1.0));
            if (std::fabs(v) <= 3.0f) return v * sigma;
        }
    }

    void apply(Act act, const double* p) {
        State& t = m_state;
        switch (act) {
            case Act::Draw:
            case Act::DrawNoVertex: {
                float len = p ? float(*p) : m_stepSigma > 0 ? t.length + jitter(m_stepSigma) : t.length;
                if (!m_polygons.empty()) {  // inside { }, F outlines the polygon (cpfg)
                    t.pos += t.H * len;
                    if (act == Act::Draw) vertex();
                    break;
                }
                segment(len);
                break;
            }
            case Act::Move:
            case Act::MoveNoVertex: {
                float len = p ? float(*p) : t.length;
                t.pos += t.H * len;
                t.lastSegment = -1;
                m_out.bounds.add(t.pos);
                if (act == Act::Move && !m_polygons.empty()) vertex();
                break;
            }
            case Act::Left: turn(t.H, t.L, p, 1.0f); break;
            case Act::Right: turn(t.H, t.L, p, -1.0f); break;
            case Act::Down: turn(t.H, t.U, p, -1.0f); break;
            case Act::Up: turn(t.H, t.U, p, 1.0f); break;
            case Act::RollLeft: turn(t.L, t.U, p, 1.0f); break;
            case Act::RollRight: turn(t.L, t.U, p, -1.0f); break;
            case Act::Around:
                t.H = -t.H;
                t.L = -t.L;
                break;
            case Act::Horizontal: {
                glm::vec3 l = glm::cross(glm::vec3(0, 1, 0), t.H);
                float n = glm::length(l);
                if (n > 1e-6f) {
                    t.L = l / n;
                    t.U = glm::cross(t.H, t.L);
                }
                break;
            }
            case Act::Push:
                m_usedBrackets = true;
                m_stack.push_back(t);
                t.order = std::uint16_t(std::min<int>(t.order + 1, 65535));
                if (m_gradient && !t.explicitColour) t.stemColour = m_byOrder[std::min<size_t>(t.order, m_byOrder.size() - 1)];
                t.length *= m_branchLength;
                t.width *= m_branchWidth;
                t.lastSegment = -1;  // a branch does not continue its parent's taper
                break;
            case Act::Pop:
                if (!m_stack.empty()) {  // an unbalanced ']' is harmless
                    t = m_stack.back();
                    m_stack.pop_back();
                }
                break;
            case Act::PolyBegin:
                m_polygons.emplace_back();
                m_polygons.back().push_back(t.pos);
                break;
            case Act::PolyVertex:
                if (!m_polygons.empty()) vertex();
                break;
            case Act::PolyEnd:
                if (!m_polygons.empty()) {
                    emitPolygon(m_polygons.back());
                    m_polygons.pop_back();
                }
                break;
            case Act::WidthDec:
            case Act::WidthInc:
                t.width = p ? float(*p) : act == Act::WidthDec ? t.width * m_widthFactor : t.width / m_widthFactor;
                m_maxWidth = std::max(m_maxWidth, t.width);
                // Taper: the segment before ends as thick as the next one starts.
                if (t.lastSegment >= 0) m_out.cylinders[size_t(t.lastSegment)].endRadius = t.width * 0.5f;
                break;
            case Act::ColourNext:
            case Act::ColourPrev:
                t.colour = p ? int(*p) : act == Act::ColourNext ? t.colour + 1 : t.colour - 1;
                t.explicitColour = true;
                t.stemColour = colour(t.colour);
                break;
            case Act::Leaf:
            case Act::Petal:
            case Act::Sphere: surface(act, p); break;
            default: break;
        }
    }

    std::uint32_t colour(int index) const {
        int n = int(m_palette.size());
        return m_palette[size_t(((index % n) + n) % n)];
    }

    void segment(float len) {
        State& t = m_state;
        t.lastSegment = std::int32_t(m_out.cylinders.size());
        CylinderInstance& c = m_out.cylinders.emplaceUninitialized();
        c.start = t.pos;
        t.pos += t.H * len;
        c.end = t.pos;
        c.startRadius = c.endRadius = t.width * 0.5f;
        c.colour = t.stemColour;
        c.order = t.order;
        c.step = m_step;
        m_out.bounds.add(t.pos);
        if (m_tropismE != 0) {  // ABOP 2.2: bend H towards T by e |H x T|
            glm::vec3 axis = glm::cross(t.H, m_tropism);
            float mag = glm::length(axis);
            if (mag > 1e-6f) {
                axis /= mag;
                float a = m_tropismE * mag;
                t.H = rodrigues(t.H, axis, a);
                t.L = rodrigues(t.L, axis, a);
                t.U = rodrigues(t.U, axis, a);
            }
        }
    }

    static glm::vec3 rodrigues(const glm::vec3& v, const glm::vec3& k, float a) {
        float c = std::cos(a), s = std::sin(a);
        return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
    }

    void vertex() {
        auto& poly = m_polygons.back();
        if (poly.empty() || glm::length(poly.back() - m_state.pos) > 1e-6f) poly.push_back(m_state.pos);
    }

    void emitPolygon(std::vector<glm::vec3>& pts) {
        if (pts.size() > 1 && glm::length(pts.front() - pts.back()) < 1e-6f) pts.pop_back();
        if (pts.size() < 3) return;
        Mesh& m = m_out.polygons;
        // Newell's normal: robust for concave and slightly non-planar outlines.
        glm::vec3 n(0);
        for (size_t i = 0; i < pts.size(); ++i) {
            const glm::vec3& a = pts[i];
            const glm::vec3& b = pts[(i + 1) % pts.size()];
            n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        float len = glm::length(n);
        if (len < 1e-12f) return;
        n /= len;
        std::uint32_t base = std::uint32_t(m.positions.size());
        std::uint32_t col = m_state.explicitColour ? colour(m_state.colour) : colour(1);
        for (const auto& p : pts) {
            m.positions.push_back(p);
            m.normals.push_back(n);
            m.colours.push_back(col);
            m_out.bounds.add(p);
        }
        triangulatePolygon(pts, base, m.indices);
    }

    void surface(Act act, const double* p) {
        State& t = m_state;
        SurfaceInstance s;
        s.position = t.pos;
        s.heading = t.H;
        s.up = t.U;
        if (act == Act::Sphere) {
            s.kind = SurfaceKind::Sphere;
            s.size = p ? float(*p) : t.width;  // radius
            s.colour = t.explicitColour ? colour(t.colour) : colour(3);
        } else {
            s.kind = act == Act::Leaf ? SurfaceKind::Leaf : SurfaceKind::Petal;
            s.size = p ? float(*p) : t.length;
            s.colour = t.explicitColour ? colour(t.colour) : act == Act::Leaf ? colour(1) : colour(5);
        }
        if (!(s.size > 0)) return;
        m_out.surfaces.push_back(s);
        m_out.bounds.add(s.position + s.heading * s.size);
        m_out.bounds.add(s.position);
    }

    void finish() {
        Geometry& out = m_out;
        // One pass over the segments: automatic width (stems in proportion to the plant,
        // 1/80 of its size at the base), colour by branch order, the thickest radius.
        float k = 1.0f;
        if (m_autoWidth && !out.bounds.empty) {
            glm::vec3 size = out.bounds.size();
            float extent = std::max({size.x, size.y, size.z});
            if (extent > 0) k = extent / 80.0f;
            for (auto& s : out.surfaces)
                if (s.kind == SurfaceKind::Sphere) s.size *= k;
        }
        if (k != 1.0f) {
            for (auto& c : out.cylinders) {
                c.startRadius *= k;
                c.endRadius *= k;
            }
        }
        float maxR = out.cylinders.empty() ? 0.0f : m_maxWidth * 0.5f * k;
        out.maxRadius = maxR;
        // A planar curve: every point in the z = 0 plane and no branches or surfaces.
        const float tol = 1e-4f * (1 + glm::length(out.bounds.size()));
        bool flat = !out.bounds.empty && std::fabs(out.bounds.min.z) < tol && std::fabs(out.bounds.max.z) < tol;
        auto view = m_g.settings.view;
        out.planarCurve = flat && view != ViewHint::Solid &&
                          (view == ViewHint::Flat || (!m_usedBrackets && out.surfaces.empty()));
    }

    const Grammar& m_g;
    const TurtleOptions& m_opt;
    Geometry& m_out;
    Rng m_rng;
    std::vector<Act> m_actions;
    std::vector<std::uint8_t> m_arity;
    std::vector<State> m_stack;
    std::vector<std::vector<glm::vec3>> m_polygons;
    std::vector<std::uint32_t> m_palette;
    std::vector<std::uint32_t> m_byOrder;  // gradient colour of each branch order
    State m_state;
    float m_angle, m_cos, m_sin, m_angleSigma, m_stepSigma;
    glm::vec3 m_tropism;
    float m_tropismE, m_widthFactor, m_branchLength, m_branchWidth;
    bool m_gradient, m_autoWidth, m_usedBrackets = false, m_colourModules = false;
    int m_maxOrder = 0;
    float m_maxWidth = 0;
    std::uint16_t m_step = 0;
};

}  // namespace

void Bounds::add(const glm::vec3& p) {
    if (empty) {
        min = max = p;
        empty = false;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Bounds::add(const Bounds& b) {
    if (b.empty) return;
    add(b.min);
    add(b.max);
}

void Geometry::clear() {
    cylinders.clear();
    surfaces.clear();
    polygons.clear();
    bounds = {};
    planarCurve = false;
    maxRadius = 0;
}

std::uint32_t defaultPaletteColour(int index) { return kDefaultPalette[((index % 16) + 16) % 16]; }

void interpret(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out) {
    out.clear();
    if (!g.interpretation.productions.empty()) {
        ModuleString drawn = applyInterpretation(g, s, options.seed);
        TurtleOptions o = options;
        o.ages = nullptr;  // the interpretation changes positions: ages no longer line up
        Turtle(g, o, out).run(drawn);
        return;
    }
    Turtle(g, options, out).run(s);
}

}  // namespace sprout
