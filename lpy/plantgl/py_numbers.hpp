#pragma once
// Python's numbers read in C++, each the way one Python expression reads it: one helper for
// the curves' bindings (bind_curves.cpp), @g's meshes (meshes.cpp) and the drawing's
// parameters (lpy/draw/). Each returns false with the Python error set where Python would
// raise, and leaves the error to the caller (cleared, or turned into its own).
#include <Python.h>

#include <climits>
#include <vector>

namespace sprout::lpy::pynum {

// `v` as Python's arithmetic takes it (a float, an int, anything with __float__ or __index__;
// not a string): what `p[c] * w` of the Python curves reads.
inline bool arithmetic(PyObject* v, double& out) {
    out = PyFloat_Check(v) ? PyFloat_AS_DOUBLE(v) : PyFloat_AsDouble(v);
    return !(out == -1.0 && PyErr_Occurred());
}

// float(v): a number, or a string of one.
inline bool floatOf(PyObject* v, double& out) {
    if (PyFloat_CheckExact(v)) {
        out = PyFloat_AS_DOUBLE(v);
        return true;
    }
    PyObject* f = PyNumber_Float(v);
    if (!f) return false;
    out = PyFloat_AS_DOUBLE(f);
    Py_DECREF(f);
    return true;
}

// float(v), or `fallback` where float() raises TypeError or ValueError (or `v` is null: a field
// not there): the num(v, default) of @g's meshing. False only for any other error.
inline bool floatOr(PyObject* v, double fallback, double& out) {
    if (!v) {
        out = fallback;
        return true;
    }
    if (floatOf(v, out)) return true;
    if (!PyErr_ExceptionMatches(PyExc_TypeError) && !PyErr_ExceptionMatches(PyExc_ValueError)) return false;
    PyErr_Clear();
    out = fallback;
    return true;
}

// int(v), clamped to long's range (LONG_MAX or LONG_MIN past it, as a bigger int compares).
inline bool intOf(PyObject* v, long& out) {
    PyObject* i = PyNumber_Long(v);
    if (!i) return false;
    int overflow = 0;
    out = PyLong_AsLongAndOverflow(i, &overflow);
    Py_DECREF(i);
    if (overflow) out = overflow > 0 ? LONG_MAX : LONG_MIN;
    return !(out == -1 && PyErr_Occurred());
}

// A PlantGL vector's list of floats (its `_v`, a new reference) where `v` is one with at least
// `n`; null (no error) for anything else.
inline PyObject* vectorList(PyObject* v, Py_ssize_t n) {
    static PyObject* const name = PyUnicode_InternFromString("_v");
    PyObject* list = PyObject_GetAttr(v, name);
    if (list && PyList_Check(list) && PyList_GET_SIZE(list) >= n) return list;
    Py_XDECREF(list);
    PyErr_Clear();
    return nullptr;
}

// A drawing's parameter as numbers (appended): an int or a float, or a sequence of at most 16
// of them (a Vector3, a tuple). False, with no error set, for anything else.
inline bool numbers(PyObject* v, std::vector<double>& out) {
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

}  // namespace sprout::lpy::pynum
