// What the turtle takes from a running model: its settings and materials as its context
// (openalea.lpy's _state) holds them, and L-Py's query modules (?P ?H ...) filled with the
// turtle's state where they stand.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "lpy/draw/draw.hpp"
#include "lpy/draw/draw_impl.hpp"

namespace sprout::lpy {

namespace {

std::uint32_t materialColour(py::handle m) {
    try {
        py::object c = m.attr("diffuseColor")();
        const double t = m.attr("transparency").cast<double>();
        auto ch = [](double x) { return std::uint32_t(std::clamp(x, 0.0, 255.0)); };
        return ch(c[py::int_(0)].cast<double>()) << 24 | ch(c[py::int_(1)].cast<double>()) << 16 |
               ch(c[py::int_(2)].cast<double>()) << 8 | ch(std::round((1 - t) * 255));
    } catch (py::error_already_set&) {
        return 0x808080FF;
    }
}

// Its specular colour, shininess and emission, as PlantGL's renderer gives them to OpenGL.
Shine materialShine(py::handle m) {
    Shine out;
    try {
        auto rgb = [&](const char* field) {
            if (!py::hasattr(m, field)) return std::uint32_t(0);
            const py::object c = m.attr(field);
            auto ch = [](double x) { return std::uint32_t(std::clamp(std::isnan(x) ? 0.0 : x, 0.0, 255.0)); };
            return ch(c[py::int_(0)].cast<double>()) << 24 | ch(c[py::int_(1)].cast<double>()) << 16 | ch(c[py::int_(2)].cast<double>()) << 8;
        };
        out.specular = rgb("specular");
        out.emission = rgb("emission");
        if (py::hasattr(m, "shininess")) out.shininess = float(std::clamp(m.attr("shininess").cast<double>(), 0.0, 1.0));
    } catch (py::error_already_set&) {
        return {};
    } catch (py::cast_error&) {
        return {};
    }
    return out;
}

// A texture material's image file (Texture2D(image=ImageTexture(..)), or an ImageTexture given
// as the material) and its colour (Texture2D's baseColor, white by default: the image as it
// is); "" for a plain material.
std::string textureFile(py::handle m, std::uint32_t& colour) {
    try {
        py::object image = py::reinterpret_borrow<py::object>(m);
        if (py::hasattr(m, "image") && !py::hasattr(m, "filename")) image = m.attr("image");
        if (image.is_none() || !py::hasattr(image, "filename")) return "";
        const std::string file = py::str(image.attr("filename")).cast<std::string>();
        colour = 0xFFFFFFFFu;
        if (py::hasattr(m, "baseColor")) {  // PlantGL's Color4: its alpha is a transparency
            const py::object c = m.attr("baseColor");
            auto ch = [&](int k) { return std::uint32_t(std::clamp(c[py::int_(k)].cast<double>(), 0.0, 255.0)); };
            colour = ch(0) << 24 | ch(1) << 16 | ch(2) << 8 | (255 - ch(3));
        }
        return file;
    } catch (py::error_already_set&) {
        return "";
    } catch (py::cast_error&) {
        return "";
    }
}

}  // namespace

TurtleDefaults turtleDefaults(const py::module_& lpyModule) {
    TurtleDefaults d;
    py::dict state = lpyModule.attr("_state");
    if (!state["angle"].is_none()) d.angle = state["angle"].cast<double>();
    d.materials = defaultMaterials();
    for (auto item : py::dict(state["materials"])) {
        const int i = item.first.cast<int>();
        if (i < 0 || i > 255) continue;
        if (size_t(i) >= d.materials.size()) d.materials.resize(size_t(i) + 1, 0xA0A0A0FF);
        std::uint32_t base = 0;
        if (std::string file = textureFile(item.second, base); !file.empty()) {
            d.materials[size_t(i)] = base;
            d.textures.push_back({i, std::move(file)});
            continue;
        }
        d.materials[size_t(i)] = materialColour(item.second);
        if (const Shine shine = materialShine(item.second); !shine.plain()) d.shines.push_back({i, shine});
    }
    return d;
}

void placeTextures(TurtleDefaults& d, const std::string& modelFile, std::vector<Diagnostic>& warnings) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = modelFile.empty() ? fs::path() : fs::path(modelFile).parent_path();
    d.folder = folder.string();
    for (auto& [index, file] : d.textures) {
        const std::string named = file;
        if (fs::path(file).is_relative() && !folder.empty()) file = (folder / file).string();
        if (!fs::is_regular_file(file, ec))
            warnings.push_back({0, 0, "material " + std::to_string(index) + "'s texture image '" + named + "' is not there: drawn in its colour",
                                Severity::Warning});
    }
}

