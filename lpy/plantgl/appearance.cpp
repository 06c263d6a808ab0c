// A Shape's appearance as the turtle draws it (bindings.hpp: shapeColour): PglTurtle::pglShape
// sets the shape's appearance as the turtle's material while it draws the shape's geometry.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "lpy/plantgl/bindings.hpp"

namespace sprout::lpy {

std::uint32_t shapeColour(PyObject* shape) {
    try {
        const py::handle s(shape);
        if (!py::hasattr(s, "appearance")) return 0;
        const py::object a = s.attr("appearance");
        if (a.is_none() || !py::hasattr(a, "diffuseColor") || !py::hasattr(a, "transparency")) return 0;  // a texture
        const py::object c = a.attr("diffuseColor")();
        const double t = a.attr("transparency").cast<double>();
        auto byte = [](double x) { return std::uint32_t(std::clamp(std::isnan(x) ? 0.0 : x, 0.0, 255.0)); };
        return byte(c[py::int_(0)].cast<double>()) << 24 | byte(c[py::int_(1)].cast<double>()) << 16 |
               byte(c[py::int_(2)].cast<double>()) << 8 | byte(std::round((1 - t) * 255));
    } catch (py::error_already_set&) {
    } catch (py::cast_error&) {
    }
    if (PyErr_Occurred()) PyErr_Clear();
    return 0;
}

std::string shapeTexture(PyObject* shape) {
    try {
        const py::handle s(shape);
        if (!py::hasattr(s, "appearance")) return "";
        py::object image = s.attr("appearance");
        if (!image.is_none() && py::hasattr(image, "image") && !py::hasattr(image, "filename")) image = image.attr("image");  // a Texture2D
        if (image.is_none() || !py::hasattr(image, "filename")) return "";
        return py::str(image.attr("filename")).cast<std::string>();
    } catch (py::error_already_set&) {
    } catch (py::cast_error&) {
    }
    if (PyErr_Occurred()) PyErr_Clear();
    return "";
}

}  // namespace sprout::lpy
