// What L-Py draws at the turtle without moving it, and its colours: PlantGL shapes (@g) made
// into surfaces of the drawing, labels (@L), frames (Frame), and the palette's entries for
// colours given as numbers (SetColor(r, g, b), InterpolateColors). Its own file: each of these
// reads Python objects or the palette, not the turtle's walk.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "core/language/surface_file.hpp"
#include "lpy/draw/draw_impl.hpp"
#include "lpy/plantgl/bindings.hpp"

namespace sprout::lpy::detail {

namespace {

// A shape's triangles in the drawing's frame: normals from the faces around each point (by
// area), a copied point's with those of the point it copies (`same`: ShapeMesh::sameNormal);
// a curve's stems alone (no triangles) keep no points.
void finishSurface(SurfaceFile& sf, const std::vector<long>& same = {}) {
    if (sf.indices.empty()) sf.positions.clear(), sf.colours.clear(), sf.uvs.clear();
    const size_t np = sf.positions.size();
    auto at = [&](std::uint32_t k) { return k < same.size() && same[k] >= 0 && size_t(same[k]) < np ? size_t(same[k]) : size_t(k); };
    sf.normals.assign(np, glm::vec3(0));
    for (size_t i = 0; i + 2 < sf.indices.size(); i += 3) {
        const glm::vec3 &a = sf.positions[sf.indices[i]], &b = sf.positions[sf.indices[i + 1]], &c = sf.positions[sf.indices[i + 2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        for (int j = 0; j < 3; ++j) sf.normals[at(sf.indices[i + size_t(j)])] += n;
    }
    for (size_t k = 0; k < std::min(same.size(), np); ++k) sf.normals[k] = sf.normals[at(std::uint32_t(k))];
    for (glm::vec3& n : sf.normals) n = glm::length(n) > 0 ? glm::normalize(n) : glm::vec3(0, 0, 1);
}

// PlantGL's shape frame is the turtle's up, right (-left) and heading (PglTurtle::transform:
// Oriented(up, -left)); the surface's is heading, left, up.
glm::vec3 fromShapeFrame(double x, double y, double z) { return {float(z), -float(y), float(x)}; }

// Sprout's AsymmetricHull (openalea.plantgl's, no subclass) given alone: meshed in C++ with its
// fields read leniently (lpy/plantgl/meshes.cpp's hullMesh), and kept even without triangles,
// as the drawing always has (a crown model draws thousands).
bool hullSurface(PyObject* shape, SurfaceFile& sf) {
    PyTypeObject* type = Py_TYPE(shape);
    if (std::string_view(type->tp_name) != "AsymmetricHull") return false;
    PyObject* module = PyObject_GetAttrString(reinterpret_cast<PyObject*>(type), "__module__");
    const bool ours = module && PyUnicode_Check(module) && std::string_view(PyUnicode_AsUTF8(module)).starts_with("openalea.plantgl");
    Py_XDECREF(module);
    PyErr_Clear();
    if (!ours) return false;
    const ShapeMesh mesh = hullMesh(shape);
    sf.positions.reserve(mesh.points.size());
    for (const auto& q : mesh.points) sf.positions.push_back(fromShapeFrame(q[0], q[1], q[2]));
    for (const auto& t : mesh.triangles)
        for (long v : t) sf.indices.push_back(std::uint32_t(v));
    return true;
}

}  // namespace

// @g's shapes: each shape object made into triangles once (lpy/plantgl/meshes.cpp), a surface
// of the drawing named after it; "" for one with no surface.
const std::string& Drawing::shapeSurface(PyObject* shape) {
    auto [it, fresh] = m_shapes.try_emplace(shape);
    if (!fresh || !shape) return it->second;
    auto sf = std::make_shared<SurfaceFile>();
    std::vector<long> same;  // the mesh's points that share a normal
    auto keep = [&] {
        finishSurface(*sf, same);
        it->second = "@g#" + std::to_string(g->surfaceFiles.size());
        g->surfaceFiles[it->second] = std::move(sf);
    };
    if (hullSurface(shape, *sf)) {
        keep();
        return it->second;
    }
    const ShapeMesh mesh = shapeMesh(shape);
    if (mesh.kind == ShapeMesh::Nothing) return it->second;  // not drawn
    const size_t np = mesh.points.size(), nt = mesh.triangles.size(), ns = mesh.segments.size();
    if (np == 0 && nt == 0 && ns == 0) it->second = "-";  // a shape with nothing to draw: no warning
    bool ok = np > 0 && np < 10'000'000 && nt < 10'000'000 && ns < 10'000'000;
    for (size_t i = 0; i < np && ok; ++i) sf->positions.push_back(fromShapeFrame(mesh.points[i][0], mesh.points[i][1], mesh.points[i][2]));
    for (size_t i = 0; i < nt && ok; ++i) {
        for (long v : mesh.triangles[i]) ok = ok && v >= 0 && size_t(v) < np;
        if (ok)
            for (long v : mesh.triangles[i]) sf->indices.push_back(std::uint32_t(v));
    }
    for (size_t i = 0; i < ns && ok; ++i) {
        const auto& e = mesh.segments[i];
        ok = e[0] >= 0 && size_t(e[0]) < np && e[1] >= 0 && size_t(e[1]) < np;
        if (ok) sf->lines.push_back(sf->positions[size_t(e[0])]), sf->lines.push_back(sf->positions[size_t(e[1])]);
    }
    if (ok && mesh.colours.size() == np) sf->colours = mesh.colours;
    if (ok && mesh.uvs.size() == np) sf->uvs = mesh.uvs;
    if (ok && mesh.sameNormal.size() == np) same = mesh.sameNormal;
    if (ok && !sf->uvs.empty() && !mesh.texture.empty()) {  // its Shape's image, found beside the model
        std::filesystem::path file(mesh.texture);
        if (file.is_relative() && !folder.empty()) file = std::filesystem::path(folder) / file;
        sf->texture = file.string();
    }
    if (ok && (!sf->indices.empty() || !sf->lines.empty())) keep();
    return it->second;
}

int Drawing::labelIndex(PyObject* text) {
    PyObject* str = text ? PyObject_Str(text) : nullptr;
    Py_ssize_t length = 0;
    const char* utf8 = str ? PyUnicode_AsUTF8AndSize(str, &length) : nullptr;
    int index = -1;
    if (utf8 && length > 0) {
        auto& labels = g->settings.labels;
        // At most 200 bytes, cut where a character begins (the text stays UTF-8: exported
        // models carry it).
        size_t n = size_t(std::min<Py_ssize_t>(length, 200));
        while (n < size_t(length) && n > 0 && (std::uint8_t(utf8[n]) & 0xC0) == 0x80) --n;
        std::string t(utf8, n);
        auto found = m_labelIndex.find(t);
        if (found == m_labelIndex.end() && labels.size() < 100000) {
            found = m_labelIndex.emplace(t, int(labels.size())).first;
            labels.push_back(t);
        }
        if (found != m_labelIndex.end()) index = found->second;
    }
    Py_XDECREF(str);
    return index;
}

int Drawing::paletteIndex(std::uint32_t rgba) {
    auto& pal = g->settings.palette;
    auto found = std::find(pal.begin(), pal.end(), rgba);
    if (found != pal.end()) return int(found - pal.begin());
    if (pal.size() < 250) {
        pal.push_back(rgba);
        return int(pal.size()) - 1;
    }
    int best = 0;
    long bestD = -1;
    for (size_t i = 0; i < pal.size(); ++i) {
        long d = 0;
        for (int shift = 8; shift <= 24; shift += 8) d += std::labs(long((pal[i] >> shift) & 0xFF) - long((rgba >> shift) & 0xFF));
        if (bestD < 0 || d < bestD) bestD = d, best = int(i);
    }
    return best;
}

// PlantGL's _frame: three arrows (heading red, up blue, left green), each a stick and a cone.
void Drawing::frame(const std::vector<double>& p) {
    const double size = p.size() >= 1 ? p[0] : 1.0, capHeight = p.size() >= 2 ? std::clamp(p[1], 0.0, 1.0) : 0.2,
                 capRadius = p.size() >= 3 ? std::max(p[2], 0.0) : 2.0;
    if (!(size > 0)) return;
    const std::pair<const char*, std::uint32_t> arrows[] = {
        {nullptr, 0xFA3232FFu}, {"^", 0x3232FAFFu}, {"+", 0x32FA32FFu}};  // heading, up, left
    for (const auto& [turn, rgba] : arrows) {
        w.put("[", {});
        if (turn) w.put(turn, {90});
        w.put(";", {double(paletteIndex(rgba))});
        w.put("!", {2 * st.width});
        if (capHeight < 1) w.put("F", {size * (1 - capHeight)});
        w.put("f", {0});  // the stick keeps its width: the cap's starts anew
        w.put("!", {2 * st.width * capRadius});
        if (capHeight > 0) w.put("F", {size * capHeight});
        w.put("!", {0});  // a cone
        w.put("]", {});
    }
}

// PlantGL mixes the two materials.
void Drawing::interpolateColours(const std::vector<double>& p) {
    const auto& pal = g->settings.palette;
    auto at = [&](double x) { return pal[size_t(std::clamp(int(std::lround(std::clamp(x, -1e6, 1e6))), 0, int(pal.size()) - 1))]; };
    const std::uint32_t a = at(p[0]), b = at(p[1]);
    const double f = p.size() >= 3 ? std::clamp(p[2], 0.0, 1.0) : 0.5;
    std::uint32_t mixed = 0;
    for (int shift = 24; shift >= 0; shift -= 8)
        mixed |= std::uint32_t(std::lround(double((a >> shift) & 0xFF) * (1 - f) + double((b >> shift) & 0xFF) * f)) << shift;
    w.put(";", {double(paletteIndex(mixed))});
}

void Drawing::textureBaseColour(const std::vector<double>& p, bool interpolate) {
    auto& pal = g->settings.palette;
    auto& textures = g->settings.textures;
    const auto image = std::find_if(textures.begin(), textures.end(), [&](const auto& t) { return t.first == st.colour; });
    if (image == textures.end() || pal.size() >= 250) return;  // not a texture: PlantGL leaves the material
    auto at = [&](double x) { return pal[size_t(std::clamp(int(std::lround(std::clamp(x, -1e6, 1e6))), 0, int(pal.size()) - 1))]; };
    auto c = [](double x) { return std::uint32_t(std::clamp(x, 0.0, 255.0)); };
    std::uint32_t rgba = 0;
    if (interpolate && p.size() >= 2) {  // the two materials' colours mixed
        const std::uint32_t a = at(p[0]), b = at(p[1]);
        const double f = p.size() >= 3 ? std::clamp(p[2], 0.0, 1.0) : 0.5;
        for (int shift = 24; shift >= 0; shift -= 8)
            rgba |= std::uint32_t(std::lround(double((a >> shift) & 0xFF) * (1 - f) + double((b >> shift) & 0xFF) * f)) << shift;
    } else if (!interpolate && p.size() >= 3) {  // Color4: its alpha a transparency
        rgba = c(p[0]) << 24 | c(p[1]) << 16 | c(p[2]) << 8 | (p.size() >= 4 ? 255 - c(p[3]) : 255u);
    } else if (!interpolate) {  // a material's diffuse colour
        rgba = at(p[0]);
    } else {
        return;
    }
    const std::string file = image->second;  // (the push below may move the list)
    pal.push_back(rgba);
    textures.push_back({int(pal.size()) - 1, file});
    w.put(";", {double(pal.size() - 1)});  // (st.colour stays the material's: ; and , count from it)
}

void Drawing::setRgbaColour(const std::vector<double>& p) {
    auto c = [](double x) { return std::uint32_t(std::clamp(x, 0.0, 255.0)); };
    const std::uint32_t rgba = c(p[0]) << 24 | c(p[1]) << 16 | c(p[2]) << 8 | (p.size() >= 4 ? c(p[3]) : 255u);
    auto& pal = g->settings.palette;
    auto found = std::find(pal.begin(), pal.end(), rgba);
    if (found == pal.end() && pal.size() < 250) {
        pal.push_back(rgba);
        found = pal.end() - 1;
    }
    if (found != pal.end()) w.put(";", {double(found - pal.begin())});
}

}  // namespace sprout::lpy::detail
