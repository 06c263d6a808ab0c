// L-Py's moves along curves, drawn by Sprout's turtle: guides that F and f follow (SetGuide,
// PlantGL's Turtle2DPath and Turtle3DPath), the cross-sections that tubes are swept with
// (SetContour) and nF's runs of steps. Its own file: a model with no guide or section never
// comes here (lpy/draw/draw_impl.hpp keeps the test that says so inline in the walk).
#include "lpy/draw/draw_impl.hpp"
#include "lpy/plantgl/bindings.hpp"

namespace sprout::lpy::detail {
namespace {

// The rotation by `angle` about unit `axis` (Rodrigues).
glm::dvec3 rotated(glm::dvec3 v, glm::dvec3 axis, double angle) {
    return v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle) + axis * glm::dot(axis, v) * (1 - std::cos(angle));
}

double degrees(double radians) { return radians * 180 / M_PI; }

}  // namespace

std::shared_ptr<GuideCurve> sampledCurve(PyObject* curve, int n) {
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

void Drawing::turnTo(Guide& g, glm::dvec3 direction) {
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
}

void Drawing::alongGuide(double& length) {
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
}

namespace {
// PlantGL's guide on a curve that has them (NURBS, Bezier): its length (getLength, stride
// steps), and each position the point at the parameter its arc-length mapping (a
// QuantisedFunction) gives, so that a turtle follows the curve as PlantGL's does.
std::shared_ptr<GuideCurve> nativeGuide(const std::shared_ptr<const curves::Nurbs>& nurbs, int stride,
                                        const std::shared_ptr<GuideCurve>& sampled);

std::shared_ptr<GuideCurve> exactGuide(PyObject* curve, std::shared_ptr<GuideCurve> sampled) {
    int stride = 0;
    if (auto nurbs = nativeNurbs(curve, stride)) return nativeGuide(nurbs, stride, sampled);
    py::handle h(curve);
    if (!py::hasattr(h, "getArcLengthToUMapping") || !py::hasattr(h, "getLength") || !py::hasattr(h, "getTangentAt")) return sampled;
    try {
        py::object c = py::reinterpret_borrow<py::object>(h);
        py::object mapping = c.attr("getArcLengthToUMapping")();
        const double length = c.attr("getLength")().cast<double>();
        if (!(length > 0)) return sampled;
        auto g = std::make_shared<GuideCurve>(*sampled);
        g->length = length;
        auto vec = [is3D = g->is3D](py::handle v) {
            std::vector<double> xyz;
            if (!numbers(v.ptr(), xyz) || xyz.size() < 2) throw py::value_error("a guide's point is not a vector");
            return glm::dvec3(xyz[0], xyz[1], is3D && xyz.size() > 2 ? xyz[2] : 0.0);
        };
        // Each evaluation is a Python call: the same t (a guide's steps repeat along every
        // tube that follows it) is evaluated once a drawing.
        auto points = std::make_shared<std::unordered_map<double, glm::dvec3>>();
        auto tangents = std::make_shared<std::unordered_map<double, glm::dvec3>>();
        g->exactPoint = [c, mapping, vec, points](double t) {
            if (auto it = points->find(t); it != points->end()) return it->second;
            const glm::dvec3 p = vec(c.attr("getPointAt")(mapping(t)));
            return (*points)[t] = p;
        };
        g->exactTangent = [c, mapping, vec, tangents](double t) {
            if (auto it = tangents->find(t); it != tangents->end()) return it->second;
            const glm::dvec3 d = vec(c.attr("getTangentAt")(mapping(t)));
            const double n = glm::length(d);
            return (*tangents)[t] = n > 0 ? d / n : d;
        };
        return g;
    } catch (py::error_already_set&) {
        PyErr_Clear();
        return sampled;
    }
}
// The same guide on one of Sprout's NURBS curves, evaluated in C++ (lpy/plantgl/bindings.hpp) as
// its Python methods would evaluate it: no Python call a step.
std::shared_ptr<GuideCurve> nativeGuide(const std::shared_ptr<const curves::Nurbs>& nurbs, int stride,
                                        const std::shared_ptr<GuideCurve>& sampled) {
    const double fk = nurbs->firstKnot(), lk = nurbs->lastKnot();
    if (stride == 0 || !((lk - fk) / stride != 0)) return sampled;  // the Python's ZeroDivisionError
    auto mapping = std::make_shared<const curves::Quantised>(curves::quantise(curves::Polyline2D(nurbs->arcLengthToU(stride)), 5 * stride));
    const double length = nurbs->length(fk, lk, stride);
    if (!(length > 0)) return sampled;
    auto g = std::make_shared<GuideCurve>(*sampled);
    g->length = length;
    const bool is3D = g->is3D;
    auto vec = [is3D](const curves::Point& p) { return glm::dvec3(p[0], p[1], is3D ? p[2] : 0.0); };
    g->exactPoint = [nurbs, mapping, vec](double t) { return vec(nurbs->pointAt((*mapping)(t))); };
    g->exactTangent = [nurbs, mapping, vec](double t) {
        const glm::dvec3 d = vec(nurbs->derivativeAt((*mapping)(t), 1));
        const double n = glm::length(d);
        return n > 0 ? d / n : d;
    };
    return g;
}
}  // namespace

bool Drawing::setGuide(PyObject* curve, double total, bool yOrientation, bool ccw) {
    std::shared_ptr<const GuideCurve>& c = m_guides[curve];
    if (!c) {
        auto sampled = sampledCurve(curve);
        if (sampled) c = exactGuide(curve, sampled);
    }
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
}

void Drawing::positionOnGuide(double at) {
    Guide& g = *st.guide;
    g.t = std::clamp(at / g.total, 0.0, 1.0);
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

void Drawing::rollGuide(double radians) {
    Guide& g = *st.guide;
    g.lastUp = rotated(g.lastUp, g.lastHeading, radians);
    g.lastLeft = rotated(g.lastLeft, g.lastHeading, radians);
}

int Drawing::sectionOf(PyObject* curve) {
    if (auto it = m_sections.find(curve); it != m_sections.end()) return it->second;
    int index = -1;
    auto c = sampledCurve(curve, 0);
    if (c && !c->is3D && g->settings.sections.size() < 10000) {
        std::vector<float> xy;
        for (const glm::dvec3& q : c->points) xy.push_back(float(q.x)), xy.push_back(float(q.y));
        g->settings.sections.push_back(std::move(xy));
        index = int(g->settings.sections.size()) - 1;
    }
    m_sections[curve] = index;
    return index;
}

// As PlantGL's turtle draws it: F(dl) repeated, then the rest (when over its GEOM_EPSILON,
// 1e-5); the radius ramps to `radius`, or is radius times the function, read from its first x
// to its last. A run with a cross-section is one swept surface.
void Drawing::stepForward(double length, double dl, double radius, PyObject* function) {
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
        if (rest > 1e-5) forward(rest, radius * valueAt(lx));
    } else if (radius >= 0) {
        begin();
        const double dw = (radius - st.width) / std::max(length, 1e-12);
        double cw = st.width;
        for (double i = 0; i < steps; ++i) cw += dw * dl, forward(dl, cw);
        if (rest > 1e-5) forward(rest, radius);
    } else {
        begin();
        for (double i = 0; i < steps; ++i) forward(dl, -1);
        if (rest > 1e-5) forward(rest, -1);
    }
    if (swept) st.inCurve = false, w.put("@Ge", {});
}

}  // namespace sprout::lpy::detail
