// The PlantGL shapes a model gives to @g (a Scene, Groups, Shapes, transformed Boxes, Spheres,
// tubes, discs, meshes, point sets, polylines) made into points, triangles and segments in
// C++, as lpy/plantgl/plantgl_drawing.py's _sprout_triangles makes them in Python: the same
// numbers in the same order (its operations written out one by one), so that the drawing is
// the same. What this does not know (a patch, a crown inside a group, a subclass, a value
// Python would read its own way or err on) is left to the Python, whole: ShapeMesh::Unknown.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "lpy/plantgl/bindings.hpp"
#include "lpy/plantgl/py_numbers.hpp"

namespace sprout::lpy {
namespace {

struct Unknown {};  // thrown: the Python draws this object

// A new reference, or Unknown (a Python error is cleared).
PyObject* own(PyObject* o) {
    if (!o) {
        PyErr_Clear();
        throw Unknown{};
    }
    return o;
}

struct Ref {  // a new reference, released at the end of the scope
    PyObject* p;
    explicit Ref(PyObject* o) : p(own(o)) {}
    Ref(const Ref&) = delete;
    Ref& operator=(const Ref&) = delete;
    ~Ref() { Py_XDECREF(p); }
};

// getattr(obj, field, default): null for the default (AttributeError only).
PyObject* attribute(PyObject* obj, const char* field) {
    PyObject* v = PyObject_GetAttrString(obj, field);
    if (v) return v;
    if (!PyErr_ExceptionMatches(PyExc_AttributeError)) {
        PyErr_Clear();
        throw Unknown{};
    }
    PyErr_Clear();
    return nullptr;
}

// float(v), or `fallback` where float() raises TypeError or ValueError (plantgl_drawing's num).
double num(PyObject* v, double fallback) {
    double d;
    if (pynum::floatOr(v, fallback, d)) return d;
    PyErr_Clear();
    throw Unknown{};
}

// float(v) (Vector3's constructor): raises where float() does.
double exact(PyObject* v) {
    double d;
    if (pynum::floatOf(v, d)) return d;
    PyErr_Clear();
    throw Unknown{};
}

// num(get(field, fallback), fallback)
double field(PyObject* obj, const char* name, double fallback) {
    PyObject* v = attribute(obj, name);
    const double d = num(v, fallback);
    Py_XDECREF(v);
    return d;
}

// tuple(v), its first `n` items (new references) in `out`; at least `n` or Unknown.
std::vector<PyObject*> items(PyObject* v, size_t n) {
    Ref t(PySequence_Tuple(v));
    if (size_t(PyTuple_GET_SIZE(t.p)) < n) throw Unknown{};
    std::vector<PyObject*> out;
    for (size_t k = 0; k < n; ++k) out.push_back(PyTuple_GET_ITEM(t.p, k));  // borrowed: t lives on below
    for (PyObject* o : out) Py_INCREF(o);
    return out;
}

// A triple of `v` (a sequence of at least 3), each by `read`.
template <class Read>
std::array<double, 3> triple(PyObject* v, Read read) {
    std::vector<PyObject*> xs = items(v, 3);
    std::array<double, 3> out{};
    try {
        for (size_t k = 0; k < 3; ++k) out[k] = read(xs[k]);
    } catch (...) {
        for (PyObject* o : xs) Py_DECREF(o);
        throw;
    }
    for (PyObject* o : xs) Py_DECREF(o);
    return out;
}

using V3 = std::array<double, 3>;

// A Box's size or a Scaled's scale: (num(v),) * 3 for a number, else num of its first three.
V3 sizes(PyObject* v, double fallback) {
    if (!PyObject_HasAttrString(v, "__len__")) {
        const double k = num(v, fallback);
        return {k, k, k};
    }
    return triple(v, [fallback](PyObject* x) { return num(x, fallback); });
}

// Vector3(v).normed(): divided by its norm where that is above 0.
V3 normed(V3 v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n > 0) return {v[0] / n, v[1] / n, v[2] / n};
    return v;
}

using M3 = std::array<V3, 3>;  // rows

// Matrix3.axisRotation(axis, angle), as plantgl_vectors.py computes it.
M3 axisRotation(const V3& axis, double angle) {
    const V3 u = normed(axis);
    const double x = u[0], y = u[1], z = u[2];
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - std::cos(angle);
    return {V3{t * x * x + c, t * x * y - s * z, t * x * z + s * y}, V3{t * x * y + s * z, t * y * y + c, t * y * z - s * x},
            V3{t * x * z - s * y, t * y * z + s * x, t * z * z + c}};
}

// Matrix3 * Matrix3 and Matrix3 * vector: each entry sum() of its products, from 0.
M3 times(const M3& a, const M3& b) {
    M3 out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[i][j] = 0.0 + a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return out;
}
V3 times(const M3& m, const V3& p) {
    V3 out{};
    for (int i = 0; i < 3; ++i) out[i] = 0.0 + m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2];
    return out;
}

