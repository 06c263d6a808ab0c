#include "lpy/draw.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include "core/language/surface_file.hpp"

namespace sprout::lpy {
namespace {

enum class Op : std::uint8_t {
    Skip, Forward, Move, StepForward, Turn, Around, Vertical, SetHead, MoveTo, LineTo, IncWidth, DecWidth, SetWidth,
    IncColour, DecColour, SetColour, Sphere, Circle, Surface, PolyBegin, PolyVertex, PolyEnd, Push, Pop,
    Bare,  // the Sprout module, without parameters
    Tropism, Elasticity, SetGuide, EndGuide, PositionOnGuide, SetContour, Sweep,
    Point,  // the Sprout module with L-Py's x y z as Sprout's
    Frame, InterpolateColours, Shape, Label,
};

struct Mapping {
    Op op;
    const char* sprout = nullptr;  // the Sprout module, for ops that keep their name
};

const std::unordered_map<std::string, Mapping>& mappings() {
    static const std::unordered_map<std::string, Mapping> m = {
        {"F", {Op::Forward, "F"}}, {"f", {Op::Move, "f"}}, {"nF", {Op::StepForward, "F"}},
        {"+", {Op::Turn, "+"}}, {"-", {Op::Turn, "-"}}, {"^", {Op::Turn, "^"}}, {"&", {Op::Turn, "&"}},
        // L-Py's / is RollL, about H by +angle (PlantGL: left towards up), which is Sprout's
        // (ABOP's) \ ; its \ is Sprout's /.
        {"/", {Op::Turn, "\\"}}, {"\\", {Op::Turn, "/"}}, {"iRollL", {Op::Turn, "\\"}}, {"iRollR", {Op::Turn, "/"}},
        {"|", {Op::Around, "|"}}, {"@v", {Op::Vertical, "$"}}, {"@R", {Op::SetHead, "@R"}},
        {"@M", {Op::MoveTo, "@M"}}, {"LineTo", {Op::LineTo, "LineTo"}}, {"OLineTo", {Op::LineTo, "OLineTo"}},
        {"LineRel", {Op::LineTo, "LineRel"}}, {"OLineRel", {Op::LineTo, "OLineRel"}}, {"MoveRel", {Op::Point, "MoveRel"}},
        {"Pinpoint", {Op::Point, "Pinpoint"}}, {"PinpointRel", {Op::Point, "PinpointRel"}},
        // The turtle's frame as three arrows (heading red, up blue, left green), and a colour
        // between two materials.
        {"Frame", {Op::Frame}}, {"InterpolateColors", {Op::InterpolateColours}},
        // A PlantGL shape at the turtle (@g(shape[, scale])): its x along the turtle's up, its y
        // to the right, its z along the heading (so a shape's coordinates are L-Py's world ones
        // for a turtle that has not turned, as a guide's are).
        {"@g", {Op::Shape}},
        // A text at the turtle (@L(text[, size]): PlantGL's label, facing the viewer).
        {"@L", {Op::Label}},
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
        // Guides: the F and f that follow go along a curve (PlantGL's Turtle2DPath).
        {"SetGuide", {Op::SetGuide}}, {"EndGuide", {Op::EndGuide}}, {"PositionOnGuide", {Op::PositionOnGuide}},
        // Cross-sections: the tubes after SetContour(curve) are swept with that curve's shape
        // (an open curve: a surface, such as a leaf blade); Sweep(path, section, length, dl,
        // radius, radiusFunction) is SetGuide, SetContour and nF together (PlantGL's sweep).
        {"SetContour", {Op::SetContour}}, {"Sweep", {Op::Sweep}},
    };
    return m;
}

// Modules that draw nothing in L-Py either (no warning when left out).
bool silent(const std::string& name) {
    static const std::set<std::string> s = {"%", "*", "None", "X", "?P", "?H", "?U", "?L", "?R", "?F",
                                            "@D", "@Di", "@Dd", "SectionResolution", "@2D", "@3D",
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

// A curve that F and f follow (SetGuide), 2D or 3D: sampled once, by the fraction of its
// length (2D curves have z = 0).
struct GuideCurve {
    std::vector<glm::dvec3> points;
    std::vector<double> at;  // the fraction of the curve's length at each point
    double length = 0;
    bool is3D = false;
    glm::dvec3 pointAt(double t) const {
        const size_t i = segment(t);
        const double span = at[i + 1] - at[i], f = span > 0 ? (t - at[i]) / span : 0;
        return points[i] + (points[i + 1] - points[i]) * std::clamp(f, 0.0, 1.0);
    }
    glm::dvec3 tangentAt(double t) const {
        const size_t i = segment(t);
        const glm::dvec3 d = points[i + 1] - points[i];
        const double n = glm::length(d);
        return n > 0 ? d / n : glm::dvec3(is3D ? 0 : 1, 0, is3D ? 1 : 0);
    }
    size_t segment(double t) const {  // the span that holds t (the last one at the end)
        const auto it = std::upper_bound(at.begin(), at.end(), t);
        return std::min(size_t(std::max<std::ptrdiff_t>(it - at.begin() - 1, 0)), points.size() - 2);
    }
};

// A guide on its way (PlantGL's Turtle2DPath and Turtle3DPath): the curve scaled to `total`
// turtle units; how far along it the turtle is (a fraction of its length), where on the curve
// it was and the curve's frame there, which the turtle's frame follows. A 2D curve lies in the
// plane of the turtle's heading and up (x, y), or of heading and left with `yOrientation`;
// `ccw` mirrors it. A 3D curve's z is the turtle's heading at the start, its x the up.
struct Guide {
    std::shared_ptr<const GuideCurve> curve;
    double total = 0, scale = 1, t = 0;
    glm::dvec3 lastPosition{0}, lastHeading{1, 0, 0}, lastLeft{0, -1, 0}, lastUp{1, 0, 0};
    bool yOrientation = false, ccw = false;
};

// The rotation by `angle` about unit `axis` (Rodrigues).
glm::dvec3 rotated(glm::dvec3 v, glm::dvec3 axis, double angle) {
    return v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle) + axis * glm::dot(axis, v) * (1 - std::cos(angle));
}

// A curve object's points, sampled as PlantGL's shapes sample it (`points(n)`; `points()`, at
// the curve's own stride, for n = 0): 2D or 3D; null for a value that is not a curve.
std::shared_ptr<GuideCurve> sampledCurve(PyObject* curve, int n = 200) {
    if (!curve || !PyObject_HasAttrString(curve, "points")) return nullptr;
    PyObject* pts = n > 0 ? PyObject_CallMethod(curve, "points", "i", n) : PyObject_CallMethod(curve, "points", nullptr);
    if (!pts) {
        PyErr_Clear();
        return nullptr;
    }
    auto c = std::make_shared<GuideCurve>();
    PyObject* seq = PySequence_Fast(pts, "points");
    Py_DECREF(pts);
    if (!seq) {
        PyErr_Clear();
        return nullptr;
    }
    bool ok = true;
    for (Py_ssize_t i = 0, n = PySequence_Fast_GET_SIZE(seq); i < n && ok; ++i) {
        std::vector<double> xyz;
        ok = numbers(PySequence_Fast_GET_ITEM(seq, i), xyz) && (xyz.size() == 2 || xyz.size() == 3) &&
             (i == 0 || (xyz.size() == 3) == c->is3D);
        if (!ok) break;
        c->is3D = xyz.size() == 3;
        c->points.emplace_back(xyz[0], xyz[1], c->is3D ? xyz[2] : 0.0);
    }
    Py_DECREF(seq);
    if (!ok || c->points.size() < 2) return nullptr;
    c->at.push_back(0);
    for (size_t i = 1; i < c->points.size(); ++i) c->at.push_back(c->at.back() + glm::length(c->points[i] - c->points[i - 1]));
    c->length = c->at.back();
    if (!(c->length > 0)) return nullptr;
    for (double& a : c->at) a /= c->length;
    return c;
}

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
    auto g = std::make_shared<Grammar>();
    g->settings.angle = {d.angle, 0};
    g->settings.step = {1, 0};
    g->settings.gradient = Toggle::Off;
    g->settings.palette = d.materials.empty() ? defaultMaterials() : d.materials;
    const int colours = int(g->settings.palette.size());
    Writer w(*g);
    struct State {
        double width = 0;
        int colour = 0;
        double tropism[3] = {0, 0, 1};  // L-Py's axes
        double elasticity = 0;
        std::optional<Guide> guide;  // a branch takes its own copy, as PlantGL's turtle does
        int section = -1;            // Settings::sections index (SetContour); -1: round
        bool inCurve = false;        // between @Gc and @Ge
    };
    std::vector<State> stack;
    State st;
    st.width = d.width;
    st.colour = std::clamp(d.colour, 0, colours - 1);
    auto bend = [&] {  // L-Py's x y z are Sprout's z x y
        if (st.elasticity > 0) w.put("@T", {st.elasticity, st.tropism[1], st.tropism[2], st.tropism[0], 1});
    };
    // PlantGL's Turtle::_applyGuide: before a move of `length`, the heading turns to the chord
    // to the point that far along the curve, and the move's length becomes the chord's (in
    // turtle units); after it (length 0), the heading turns to the curve's own direction there.
    // A guide is done once a move starts at its end. The turns are written as L-Py's turns.
    auto degrees = [](double radians) { return radians * 180 / M_PI; };
    auto turnTo = [&](Guide& g, glm::dvec3 direction) {
        if (!g.curve->is3D) {
            double deviation = std::atan2(g.lastHeading.x * direction.y - g.lastHeading.y * direction.x,
                                          g.lastHeading.x * direction.x + g.lastHeading.y * direction.y);
            if (g.ccw) deviation = -deviation;
            // About the left axis (PlantGL: by -deviation, L-Py's ^), or the up axis (its +).
            if (std::fabs(deviation) > 1e-12) w.put(g.yOrientation ? "+" : "^", {degrees(deviation)});
            g.lastHeading = direction;
            return;
        }
        // 3D: the direction in the curve's last frame is the new heading in the turtle's frame
        // (heading, left, up); the turtle turns to it about their common normal: a roll taking
        // the left axis to that normal, a turn about it (&), and the roll back. The curve's
        // frame turns alike.
        const glm::dvec3 local(glm::dot(direction, g.lastHeading), glm::dot(direction, g.lastLeft), glm::dot(direction, g.lastUp));
        const double sine = std::hypot(local.y, local.z), angle = std::atan2(sine, local.x);
        if (sine > 1e-12) {
            const double roll = std::atan2(local.y, -local.z);  // the normal (0, -up, left) from the left axis
            w.put("\\", {degrees(roll)});  // Sprout's \: about H by +roll (L-Py's /)
            w.put("&", {degrees(angle)});
            w.put("/", {degrees(roll)});
            const glm::dvec3 axis = glm::normalize(glm::cross(g.lastHeading, direction));
            g.lastLeft = glm::normalize(rotated(g.lastLeft, axis, angle));
            g.lastUp = glm::normalize(rotated(g.lastUp, axis, angle));
        }
        g.lastHeading = direction;
    };
    auto guideBefore = [&](double& length) {
        if (!st.guide || !(length > 0)) return;
        Guide& g = *st.guide;
        if (g.t >= 1.0) {
            st.guide.reset();
            return;
        }
        const double next = g.t + length / g.total, rest = next - 1.0;
        const glm::dvec3 at = g.curve->pointAt(std::min(next, 1.0));
        glm::dvec3 chord = at - g.lastPosition;
        if (rest > 1e-12) chord += g.curve->tangentAt(1.0) * (rest * g.curve->length);  // past its end: straight on
        const double n = glm::length(chord);
        if (!(n > 0)) return;
        length = n * g.scale;
        g.t = std::min(next, 1.0);
        g.lastPosition = at;
        turnTo(g, chord / n);
    };
    auto guideAfter = [&] {
        if (st.guide) turnTo(*st.guide, st.guide->curve->tangentAt(st.guide->t));
    };
    std::unordered_map<PyObject*, std::shared_ptr<const GuideCurve>> curves;  // sampled once a drawing
    std::unordered_map<PyObject*, int> sections;  // each section curve's Settings::sections index
    auto sectionOf = [&](PyObject* curve) {
        if (auto it = sections.find(curve); it != sections.end()) return it->second;
        int index = -1;
        auto c = sampledCurve(curve, 0);
        if (c && !c->is3D && g->settings.sections.size() < 10000) {
            std::vector<float> xy;
            for (const glm::dvec3& q : c->points) xy.push_back(float(q.x)), xy.push_back(float(q.y));
            g->settings.sections.push_back(std::move(xy));
            index = int(g->settings.sections.size()) - 1;
        }
        sections[curve] = index;
        return index;
    };
    // @g's shapes: each shape object made into triangles once (by the PlantGL module's
    // _sprout_triangles), a surface of the drawing named after it; "" for one with no surface.
    std::unordered_map<PyObject*, std::string> shapes;
    std::unordered_map<std::string, int> labelIndex;  // each text's Settings::labels index
    auto shapeSurface = [&](PyObject* shape) -> const std::string& {
        auto [it, fresh] = shapes.try_emplace(shape);
        if (!fresh || !shape) return it->second;
        PyObject* pgl = PyImport_ImportModule("openalea.plantgl.all");
        PyObject* r = pgl ? PyObject_CallMethod(pgl, "_sprout_triangles", "O", shape) : nullptr;
        Py_XDECREF(pgl);
        PyObject *points = nullptr, *triangles = nullptr, *segments = nullptr;
        auto sf = std::make_shared<SurfaceFile>();
        const Py_ssize_t parts = r && PyTuple_Check(r) ? PyTuple_GET_SIZE(r) : 0;  // (points, triangles[, segments])
        if ((parts == 2 || parts == 3) && (points = PySequence_Fast(PyTuple_GET_ITEM(r, 0), "points")) &&
            (triangles = PySequence_Fast(PyTuple_GET_ITEM(r, 1), "triangles")) &&
            (segments = PySequence_Fast(parts == 3 ? PyTuple_GET_ITEM(r, 2) : PyTuple_GET_ITEM(r, 1), "segments"))) {
            const Py_ssize_t np = PySequence_Fast_GET_SIZE(points), nt = PySequence_Fast_GET_SIZE(triangles),
                             ns = parts == 3 ? PySequence_Fast_GET_SIZE(segments) : 0;
            if (np == 0 && nt == 0 && ns == 0) it->second = "-";  // a shape with nothing to draw: no warning
            bool ok = np > 0 && np < 10'000'000 && nt < 10'000'000 && ns < 10'000'000;
            for (Py_ssize_t i = 0; i < np && ok; ++i) {
                std::vector<double> q;
                ok = numbers(PySequence_Fast_GET_ITEM(points, i), q) && q.size() == 3;
                // PlantGL's shape frame is the turtle's up, right (-left) and heading (PglTurtle::
                // transform: Oriented(up, -left)); the surface's is heading, left, up.
                if (ok) sf->positions.emplace_back(float(q[2]), -float(q[1]), float(q[0]));
            }
            for (Py_ssize_t i = 0; i < nt && ok; ++i) {
                std::vector<double> t;
                ok = numbers(PySequence_Fast_GET_ITEM(triangles, i), t) && t.size() == 3;
                for (double v : t) ok = ok && v >= 0 && v < double(np);
                if (ok)
                    for (double v : t) sf->indices.push_back(std::uint32_t(v));
            }
            for (Py_ssize_t i = 0; i < ns && ok; ++i) {
                std::vector<double> e;
                ok = numbers(PySequence_Fast_GET_ITEM(segments, i), e) && e.size() == 2 && e[0] >= 0 && e[0] < double(np) &&
                     e[1] >= 0 && e[1] < double(np);
                if (ok) sf->lines.push_back(sf->positions[size_t(e[0])]), sf->lines.push_back(sf->positions[size_t(e[1])]);
            }
            if (ok && sf->indices.empty()) sf->positions.clear();  // a curve: its stems only
            if (ok && (!sf->indices.empty() || !sf->lines.empty())) {  // normals: the faces' around each point, by area
                sf->normals.assign(sf->positions.size(), glm::vec3(0));
                for (size_t i = 0; i + 2 < sf->indices.size(); i += 3) {
                    const glm::vec3 &a = sf->positions[sf->indices[i]], &b = sf->positions[sf->indices[i + 1]],
                                    &c = sf->positions[sf->indices[i + 2]];
                    const glm::vec3 n = glm::cross(b - a, c - a);
                    for (int j = 0; j < 3; ++j) sf->normals[sf->indices[i + size_t(j)]] += n;
                }
                for (glm::vec3& n : sf->normals) n = glm::length(n) > 0 ? glm::normalize(n) : glm::vec3(0, 0, 1);
                it->second = "@g#" + std::to_string(g->surfaceFiles.size());
                g->surfaceFiles[it->second] = std::move(sf);
            }
        }
        Py_XDECREF(points);
        Py_XDECREF(triangles);
        Py_XDECREF(segments);
        Py_XDECREF(r);
        if (PyErr_Occurred()) PyErr_Clear();
        return it->second;
    };
    // The palette entry of a colour, added when it is new (up to 250 entries; else the nearest).
    auto paletteIndex = [&](std::uint32_t rgba) {
        auto& pal = g->settings.palette;
        auto found = std::find(pal.begin(), pal.end(), rgba);
        if (found != pal.end()) return int(found - pal.begin());
        if (pal.size() < 250) {
            pal.push_back(rgba);
            return int(pal.size()) - 1;
        }
        int best = 0;
        long bestD = -1;
        for (size_t i = 0; i < pal.size(); ++i) {
            long d = 0;
            for (int shift = 8; shift <= 24; shift += 8) d += std::labs(long((pal[i] >> shift) & 0xFF) - long((rgba >> shift) & 0xFF));
            if (bestD < 0 || d < bestD) bestD = d, best = int(i);
        }
        return best;
    };
    auto setGuide = [&](PyObject* curve, double total, bool yOrientation, bool ccw) {
        std::shared_ptr<const GuideCurve>& c = curves[curve];
        if (!c) c = sampledCurve(curve);
        if (!c) return false;
        Guide g;
        g.curve = c;
        g.total = total > 0 ? total : c->length;
        g.scale = g.total / c->length;
        g.yOrientation = yOrientation;
        g.ccw = ccw;
        g.lastPosition = c->points.front();
        if (c->is3D) g.lastHeading = {0, 0, 1};
        else g.lastHeading = yOrientation ? glm::dvec3(0, ccw ? -1 : 1, 0) : glm::dvec3(ccw ? -1 : 1, 0, 0);
        st.guide = g;
        return true;
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
    auto setWidth = [&](double width) {
        if (!(width >= 0)) return;
        st.width = width;
        w.put("!", {2 * width});
    };
    // F(length[, top]): a frustum to the top radius. In a generalized cylinder the width is
    // set first (the point it adds takes it); with a cross-section outside one, the step is a
    // swept piece of its own (PlantGL's _sweep).
    auto forward = [&](double length, double top) {
        const bool piece = st.section >= 0 && !st.inCurve;
        guideBefore(length);
        bend();
        if (piece) w.put("@Gs", {});
        if ((piece || st.inCurve) && top >= 0) setWidth(top);
        w.put("F", {length});
        if (piece) w.put("@Ge", {});
        if (!piece && !st.inCurve && top >= 0) setWidth(top);
        guideAfter();
    };
    // nF(length, dl[, radius[, radiusFunction]]) as PlantGL's turtle draws it: F(dl) repeated,
    // then the rest; the radius ramps to `radius`, or is radius times the function, read from
    // its first x to its last. A run with a cross-section is one swept surface.
    auto stepForward = [&](double length, double dl, double radius, PyObject* function) {
        if (!(dl > 0) || !(length >= 0)) return;
        const double steps = std::min(std::floor(length / dl), 100000.0), rest = length - steps * dl;
        const bool swept = st.section >= 0 && !st.inCurve;
        auto begin = [&] {  // the swept surface starts at the first width
            if (swept) st.inCurve = true, w.put("@Gs", {});
        };
        double fx = 0, lx = 1;
        auto valueAt = [&](double x) {
            PyObject* r = PyObject_CallFunction(function, "d", x);
            const double v = r ? PyFloat_AsDouble(r) : 1.0;
            Py_XDECREF(r);
            if (PyErr_Occurred()) PyErr_Clear(), leftOut.insert("a radius function that gives no number");
            return std::isfinite(v) ? v : 1.0;
        };
        if (function && function != Py_None) {
            for (auto [attr, out] : {std::pair{"firstx", &fx}, std::pair{"lastx", &lx}}) {
                PyObject* v = PyObject_GetAttrString(function, attr);
                if (v && PyCallable_Check(v)) Py_SETREF(v, PyObject_CallNoArgs(v));
                if (v) *out = PyFloat_AsDouble(v);
                Py_XDECREF(v);
                if (PyErr_Occurred()) PyErr_Clear();
            }
            const double du = (dl / std::max(length, 1e-12)) * (lx - fx);
            double u = fx;
            setWidth(valueAt(u) * radius);
            begin();
            for (double i = 0; i < steps; ++i) u += du, forward(dl, valueAt(u) * radius);
            if (rest > 1e-9) forward(rest, radius * valueAt(lx));
        } else if (radius >= 0) {
            begin();
            const double dw = (radius - st.width) / std::max(length, 1e-12);
            double cw = st.width;
            for (double i = 0; i < steps; ++i) cw += dw * dl, forward(dl, cw);
            if (rest > 1e-9) forward(rest, radius);
        } else {
            begin();
            for (double i = 0; i < steps; ++i) forward(dl, -1);
            if (rest > 1e-9) forward(rest, -1);
        }
        if (swept) st.inCurve = false, w.put("@Ge", {});
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
        auto setColour = [&](int index) {
            if (index < 0 || index >= colours) return;  // L-Py ignores an index past its materials
            st.colour = index;
            w.put(";", {double(index)});
        };
        switch (mp.op) {
            case Op::Forward:
                forward(p.empty() ? 1.0 : p[0], p.size() >= 2 ? p[1] : -1);  // L-Py's default step is 1
                break;
            case Op::Move: {  // f(length = 1), along a guide when one is set
                double length = p.empty() ? 1.0 : p[0];
                guideBefore(length);
                bend();
                w.put(mp.sprout, {length});
                guideAfter();
                break;
            }
            case Op::StepForward:  // nF(length, dl[, radius[, radiusFunction]])
                if (p.size() >= 2) stepForward(p[0], p[1], n >= 3 ? number(k, 2, -1) : -1, s.object(k, 3));
                break;
            case Op::SetGuide: {  // SetGuide(curve, length[, yOrientation[, ccw]]); none: cleared
                PyObject* curve = s.object(k, 0);
                if (!curve) st.guide.reset();
                else if (!setGuide(curve, number(k, 1, 0), number(k, 2, 0) != 0, number(k, 3, 0) != 0))
                    leftOut.insert(name + " with a value that is not a curve");
                break;
            }
            case Op::SetContour: {  // SetContour(curve); none: round again
                PyObject* curve = s.object(k, 0);
                st.section = curve ? sectionOf(curve) : -1;
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
                if (!setGuide(path, length, false, false)) leftOut.insert(name + " with a path that is not a curve");
                st.section = sectionOf(section);
                if (st.section < 0) leftOut.insert(name + " with a section that is not a 2D curve");
                w.put("SetContour", {double(st.section)});
                stepForward(length, dl, number(k, 4, 1.0), s.object(k, 5));
                break;
            }
            case Op::EndGuide: st.guide.reset(); break;
            case Op::PositionOnGuide:  // PositionOnGuide(t): t turtle units along it
                if (st.guide && !p.empty()) {
                    Guide& g = *st.guide;
                    g.t = std::clamp(p[0] / g.total, 0.0, 1.0);
                    g.lastPosition = g.curve->pointAt(g.t);
                    g.lastHeading = g.curve->tangentAt(g.t);
                    if (g.curve->is3D) {  // PlantGL: the curve's normal as up (here: the frame kept upright)
                        const glm::dvec3 left = glm::cross(g.lastUp, g.lastHeading);
                        if (glm::length(left) > 1e-9) {
                            g.lastLeft = glm::normalize(left);
                            g.lastUp = glm::normalize(glm::cross(g.lastHeading, g.lastLeft));
                        }
                    }
                }
                break;
            case Op::Turn:
                if (p.empty()) w.put(mp.sprout, {});
                else w.put(mp.sprout, {p[0]});
                // An intrinsic roll turns a 3D guide's frame with the turtle's (PlantGL's iRollL).
                if (st.guide && st.guide->curve->is3D && (name == "iRollL" || name == "iRollR")) {
                    Guide& g = *st.guide;
                    const double a = (p.empty() ? d.angle : p[0]) * M_PI / 180 * (name == "iRollL" ? 1 : -1);
                    g.lastUp = rotated(g.lastUp, g.lastHeading, a);
                    g.lastLeft = rotated(g.lastLeft, g.lastHeading, a);
                }
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
            case Op::Label: {  // @L(text[, size])
                PyObject* text = s.object(k, 0);
                PyObject* str = text ? PyObject_Str(text) : nullptr;
                Py_ssize_t length = 0;
                const char* utf8 = str ? PyUnicode_AsUTF8AndSize(str, &length) : nullptr;
                if (utf8 && length > 0) {
                    auto& labels = g->settings.labels;
                    // At most 200 bytes, cut where a character begins (the text stays UTF-8:
                    // exported models carry it).
                    size_t n = size_t(std::min<Py_ssize_t>(length, 200));
                    while (n < size_t(length) && n > 0 && (std::uint8_t(utf8[n]) & 0xC0) == 0x80) --n;
                    std::string t(utf8, n);
                    auto found = labelIndex.find(t);
                    if (found == labelIndex.end() && labels.size() < 100000) {
                        found = labelIndex.emplace(t, int(labels.size())).first;
                        labels.push_back(t);
                    }
                    if (found != labelIndex.end()) w.put("Label", {double(found->second), number(k, 1, 13)});
                }
                Py_XDECREF(str);
                if (PyErr_Occurred()) PyErr_Clear();
                break;
            }
            case Op::Shape: {  // @g(shape[, scale])
                const std::string& surface = shapeSurface(s.object(k, 0));
                if (surface.empty()) leftOut.insert(name + " with text or what is not a PlantGL shape");
                else if (surface != "-") w.put(surface.c_str(), {number(k, 1, 1.0)});
                break;
            }
            case Op::Point:  // L-Py's x y z are Sprout's z x y
                if (p.size() >= 3) w.put(mp.sprout, {p[1], p[2], p[0]});
                break;
            case Op::Frame: {  // Frame(size = 1, capHeightRatio = 0.2, capRadiusRatio = 2): PlantGL's _frame
                const double size = p.size() >= 1 ? p[0] : 1.0, capHeight = p.size() >= 2 ? std::clamp(p[1], 0.0, 1.0) : 0.2,
                             capRadius = p.size() >= 3 ? std::max(p[2], 0.0) : 2.0;
                if (!(size > 0)) break;
                const std::pair<const char*, std::uint32_t> arrows[] = {
                    {nullptr, 0xFA3232FFu}, {"^", 0x3232FAFFu}, {"+", 0x32FA32FFu}};  // heading, up, left
                for (const auto& [turn, rgba] : arrows) {
                    w.put("[", {});
                    if (turn) w.put(turn, {90});
                    w.put(";", {double(paletteIndex(rgba))});
                    w.put("!", {2 * st.width});
                    if (capHeight < 1) w.put("F", {size * (1 - capHeight)});
                    w.put("f", {0});  // the stick keeps its width: the cap's starts anew
                    w.put("!", {2 * st.width * capRadius});
                    if (capHeight > 0) w.put("F", {size * capHeight});
                    w.put("!", {0});  // a cone
                    w.put("]", {});
                }
                break;
            }
            case Op::InterpolateColours: {  // InterpolateColors(i, j, alpha): PlantGL mixes the two materials
                if (p.size() < 2) break;
                const auto& pal = g->settings.palette;
                auto at = [&](double x) { return pal[size_t(std::clamp(int(std::lround(std::clamp(x, -1e6, 1e6))), 0, int(pal.size()) - 1))]; };
                const std::uint32_t a = at(p[0]), b = at(p[1]);
                const double f = p.size() >= 3 ? std::clamp(p[2], 0.0, 1.0) : 0.5;
                std::uint32_t mixed = 0;
                for (int shift = 24; shift >= 0; shift -= 8)
                    mixed |= std::uint32_t(std::lround(double((a >> shift) & 0xFF) * (1 - f) + double((b >> shift) & 0xFF) * f)) << shift;
                w.put(";", {double(paletteIndex(mixed))});
                break;
            }
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
