#include "app/export/svg.hpp"

#include "core/base/atomic_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>

#include "app/mesh/bake.hpp"
#include "app/mesh/meshes.hpp"

namespace sprout::exporter {
namespace {

struct Projection {
    int u = 0, v = 1;        // world axes drawn right and up
    float scale = 1, ou = 0, ov = 0, height = 1000;
    glm::vec2 operator()(const glm::vec3& p) const {
        return {(p[u] - ou) * scale, height - (p[v] - ov) * scale};
    }
};

void num(std::string& s, float x) {
    char tmp[32];
    auto r = std::to_chars(tmp, tmp + sizeof tmp, x, std::chars_format::fixed, 2);
    if (r.ec != std::errc()) r = std::to_chars(tmp, tmp + sizeof tmp, x);  // past 1e29: shortest form (1e+30)
    s.append(tmp, r.ptr);
}

std::string rgb(std::uint32_t c) {
    char b[16];
    std::snprintf(b, sizeof b, "#%06x", unsigned(c >> 8));
    return b;
}

}  // namespace

bool writeSvg(const Geometry& g, const std::string& path, const ExportOptions& o, ExportStats& st, std::string& error) {
    // The plane: drop the axis along which the plant is flattest (planar systems), else the
    // front view (x right, y up) the renderer shows.
    const Bounds bounds = g.extent();  // the plant and a VLab object's background scene
    const glm::vec3 size = bounds.empty ? glm::vec3(1.0f) : bounds.size();
    Projection pr;
    if (g.planarCurve) {
        int flat = size.x <= size.y && size.x <= size.z ? 0 : size.y <= size.z ? 1 : 2;
        pr.u = flat == 0 ? 2 : 0;
        pr.v = flat == 1 ? 2 : 1;
    }
    const float w = std::max(size[pr.u], 1e-6f), h = std::max(size[pr.v], 1e-6f);
    const float big = std::max(w, h);
    pr.scale = 1000.0f / big;
    const float margin = 20.0f;
    const float W = w * pr.scale + 2 * margin, H = h * pr.scale + 2 * margin;
    pr.ou = (bounds.empty ? 0 : bounds.min[pr.u]) - margin / pr.scale;
    pr.ov = (bounds.empty ? 0 : bounds.min[pr.v]) - margin / pr.scale;
    pr.height = H;
    const float minWidth = 0.6f;  // a hairline still shows

    std::string s;
    s.reserve(1 << 20);
    s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- " + o.generator + " -->\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ";
    num(s, W), s += " ", num(s, H);
    s += "\" width=\"";
    num(s, W), s += "\" height=\"", num(s, H);
    s += "\">\n<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";

    // Stems: consecutive connected segments of one colour and width make one polyline.
    std::size_t i = 0;
    const auto& cyl = g.cylinders;
    while (i < cyl.size()) {
        const CylinderInstance& c0 = cyl[i];
        float width = std::max((c0.startRadius + c0.endRadius) * pr.scale, minWidth);
        s += "<polyline stroke=\"" + rgb(c0.colour) + "\" stroke-width=\"";
        num(s, width);
        if ((c0.colour & 0xffu) != 0xffu) s += "\" stroke-opacity=\"" + std::to_string(float(c0.colour & 0xffu) / 255.0f);
        s += "\" points=\"";
        glm::vec2 p = pr(c0.start);
        num(s, p.x), s += ",", num(s, p.y);
        std::size_t j = i;
        for (;;) {
            glm::vec2 q = pr(cyl[j].end);
            s += " ", num(s, q.x), s += ",", num(s, q.y);
            ++st.stems;
            if (j + 1 >= cyl.size()) break;
            const CylinderInstance &a = cyl[j], &b = cyl[j + 1];
            float wb = std::max((b.startRadius + b.endRadius) * pr.scale, minWidth);
            if (b.colour != a.colour || std::fabs(wb - width) > 0.05f || glm::length(b.start - a.end) * pr.scale > 0.01f) break;
            ++j;
        }
        s += "\"/>\n";
        i = j + 1;
    }
    s += "</g>\n";

    // Leaves, petals, spheres and polygons: filled triangles, one path per colour.
    mesh::BakedMesh baked;
    const mesh::SurfaceMesh leaf = mesh::makeLeaf(), petal = mesh::makePetal(), sphere = mesh::makeSphere(12, 8);
    for (const auto& x : g.surfaces)
        mesh::bakeSurface(x, x.kind == SurfaceKind::Leaf ? leaf : x.kind == SurfaceKind::Petal ? petal : sphere, baked);
    mesh::bakePolygons(g.polygons, baked);
    std::map<std::uint32_t, std::string> fills;
    for (std::size_t t = 0; t + 2 < baked.indices.size(); t += 3) {
        const auto& a = baked.vertices[baked.indices[t]];
        std::string& d = fills[a.colour];
        for (int k = 0; k < 3; ++k) {
            glm::vec2 q = pr(baked.vertices[baked.indices[t + k]].position);
            d += k ? "L" : "M";
            num(d, q.x), d += ",", num(d, q.y);
        }
        d += "Z";
        ++st.triangles;
    }
    for (const auto& [colour, d] : fills) {
        // A hairline of the same colour closes the seams between triangles.
        s += "<path fill=\"" + rgb(colour) + "\" stroke=\"" + rgb(colour) + "\" stroke-width=\"0.3\" stroke-linejoin=\"round\" d=\"" +
             d + "\"/>\n";
    }
    st.materials = fills.size();
    // Texts (L-Py's @L labels) where they stand, in their colour and size (pixels of the view).
    for (const Geometry::Label& l : g.labels) {
        const glm::vec2 q = pr(l.position);
        s += "<text x=\"";
        num(s, q.x), s += "\" y=\"", num(s, q.y);
        s += "\" font-family=\"sans-serif\" font-size=\"";
        num(s, l.size);
        s += "\" fill=\"" + rgb(l.colour) + "\">";
        for (char c : l.text) {
            if (c == '<') s += "&lt;";
            else if (c == '>') s += "&gt;";
            else if (c == '&') s += "&amp;";
            else if (std::uint8_t(c) >= 0x20 || c == '\t') s += c;
        }
        s += "</text>\n";
    }
    s += "</svg>\n";

    if (!writeFileAtomically(path, s, error)) return false;
    st.bytes = s.size();
    return true;
}

}  // namespace sprout::exporter