struct Mesher {
    ShapeMesh of(PyObject* obj, int depth);

    // Points (r cos, r sin, z) around the z axis, n of them (plantgl_drawing's ring).
    static void ring(ShapeMesh& m, double r, double z, long n) {
        for (long i = 0; i < n; ++i) {
            const double a = 2 * M_PI * double(i) / double(n);
            m.points.push_back({r * std::cos(a), r * std::sin(a), z});
        }
    }
    // Rings of (radius, z) swept about z, and caps at the profile's entries `caps` (-1: the last).
    static ShapeMesh tube(const std::vector<std::array<double, 2>>& profile, long n, std::initializer_list<int> caps) {
        ShapeMesh m;
        m.kind = ShapeMesh::Mesh;
        for (size_t j = 0; j < profile.size(); ++j) {
            ring(m, profile[j][0], profile[j][1], n);
            if (j) {
                const long a = long(j - 1) * n, b = long(j) * n;
                for (long i = 0; i < n; ++i) {
                    m.triangles.push_back({a + i, a + (i + 1) % n, b + (i + 1) % n});
                    m.triangles.push_back({a + i, b + (i + 1) % n, b + i});
                }
            }
        }
        for (int j : caps) {
            const auto& [r, z] = profile[j >= 0 ? size_t(j) : profile.size() - 1];
            if (r > 0) {
                const long c = long(m.points.size());
                m.points.push_back({0.0, 0.0, z});
                const long first = j >= 0 ? j * n : long(profile.size() - 1) * n;
                for (long i = 0; i < n; ++i) m.triangles.push_back({c, first + (i + 1) % n, first + i});
            }
        }
        return m;
    }
    // int(num(get(name, fallback), fallback)) clamped to [low, high]; Unknown where int() raises.
    static long count(PyObject* obj, const char* name, double fallback, long low, long high) {
        const double v = field(obj, name, fallback);
        if (!std::isfinite(v)) throw Unknown{};
        return long(std::max(double(low), std::min(double(high), std::trunc(v))));
    }
};

