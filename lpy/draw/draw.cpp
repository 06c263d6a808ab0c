// L-Py's drawing (lpy/draw/draw.hpp): the walk over a derived string, each module's mapping to
// Sprout's turtle and what it writes. The rare parts are in guides.cpp (guides,
// cross-sections, nF) and shapes.cpp (@g's shapes, labels, frames, colours as numbers);
// what every F does is inline in lpy/draw/draw_impl.hpp.

// Index of this file:
//   [SECTION] L-Py's modules as Sprout's turtle's
//   [SECTION] the turtle's defaults
//   [SECTION] the two kinds of string
//   [SECTION] a module drawn: moves, then looks
//   [SECTION] the walk
//   [SECTION] drawable()

#include "lpy/draw/draw.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include "lpy/draw/draw_impl.hpp"
#include "lpy/translate/turtle_vocabulary.hpp"

namespace sprout::lpy {
namespace {

//-----------------------------------------------------------------------------
// [SECTION] L-Py's modules as Sprout's turtle's
//-----------------------------------------------------------------------------
using detail::Drawing;
using detail::numbers;
using detail::TurtleState;
using Op = TurtleOp;

struct Mapping {
    Op op;
    const char* sprout = nullptr;  // the Sprout module, for ops that keep their name
};

// Each drawn module's mapping, from the turtle's vocabulary (lpy/translate/turtle_vocabulary.hpp).
const std::unordered_map<std::string, Mapping>& mappings() {
    static const std::unordered_map<std::string, Mapping> m = [] {
        std::unordered_map<std::string, Mapping> out;
        for (const TurtleWord& w : kTurtleVocabulary)
            if (w.op != Op::LeftOut && w.op != Op::Silent) out.emplace(w.names[0], Mapping{w.op, w.sprout});
        return out;
    }();
    return m;
}

// Modules that draw nothing in L-Py either (no warning when left out).
bool silent(const std::string& name) {
    static const std::set<std::string> s = [] {
        std::set<std::string> out;
        for (const TurtleWord& w : kTurtleVocabulary)
            if (w.op == Op::Silent) out.insert(w.names[0]);
        return out;
    }();
    return s.count(name) > 0;
}

}  // namespace

//-----------------------------------------------------------------------------
// [SECTION] the turtle's defaults
//-----------------------------------------------------------------------------
std::vector<std::uint32_t> defaultMaterials() {
    // PlantGL's turtle: ambient colours with diffuse 3 (material 0: ambient 80 grey, diffuse 2).
    auto rgb = [](int r, int g, int b, double diffuse) {
        auto c = [&](int x) { return std::uint32_t(std::min(255.0, std::floor(x * diffuse))); };
        return c(r) << 24 | c(g) << 16 | c(b) << 8 | 0xFFu;
    };
    return {rgb(80, 80, 80, 2), rgb(65, 45, 15, 3), rgb(30, 60, 10, 3), rgb(60, 0, 0, 3),
            rgb(60, 60, 15, 3), rgb(0, 0, 60, 3), rgb(60, 0, 60, 3)};
}

namespace detail {

Drawing::Drawing(const TurtleDefaults& d) : g(std::make_shared<Grammar>()), w(*g) {
    g->settings.angle = {d.angle, 0};
    g->settings.step = {1, 0};
    g->settings.gradient = Toggle::Off;
    g->settings.polygonEdgesDrawn = true;  // PlantGL's F inside { } draws its cylinder too
    g->settings.view = ViewHint::Solid;    // PlantGL draws every F as a cylinder: a flat model is no line drawing
    g->settings.palette = d.materials.empty() ? defaultMaterials() : d.materials;
    g->settings.shines = d.shines;
    g->settings.textures = d.textures;
    folder = d.folder;
    colours = int(g->settings.palette.size());
    st.width = d.width;
    st.colour = std::clamp(d.colour, 0, colours - 1);
}

}  // namespace detail

namespace {

//-----------------------------------------------------------------------------
// [SECTION] the two kinds of string
//-----------------------------------------------------------------------------
// The two kinds of string, read alike: a module's class, and its numbers appended to `p`
// (false when one of its values is not a number); the count of its values.
struct FromPython {
    const LString& s;
    size_t size() const { return s.size(); }
    int cls(size_t k) const { return s[k].cls; }
    PyObject* object(size_t k, size_t a) const {  // the module's a-th value, borrowed
        const LModule& m = s[k];
        return m.args && Py_ssize_t(a) < PyTuple_GET_SIZE(m.args.ptr()) ? PyTuple_GET_ITEM(m.args.ptr(), Py_ssize_t(a)) : nullptr;
    }
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
    std::vector<std::uint32_t> first;  // where each module's numbers start
    explicit FromNumbers(const NumString& string) : s(string), first(string.size()) {
        std::uint32_t at = 0;
        for (size_t k = 0; k < s.size(); ++k) first[k] = at, at += s.shape(k).n;
    }
    size_t size() const { return s.size(); }
    int cls(size_t k) const { return s.shape(k).cls; }
    PyObject* object(size_t, size_t) const { return nullptr; }  // numbers only
    size_t values(size_t k, std::vector<double>& p, bool&) const {
        const std::uint32_t n = s.shape(k).n;
        p.insert(p.end(), s.params.data() + first[k], s.params.data() + first[k] + n);
        return n;
    }
};

//-----------------------------------------------------------------------------
// [SECTION] a module drawn: moves, then looks
//-----------------------------------------------------------------------------
// The module's a-th value as a number (a Python value read as PlantGL reads it).
template <class Source>
double numberAt(const Source& s, size_t k, size_t a, double otherwise) {
    PyObject* v = s.object(k, a);
    if (!v) {  // the native path's strings: numbers only
        std::vector<double> q;
        bool all = true;
        s.values(k, q, all);
        return a < q.size() && std::isfinite(q[a]) ? q[a] : otherwise;
    }
    const double d = PyFloat_AsDouble(v);
    if (PyErr_Occurred()) {  // not a number (None, a curve): as if not given
        PyErr_Clear();
        return otherwise;
    }
    return std::isfinite(d) ? d : otherwise;
}

// A module the walk draws: its name, its mapping, its numbers (p; allNumbers: all its values
// were numbers) and the count of its values (n).
template <class Source>
struct Module {
    const Source& s;
    size_t k;
    const std::string& name;
    const Mapping& mp;
    const std::vector<double>& p;
    size_t n;
    bool allNumbers;
    double number(size_t a, double otherwise) const { return numberAt(s, k, a, otherwise); }
    PyObject* object(size_t a) const { return s.object(k, a); }
};

// The turtle's moves, turns, branches and guides; false for a module that is not one.
template <class Source>
bool drawMove(Drawing& dr, const Module<Source>& m, const TurtleDefaults& d) {
    switch (m.mp.op) {
        case Op::Forward:
            dr.forward(m.p.empty() ? 1.0 : m.p[0], m.p.size() >= 2 ? m.p[1] : -1);  // L-Py's default step is 1
            break;
        case Op::Move: {  // f(length = 1), along a guide when one is set
            double length = m.p.empty() ? 1.0 : m.p[0];
            dr.guideBefore(length);
            dr.bend();
            dr.w.put(m.mp.sprout, {length});
            dr.guideAfter();
            break;
        }
        case Op::StepForward:  // nF(length, dl[, radius[, radiusFunction]])
            if (m.p.size() >= 2) dr.stepForward(m.p[0], m.p[1], m.n >= 3 ? m.number(2, -1) : -1, m.object(3));
            break;
        case Op::SetGuide: {  // SetGuide(curve, length[, yOrientation[, ccw]]); none: cleared
            PyObject* curve = m.object(0);
            if (!curve) dr.st.guide.reset();
            else if (!dr.setGuide(curve, m.number(1, 0), m.number(2, 0) != 0, m.number(3, 0) != 0))
                dr.leftOut.insert(m.name + " with a value that is not a curve");
            break;
        }
        case Op::SetContour: {  // SetContour(curve); none: round again
            PyObject* curve = m.object(0);
            dr.st.section = curve ? dr.sectionOf(curve) : -1;
            if (curve && dr.st.section < 0) dr.leftOut.insert(m.name + " with a value that is not a 2D curve");
            dr.w.put("SetContour", {double(dr.st.section)});
            break;
        }
        case Op::Sweep: {  // Sweep(path, section, length, dl[, radius = 1[, radiusFunction]])
            PyObject* path = m.object(0);
            PyObject* section = m.object(1);
            const double length = m.number(2, 0), dl = m.number(3, 0);
            if (!path || !section || !(length > 0) || !(dl > 0)) {
                dr.leftOut.insert(m.name + " without a path, a section, a length and a step");
                break;
            }
            if (!dr.setGuide(path, length, false, false)) dr.leftOut.insert(m.name + " with a path that is not a curve");
            dr.st.section = dr.sectionOf(section);
            if (dr.st.section < 0) dr.leftOut.insert(m.name + " with a section that is not a 2D curve");
            dr.w.put("SetContour", {double(dr.st.section)});
            dr.stepForward(length, dl, m.number(4, 1.0), m.object(5));
            break;
        }
        case Op::EndGuide: dr.st.guide.reset(); break;
        case Op::PositionOnGuide:  // PositionOnGuide(t): t turtle units along it
            if (dr.st.guide && !m.p.empty()) dr.positionOnGuide(m.p[0]);
            break;
        case Op::Turn:
            if (m.p.empty()) dr.w.put(m.mp.sprout, {});
            else dr.w.put(m.mp.sprout, {m.p[0]});
            // An intrinsic roll turns a 3D guide's frame with the turtle's (PlantGL's iRollL).
            if (dr.st.guide && dr.st.guide->curve->is3D && (m.name == "iRollL" || m.name == "iRollR"))
                dr.rollGuide((m.p.empty() ? d.angle : m.p[0]) * M_PI / 180 * (m.name == "iRollL" ? 1 : -1));
            break;
        case Op::Around:
        case Op::Vertical:
        case Op::PolyBegin:
        case Op::PolyVertex:
        case Op::PolyEnd:
        case Op::Bare:
            dr.w.put(m.mp.sprout, {});
            if (m.mp.sprout == std::string_view("@Gs")) dr.st.inCurve = true;
            if (m.mp.sprout == std::string_view("@Ge")) dr.st.inCurve = false;
            break;
        case Op::Push:
            dr.stack.push_back(dr.st);
            dr.w.put("[", {});
            break;
        case Op::Pop:
            if (!dr.stack.empty()) {
                dr.st = dr.stack.back();
                dr.stack.pop_back();
            }
            dr.w.put("]", {});
            break;
        case Op::SetHead:  // L-Py's x y z are Sprout's z x y
            if (m.p.size() >= 6) dr.w.put("@R", {m.p[1], m.p[2], m.p[0], m.p[4], m.p[5], m.p[3]});
            else if (m.p.size() >= 3) dr.w.put("@R", {m.p[1], m.p[2], m.p[0]});
            else if (m.p.empty()) dr.w.put("@R", {0, 1, 0, 0, 0, 1});
            break;
        case Op::MoveTo:
            if (m.p.size() >= 3) dr.w.put("@M", {m.p[1], m.p[2], m.p[0]});
            else if (m.p.empty()) dr.w.put("@M", {0, 0, 0});
            break;
        case Op::Numbers:
            if (!m.p.empty()) dr.w.put(m.mp.sprout, m.p);
            break;
        case Op::Point:  // L-Py's x y z are Sprout's z x y
            if (m.p.size() >= 3) dr.w.put(m.mp.sprout, {m.p[1], m.p[2], m.p[0]});
            break;
        case Op::LineTo:  // L-Py's x y z are Sprout's z x y
            if (m.p.size() >= 3 && dr.queryWalk) dr.bend();  // PlantGL's oLineTo steps with F
            if (m.p.size() >= 3) dr.w.put(m.mp.sprout, {m.p[1], m.p[2], m.p[0]});
            if (m.p.size() >= 4) dr.setWidth(m.p[3]);
            break;
        default: return false;
    }
    return true;
}

// What the turtle draws with: widths, colours, tropism, shapes, labels, frames.
template <class Source>
void drawLook(Drawing& dr, const Module<Source>& m, bool queries) {
    switch (m.mp.op) {
        case Op::Label: {  // @L(text[, size])
            const int index = dr.labelIndex(m.object(0));
            if (index >= 0) dr.w.put("Label", {double(index), m.number(1, 13)});
            if (PyErr_Occurred()) PyErr_Clear();
            break;
        }
        case Op::Shape: {  // @g(shape[, scale])
            // Not for the query walk, which reads frames only (@g does not move the turtle):
            // made into triangles, a grid's hundred boxes each step were most of its time.
            if (queries) break;
            const std::string& surface = dr.shapeSurface(m.object(0));
            if (surface.empty()) dr.leftOut.insert(m.name + " with text or what is not a PlantGL shape");
            else if (surface != "-") dr.w.put(surface.c_str(), {m.number(1, 1.0)});
            break;
        }
        case Op::Frame:  // Frame(size = 1, capHeightRatio = 0.2, capRadiusRatio = 2): PlantGL's _frame
            dr.frame(m.p);
            break;
        case Op::InterpolateColours:  // InterpolateColors(i, j, alpha): PlantGL mixes the two materials
            if (m.p.size() >= 2) dr.interpolateColours(m.p);
            break;
        case Op::TextureBaseColour:  // TextureBaseColor(index | r, g, b[, a]), InterpolateTextureBaseColors(i, j, alpha)
            if (!m.p.empty()) dr.textureBaseColour(m.p, m.name == "InterpolateTextureBaseColors");
            break;
        case Op::IncWidth:
        case Op::DecWidth:
            if (!m.p.empty()) dr.setWidth(m.p[0]);
            else dr.setWidth(m.mp.op == Op::IncWidth ? dr.st.width + 1 : dr.st.width - 1 >= 0 ? dr.st.width - 1 : -1);
            break;
        case Op::SetWidth:
            if (!m.p.empty()) dr.setWidth(m.p[0]);
            break;
        case Op::IncColour:
        case Op::DecColour:
            if (!m.p.empty() && m.allNumbers) dr.setColour(int(std::lround(std::clamp(m.p[0], -1e6, 1e6))));
            else dr.setColour(m.mp.op == Op::IncColour ? dr.st.colour + 1 : dr.st.colour - 1);
            break;
        case Op::SetColour:
            if (m.p.size() == 1) dr.setColour(int(std::lround(std::clamp(m.p[0], -1e6, 1e6))));
            else if (m.p.empty() && m.n == 0) dr.setColour(dr.st.colour);
            else if (m.p.size() >= 3) dr.setRgbaColour(m.p);
            else dr.leftOut.insert(m.name + " with a Material");
            break;
        case Op::Tropism:
            if (m.p.size() >= 3) dr.st.tropism[0] = m.p[0], dr.st.tropism[1] = m.p[1], dr.st.tropism[2] = m.p[2];
            else if (m.p.empty()) dr.st.tropism[0] = 0, dr.st.tropism[1] = 0, dr.st.tropism[2] = 1;
            break;
        case Op::Elasticity:
            // One value: set when it is in [0, 1] (else L-Py warns and keeps the elasticity); otherwise 0.
            if (m.n != 1) dr.st.elasticity = 0;
            else if (m.p.size() == 1 && m.p[0] >= 0 && m.p[0] <= 1) dr.st.elasticity = m.p[0];
            break;
        case Op::Sphere:
            dr.w.put("@O", {m.p.empty() ? dr.st.width : m.p[0]});
            break;
        case Op::Circle:
            dr.w.put("@c", {m.p.empty() ? dr.st.width : m.p[0]});
            break;
        case Op::Surface:
            // `~l(size)`: L-Py's predefined leaf; other names are surfaces a file defines.
            dr.w.put("~l", {m.p.empty() ? 1.0 : m.p[0]});
            break;
        default: break;
    }
}

//-----------------------------------------------------------------------------
// [SECTION] the walk
//-----------------------------------------------------------------------------
template <class Source>
std::shared_ptr<Grammar> drawableOf(const Source& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                    std::vector<std::string>* warnings, bool queries, std::vector<std::uint32_t>* sourceOf) {
    Drawing dr(d);
    dr.queryWalk = queries;
    const std::shared_ptr<Grammar>& g = dr.g;
    detail::Writer& w = dr.w;
    TurtleState& st = dr.st;
    std::set<std::string>& leftOut = dr.leftOut;
    w.put("!", {2 * st.width});
    w.put(";", {double(st.colour)});
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
        const Module<Source> m{s, k, name, *mappingOf[size_t(cls)], p, n, allNumbers};
        if (!drawMove(dr, m, d)) drawLook(dr, m, queries);
    }
    if (sourceOf) sourceOf->resize(g->axiom.size(), std::uint32_t(s.size() == 0 ? 0 : s.size() - 1));
    if (warnings)
        for (const auto& name : leftOut) warnings->push_back(name);
    return std::move(dr.g);
}

}  // namespace

//-----------------------------------------------------------------------------
// [SECTION] drawable()
//-----------------------------------------------------------------------------
std::shared_ptr<Grammar> drawable(const LString& s, const ModuleClasses& classes, const TurtleDefaults& d, std::vector<std::string>* warnings,
                                  bool queries, std::vector<std::uint32_t>* sourceOf) {
    return drawableOf(FromPython{s}, classes, d, warnings, queries, sourceOf);
}

std::shared_ptr<Grammar> drawable(const NumString& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                  std::vector<std::string>* warnings) {
    return drawableOf(FromNumbers{s}, classes, d, warnings, false, nullptr);
}

}  // namespace sprout::lpy