#include "lpy/draw.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

namespace sprout::lpy {
namespace {

enum class Op : std::uint8_t {
    Skip, Forward, Move, StepForward, Turn, Around, Vertical, SetHead, MoveTo, LineTo, IncWidth, DecWidth, SetWidth,
    IncColour, DecColour, SetColour, Sphere, Circle, Surface, PolyBegin, PolyVertex, PolyEnd, Push, Pop,
    Bare,  // the Sprout module, without parameters
    Tropism, Elasticity,
};

struct Mapping {
    Op op;
    const char* sprout = nullptr;  // the Sprout module, for ops that keep their name
};

const std::unordered_map<std::string, Mapping>& mappings() {
    static const std::unordered_map<std::string, Mapping> m = {
        {"F", {Op::Forward, "F"}}, {"f", {Op::Move, "f"}}, {"nF", {Op::StepForward, "F"}},
        {"+", {Op::Turn, "+"}}, {"-", {Op::Turn, "-"}}, {"^", {Op::Turn, "^"}}, {"&", {Op::Turn, "&"}},
        {"/", {Op::Turn, "/"}}, {"\\", {Op::Turn, "\\"}}, {"iRollL", {Op::Turn, "/"}}, {"iRollR", {Op::Turn, "\\"}},
        {"|", {Op::Around, "|"}}, {"@v", {Op::Vertical, "$"}}, {"@R", {Op::SetHead, "@R"}},
        {"@M", {Op::MoveTo, "@M"}}, {"LineTo", {Op::LineTo, "LineTo"}}, {"OLineTo", {Op::LineTo, "OLineTo"}},
        {"_", {Op::IncWidth}}, {"!", {Op::DecWidth}}, {"SetWidth", {Op::SetWidth}},
        {";", {Op::IncColour}}, {",", {Op::DecColour}}, {"SetColor", {Op::SetColour}},
        {"@O", {Op::Sphere, "@O"}}, {"@o", {Op::Circle, "@c"}}, {"~", {Op::Surface, "~l"}},
        {"{", {Op::PolyBegin, "{"}}, {".", {Op::PolyVertex, "."}}, {"}", {Op::PolyEnd, "}"}},
        {"[", {Op::Push, "["}}, {"]", {Op::Pop, "]"}},
        // Generalized cylinders: the stems between StartGC and EndGC are one smooth tube
        // (Sprout's cpfg @Gs ... @Ge: each F a control point).
        {"@Gc", {Op::Bare, "@Gs"}}, {"@Ge", {Op::Bare, "@Ge"}},
        // Tropism: before each F and f, H turns towards the tropism vector by the elasticity
        // times the angle between them (Sprout's @T with a direction).
        {"@Tp", {Op::Tropism}}, {"@Ts", {Op::Elasticity}},
    };
    return m;
}

// Modules that draw nothing in L-Py either (no warning when left out).
bool silent(const std::string& name) {
    static const std::set<std::string> s = {"%", "*", "None", "X", "?P", "?H", "?U", "?L", "?R", "?F",
                                            "@D", "@Di", "@Dd", "SectionResolution", "SetContour", "EndGuide", "@2D", "@3D",
                                            "TextureScale", "TextureUScale", "TextureVScale", "TextureTranslation", "TextureRotation",
                                            "TextureTransformation", "x", "or", "=]", "?I", "new"};
    return s.count(name) > 0;
}

// A parameter as numbers: a number, or a vector/sequence of numbers (Vector3, tuple).
bool numbers(PyObject* v, std::vector<double>& out) {
    if (PyFloat_Check(v) || PyLong_Check(v)) {
        const double d = PyFloat_Check(v) ? PyFloat_AS_DOUBLE(v) : PyLong_AsDouble(v);
        if (PyErr_Occurred()) {
            PyErr_Clear();
            return false;
        }
        out.push_back(d);
        return true;
    }
    if (PyUnicode_Check(v) || !PySequence_Check(v)) return false;
    const Py_ssize_t n = PySequence_Size(v);
    if (n < 0 || n > 16) {
        PyErr_Clear();
        return false;
    }
    for (Py_ssize_t k = 0; k < n; ++k) {
        PyObject* item = PySequence_GetItem(v, k);
        if (!item) {
            PyErr_Clear();
            return false;
        }
        const bool ok = (PyFloat_Check(item) || PyLong_Check(item)) && numbers(item, out);
        Py_DECREF(item);
        if (!ok) return false;
    }
    return true;
}

class Writer {
public:
    Writer(Grammar& g) : m_g(g) {}
    void put(const char* name, std::initializer_list<double> params) {
        const int arity = int(std::min<size_t>(params.size(), size_t(Alphabet::kMaxArity)));
        // Names are the mapping's literals: each (name, arity) is interned once.
        std::optional<SymbolId>& id = m_ids[{name, arity}];
        if (!id) id = m_g.alphabet.intern(name, arity);
        if (!id) return;
        m_g.axiom.symbols.push_back(*id);
        for (int k = 0; k < arity; ++k) {
            const double v = params.begin()[k];
            m_g.axiom.params.push_back(std::isfinite(v) ? v : 0.0);
        }
    }

private:
    Grammar& m_g;
    std::map<std::pair<const char*, int>, std::optional<SymbolId>> m_ids;
};

}  // namespace

std::vector<std::uint32_t> defaultMaterials() {
    // PlantGL's turtle: ambient colours with diffuse 3 (material 0: ambient 80 grey, diffuse 2).
    auto rgb = [](int r, int g, int b, double diffuse) {
        auto c = [&](int x) { return std::uint32_t(std::min(255.0, std::floor(x * diffuse))); };
        return c(r) << 24 | c(g) << 16 | c(b) << 8 | 0xFFu;
    };
    return {rgb(80, 80, 80, 2), rgb(65, 45, 15, 3), rgb(30, 60, 10, 3), rgb(60, 0, 0, 3),
            rgb(60, 60, 15, 3), rgb(0, 0, 60, 3), rgb(60, 0, 60, 3)};
}

namespace {

// The two kinds of string, read alike: a module's class, and its numbers appended to `p`
// (false when one of its values is not a number); the count of its values.
struct FromPython {
    const LString& s;
    size_t size() const { return s.size(); }
    int cls(size_t k) const { return s[k].cls; }
    size_t values(size_t k, std::vector<double>& p, bool& allNumbers) const {
        const LModule& m = s[k];
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        for (Py_ssize_t a = 0; a < n; ++a)
            if (!numbers(PyTuple_GET_ITEM(m.args.ptr(), a), p)) allNumbers = false;
        return size_t(n);
    }
};
struct FromNumbers {
    const NumString& s;
    size_t size() const { return s.size(); }
    int cls(size_t k) const { return s.modules[k].cls; }
    size_t values(size_t k, std::vector<double>& p, bool&) const {
        const NumString::Module& m = s.modules[k];
        p.insert(p.end(), s.params.data() + m.first, s.params.data() + m.first + m.n);
        return m.n;
    }
};

template <class Source>
std::shared_ptr<Grammar> drawableOf(const Source& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                    std::vector<std::string>* warnings, bool queries, std::vector<std::uint32_t>* sourceOf) {
    auto g = std::make_shared<Grammar>();
    g->settings.angle = {d.angle, 0};
    g->settings.step = {1, 0};
    g->settings.gradient = Toggle::Off;
    g->settings.palette = d.materials.empty() ? defaultMaterials() : d.materials;
    const int colours = int(g->settings.palette.size());
    Writer w(*g);
    struct State {
        double width;
        int colour;
        double tropism[3] = {0, 0, 1};  // L-Py's axes
        double elasticity = 0;
    };
    std::vector<State> stack;
    State st{d.width, std::clamp(d.colour, 0, colours - 1)};
    auto bend = [&] {  // L-Py's x y z are Sprout's z x y
        if (st.elasticity > 0) w.put("@T", {st.elasticity, st.tropism[1], st.tropism[2], st.tropism[0], 1});
    };
    w.put("!", {2 * st.width});
    w.put(";", {double(st.colour)});
    std::set<std::string> leftOut;
    // Each class's mapping, looked up by name once.
    const auto& map = mappings();
    enum : std::uint8_t { kUnseen, kQuery, kMapped, kLeftOut };
    std::vector<std::uint8_t> kindOf(classes.size(), kUnseen);
    std::vector<const Mapping*> mappingOf(classes.size(), nullptr);
    std::vector<double> p;
    for (size_t k = 0; k < s.size(); ++k) {
        // What the module before wrote (the first pieces, width and colour: the first module).
        if (sourceOf) sourceOf->resize(g->axiom.size(), std::uint32_t(k == 0 ? 0 : k - 1));
        const int cls = s.cls(k);
        if (cls < 0 || size_t(cls) >= kindOf.size()) continue;
        std::uint8_t& kind = kindOf[size_t(cls)];
        const std::string& name = classes.name(cls);
        if (kind == kUnseen) {
            auto it = map.find(name);
            if (queries && Engine::isQuery(name)) {
                kind = kQuery;
            } else if (it != map.end()) {
                kind = kMapped;
                mappingOf[size_t(cls)] = &it->second;
            } else {
                kind = kLeftOut;
                if (!silent(name) && classes.isPredefined(cls)) leftOut.insert(name);
            }
        }
        if (kind == kQuery) {
            w.put("?P", {});
            continue;
        }
        if (kind != kMapped) continue;
        p.clear();
        bool allNumbers = true;
        const size_t n = s.values(k, p, allNumbers);
        const Mapping& mp = *mappingOf[size_t(cls)];
        auto setWidth = [&](double width) {
            if (!(width >= 0)) return;
            st.width = width;
            w.put("!", {2 * width});
        };
        auto setColour = [&](int index) {
            if (index < 0 || index >= colours) return;  // L-Py ignores an index past its materials
            st.colour = index;
            w.put(";", {double(index)});
        };
        switch (mp.op) {
            case Op::Forward:
            case Op::Move:
                bend();
                if (p.empty()) w.put(mp.sprout, {});
                else w.put(mp.sprout, {p[0]});
                if (mp.op == Op::Forward && p.size() >= 2) setWidth(p[1]);  // a frustum up to the top radius
                break;
            case Op::StepForward: {  // nF(length, dl): F(dl) repeated, then the rest
                if (p.size() < 2 || !(p[1] > 0) || !(p[0] >= 0)) break;
                const double steps = std::min(std::floor(p[0] / p[1]), 100000.0);
                for (double k = 0; k < steps; ++k) bend(), w.put("F", {p[1]});
                if (const double rest = p[0] - steps * p[1]; rest > 1e-9) bend(), w.put("F", {rest});
                break;
            }
            case Op::Turn:
                if (p.empty()) w.put(mp.sprout, {});
                else w.put(mp.sprout, {p[0]});
                break;
            case Op::Around:
            case Op::Vertical:
            case Op::PolyBegin:
            case Op::PolyVertex:
            case Op::PolyEnd:
            case Op::Bare: w.put(mp.sprout, {}); break;
            case Op::Push:
                stack.push_back(st);
                w.put("[", {});
                break;
            case Op::Pop:
                if (!stack.empty()) {
                    st = stack.back();
                    stack.pop_back();
                }
                w.put("]", {});
                break;
            case Op::SetHead:  // L-Py's x y z are Sprout's z x y
                if (p.size() >= 6) w.put("@R", {p[1], p[2], p[0], p[4], p[5], p[3]});
                else if (p.size() >= 3) w.put("@R", {p[1], p[2], p[0]});
                else if (p.empty()) w.put("@R", {0, 1, 0, 0, 0, 1});
                break;
            case Op::MoveTo:
                if (p.size() >= 3) w.put("@M", {p[1], p[2], p[0]});
                else if (p.empty()) w.put("@M", {0, 0, 0});
                break;
            case Op::LineTo:  // L-Py's x y z are Sprout's z x y
                if (p.size() >= 3) w.put(mp.sprout, {p[1], p[2], p[0]});
                if (p.size() >= 4) setWidth(p[3]);
                break;
            case Op::IncWidth:
            case Op::DecWidth:
                if (!p.empty()) setWidth(p[0]);
                else setWidth(mp.op == Op::IncWidth ? st.width + 1 : st.width - 1 >= 0 ? st.width - 1 : -1);
                break;
            case Op::SetWidth:
                if (!p.empty()) setWidth(p[0]);
                break;
            case Op::IncColour:
            case Op::DecColour:
                if (!p.empty() && allNumbers) setColour(int(std::lround(std::clamp(p[0], -1e6, 1e6))));
                else setColour(mp.op == Op::IncColour ? st.colour + 1 : st.colour - 1);
                break;
            case Op::SetColour:
                if (p.size() == 1) setColour(int(std::lround(std::clamp(p[0], -1e6, 1e6))));
                else if (p.empty() && n == 0) setColour(st.colour);
                else if (p.size() >= 3) {
                    auto c = [](double x) { return std::uint32_t(std::clamp(x, 0.0, 255.0)); };
                    const std::uint32_t rgba = c(p[0]) << 24 | c(p[1]) << 16 | c(p[2]) << 8 | (p.size() >= 4 ? c(p[3]) : 255u);
                    auto& pal = g->settings.palette;
                    auto found = std::find(pal.begin(), pal.end(), rgba);
                    if (found == pal.end() && pal.size() < 250) {
                        pal.push_back(rgba);
                        found = pal.end() - 1;
                    }
                    if (found != pal.end()) w.put(";", {double(found - pal.begin())});
                } else {
                    leftOut.insert(name + " with a Material");
                }
                break;
            case Op::Tropism:
                if (p.size() >= 3) st.tropism[0] = p[0], st.tropism[1] = p[1], st.tropism[2] = p[2];
                else if (p.empty()) st.tropism[0] = 0, st.tropism[1] = 0, st.tropism[2] = 1;
                break;
            case Op::Elasticity:
                st.elasticity = p.empty() ? 0.0 : std::clamp(p[0], 0.0, 1.0);
                break;
                        case Op::Sphere:
                w.put("@O", {p.empty() ? st.width : p[0]});
                break;
            case Op::Circle:
                w.put("@c", {p.empty() ? st.width : p[0]});
                break;
            case Op::Surface:
                // `~l(size)`: L-Py's predefined leaf; other names are surfaces a file defines.
                w.put("~l", {p.empty() ? 1.0 : p[0]});
                break;
            case Op::Skip: break;
        }
    }
    if (sourceOf) sourceOf->resize(g->axiom.size(), std::uint32_t(s.size() == 0 ? 0 : s.size() - 1));
    if (warnings)
        for (const auto& name : leftOut) warnings->push_back(name);
    return g;
}

}  // namespace

std::shared_ptr<Grammar> drawable(const LString& s, const ModuleClasses& classes, const TurtleDefaults& d, std::vector<std::string>* warnings,
                                  bool queries, std::vector<std::uint32_t>* sourceOf) {
    return drawableOf(FromPython{s}, classes, d, warnings, queries, sourceOf);
}

std::shared_ptr<Grammar> drawable(const NumString& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                  std::vector<std::string>* warnings) {
    return drawableOf(FromNumbers{s}, classes, d, warnings, false, nullptr);
}

}  // namespace sprout::lpy
