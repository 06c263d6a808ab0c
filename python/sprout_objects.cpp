// `import sprout`: a model's graphical objects as the viewer's editors read and write them
// (issue 52): an L-Py model's 2D curves and materials, in its text.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>

#include "app/plant/lpy_materials.hpp"
#include "app/plant/lpy_objects.hpp"
#include "app/plant/lpy_patches.hpp"
#include "app/plant/lsys_curves.hpp"
#include "app/plant/text_edit.hpp"
#include "core/base/read_file.hpp"
#include "core/language/vlab/colours.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/surface_patches.hpp"
#include "lpy/lpy.hpp"

namespace py = pybind11;
using namespace sprout;

namespace {

// An L-Py model's scalars and patches, a .lsys grammar's functions and contours.
void bindMoreObjects(py::module_& m) {
    m.def(
        "lpy_scalars",
        [](const std::string& text) {
            py::list out;
            for (const LpyScalar& sc : lpyScalars(text)) {
                py::dict d;
                d["name"] = sc.name;
                d["kind"] = sc.kind == LpyScalar::Kind::Bool        ? "Bool"
                            : sc.kind == LpyScalar::Kind::Integer ? "Integer"
                            : sc.kind == LpyScalar::Kind::Category ? "Category"
                                                                   : "Float";
                d["value"] = sc.value;
                d["min"] = sc.min;
                d["max"] = sc.max;
                out.append(d);
            }
            return out;
        },
        py::arg("text"), "The scalars of an L-Py model's INITIALISATION part: name, kind (Integer, Float, Bool, Category: a heading), value, min, max");
    m.def(
        "set_lpy_scalar",
        [](const std::string& text, const std::string& name, double value) {
            if (!std::isfinite(value)) throw py::value_error("a scalar's value is a finite number");
            for (const LpyScalar& sc : lpyScalars(text))
                if (sc.name == name) {
                    if (sc.kind == LpyScalar::Kind::Category) throw py::value_error(name + " is a category, a heading with no value");
                    return setLpyScalar(text, sc, value);
                }
            throw py::key_error("no scalar " + name + " in the model's INITIALISATION part");
        },
        py::arg("text"), py::arg("name"), py::arg("value"), "The model's text with that scalar's value written in place");
    m.def(
        "lpy_patches",
        [](const std::string& text) {
            py::list out;
            for (const LpyPatch& p : lpyPatches(text)) {
                py::dict d;
                d["name"] = p.name;
                d["points"] = p.rows;
                d["udegree"] = p.udegree;
                d["vdegree"] = p.vdegree;
                out.append(d);
            }
            return out;
        },
        py::arg("text"), "The NurbsPatch objects of an L-Py model: name, points (rows along u of (x, y, z, w) along v), udegree, vdegree");
    m.def(
        "set_lpy_patch",
        [](const std::string& text, const std::string& name, const std::vector<std::vector<std::array<double, 4>>>& rows) {
            for (const auto& row : rows)
                for (const auto& q : row)
                    for (double x : q)
                        if (!std::isfinite(x)) throw py::value_error("a patch's points are finite numbers");
            const std::vector<LpyPatch> all = lpyPatches(text);
            for (auto it = all.rbegin(); it != all.rend(); ++it)
                if (it->name == name) {
                    // Another shape is rows or columns added or taken away (issue 52's tools): a
                    // matrix still, of at least the patch's degree + 1 each way.
                    bool matrix = rows.size() >= size_t(it->udegree) + 1 && rows.size() <= 64;
                    for (const auto& row : rows) matrix = matrix && row.size() == rows.front().size() && row.size() >= size_t(it->vdegree) + 1 && row.size() <= 64;
                    if (!matrix)
                        throw py::value_error("a patch's points are rows of one length, at least its degrees + 1 (" +
                                              std::to_string(it->udegree + 1) + " x " + std::to_string(it->vdegree + 1) + ")");
                    return setLpyPatchPoints(text, *it, rows);
                }
            throw py::key_error("no patch " + name + " in the model's INITIALISATION part");
        },
        py::arg("text"), py::arg("name"), py::arg("points"), "The model's text with that patch's control points written in place");
    m.def(
        "lsys_curves",
        [](const std::string& text) {
            py::list out;
            for (const LsysCurve& c : lsysCurves(text)) {
                py::dict d;
                d["name"] = c.name;
                d["kind"] = c.function ? "function" : "contour";
                d["closed"] = c.closed;
                d["line"] = c.line;
                std::vector<std::array<double, 2>> pts;
                for (const auto& p : c.points) pts.push_back({p[0], p[1]});
                d["points"] = pts;
                out.append(d);
            }
            return out;
        },
        py::arg("text"), "The function: and contour: lines of a .lsys grammar: name, kind, closed, line, points (x, y)");
    m.def(
        "set_lsys_curve",
        [](const std::string& text, const std::string& name, const std::vector<std::array<double, 2>>& points) {
            if (points.size() < 2) throw py::value_error("a curve has two points at least");
            std::vector<std::array<double, 3>> pts;
            for (const auto& p : points) {
                if (!std::isfinite(p[0]) || !std::isfinite(p[1])) throw py::value_error("a curve's points are finite numbers");
                pts.push_back({p[0], p[1], 1});
            }
            for (const LsysCurve& c : lsysCurves(text))
                if (c.name == name) return setLsysCurvePoints(text, c, pts);
            throw py::key_error("no function or contour " + name + " in the grammar");
        },
        py::arg("text"), py::arg("name"), py::arg("points"), "The grammar's text with that function's or contour's points written in place");
}

}  // namespace

