// Sprout's openalea.plantgl on C++ for PlantGL's light module (lpy/plantgl/plantgl_light.py):
// `_ZBuffer` (lpy/plantgl/zbuffer.hpp) drawing the shapes of a scene as meshes.cpp meshes them,
// and `_mesh_bounds`, the bounds of what a shape or scene draws (BoundingBox(scene)).
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include "lpy/plantgl/bindings.hpp"
#include "lpy/plantgl/zbuffer.hpp"

namespace sprout::lpy {
namespace {

ZBuffer::Vec vec3(py::handle v) {
    ZBuffer::Vec out{0, 0, 0};
    size_t k = 0;
    for (py::handle x : v) {
        if (k == 3) break;
        out[k++] = x.cast<double>();
    }
    return out;
}

// A shape's id as PlantGL's unsigned one: Shape::NOID where it has none (or one below 0).
std::uint32_t idOf(py::handle shape) {
    if (!py::hasattr(shape, "id")) return ZBuffer::kNoId;
    py::object id = shape.attr("id");
    if (!py::isinstance<py::int_>(id)) return ZBuffer::kNoId;
    const long long v = id.cast<long long>();
    return v < 0 || v > 0xFFFFFFFFLL ? ZBuffer::kNoId : std::uint32_t(v);
}

// What one shape draws: its triangles, and its segments as a polyline of its width.
void draw(ZBuffer& z, py::handle shape, std::uint32_t id) {
    const ShapeMesh mesh = shapeMesh(shape.ptr());
    if (mesh.kind == ShapeMesh::Nothing) return;
    const auto at = [&](long k) -> const ZBuffer::Vec& { return mesh.points[size_t(k)]; };
    const long n = long(mesh.points.size());
    for (const auto& t : mesh.triangles)
        if (t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && t[0] < n && t[1] < n && t[2] < n) z.triangle(at(t[0]), at(t[1]), at(t[2]), id);
    int width = 1;
    if (!mesh.segments.empty() && py::hasattr(shape, "geometry")) {
        py::object g = shape.attr("geometry");
        if (py::hasattr(g, "width") && py::isinstance<py::int_>(g.attr("width"))) width = g.attr("width").cast<int>();
    }
    for (const auto& s : mesh.segments)
        if (s[0] >= 0 && s[1] >= 0 && s[0] < n && s[1] < n) z.segment(at(s[0]), at(s[1]), width, id);
}

}  // namespace

void defineProjection(py::module_& m) {
    py::class_<ZBuffer>(m, "_ZBuffer")
        .def(py::init<int, int, std::uint32_t>(), py::arg("width"), py::arg("height"), py::arg("defaultId") = ZBuffer::kNoId)
        .def_property_readonly("width", &ZBuffer::width)
        .def_property_readonly("height", &ZBuffer::height)
        .def("setOrthographicCamera", &ZBuffer::setOrthographicCamera)
        .def("lookAt", [](ZBuffer& z, py::handle eye, py::handle centre, py::handle up) { z.lookAt(vec3(eye), vec3(centre), vec3(up)); })
        // Each shape of `shapes` (a Scene, a list) drawn with its id (Shape::NOID where none).
        .def("process", [](ZBuffer& z, py::iterable shapes) {
            for (py::handle shape : shapes) draw(z, shape, idOf(shape));
        })
        .def("worldToRaster", [](const ZBuffer& z, py::handle p) {
            const auto r = z.worldToRaster(vec3(p));
            return py::make_tuple(r[0], r[1], r[2]);
        })
        .def("idhistogram", &ZBuffer::idHistogram)
        .def("idAt", [](const ZBuffer& z, int x, int y) -> py::object {
            if (x < 0 || y < 0 || x >= z.width() || y >= z.height()) throw py::index_error("pixel out of the image");
            return py::int_(z.idAt(x, y));
        })
        .def("depthAt", [](const ZBuffer& z, int x, int y) {
            if (x < 0 || y < 0 || x >= z.width() || y >= z.height()) throw py::index_error("pixel out of the image");
            return z.depthAt(x, y);
        });
    // The lower and upper corners of what `obj` (a shape, a geometry, a scene, a list) draws,
    // None where it draws nothing.
    m.def("_mesh_bounds", [](py::handle obj) -> py::object {
        const ShapeMesh mesh = shapeMesh(obj.ptr());
        if (mesh.kind == ShapeMesh::Nothing || mesh.points.empty()) return py::none();
        ZBuffer::Vec lo = mesh.points[0], hi = mesh.points[0];
        for (const auto& p : mesh.points)
            for (size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
        return py::make_tuple(py::make_tuple(lo[0], lo[1], lo[2]), py::make_tuple(hi[0], hi[1], hi[2]));
    });
}

}  // namespace sprout::lpy
