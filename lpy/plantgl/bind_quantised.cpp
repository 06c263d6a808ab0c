// PlantGL's QuantisedFunction called from Python: y = f(x), read from its samples by linear
// interpolation. The Python class (lpy/plantgl/plantgl_curves.py) derives from this type, whose
// call is C: models call their functions by the hundred thousand (spacecolonization's
// generate_points drew 180 k profile(z) in Python frames). The numbers are the Python's, in
// its order: anything it would not read the same way (an unusual x, a value not a float, a
// NaN) goes to the class's _call_python, the code it replaces.
#include <cmath>

#include "lpy/plantgl/bindings.hpp"

namespace py = pybind11;

namespace sprout::lpy {
namespace {

struct Quantised {
    PyObject_HEAD
    PyObject* values;  // _values: a list of the samples
    PyObject* first;   // _first, _last: the x of the first and last sample
    PyObject* last;
};

// x as a double, where the Python reads it as that double (a float, or an int of at most 53 bits).
bool exactNumber(PyObject* o, double& x) {
    if (PyFloat_CheckExact(o)) return x = PyFloat_AS_DOUBLE(o), true;
    if (!PyLong_CheckExact(o)) return false;
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(o, &overflow);
    if (overflow || (v == -1 && PyErr_Occurred()) || v > (1LL << 53) || v < -(1LL << 53)) return PyErr_Clear(), false;
    return x = double(v), true;
}

PyObject* call(PyObject* self, PyObject* args, PyObject* kwargs) {
    auto* q = reinterpret_cast<Quantised*>(self);
    double x = 0;
    if (!kwargs && PyTuple_GET_SIZE(args) == 1 && q->values && PyList_CheckExact(q->values) && q->first &&
        PyFloat_CheckExact(q->first) && q->last && PyFloat_CheckExact(q->last) && exactNumber(PyTuple_GET_ITEM(args, 0), x)) {
        const Py_ssize_t n = PyList_GET_SIZE(q->values);
        const double first = PyFloat_AS_DOUBLE(q->first), last = PyFloat_AS_DOUBLE(q->last);
        // x = min(max(x, first), last)
        if (first > x) x = first;
        if (last < x) x = last;
        // index = (n - 1) * (x - first) / (last - first) if last != first else 0.0
        double index = 0.0;
        if (last != first) {
            const double scaled = double(n - 1) * (x - first);
            index = scaled / (last - first);
        }
        if (n > 0 && std::isfinite(index) && index >= 0 && index < 1e15) {
            const double floor = std::floor(index);
            const Py_ssize_t k = Py_ssize_t(floor);
            const double diff = index - floor;
            if (k >= n - 1 || std::fabs(diff) < 1e-5) {
                PyObject* v = PyList_GET_ITEM(q->values, k < n - 1 ? k : n - 1);
                Py_INCREF(v);
                return v;
            }
            PyObject *a = PyList_GET_ITEM(q->values, k), *b = PyList_GET_ITEM(q->values, k + 1);
            if (PyFloat_CheckExact(a) && PyFloat_CheckExact(b)) {
                // (1 - diff) * values[floor] + diff * values[floor + 1], each product rounded
                const double left = (1.0 - diff) * PyFloat_AS_DOUBLE(a);
                const double right = diff * PyFloat_AS_DOUBLE(b);
                return PyFloat_FromDouble(left + right);
            }
        }
    }
    static PyObject* const slow = PyUnicode_InternFromString("_call_python");
    PyObject* method = PyObject_GetAttr(self, slow);
    if (!method) return nullptr;
    PyObject* r = PyObject_Call(method, args, kwargs);
    Py_DECREF(method);
    return r;
}

PyObject* get(PyObject* self, void* field) {
    PyObject* v = *reinterpret_cast<PyObject**>(reinterpret_cast<char*>(self) + reinterpret_cast<std::size_t>(field));
    if (!v) {
        PyErr_SetString(PyExc_AttributeError, "the function has no samples yet");
        return nullptr;
    }
    Py_INCREF(v);
    return v;
}

int set(PyObject* self, PyObject* value, void* field) {
    PyObject*& slot = *reinterpret_cast<PyObject**>(reinterpret_cast<char*>(self) + reinterpret_cast<std::size_t>(field));
    Py_XINCREF(value);
    Py_XSETREF(slot, value);
    return 0;
}

int traverse(PyObject* self, visitproc visit, void* arg) {
    auto* q = reinterpret_cast<Quantised*>(self);
    Py_VISIT(q->values);
    Py_VISIT(q->first);
    Py_VISIT(q->last);
    Py_VISIT(Py_TYPE(self));
    return 0;
}

int clear(PyObject* self) {
    auto* q = reinterpret_cast<Quantised*>(self);
    Py_CLEAR(q->values);
    Py_CLEAR(q->first);
    Py_CLEAR(q->last);
    return 0;
}

void dealloc(PyObject* self) {
    PyTypeObject* type = Py_TYPE(self);
    PyObject_GC_UnTrack(self);
    clear(self);
    type->tp_free(self);
    Py_DECREF(type);
}

#define SPROUT_FIELD(name) reinterpret_cast<void*>(offsetof(Quantised, name))
PyGetSetDef fields[] = {
    {"_values", get, set, nullptr, SPROUT_FIELD(values)},
    {"_first", get, set, nullptr, SPROUT_FIELD(first)},
    {"_last", get, set, nullptr, SPROUT_FIELD(last)},
    {nullptr, nullptr, nullptr, nullptr, nullptr},
};
#undef SPROUT_FIELD

PyType_Slot slots[] = {
    {Py_tp_call, reinterpret_cast<void*>(call)},
    {Py_tp_getset, fields},
    {Py_tp_traverse, reinterpret_cast<void*>(traverse)},
    {Py_tp_clear, reinterpret_cast<void*>(clear)},
    {Py_tp_dealloc, reinterpret_cast<void*>(dealloc)},
    {Py_tp_new, reinterpret_cast<void*>(PyType_GenericNew)},
    {Py_tp_doc, const_cast<char*>("QuantisedFunction's samples and its call, in C.")},
    {0, nullptr},
};

PyType_Spec spec = {"_sprout_lpy._QuantisedBase", sizeof(Quantised), 0,
                    Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE | Py_TPFLAGS_HAVE_GC, slots};

}  // namespace

void defineQuantised(py::module_& m) {
    PyObject* type = PyType_FromSpec(&spec);
    if (!type) throw py::error_already_set();
    m.attr("_QuantisedBase") = py::reinterpret_steal<py::object>(type);
}

}  // namespace sprout::lpy