// add(mesh, transform) of _sprout_triangles: its points (transformed), triangles and segments
// after the points so far.
template <class Transform>
void add(ShapeMesh& to, const ShapeMesh& mesh, Transform f) {
    if (mesh.kind != ShapeMesh::Mesh) return;
    const long base = long(to.points.size());
    for (const V3& p : mesh.points) to.points.push_back(f(p));
    for (const auto& t : mesh.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    for (const auto& s : mesh.segments) to.segments.push_back({s[0] + base, s[1] + base});
}
void add(ShapeMesh& to, const ShapeMesh& mesh) {
    add(to, mesh, [](const V3& p) { return p; });
}

// result(): the mesh, or None where it has neither triangles nor segments.
ShapeMesh result(ShapeMesh m) {
    m.kind = m.triangles.empty() && m.segments.empty() ? ShapeMesh::Nothing : ShapeMesh::Mesh;
    return m;
}

ShapeMesh Mesher::of(PyObject* obj, int depth) {
    ShapeMesh m;
    if (depth > 32) return m;  // None
    const std::string_view name(Py_TYPE(obj)->tp_name);
    if (PyList_Check(obj) || PyTuple_Check(obj) || name == "Scene" || name == "Group") {
        PyObject* list = name == "Group" ? attribute(obj, "geometryList") : nullptr;
        const Ref source(list ? list : (Py_INCREF(obj), obj));
        Ref seq(PySequence_Fast(source.p, "shapes"));
        for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) add(m, of(PySequence_Fast_GET_ITEM(seq.p, k), depth + 1));
        m = result(std::move(m));
        if (m.kind == ShapeMesh::Nothing) m = ShapeMesh{ShapeMesh::Mesh, {}, {}, {}};  // an empty group: a shape with nothing to draw
        return m;
    }
    if (name == "Shape") {
        PyObject* g = attribute(obj, "geometry");
        const Ref keep(g ? g : (Py_INCREF(Py_None), Py_None));
        return of(keep.p, depth + 1);
    }
    if (name == "Polyline") {
        PyObject* list = attribute(obj, "pointList");
        const Ref keep(list ? list : (Py_INCREF(Py_None), Py_None));
        Ref seq(PySequence_Fast(keep.p, "points"));
        for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) {
            Ref q(PySequence_Tuple(PySequence_Fast_GET_ITEM(seq.p, k)));  // (tuple(q) + (0.0, 0.0))[:3]
            V3 p{0.0, 0.0, 0.0};
            for (Py_ssize_t c = 0; c < 3 && c < PyTuple_GET_SIZE(q.p); ++c) p[size_t(c)] = num(PyTuple_GET_ITEM(q.p, c), 0);
            if (PyTuple_GET_SIZE(q.p) == 0) throw Unknown{};  // (0.0, 0.0)[:3]: two numbers, as Python has it
            m.points.push_back(p);
        }
        for (long k = 0; k + 1 < long(m.points.size()); ++k) m.segments.push_back({k, k + 1});
        return result(std::move(m));
    }
    if (name == "Scaled" || name == "Translated" || name == "AxisRotated" || name == "EulerRotated" || name == "Oriented") {
        PyObject* g = attribute(obj, "geometry");
        const Ref keep(g ? g : (Py_INCREF(Py_None), Py_None));
        const ShapeMesh inner = of(keep.p, depth + 1);
        if (inner.kind == ShapeMesh::Nothing) return m;
        if (name == "Scaled") {
            PyObject* sv = attribute(obj, "scale");
            const Ref ks(sv ? sv : PyLong_FromLong(1));
            const V3 s = sizes(ks.p, 1);
            add(m, inner, [&](const V3& p) { return V3{p[0] * s[0], p[1] * s[1], p[2] * s[2]}; });
        } else if (name == "Translated") {
            PyObject* tv = attribute(obj, "translation");
            if (!tv) throw Unknown{};  // the default (0, 0, 0): rare; the Python
            const Ref kt(tv);
            const V3 t = triple(kt.p, [](PyObject* x) { return num(x, 0); });
            add(m, inner, [&](const V3& p) { return V3{p[0] + t[0], p[1] + t[1], p[2] + t[2]}; });
        } else if (name == "AxisRotated") {
            PyObject* av = attribute(obj, "axis");
            if (!av) throw Unknown{};
            const Ref ka(av);
            const M3 r = axisRotation(normed(triple(ka.p, exact)), field(obj, "angle", 0));
            add(m, inner, [&](const V3& p) { return times(r, p); });
        } else if (name == "EulerRotated") {
            const double a = field(obj, "azimuth", 0), e = field(obj, "elevation", 0), ro = field(obj, "roll", 0);
            const M3 r = times(times(axisRotation({0, 0, 1}, a), axisRotation({0, 1, 0}, e)), axisRotation({1, 0, 0}, ro));
            add(m, inner, [&](const V3& p) { return times(r, p); });
        } else {  // Oriented
            PyObject* pv = attribute(obj, "primary");
            PyObject* sv = attribute(obj, "secondary");
            const Ref kp(pv ? pv : Py_BuildValue("(iii)", 1, 0, 0)), ks(sv ? sv : Py_BuildValue("(iii)", 0, 1, 0));
            const V3 x = normed(triple(kp.p, exact)), y = normed(triple(ks.p, exact));
            const V3 z = normed({x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]});
            add(m, inner, [&](const V3& p) {  // x * p[0] + y * p[1] + z * p[2], vector by vector
                const V3 a{x[0] * p[0], x[1] * p[0], x[2] * p[0]}, b{y[0] * p[1], y[1] * p[1], y[2] * p[1]};
                const V3 ab{a[0] + b[0], a[1] + b[1], a[2] + b[2]}, c{z[0] * p[2], z[1] * p[2], z[2] * p[2]};
                return V3{ab[0] + c[0], ab[1] + c[1], ab[2] + c[2]};
            });
        }
        return result(std::move(m));
    }
    if (name == "Box") {
        PyObject* sv = attribute(obj, "size");
        const Ref args(own(PyObject_GetAttrString(obj, "args")));
        const Py_ssize_t nargs = PyObject_Length(args.p);
        if (nargs < 0) throw Unknown{};
        PyObject* chosen = nargs >= 3 ? PySequence_GetSlice(args.p, 0, 3) : sv ? (Py_INCREF(sv), sv) : Py_BuildValue("(ddd)", 0.5, 0.5, 0.5);
        Py_XDECREF(sv);
        const Ref ks(chosen);
        const V3 s = sizes(ks.p, 0.5);
        m.kind = ShapeMesh::Mesh;
        for (int axis = 0; axis < 3; ++axis)
            for (int sign : {-1, 1}) {
                const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
                const long base = long(m.points.size());
                for (const auto& [du, dv] : {std::array<int, 2>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                    V3 p{0.0, 0.0, 0.0};
                    p[size_t(axis)] = sign * s[size_t(axis)], p[size_t(u)] = du * s[size_t(u)], p[size_t(v)] = dv * s[size_t(v)];
                    m.points.push_back(p);
                }
                m.triangles.push_back({base, base + 1, base + 2});
                m.triangles.push_back({base, base + 2, base + 3});
            }
        return m;
    }
    if (name != "Sphere" && name != "Cylinder" && name != "Cone" && name != "Frustum" && name != "Paraboloid" && name != "Disc" &&
        name != "TriangleSet" && name != "QuadSet" && name != "FaceSet" && name != "PointSet")
        throw Unknown{};  // a curve, a patch, a crown, None, ...: the Python says
    if (name == "PointSet") {  // (before `slices` in the Python: it never reads it)
        PyObject* list = attribute(obj, "pointList");
        const Ref keep(list ? list : PyTuple_New(0));
        Ref seq(PySequence_Fast(keep.p, "points"));
        std::vector<V3> points;
        for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) {
            Ref q(PySequence_Tuple(PySequence_Fast_GET_ITEM(seq.p, k)));
            if (PyTuple_GET_SIZE(q.p) == 0) throw Unknown{};
            V3 p{0.0, 0.0, 0.0};
            for (Py_ssize_t c = 0; c < 3 && c < PyTuple_GET_SIZE(q.p); ++c) p[size_t(c)] = num(PyTuple_GET_ITEM(q.p, c), 0);
            points.push_back(p);
        }
        if (points.empty()) return ShapeMesh{ShapeMesh::Mesh, {}, {}, {}};
        double extent = 0;
        for (int k = 0; k < 3; ++k) {
            double lo = points[0][size_t(k)], hi = points[0][size_t(k)];
            for (const V3& q : points) lo = q[size_t(k)] < lo ? q[size_t(k)] : lo, hi = q[size_t(k)] > hi ? q[size_t(k)] : hi;
            const double e = hi - lo;
            if (k == 0 || e > extent) extent = e;
            if (std::isnan(lo) || std::isnan(hi)) throw Unknown{};  // Python's min and max take NaN their own way
        }
        const double r = extent > 0 ? 0.005 * extent : 0.01;
        static const int dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        static const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        for (const V3& q : points) {
            const long base = long(m.points.size());
            for (const auto& d : dirs) m.points.push_back({q[0] + d[0] * r, q[1] + d[1] * r, q[2] + d[2] * r});
            for (const auto& f : faces) m.triangles.push_back({base + f[0], base + f[1], base + f[2]});
        }
        return result(std::move(m));
    }
    const long slices = count(obj, "slices", 8, 3, 64);
    if (name == "Sphere") {
        const double r = field(obj, "radius", 0.5);
        const long stacks = count(obj, "stacks", 8, 2, 64);
        std::vector<std::array<double, 2>> prof;
        for (long i = 0; i <= stacks; ++i) {
            const double a = M_PI * double(i) / double(stacks);
            prof.push_back({r * std::sin(a), -r * std::cos(a)});
        }
        return tube(prof, slices, {});
    }
    if (name == "Cylinder" || name == "Cone" || name == "Frustum") {
        const double r = field(obj, "radius", 0.5), h = field(obj, "height", 1);
        const double top = name == "Cylinder" ? r : name == "Cone" ? 0.0 : r * field(obj, "taper", 0.5);
        return tube({{r, 0.0}, {top, h}}, slices, {0, -1});
    }
    if (name == "Paraboloid") {
        const double r = field(obj, "radius", 0.5), h = field(obj, "height", 1), given = field(obj, "shape", 2);
        const double shape = given > 1e-3 ? given : 1e-3;  // max(1e-3, shape)
        const long stacks = count(obj, "stacks", 8, 2, 64);
        std::vector<std::array<double, 2>> prof;
        for (long i = 0; i <= stacks; ++i) {
            const double left = 1 - double(i) / double(stacks);
            prof.push_back({r * std::pow(left > 0.0 ? left : 0.0, 1 / shape), h * double(i) / double(stacks)});
        }
        return tube(prof, slices, {0});
    }
    if (name == "Disc") {
        const double r = field(obj, "radius", 0.5);
        m.kind = ShapeMesh::Mesh;
        m.points.push_back({0.0, 0.0, 0.0});
        ring(m, r, 0.0, slices);
        for (long i = 0; i < slices; ++i) m.triangles.push_back({0, 1 + i, 1 + (i + 1) % slices});
        return m;
    }
    // TriangleSet, QuadSet, FaceSet
    PyObject* list = attribute(obj, "pointList");
    const Ref keepPoints(list ? list : PyTuple_New(0));
    Ref seq(PySequence_Fast(keepPoints.p, "points"));
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k)
        m.points.push_back(triple(PySequence_Fast_GET_ITEM(seq.p, k), [](PyObject* x) { return num(x, 0); }));
    PyObject* faces = attribute(obj, "indexList");
    const Ref keepFaces(faces ? faces : PyTuple_New(0));
    Ref fseq(PySequence_Fast(keepFaces.p, "faces"));
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(fseq.p); ++k) {
        Ref face(PySequence_Fast(PySequence_Fast_GET_ITEM(fseq.p, k), "face"));
        std::vector<long> f;
        for (Py_ssize_t j = 0; j < PySequence_Fast_GET_SIZE(face.p); ++j) {
            PyObject* i = PySequence_Fast_GET_ITEM(face.p, j);
            if (!PyLong_CheckExact(i)) throw Unknown{};  // int(i) of anything else: the Python
            const long v = PyLong_AsLong(i);
            if (v < 0 || (v == -1 && PyErr_Occurred())) throw Unknown{};
            f.push_back(v);
        }
        if (f.empty()) throw Unknown{};  // f[0] of an empty face raises in the Python
        for (size_t j = 1; j + 1 < f.size(); ++j)
            if (std::max({f[0], f[j], f[j + 1]}) < long(m.points.size())) m.triangles.push_back({f[0], f[j], f[j + 1]});
    }
    m.kind = m.triangles.empty() ? ShapeMesh::Nothing : ShapeMesh::Mesh;
    return m;
}

}  // namespace

ShapeMesh shapeMesh(PyObject* obj) {
    try {
        return Mesher().of(obj, 0);
    } catch (Unknown&) {
        if (PyErr_Occurred()) PyErr_Clear();
        return ShapeMesh{ShapeMesh::Unknown, {}, {}, {}};
    }
}

}  // namespace sprout::lpy
