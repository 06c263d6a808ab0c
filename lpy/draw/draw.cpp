// L-Py's drawing (lpy/draw/draw.hpp): the walk over a derived string, each module's mapping to
// Sprout's turtle and what it writes. The rare parts are in guides.cpp (guides,
// cross-sections, nF) and shapes.cpp (@g's shapes, labels, frames, colours as numbers);
// what every F does is inline in lpy/draw/draw_impl.hpp.
#include "lpy/draw/draw.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include "lpy/draw/draw_impl.hpp"
#include "lpy/translate/turtle_vocabulary.hpp"

namespace sprout::lpy {
namespace {

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
    g->settings.palette = d.materials.empty() ? defaultMaterials() : d.materials;
    colours = int(g->settings.palette.size());
    st.width = d.width;
    st.colour = std::clamp(d.colour, 0, colours - 1);
}

}  // namespace detail

namespace {

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

template <class Source>
std::shared_ptr<Grammar> drawableOf(const Source& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                    std::vector<std::string>* warnings, bool queries, std::vector<std::uint32_t>* sourceOf) {
    Drawing dr(d);
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
    // The module's a-th value as a number (a Python value read as PlantGL reads it).
    auto number = [&](size_t k, size_t a, double otherwise) {
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
    };
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
        switch (mp.op) {
            case Op::Forward:
                dr.forward(p.empty() ? 1.0 : p[0], p.size() >= 2 ? p[1] : -1);  // L-Py's default step is 1
                break;
            case Op::Move: {  // f(length = 1), along a guide when one is set
                double length = p.empty() ? 1.0 : p[0];
                dr.guideBefore(length);
                dr.bend();
                w.put(mp.sprout, {length});
                dr.guideAfter();
                break;
            }
            case Op::StepForward:  // nF(length, dl[, radius[, radiusFunction]])
                if (p.size() >= 2) dr.stepForward(p[0], p[1], n >= 3 ? number(k, 2, -1) : -1, s.object(k, 3));
                break;
            case Op::SetGuide: {  // SetGuide(curve, length[, yOrientation[, ccw]]); none: cleared
                PyObject* curve = s.object(k, 0);
                if (!curve) st.guide.reset();
                else if (!dr.setGuide(curve, number(k, 1, 0), number(k, 2, 0) != 0, number(k, 3, 0) != 0))
                    leftOut.insert(name + " with a value that is not a curve");
                break;
            }
            case Op::SetContour: {  // SetContour(curve); none: round again
                PyObject* curve = s.object(k, 0);
                st.section = curve ? dr.sectionOf(curve) : -1;
                if (curve && st.section < 0) leftOut.insert(name + " with a value that is not a 2D curve");
                w.put("SetContour", {double(st.section)});
                break;
            }
            case Op::Sweep: {  // Sweep(path, section, length, dl[, radius = 1[, radiusFunction]])
                PyObject* path = s.object(k, 0);
                PyObject* section = s.object(k, 1);
                const double length = number(k, 2, 0), dl = number(k, 3, 0);
                if (!path || !section || !(length > 0) || !(dl > 0)) {
                    leftOut.insert(name + " without a path, a section, a length and a step");
                    break;
                }
                if (!dr.setGuide(path, length, false, false)) leftOut.insert(name + " with a path that is not a curve");
                st.section = dr.sectionOf(section);
                if (st.section < 0) leftOut.insert(name + " with a section that is not a 2D curve");
                w.put("SetContour", {double(st.section)});
                dr.stepForward(length, dl, number(k, 4, 1.0), s.object(k, 5));
                break;
            }
            case Op::EndGuide: st.guide.reset(); break;
            case Op::PositionOnGuide:  // PositionOnGuide(t): t turtle units along it
                if (st.guide && !p.empty()) dr.positionOnGuide(p[0]);
                break;
            case Op::Turn:
                if (p.empty()) w.put(mp.sprout, {});
                else w.put(mp.sprout, {p[0]});
                // An intrinsic roll turns a 3D guide's frame with the turtle's (PlantGL's iRollL).
                if (st.guide && st.guide->curve->is3D && (name == "iRollL" || name == "iRollR"))
                    dr.rollGuide((p.empty() ? d.angle : p[0]) * M_PI / 180 * (name == "iRollL" ? 1 : -1));
                break;
            case Op::Around:
            case Op::Vertical:
            case Op::PolyBegin:
            case Op::PolyVertex:
            case Op::PolyEnd:
            case Op::Bare:
                w.put(mp.sprout, {});
                if (mp.sprout == std::string_view("@Gs")) st.inCurve = true;
                if (mp.sprout == std::string_view("@Ge")) st.inCurve = false;
                break;
            case Op::Push:
                dr.stack.push_back(st);
                w.put("[", {});
                break;
            case Op::Pop:
                if (!dr.stack.empty()) {
                    st = dr.stack.back();
                    dr.stack.pop_back();
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
            case Op::Label: {  // @L(text[, size])
                const int index = dr.labelIndex(s.object(k, 0));
                if (index >= 0) w.put("Label", {double(index), number(k, 1, 13)});
                if (PyErr_Occurred()) PyErr_Clear();
                break;
            }
            case Op::Shape: {  // @g(shape[, scale])
                // Not for the query walk, which reads frames only (@g does not move the turtle):
                // made into triangles, a grid's hundred boxes each step were most of its time.
                if (queries) break;
                const std::string& surface = dr.shapeSurface(s.object(k, 0));
                if (surface.empty()) leftOut.insert(name + " with text or what is not a PlantGL shape");
                else if (surface != "-") w.put(surface.c_str(), {number(k, 1, 1.0)});
                break;
            }
            case Op::Point:  // L-Py's x y z are Sprout's z x y
                if (p.size() >= 3) w.put(mp.sprout, {p[1], p[2], p[0]});
                break;
            case Op::Frame:  // Frame(size = 1, capHeightRatio = 0.2, capRadiusRatio = 2): PlantGL's _frame
                dr.frame(p);
                break;
            case Op::InterpolateColours:  // InterpolateColors(i, j, alpha): PlantGL mixes the two materials
                if (p.size() >= 2) dr.interpolateColours(p);
                break;
            case Op::LineTo:  // L-Py's x y z are Sprout's z x y
                if (p.size() >= 3) w.put(mp.sprout, {p[1], p[2], p[0]});
                if (p.size() >= 4) dr.setWidth(p[3]);
                break;
            case Op::IncWidth:
            case Op::DecWidth:
                if (!p.empty()) dr.setWidth(p[0]);
                else dr.setWidth(mp.op == Op::IncWidth ? st.width + 1 : st.width - 1 >= 0 ? st.width - 1 : -1);
                break;
            case Op::SetWidth:
                if (!p.empty()) dr.setWidth(p[0]);
                break;
            case Op::IncColour:
            case Op::DecColour:
                if (!p.empty() && allNumbers) dr.setColour(int(std::lround(std::clamp(p[0], -1e6, 1e6))));
                else dr.setColour(mp.op == Op::IncColour ? st.colour + 1 : st.colour - 1);
                break;
            case Op::SetColour:
                if (p.size() == 1) dr.setColour(int(std::lround(std::clamp(p[0], -1e6, 1e6))));
                else if (p.empty() && n == 0) dr.setColour(st.colour);
                else if (p.size() >= 3) dr.setRgbaColour(p);
                else leftOut.insert(name + " with a Material");
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
            case Op::Skip:
            case Op::LeftOut:  // (never mapped)
            case Op::Silent: break;
        }
    }
    if (sourceOf) sourceOf->resize(g->axiom.size(), std::uint32_t(s.size() == 0 ? 0 : s.size() - 1));
    if (warnings)
        for (const auto& name : leftOut) warnings->push_back(name);
    return std::move(dr.g);
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