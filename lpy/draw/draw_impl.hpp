#pragma once
// Internals of L-Py's drawing (lpy/draw/draw.hpp), shared by draw.cpp (the walk over the string:
// each module's mapping and what it writes), guides.cpp (F, f and nF along guides, with
// cross-sections) and shapes.cpp (@g's shapes, labels, frames and the palette). What the
// walk does for every module (F, the width, the writer) is inline here, so that the walk's
// loop keeps it inlined; what is rare is in the other two files.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "lpy/draw/draw.hpp"
#include "lpy/plantgl/py_numbers.hpp"

namespace sprout::lpy::detail {

// A parameter as numbers: a number, or a vector/sequence of numbers (Vector3, tuple).
using pynum::numbers;

class Writer {
public:
    Writer(Grammar& g) : m_g(g) {}
    void put(const char* name, std::initializer_list<double> params) { put(name, params.begin(), params.size()); }
    void put(const char* name, const std::vector<double>& params) { put(name, params.data(), params.size()); }
    void put(const char* name, const double* params, size_t count) {
        const int arity = int(std::min<size_t>(count, size_t(Alphabet::kMaxArity)));
        // Names are the mapping's literals: each (name, arity) is interned once.
        std::optional<SymbolId>& id = m_ids[{name, arity}];
        if (!id) id = m_g.alphabet.intern(name, arity);
        if (!id) return;
        m_g.axiom.symbols.push_back(*id);
        for (int k = 0; k < arity; ++k) {
            const double v = params[k];
            m_g.axiom.params.push_back(std::isfinite(v) ? v : 0.0);
        }
    }

private:
    Grammar& m_g;
    std::map<std::pair<const char*, int>, std::optional<SymbolId>> m_ids;
};

// A curve that F and f follow (SetGuide), 2D or 3D: sampled once, by the fraction of its
// length (2D curves have z = 0).
struct GuideCurve {
    std::vector<glm::dvec3> points;
    std::vector<double> at;  // the fraction of the curve's length at each point
    double length = 0;
    bool is3D = false;
    // A guide's curve as PlantGL follows it (Turtle2DPath): its point at the parameter its
    // arc-length mapping gives for t, and its tangent there; unset for a curve without them
    // (then the polyline through its points).
    std::function<glm::dvec3(double)> exactPoint, exactTangent;
    glm::dvec3 pointAt(double t) const {
        if (exactPoint) return exactPoint(t);
        const size_t i = segment(t);
        const double span = at[i + 1] - at[i], f = span > 0 ? (t - at[i]) / span : 0;
        return points[i] + (points[i + 1] - points[i]) * std::clamp(f, 0.0, 1.0);
    }
    glm::dvec3 tangentAt(double t) const {
        if (exactTangent) return exactTangent(t);
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

// A curve object's points, sampled as PlantGL's shapes sample it (`points(n)`; `points()`, at
// the curve's own stride, for n = 0): 2D or 3D; null for a value that is not a curve.
std::shared_ptr<GuideCurve> sampledCurve(PyObject* curve, int n = 200);

// What L-Py's turtle keeps that Sprout's does not; a branch ([) keeps a copy.
struct TurtleState {
    double width = 0;
    int colour = 0;
    double tropism[3] = {0, 0, 1};  // L-Py's axes
    double elasticity = 0;
    std::optional<Guide> guide;  // a branch takes its own copy, as PlantGL's turtle does
    int section = -1;            // Settings::sections index (SetContour); -1: round
    bool inCurve = false;        // between @Gc and @Ge
};

// A drawing under way: the grammar it writes (settings, surfaces, the axiom through `w`), the
// turtle's state and its stack, and what it left out (one line per kind, for the warnings).
class Drawing {
public:
    explicit Drawing(const TurtleDefaults& d);  // draw.cpp

    std::shared_ptr<Grammar> g;
    Writer w;
    int colours = 0;  // the materials an index may name (SetColor, ;)
    std::string folder;  // the model's: where a Shape's image named relative to it is
    TurtleState st;
    std::vector<TurtleState> stack;
    std::set<std::string> leftOut;
    // A query walk's (drawable(..., queries = true)): its string is walked by PlantGL's turtle
    // (frames.cpp), whose LineTo bends by the tropism as its F does; Sprout's turtle does not.
    bool queryWalk = false;

    void bend() {  // L-Py's x y z are Sprout's z x y
        if (st.elasticity > 0) w.put("@T", {st.elasticity, st.tropism[1], st.tropism[2], st.tropism[0], 1});
    }
    // PlantGL's Turtle::_applyGuide: before a move of `length`, the heading turns to the chord
    // to the point that far along the curve, and the move's length becomes the chord's (in
    // turtle units); after it (length 0), the heading turns to the curve's own direction there.
    // A guide is done once a move starts at its end. The turns are written as L-Py's turns.
    void guideBefore(double& length) {
        if (!st.guide || !(length > 0)) return;
        alongGuide(length);
    }
    void guideAfter() {
        if (st.guide) turnTo(*st.guide, st.guide->curve->tangentAt(st.guide->t));
    }
    void setWidth(double width) {
        if (!(width >= 0)) return;
        st.width = width;
        w.put("!", {2 * width});
    }
    void setColour(int index) {
        if (index < 0 || index >= colours) return;  // L-Py ignores an index past its materials
        st.colour = index;
        w.put(";", {double(index)});
    }
    // F(length[, top]): a frustum to the top radius. In a generalized cylinder the width is
    // set first (the point it adds takes it); with a cross-section outside one, the step is a
    // swept piece of its own (PlantGL's _sweep).
    void forward(double length, double top) {
        const bool piece = st.section >= 0 && !st.inCurve;
        guideBefore(length);
        bend();
        if (piece) w.put("@Gs", {});
        if ((piece || st.inCurve) && top >= 0) setWidth(top);
        w.put("F", {length});
        if (piece) w.put("@Ge", {});
        if (!piece && !st.inCurve && top >= 0) setWidth(top);
        guideAfter();
    }

    // guides.cpp
    // The move of guideBefore, on a guide.
    void alongGuide(double& length);
    void turnTo(Guide& guide, glm::dvec3 direction);
    // SetGuide(curve, total[, yOrientation[, ccw]]); false for a value that is not a curve.
    bool setGuide(PyObject* curve, double total, bool yOrientation, bool ccw);
    void positionOnGuide(double at);  // PositionOnGuide(at): `at` turtle units along it
    void rollGuide(double radians);   // an intrinsic roll turns a 3D guide's frame too
    // A section curve's Settings::sections index (added once); -1 for one that is not 2D.
    int sectionOf(PyObject* curve);
    // nF(length, dl[, radius[, radiusFunction]]).
    void stepForward(double length, double dl, double radius, PyObject* function);

    // shapes.cpp
    // @g's shape: the name of the surface it was made into (once); "" for one with no
    // surface, "-" for one with nothing to draw.
    const std::string& shapeSurface(PyObject* shape);
    // @L's text: its Settings::labels index (added once); -1 for none.
    int labelIndex(PyObject* text);
    // The palette entry of a colour, added when it is new (up to 250 entries; else the nearest).
    int paletteIndex(std::uint32_t rgba);
    void frame(const std::vector<double>& p);                 // Frame(size, capHeightRatio, capRadiusRatio)
    void interpolateColours(const std::vector<double>& p);    // InterpolateColors(i, j, alpha)
    void setRgbaColour(const std::vector<double>& p);         // SetColor(r, g, b[, a])
    // TextureBaseColor(index | r, g, b[, a]) or InterpolateTextureBaseColors(i, j, alpha): the
    // texture material the turtle has drawn times that colour from now on (a palette entry of
    // its own with the same image); nothing for a plain material, as PlantGL.
    void textureBaseColour(const std::vector<double>& p, bool interpolate);

private:
    std::unordered_map<PyObject*, std::shared_ptr<const GuideCurve>> m_curves;  // sampled once a drawing
    std::unordered_map<PyObject*, std::shared_ptr<const GuideCurve>> m_guides;  // the same, followed as PlantGL follows a guide
    std::unordered_map<PyObject*, int> m_sections;  // each section curve's Settings::sections index
    std::unordered_map<PyObject*, std::string> m_shapes;  // each @g shape's surface
    std::unordered_map<std::string, int> m_labelIndex;    // each text's Settings::labels index
};

// The frame of L-Py's turtle at a query module, in L-Py's axes and in double precision.
struct PglFrame {
    glm::dvec3 position, heading, up, left;
};
// frames.cpp: the frame at each query module (`?P`) of a query walk's drawable grammar
// (drawable(..., queries = true)), as PlantGL's turtle computes it, in double precision.
std::vector<PglFrame> queryFrames(const Grammar& g);

}  // namespace sprout::lpy::detail