void bindModelObjects(py::module_& m) {
    m.def(
        "_vlab_rewrite",
        [](const std::string& path) -> py::object {
            // A VLab object's file read and written again in its editor's format (tests/reference/
            // vlab_files_roundtrip.py gives cpfg the files Sprout writes); None: not one Sprout writes.
            const std::string ext = std::filesystem::path(path).extension().string();
            const std::optional<std::string> text = readFile(path);
            if (!text) return py::none();
            std::string error;
            if (ext == ".func") {
                const FunctionRead r = readFunction(*text, path, -1);
                if (r.ok() && r.file) return py::bytes(writeFunction(*r.file));
            } else if (ext == ".fset") {
                const FunctionSetRead r = readFunctionSet(*text, path);
                if (r.ok()) return py::bytes(writeFunctionSet(r.files));
            } else if (ext == ".con" && text->rfind("version:", 0) == 0) {
                const CurveRead r = readCurve(*text, path, 100);
                if (r.ok()) return py::bytes(writeCurve(r.curve));
            } else if (ext == ".con") {
                const ContourRead r = readContour(*text, path);
                if (r.ok() && r.file) return py::bytes(writeContour(*r.file));
            } else if (ext == ".cset") {
                const ContourSetRead r = readContourSet(*text, path);
                if (r.ok()) return py::bytes(writeContourSet(r.files));
            } else if (ext == ".s") {
                const SurfacePatchesRead r = readSurfacePatches(*text, path);
                if (r.ok()) return py::bytes(writeSurfacePatches(*r.surface));
            } else if (ext == ".mat") {
                if (auto set = vlab::readMaterials(*text, error)) return py::bytes(vlab::writeMaterials(*set));
            } else if (ext == ".map") {
                if (auto map = vlab::readColourMap(*text, error)) return py::bytes(vlab::writeColourMap(*map));
            }
            return py::none();
        },
        py::arg("path"), "A VLab object's .func/.fset/.con/.cset/.s/.mat/.map read and written again by Sprout's writers (None: not read)");
    m.def(
        "_lpy_curve_samples",
        [](const std::string& kind, int degree, const std::vector<std::array<double, 3>>& points, int samples) {
            return lpy::curveSamples(kind == "Bezier" ? 1 : kind == "Polyline" ? 2 : 0, degree, points, samples);
        },
        "Points along an L-Py curve as PlantGL evaluates it (the picture of sprout.editor)");
    // An L-Py model's 2D curves as the viewer's curve editor reads and writes them (issue 52).
    m.def(
        "lpy_curves",
        [](const std::string& text) {
            py::list out;
            const std::vector<LpyCurve> all = lpyCurves(text);
            for (size_t k = 0; k < all.size(); ++k) {
                const LpyCurve& c = all[k];
                py::dict d;
                d["name"] = c.name;
                d["key"] = lpyCurveKey(all, k);  // NAME#k: a version before the last, which several panels set
                d["kind"] = c.kind == LpyCurve::Kind::Bezier ? "Bezier" : c.kind == LpyCurve::Kind::Polyline ? "Polyline" : "NURBS";
                d["function"] = c.function;
                d["degree"] = c.degree;
                d["line"] = c.line;
                d["points"] = c.points;
                out.append(d);
            }
            return out;
        },
        py::arg("text"),
        "The 2D curves of an L-Py model's INITIALISATION part: name, key (NAME#k for a version before the last), kind, function, "
        "degree, line, points (x, y, w)");
    m.def(
        "set_lpy_curve",
        [](const std::string& text, const std::string& name, const std::vector<std::array<double, 3>>& points) {
            if (points.size() < 2) throw py::value_error("a curve has two points at least");
            for (const auto& p : points)
                if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                    throw py::value_error("a curve's points are finite numbers");
            const std::vector<LpyCurve> curves = lpyCurves(text);
            if (const LpyCurve* c = lpyCurveNamed(curves, name)) return setLpyCurvePoints(text, *c, points);  // NAME, or NAME#k
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
            if (field == "image") {  // a texture material's image file
                const std::vector<LpyMaterial> all = lpyMaterials(text);
                for (auto it = all.rbegin(); it != all.rend(); ++it)
                    if (it->index == index && !it->texture.empty()) {
                        std::string error;
                        const std::string out = setLpyTextureFile(text, *it, value.cast<std::string>(), error);
                        if (out.empty()) throw py::value_error(error);
                        return out;
                    }
                throw py::key_error("no texture material " + std::to_string(index) + " in the model's INITIALISATION part");
            }
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
        "The model's text with that field of material `index` set (a colour: three numbers 0..255; a texture's `image`: its file), as L-Py Studio writes it");
    bindMoreObjects(m);
}
