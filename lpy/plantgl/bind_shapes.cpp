// Sprout's openalea.plantgl on C++: Point3Grid's grid (`_sprout_lpy._PointGrid`, which the
// Python class of lpy/plantgl/plantgl_grids.py holds; a space colonisation model asks it
// thousands of cone and ball queries a step) and @g's meshes for tests (`_shape_mesh`,
// lpy/plantgl/meshes.cpp).
#include <pybind11/stl.h>

#include "lpy/plantgl/point_grid.hpp"
#include "lpy/plantgl/bindings.hpp"

namespace sprout::lpy {
namespace {

PointGrid::Vec vec3(py::handle v) {
    PointGrid::Vec out{0, 0, 0};
    size_t k = 0;
    for (py::handle x : v) {
        if (k == 3) break;
        out[k++] = x.cast<double>();
    }
    return out;
}

std::vector<PointGrid::Vec> points(py::iterable pts) {
    std::vector<PointGrid::Vec> out;
    for (py::handle p : pts) out.push_back(vec3(p));
    return out;
}

py::list indices(const std::vector<std::uint32_t>& found) {
    py::list out(found.size());
    for (size_t k = 0; k < found.size(); ++k) out[k] = py::int_(found[k]);
    return out;
}

}  // namespace

void definePointGrid(py::module_& m) {
    // A shape given to @g as lpy/plantgl/meshes.cpp makes it, without the copies of its points
    // that carry texture coordinates: (points, triangles, segments), None where nothing is drawn.
    m.def("_shape_mesh", [](py::handle shape) -> py::object {
        const ShapeMesh mesh = welded(shapeMesh(shape.ptr()));
        if (mesh.kind == ShapeMesh::Nothing) return py::none();
        py::list points, triangles, segments;
        for (const auto& p : mesh.points) points.append(py::make_tuple(p[0], p[1], p[2]));
        for (const auto& t : mesh.triangles) triangles.append(py::make_tuple(t[0], t[1], t[2]));
        for (const auto& e : mesh.segments) segments.append(py::make_tuple(e[0], e[1]));
        return py::make_tuple(points, triangles, segments);
    });
    py::class_<PointGrid>(m, "_PointGrid")
        .def(py::init([](py::iterable pts, py::handle size, py::handle lower, py::handle upper) {
                 return PointGrid(points(pts), vec3(size), vec3(lower), vec3(upper));
             }),
             py::arg("points"), py::arg("size"), py::arg("lower"), py::arg("upper"))
        .def("__len__", &PointGrid::size)
        .def("ball", [](const PointGrid& g, py::handle c, double r) { return indices(g.ballQuery(vec3(c), r)); })
        .def("cone", [](const PointGrid& g, py::handle c, py::handle d, double r, double a) {
            return indices(g.coneQuery(vec3(c), vec3(d), r, a));
        })
        .def("disable", [](PointGrid& g, long i) { return i >= 0 && g.disable(size_t(i)); })
        .def("enable", [](PointGrid& g, long i) { return i >= 0 && g.enable(size_t(i)); })
        .def("disable_all", [](PointGrid& g, py::iterable is) {
            for (py::handle i : is) g.disable(i.cast<size_t>());
        })
        .def("enable_all", [](PointGrid& g, py::iterable is) {
            for (py::handle i : is) g.enable(i.cast<size_t>());
        })
        .def("enabled", [](const PointGrid& g, long i) { return i >= 0 && g.enabled(size_t(i)); })
        .def("enabled_indices", [](const PointGrid& g) {
            std::vector<std::uint32_t> out;
            for (size_t i = 0; i < g.size(); ++i)
                if (g.enabled(i)) out.push_back(std::uint32_t(i));
            return indices(out);
        });
}

}  // namespace sprout::lpy