// L-Py's query pre-pass (src/cpp/lsystem.cpp `__step`, module.cpp `_setValues`): the string
// with its interpretation rules drawn by a turtle that keeps no picture, and each query
// module given the turtle's state where it stands.
// The k-th query module of the interpreted string is the k-th of the string.
namespace {
void fillQueriesOnce(Engine& engine, LString& s, const TurtleDefaults& d);
}  // namespace

void fillQueries(Engine& engine, LString& s, const TurtleDefaults& d) {
    // L-Py's turtle fills each query module as it passes it, and the interpretation rules after
    // it see its value. Sprout interprets first, then walks: where a query module had no value
    // yet and an interpretation rule reads one, the walk is made again with the values filled.
    bool bare = false;
    for (const LModule& m : s)
        if (Engine::isQuery(engine.translation().classes.name(m.cls)) && (!m.args || PyTuple_GET_SIZE(m.args.ptr()) == 0)) bare = true;
    fillQueriesOnce(engine, s, d);
    if (bare && engine.interpretationReadsQueries) fillQueriesOnce(engine, s, d);
}

namespace {
void fillQueriesOnce(Engine& engine, LString& s, const TurtleDefaults& d) {
    const ModuleClasses& classes = engine.translation().classes;
    // The string drawn, each module knowing its module in `s` (an interpretation rule's
    // modules come from the module it rewrote): the turtle's k-th query frame is the k-th query
    // module drawn, which is written back where that module is one of `s` copied as it is. A
    // query module an interpretation rule rewrites is not passed by L-Py's turtle: it keeps its values.
    const LString shown = engine.interpret(s);  // (Engine::interpret sets parent and rule so)
    auto g = drawable(shown, classes, d, nullptr, true);
    // The frames as L-Py's turtle has them: PlantGL's arithmetic in double (frames.cpp), not
    // Sprout's single-precision turtle, so that the numbers read back are L-Py's.
    const std::vector<detail::PglFrame> frames = detail::queryFrames(*g);
    py::object vector3 = py::module_::import("openalea.plantgl.all").attr("Vector3");
    auto lpyVector = [&](const glm::dvec3& v) { return vector3(v.x, v.y, v.z); };
    size_t k = 0;
    for (const LModule& drawn : shown) {
        if (!Engine::isQuery(classes.name(drawn.cls))) continue;
        if (k >= frames.size()) break;
        const detail::PglFrame& f = frames[k++];
        if (drawn.rule != -1 || drawn.parent >= s.size() || s[drawn.parent].cls != drawn.cls) continue;
        LModule& m = s[drawn.parent];
        const std::string& name = classes.name(m.cls);
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        if (name[1] == 'F') {
            m.args = py::make_tuple(lpyVector(f.position), lpyVector(f.heading), lpyVector(f.up), lpyVector(f.left));
            continue;
        }
        const glm::dvec3 v = name[1] == 'P' ? f.position : name[1] == 'H' ? f.heading : name[1] == 'U' ? f.up : name[1] == 'L' ? f.left : -f.left;
        // As L-Py's ParamModule::_setValues: three values or more, the first three are x, y, z;
        // two, x and y; one number, x; one other value (a Vector3, a list), its first items
        // set in place; none, a Vector3.
        const double xyz[3] = {v.x, v.y, v.z};
        if (n >= 2) {
            py::list args(m.args);
            for (Py_ssize_t k = 0; k < std::min<Py_ssize_t>(n, 3); ++k) args[size_t(k)] = py::float_(xyz[k]);
            m.args = py::tuple(args);
        } else if (n == 1) {
            py::object arg = py::reinterpret_borrow<py::object>(PyTuple_GET_ITEM(m.args.ptr(), 0));
            if (PyFloat_Check(arg.ptr()) || PyLong_Check(arg.ptr())) {
                m.args = py::make_tuple(xyz[0]);
            } else {
                const Py_ssize_t size = PyObject_Length(arg.ptr());
                if (size < 0) throw py::error_already_set();
                for (Py_ssize_t k = 0; k < std::min<Py_ssize_t>(size, 3); ++k) arg.attr("__setitem__")(k, xyz[k]);
            }
        } else {
            m.args = py::make_tuple(lpyVector(v));
        }
    }
}
}  // namespace

}  // namespace sprout::lpy
