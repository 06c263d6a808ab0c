// PlantGL's curve arithmetic for Sprout's Python PlantGL (lpy/plantgl/plantgl_curves.py): the
// classes there keep their interface and build one of these evaluators per curve (cached on
// the curve, rebuilt when it changes), which evaluates it in C++ (lpy/plantgl/curves.hpp) with
// the same numbers. Bulk operations (a length, a mapping, a quantised function, a curve's
// points, a patch's grid) are one call each. Points come back as lists, which the Python
// makes its vectors with.
#include <pybind11/stl.h>

#include <cmath>

#include "lpy/plantgl/curves.hpp"
#include "lpy/plantgl/bindings.hpp"
#include "lpy/plantgl/py_numbers.hpp"

namespace py = pybind11;

namespace sprout::lpy {
namespace {

double number(PyObject* v) {
    double d;
    if (!pynum::arithmetic(v, d)) throw py::error_already_set();
    return d;
}

// A point's first `n` numbers, read as the Python reads them (p[c]): a PlantGL vector's
// list directly, anything else by indexing (an IndexError where it is shorter).
void readPoint(py::handle p, int n, std::vector<double>& out) {
    if (PyObject* v = pynum::vectorList(p.ptr(), n)) {
        const py::object keep = py::reinterpret_steal<py::object>(v);
        for (int c = 0; c < n; ++c) out.push_back(number(PyList_GET_ITEM(v, c)));
        return;
    }
    for (int c = 0; c < n; ++c) {
        py::object item = py::reinterpret_steal<py::object>(PySequence_GetItem(p.ptr(), c));
        if (!item) throw py::error_already_set();
        out.push_back(number(item.ptr()));
    }
}

std::vector<double> numbersOf(py::handle seq) {
    std::vector<double> out;
    for (py::handle k : seq) out.push_back(number(k.ptr()));
    return out;
}

py::list listOf(const curves::Point& p, int dim) {
    py::list out(dim);
    for (int c = 0; c < dim; ++c) PyList_SET_ITEM(out.ptr(), c, PyFloat_FromDouble(p[c]));
    return out;
}

// Python's ZeroDivisionError where the Python divides by zero (a stride of 0, a curve of one
// knot's span), instead of the C++'s infinities.
void refuseZero(double divisor) {
    if (divisor == 0) {
        PyErr_SetString(PyExc_ZeroDivisionError, "float division by zero");
        throw py::error_already_set();
    }
}

// QuantisedFunction's state: (first x, last x, the values).
py::tuple stateOf(const curves::Quantised& q) { return py::make_tuple(q.firstx, q.lastx, py::cast(q.values)); }

curves::Polyline2D polylineOf(py::handle points) {
    std::vector<std::array<double, 2>> pts;
    std::vector<double> xy;
    for (py::handle p : points) {
        xy.clear();
        readPoint(p, 2, xy);
        pts.push_back({xy[0], xy[1]});
    }
    return curves::Polyline2D(std::move(pts));
}

// A patch's row as the Python's NurbsCurve constructor makes its points: (x, y, z, w), the
// weight 1 where a point has three numbers (and a shorter one padded with zeros after it).
std::vector<double> patchRow(py::handle row) {
    std::vector<double> out;
    for (py::handle p : row) {
        const Py_ssize_t n = py::len(p);
        std::vector<double> v;
        readPoint(p, int(std::min<Py_ssize_t>(n, 3)), v);
        v.push_back(n > 3 ? number(py::reinterpret_borrow<py::object>(p)[py::int_(3)].ptr()) : 1.0);
        v.resize(4, 0.0);
        out.insert(out.end(), v.begin(), v.end());
    }
    return out;
}

// A patch as _PglPatch makes it: (rows of points, udegree, vdegree, uknots or None, vknots or
// None).
std::shared_ptr<curves::NurbsPatch> patchOf(py::handle rows, int udegree, int vdegree, py::handle uknots, py::handle vknots) {
    std::vector<std::vector<double>> pts;
    for (py::handle row : rows) pts.push_back(patchRow(row));
    auto knots = [](py::handle k) { return k.is_none() ? std::vector<double>{} : numbersOf(k); };
    return std::make_shared<curves::NurbsPatch>(std::move(pts), udegree, vdegree, knots(uknots), knots(vknots));
}

// A volume's control points, [u][v][w] each (x, y, z, w) as the Python reads p[0] to p[3].
curves::NurbsVolume volumeOf(py::handle grid, std::array<int, 3> degrees, py::tuple knots) {
    curves::NurbsVolume::Grid ctrl;
    std::vector<double> xyzw;
    for (py::handle plane : grid) {
        ctrl.emplace_back();
        for (py::handle line : plane) {
            ctrl.back().emplace_back();
            for (py::handle p : line) {
                xyzw.clear();
                readPoint(p, 4, xyzw);
                ctrl.back().back().push_back({xyzw[0], xyzw[1], xyzw[2], xyzw[3]});
            }
        }
    }
    return curves::NurbsVolume(std::move(ctrl), degrees, {numbersOf(knots[0]), numbersOf(knots[1]), numbersOf(knots[2])});
}

}  // namespace

std::vector<curves::Point> patchGrid(PyObject* rows, int udegree, int vdegree, int n) {
    return patchOf(py::handle(rows), udegree, vdegree, py::none(), py::none())->grid(n);
}

std::shared_ptr<const curves::Nurbs> nativeNurbs(PyObject* curve, int& stride) {
    py::handle h(curve);
    try {
        if (!py::hasattr(h, "_sprout_native")) return nullptr;
        py::object native = h.attr("_sprout_native")();
        py::object s = h.attr("stride");
        // range(stride) in the Python: an int, or the Python's own way (its error)
        if (native.is_none() || !py::isinstance<py::int_>(s) || py::isinstance<py::bool_>(s)) return nullptr;
        stride = s.cast<int>();
        return native.cast<std::shared_ptr<curves::Nurbs>>();
    } catch (py::error_already_set&) {
        PyErr_Clear();
    } catch (py::cast_error&) {
    }
    return nullptr;
}

void definePlantGL(py::module_& m) {
    using curves::Nurbs;
    py::class_<Nurbs, std::shared_ptr<Nurbs>>(m, "_PglNurbs")
        // (dimension, degree, knots, control points (x, y, [z,] w) as the curve keeps them)
        .def(py::init([](int dim, int degree, py::handle knots, py::handle points) {
            std::vector<double> ctrl;
            for (py::handle p : points) readPoint(p, dim + 1, ctrl);
            return std::make_shared<Nurbs>(dim, degree, numbersOf(knots), std::move(ctrl));
        }))
        .def("point", [](const Nurbs& c, double u) { return listOf(c.pointAt(u), c.dim()); })
        .def("derivative", [](const Nurbs& c, double u, int d) { return listOf(c.derivativeAt(u, d), c.dim()); })
        .def("normal", [](const Nurbs& c, double u) { return listOf(c.normalAt(u), c.dim()); })
        .def("length", [](const Nurbs& c, double begin, double end, double stride) {
            refuseZero((c.lastKnot() - c.firstKnot()) / stride);
            return c.length(begin, end, stride);
        })
        .def("points", [](const Nurbs& c, int n) {
            if (n == 1) refuseZero(0);
            py::list out;
            for (const curves::Point& p : c.sample(n)) out.append(listOf(p, c.dim()));
            return out;
        })
        // getArcLengthToUMapping / getUToArcLengthMapping: the QuantisedFunction's state.
        .def("arc_to_u", [](const Nurbs& c, int stride) {
            refuseZero((c.lastKnot() - c.firstKnot()) / stride);
            return stateOf(curves::quantise(curves::Polyline2D(c.arcLengthToU(stride)), 5 * stride));
        })
        .def("u_to_arc", [](const Nurbs& c, int stride) {
            refuseZero((c.lastKnot() - c.firstKnot()) / stride);
            return stateOf(curves::quantise(curves::Polyline2D(c.uToArcLength(stride)), 5 * stride));
        })
        .def("quantised", [](const Nurbs& c, int sampling) { return stateOf(curves::quantise(c, sampling)); });

    // QuantisedFunction(Polyline2D(points), sampling)'s state.
    m.def("_pgl_quantised_polyline", [](py::handle points, int sampling) { return stateOf(curves::quantise(polylineOf(points), sampling)); });

    py::class_<curves::NurbsPatch, std::shared_ptr<curves::NurbsPatch>>(m, "_PglPatch")
        // (rows of points, udegree, vdegree, uknots or None, vknots or None)
        .def(py::init(&patchOf))
        .def("point", [](const curves::NurbsPatch& p, double u, double v) { return listOf(p.pointAt(u, v), 3); })
        // The drawing's (n + 1)^2 points, as tuples.
        .def("grid", [](const curves::NurbsPatch& p, int n) {
            refuseZero(n);
            py::list out;
            for (const curves::Point& q : p.grid(n)) out.append(py::make_tuple(q[0], q[1], q[2]));
            return out;
        });

    // NurbsPatch3D.getPointAt: (control points [u][v][w], (degrees), (knots), u, v, w), the
    // point's (x, y, z).
    m.def("_pgl_volume_point", [](py::handle grid, std::array<int, 3> degrees, py::tuple knots, double u, double v,
                                  double w) { return listOf(volumeOf(grid, degrees, knots).pointAt(u, v, w), 3); });
    // The uniform clamped knots of n control points of a degree (NurbsCurve2D's and
    // NurbsPatch3D's default knots).
    m.def("_pgl_uniform_knots", [](int n, int degree) { return curves::uniformClampedKnots(n, degree); });
    // NurbsPatch's iso sections: the control points of the section at t, each (x, y, z, w) the
    // point at t of a row (columns False) or a column (True) of the patch's points (a point
    // of two or three numbers padded with 1s, as the Python pads them).
    m.def("_pgl_iso_points", [](py::handle rows, int degree, py::handle knotList, double t, bool columns) {
        std::vector<std::vector<std::array<double, 4>>> grid;
        for (py::handle row : rows) {
            grid.emplace_back();
            for (py::handle p : row) {
                const Py_ssize_t n = PySequence_Size(p.ptr());
                if (n < 0) throw py::error_already_set();
                std::vector<double> xs;
                readPoint(p, int(std::min<Py_ssize_t>(n, 4)), xs);
                std::array<double, 4> q{1.0, 1.0, 1.0, 1.0};
                for (size_t c = 0; c < xs.size(); ++c) q[c] = xs[c];
                grid.back().push_back(q);
            }
        }
        const std::vector<double> knots = numbersOf(knotList);
        const size_t lines = columns ? (grid.empty() ? 0 : grid[0].size()) : grid.size();
        py::list out;
        std::vector<std::array<double, 4>> line;
        for (size_t k = 0; k < lines; ++k) {
            line.clear();
            if (columns)
                for (const auto& row : grid) line.push_back(row.at(k));
            else
                line = grid[k];
            const std::array<double, 4> q = curves::weightedPointAt(line, degree, knots, t);
            out.append(py::make_tuple(q[0], q[1], q[2], q[3]));
        }
        return out;
    });
    defineProjection(m);  // the light module's z-buffer (bind_light.cpp)
}

}  // namespace sprout::lpy
