// `import sprout`: a model's graphical objects as the viewer's editors read and write them
// (issue 52): an L-Py model's 2D curves and materials, in its text.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>

#include "app/plant/lpy_materials.hpp"
#include "app/plant/lpy_objects.hpp"

namespace py = pybind11;
using namespace sprout;

void bindModelObjects(py::module_& m) {
    // An L-Py model's 2D curves as the viewer's curve editor reads and writes them (issue 52).
    m.def(
        "lpy_curves",
        [](const std::string& text) {
            py::list out;
            for (const LpyCurve& c : lpyCurves(text)) {
                py::dict d;
                d["name"] = c.name;
                d["kind"] = c.kind == LpyCurve::Kind::Bezier ? "Bezier" : c.kind == LpyCurve::Kind::Polyline ? "Polyline" : "NURBS";
                d["function"] = c.function;
                d["degree"] = c.degree;
                d["line"] = c.line;
                d["points"] = c.points;
                out.append(d);
            }
            return out;
        },
        py::arg("text"), "The 2D curves of an L-Py model's INITIALISATION part: name, kind, function, degree, line, points (x, y, w)");
    m.def(
        "set_lpy_curve",
        [](const std::string& text, const std::string& name, const std::vector<std::array<double, 3>>& points) {
            if (points.size() < 2) throw py::value_error("a curve has two points at least");
            for (const auto& p : points)
                if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                    throw py::value_error("a curve's points are finite numbers");
            const std::vector<LpyCurve> curves = lpyCurves(text);
            if (const LpyCurve* c = lastLpyCurve(curves, name)) return setLpyCurvePoints(text, *c, points);
            throw py::key_error("no curve " + name + " in the model's INITIALISATION part");
        },
        py::arg("text"), py::arg("name"), py::arg("points"),
        "The model's text with that curve's control points replaced (as L-Py Studio writes them; a name several panels "
        "set: the last, which the model uses); the rest as it was");
    m.def(
        "lpy_materials",
        [](const std::string& text) {
            py::list out;
            for (const LpyMaterial& mat : lpyMaterials(text)) {
                py::dict d;
                d["index"] = mat.index;
                d["name"] = mat.name;
                d["line"] = mat.line;
                if (!mat.texture.empty()) {
                    d["texture"] = mat.texture;
                } else {
                    d["ambient"] = mat.ambient;
                    d["diffuse"] = mat.diffuse;
                    d["specular"] = mat.specular;
                    d["emission"] = mat.emission;
                    d["shininess"] = mat.shininess;
                    d["transparency"] = mat.transparency;
                }
                out.append(d);
            }
            return out;
        },
        py::arg("text"),
        "The materials an L-Py model's INITIALISATION part sets: index, name, line, and PlantGL's ambient, diffuse, specular, "
        "emission, shininess, transparency (colours 0..255), or the texture's image");
    m.def(
        "set_lpy_material",
        [](const std::string& text, int index, const std::string& field, py::object value) {
            const auto f = lpyMaterialFieldNamed(field);
            if (!f) throw py::key_error("no material field " + field + " (ambient, diffuse, specular, emission, shininess, transparency)");
            const LpyMaterial* found = nullptr;
            const std::vector<LpyMaterial> all = lpyMaterials(text);
            for (const LpyMaterial& mat : all)
                if (mat.index == index && mat.texture.empty()) found = &mat;
            if (!found) throw py::key_error("no material " + std::to_string(index) + " in the model's INITIALISATION part");
            LpyMaterial v = *found;
            if (*f == LpyMaterial::Ambient || *f == LpyMaterial::Specular || *f == LpyMaterial::Emission) {
                const auto c = value.cast<std::array<double, 3>>();
                std::array<int, 3> rgb{};
                for (size_t i = 0; i < 3; ++i) {
                    if (!(c[i] >= 0 && c[i] <= 255)) throw py::value_error("a colour's numbers are 0 to 255");
                    rgb[i] = int(std::lround(c[i]));
                }
                (*f == LpyMaterial::Ambient ? v.ambient : *f == LpyMaterial::Specular ? v.specular : v.emission) = rgb;
            } else {
                const double x = value.cast<double>();
                if (!std::isfinite(x) || x < 0 || (*f != LpyMaterial::Diffuse && x > 1))
                    throw py::value_error(field + (*f == LpyMaterial::Diffuse ? " is 0 or more" : " is 0 to 1"));
                if (*f == LpyMaterial::Diffuse && x > lpyMostDiffuse(v.ambient))
                    throw py::value_error("diffuse keeps ambient x diffuse within 255 (PlantGL's Material): at most " +
                                          std::to_string(lpyMostDiffuse(v.ambient)) + " for this ambient colour");
                (*f == LpyMaterial::Diffuse ? v.diffuse : *f == LpyMaterial::Shininess ? v.shininess : v.transparency) = x;
            }
            return setLpyMaterial(text, *found, *f, v);
        },
        py::arg("text"), py::arg("index"), py::arg("field"), py::arg("value"),
        "The model's text with that field of material `index` set (a colour: three numbers 0..255), as L-Py Studio writes it");
}
