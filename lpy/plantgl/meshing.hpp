#pragma once
// What lpy/plantgl/meshes.cpp and solids.cpp share while they mesh a model's PlantGL shapes:
// Python's values read as the Python meshing read them (Raises where it raised: the shape is
// not drawn), an empty mesh and its result, and the solids solids.cpp meshes.

#include <algorithm>
#include <cmath>
#include <string_view>

#include "lpy/plantgl/bindings.hpp"
#include "lpy/plantgl/py_numbers.hpp"
#include "lpy/plantgl/vector_math.hpp"

namespace sprout::lpy::meshing {

struct Raises {};  // thrown: the shape is not drawn (any Python error is cleared)

[[noreturn]] inline void raise() {
    PyErr_Clear();
    throw Raises{};
}

// A new reference, or Raises.
inline PyObject* own(PyObject* o) {
    if (!o) raise();
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
inline PyObject* attribute(PyObject* obj, const char* field) {
    PyObject* v = PyObject_GetAttrString(obj, field);
    if (v) return v;
    if (!PyErr_ExceptionMatches(PyExc_AttributeError)) raise();
    PyErr_Clear();
    return nullptr;
}

// getattr(obj, field, fallback), `fallback` a new reference (released where not used).
inline PyObject* attributeOr(PyObject* obj, const char* field, PyObject* fallback) {
    PyObject* v = attribute(obj, field);
    if (!v) return fallback;
    Py_XDECREF(fallback);
    return v;
}
inline PyObject* none() { return Py_NewRef(Py_None); }

// num(v, default): float(v), or the default where float() raises TypeError or ValueError.
inline double num(PyObject* v, double fallback) {
    double d;
    if (!pynum::floatOr(v, fallback, d)) raise();
    return d;
}

// float(v), raising where float() does.
inline double exact(PyObject* v) {
    double d;
    if (!pynum::floatOf(v, d)) raise();
    return d;
}

// num(get(name, fallback), fallback)
inline double field(PyObject* obj, const char* name, double fallback) {
    PyObject* v = attribute(obj, name);
    const double d = num(v, fallback);
    Py_XDECREF(v);
    return d;
}

using pglmath::V3;
using pglmath::M3;
using pglmath::normed;
using pglmath::axisRotation;
using pglmath::times;

// tuple(v)[:3], each item by `read`, zeros after; how many there were in `n`.
template <class Read>
inline V3 upToThree(PyObject* v, Read read, Py_ssize_t& n) {
    const Ref t(PySequence_Tuple(v));
    n = std::min<Py_ssize_t>(3, PyTuple_GET_SIZE(t.p));
    V3 out{0.0, 0.0, 0.0};
    for (Py_ssize_t k = 0; k < n; ++k) out[size_t(k)] = read(PyTuple_GET_ITEM(t.p, k));
    return out;
}
inline double num0(PyObject* x) { return num(x, 0); }

// A point as the Python read it, (tuple(q) + (0.0, 0.0))[:3] each by num(x, 0): false where q
// is empty (the Python's point was two zeros, which the drawing refuses).
inline bool point(PyObject* q, V3& p) {
    Py_ssize_t n = 0;
    p = upToThree(q, num0, n);
    return n > 0;
}

// A Box's size or a Scaled's scale: (num(v),) * 3 for what has no length, else num of
// tuple(v)[:3] (`n` of them).
inline V3 sizes(PyObject* v, double fallback, Py_ssize_t& n) {
    if (!PyObject_HasAttrString(v, "__len__")) {
        const double k = num(v, fallback);
        n = 3;
        return {k, k, k};
    }
    return upToThree(v, [fallback](PyObject* x) { return num(x, fallback); }, n);
}

// Vector3(*tuple(v)[:3]) (plantgl_vectors.py): float() of each, zeros after; one item with a
// length is the vector's numbers itself.
inline V3 vector3(PyObject* v) {
    const Ref t(PySequence_Tuple(v));
    Py_ssize_t n = 0;
    if (PyTuple_GET_SIZE(t.p) == 1 && PyObject_HasAttrString(PyTuple_GET_ITEM(t.p, 0), "__len__"))
        return upToThree(PyTuple_GET_ITEM(t.p, 0), exact, n);
    return upToThree(t.p, exact, n);
}

// int(num(get(name, fallback), fallback)) clamped to [low, high]; Raises where int() does.
inline long count(PyObject* obj, const char* name, double fallback, long low, long high) {
    const double v = field(obj, name, fallback);
    if (!std::isfinite(v)) raise();
    return long(std::max(double(low), std::min(double(high), std::trunc(v))));
}

inline ShapeMesh mesh() { return ShapeMesh{ShapeMesh::Mesh, {}, {}, {}, {}}; }

// The mesh, or Nothing where it has neither triangles nor segments.
inline ShapeMesh result(ShapeMesh m) {
    m.kind = m.triangles.empty() && m.segments.empty() ? ShapeMesh::Nothing : ShapeMesh::Mesh;
    return m;
}

// Box: six faces of two triangles, half sizes its size (or its first three arguments).
ShapeMesh box(PyObject* obj);
// The shapes of revolution about z (Sphere, Cylinder, Cone, Frustum, Paraboloid, Disc),
// `slices` points a ring; empty (Nothing) for another name.
ShapeMesh solid(PyObject* obj, std::string_view name, long slices);

}  // namespace sprout::lpy::meshing
