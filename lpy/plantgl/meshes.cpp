// The PlantGL shapes a model gives to @g (a Scene, Groups, Shapes, transformed shapes, Boxes,
// Spheres, tubes, discs, meshes, point sets, polylines, curves, patches, crowns) made into
// points, triangles and segments: the only meshing of them, written from the Python meshing
// Sprout had before (plantgl_drawing.py's _sprout_triangles) with the same numbers in the same
// order (its operations written out one by one), so that the drawing is the same. Where the
// Python raised, or gave what the drawing refused (a point of fewer than three numbers), the
// shape is not drawn: Raises.
//
// Index of this file:
//   [SECTION] Python's values, read as the Python meshing read them: meshing.hpp
//   [SECTION] Vectors and matrices (plantgl_vectors.py's arithmetic): vector_math.hpp
//   [SECTION] Meshes put together
//   [SECTION] Groups and transformations
//   [SECTION] Solids (Box, Sphere, Cylinder, Cone, Frustum, Paraboloid, Disc): solids.cpp
//   [SECTION] Points, faces, curves and patches
//   [SECTION] The crown (AsymmetricHull)
//   [SECTION] The shape's kind, and shapeMesh
#include <algorithm>
#include <cmath>
#include <string_view>

#include "lpy/plantgl/asymmetric_hull.hpp"
#include "lpy/plantgl/bindings.hpp"
#include "lpy/plantgl/meshing.hpp"
#include "lpy/plantgl/py_numbers.hpp"
#include "lpy/plantgl/vector_math.hpp"

namespace sprout::lpy {
namespace meshing {
namespace {

// [SECTION] Python's values, read as the Python meshing read them: meshing.hpp

// [SECTION] Vectors and matrices (plantgl_vectors.py's arithmetic): vector_math.hpp

// [SECTION] Meshes put together

// `mesh`'s points (transformed), triangles and segments after the points so far.
template <class Transform>
void add(ShapeMesh& to, const ShapeMesh& mesh, Transform f) {
    if (mesh.kind != ShapeMesh::Mesh) return;
    const long base = long(to.points.size());
    if (!mesh.colours.empty() || !to.colours.empty())  // the colours stay with their points
        to.colours.resize(size_t(base), 0), to.colours.insert(to.colours.end(), mesh.colours.begin(), mesh.colours.end()),
            to.colours.resize(size_t(base) + mesh.points.size(), 0);
    if (to.texture.empty()) to.texture = mesh.texture;
    if (!mesh.uvs.empty() || !to.uvs.empty())  // and the texture coordinates (none: 0, 0)
        to.uvs.resize(size_t(base)), to.uvs.insert(to.uvs.end(), mesh.uvs.begin(), mesh.uvs.end()), to.uvs.resize(size_t(base) + mesh.points.size());
    if (!mesh.sameNormal.empty() || !to.sameNormal.empty()) {  // and which share a normal (none: each its own)
        for (long k = long(to.sameNormal.size()); k < base; ++k) to.sameNormal.push_back(k);
        for (size_t k = 0; k < mesh.points.size(); ++k) to.sameNormal.push_back(base + (k < mesh.sameNormal.size() ? mesh.sameNormal[k] : long(k)));
    }
    // An index below 0 (a face set's, kept) reaches back into the meshes before, over their
    // points as they were before copies were made (ShapeMesh::sameNormal): the copies skipped.
    std::vector<long> uncopied;  // the points before, copies left out: made once, when an index needs it
    auto at = [&](long v) {
        if (v >= 0 || to.sameNormal.empty()) return v + base;
        if (uncopied.empty())
            for (long k = 0; k < base; ++k)
                if (to.sameNormal[size_t(k)] == k) uncopied.push_back(k);
        const long n = long(uncopied.size());
        return -v <= n ? uncopied[size_t(n + v)] : -1;  // before the first point: refused, as it was
    };
    for (const V3& p : mesh.points) to.points.push_back(f(p));
    for (const auto& t : mesh.triangles) to.triangles.push_back({at(t[0]), at(t[1]), at(t[2])});
    for (const auto& s : mesh.segments) to.segments.push_back({at(s[0]), at(s[1])});
}
void add(ShapeMesh& to, const ShapeMesh& mesh) {
    add(to, mesh, [](const V3& p) { return p; });
}

// The (n + 1)^2 points of a grid, i outer, as two triangles a cell.
ShapeMesh gridMesh(std::vector<V3> points, long n) {
    ShapeMesh m = mesh();
    m.points = std::move(points);
    for (long i = 0; i < n; ++i)
        for (long j = 0; j < n; ++j) {
            m.triangles.push_back({i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1});
            m.triangles.push_back({i * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1});
        }
    return m;
}

ShapeMesh of(PyObject* obj, int depth);

// [SECTION] Groups and transformations

// A list, a tuple, a Scene or a Group (its geometryList): its shapes' meshes one after the
// other; an empty group is a shape with nothing to draw.
ShapeMesh group(PyObject* obj, bool isGroup, int depth) {
    PyObject* list = isGroup ? attribute(obj, "geometryList") : nullptr;
    const Ref source(list ? list : Py_NewRef(obj));
    const Ref seq(PySequence_Fast(source.p, "shapes"));
    ShapeMesh m;
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) add(m, of(PySequence_Fast_GET_ITEM(seq.p, k), depth + 1));
    m = result(std::move(m));
    return m.kind == ShapeMesh::Nothing ? mesh() : m;
}

ShapeMesh geometryOf(PyObject* obj, int depth) {
    const Ref g(attributeOr(obj, "geometry", none()));
    return of(g.p, depth + 1);
}

// A Shape: its geometry in its appearance's colour (shapeColour) where an inner one gave none.
ShapeMesh shapeOf(PyObject* obj, int depth) {
    ShapeMesh m = geometryOf(obj, depth);
    std::uint32_t rgba = m.kind == ShapeMesh::Mesh ? shapeColour(obj) : 0;
    if (m.kind == ShapeMesh::Mesh && m.texture.empty() && !m.uvs.empty() && !(m.texture = shapeTexture(obj)).empty())
        rgba = 0xFFFFFFFFu;  // its image as it is (Texture2D's base colour), not the turtle's colour times it
    if (rgba) m.colours.resize(m.points.size(), 0);
    for (std::uint32_t& k : m.colours) k = k ? k : rgba;
    return m;
}

// x * p[0] + y * p[1] + z * p[2] of PlantGL's vectors, vector by vector.
V3 combined(const V3& x, const V3& y, const V3& z, const V3& p) {
    const V3 a{x[0] * p[0], x[1] * p[0], x[2] * p[0]}, b{y[0] * p[1], y[1] * p[1], y[2] * p[1]};
    const V3 ab{a[0] + b[0], a[1] + b[1], a[2] + b[2]}, c{z[0] * p[2], z[1] * p[2], z[2] * p[2]};
    return V3{ab[0] + c[0], ab[1] + c[1], ab[2] + c[2]};
}

// Scaled, Translated, AxisRotated, EulerRotated, Oriented: the inner shape's mesh, moved.
ShapeMesh transformed(PyObject* obj, std::string_view name, int depth) {
    const ShapeMesh inner = geometryOf(obj, depth);
    if (inner.kind == ShapeMesh::Nothing) return {};
    // A scale or translation of fewer than three numbers raised at the first point moved.
    auto check = [&](Py_ssize_t n) {
        if (n < 3 && !inner.points.empty()) raise();
    };
    ShapeMesh m;
    if (name == "Scaled") {
        const Ref sv(attributeOr(obj, "scale", PyLong_FromLong(1)));
        Py_ssize_t n = 0;
        const V3 s = sizes(sv.p, 1, n);
        check(n);
        add(m, inner, [&](const V3& p) { return V3{p[0] * s[0], p[1] * s[1], p[2] * s[2]}; });
    } else if (name == "Translated") {
        const Ref tv(attributeOr(obj, "translation", Py_BuildValue("(iii)", 0, 0, 0)));
        Py_ssize_t n = 0;
        const V3 t = upToThree(tv.p, num0, n);
        check(n);
        add(m, inner, [&](const V3& p) { return V3{p[0] + t[0], p[1] + t[1], p[2] + t[2]}; });
    } else if (name == "AxisRotated") {
        const Ref av(attributeOr(obj, "axis", Py_BuildValue("(iii)", 0, 0, 1)));
        const M3 r = axisRotation(normed(vector3(av.p)), field(obj, "angle", 0));
        add(m, inner, [&](const V3& p) { return times(r, p); });
    } else if (name == "EulerRotated") {  // z (azimuth), then y (elevation), then x (roll)
        const double a = field(obj, "azimuth", 0), e = field(obj, "elevation", 0), ro = field(obj, "roll", 0);
        const M3 r = times(times(axisRotation({0, 0, 1}, a), axisRotation({0, 1, 0}, e)), axisRotation({1, 0, 0}, ro));
        add(m, inner, [&](const V3& p) { return times(r, p); });
    } else {  // Oriented
        const Ref pv(attributeOr(obj, "primary", Py_BuildValue("(iii)", 1, 0, 0)));
        const V3 x = normed(vector3(pv.p));
        const Ref sv(attributeOr(obj, "secondary", Py_BuildValue("(iii)", 0, 1, 0)));
        const V3 y = normed(vector3(sv.p));
        const V3 z = normed({x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]});
        add(m, inner, [&](const V3& p) { return combined(x, y, z, p); });
    }
    return result(std::move(m));
}

// [SECTION] Solids (Box, Sphere, Cylinder, Cone, Frustum, Paraboloid, Disc): solids.cpp

// [SECTION] Points, faces, curves and patches

// A polyline's points (a Polyline's pointList, a curve's points()) and the segments between.
ShapeMesh polyline(PyObject* points) {
    const Ref seq(PySequence_Fast(points, "points"));
    ShapeMesh m;
    bool whole = true;
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) {
        V3 p;
        whole = point(PySequence_Fast_GET_ITEM(seq.p, k), p) && whole;
        m.points.push_back(p);
    }
    for (long k = 0; k + 1 < long(m.points.size()); ++k) m.segments.push_back({k, k + 1});
    if (!whole && !m.segments.empty()) raise();
    return result(std::move(m));
}

// Each point a small octahedron, its size from the set's extent.
ShapeMesh pointSet(PyObject* obj) {
    const Ref list(attributeOr(obj, "pointList", PyTuple_New(0)));
    const Ref seq(PySequence_Fast(list.p, "points"));
    std::vector<V3> points;
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) {
        V3 p;
        if (!point(PySequence_Fast_GET_ITEM(seq.p, k), p)) raise();  // q[2] of the Python's two zeros
        points.push_back(p);
    }
    if (points.empty()) return mesh();
    // max(max(q[k]) - min(q[k]) for k in range(3)): Python's min and max keep the first unless
    // another is smaller (larger), as these comparisons do, NaN included.
    double extent = 0;
    for (int k = 0; k < 3; ++k) {
        double lo = points[0][size_t(k)], hi = points[0][size_t(k)];
        for (const V3& q : points) lo = q[size_t(k)] < lo ? q[size_t(k)] : lo, hi = q[size_t(k)] > hi ? q[size_t(k)] : hi;
        const double e = hi - lo;
        if (k == 0 || e > extent) extent = e;
    }
    const double r = extent > 0 ? 0.005 * extent : 0.01;
    static const int dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    ShapeMesh m;
    for (const V3& q : points) {
        const long base = long(m.points.size());
        for (const auto& d : dirs) m.points.push_back({q[0] + d[0] * r, q[1] + d[1] * r, q[2] + d[2] * r});
        for (const auto& f : faces) m.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    }
    return result(std::move(m));
}

// A texCoordList's (u, v) pairs; where one is not two numbers, none.
std::vector<std::array<float, 2>> uvList(PyObject* list) {
    std::vector<std::array<float, 2>> out;
    const Py_ssize_t n = PyObject_Length(list);
    for (Py_ssize_t k = 0; k < n; ++k) {
        PyObject* q = PySequence_GetItem(list, k);
        std::vector<double> c;
        const bool ok = q && pynum::numbers(q, c) && c.size() >= 2;
        Py_XDECREF(q);
        if (!ok) return {};
        out.push_back({float(std::clamp(c[0], -1e30, 1e30)), float(std::clamp(c[1], -1e30, 1e30))});  // (NaN: kept)
    }
    PyErr_Clear();
    return out;
}

// A face set's texture coordinates by face (texCoordIndexList: each face's corners' entries in
// `uvs`): each face's corners become copies of their points (sharing their normals) with their
// own (u, v), the triangles on the copies. Where the lists do not match the faces, none.
void cornerUvs(ShapeMesh& m, const std::vector<std::vector<long>>& faces, const std::vector<std::array<float, 2>>& uvs, PyObject* index) {
    const Py_ssize_t nf = PyObject_Length(index);
    if (nf != Py_ssize_t(faces.size())) return PyErr_Clear();
    std::vector<std::vector<long>> corners;
    for (Py_ssize_t k = 0; k < nf; ++k) {
        PyObject* face = PySequence_GetItem(index, k);
        std::vector<double> c;
        const bool ok = face && pynum::numbers(face, c) && c.size() == faces[size_t(k)].size();
        Py_XDECREF(face);
        if (!ok) return PyErr_Clear();
        corners.emplace_back();
        for (double x : c) {
            if (!(x >= 0 && x < double(uvs.size()))) return;
            corners.back().push_back(long(x));
        }
    }
    const long np = long(m.points.size());
    m.uvs.assign(size_t(np), {0.0f, 0.0f});
    m.sameNormal.resize(size_t(np));
    for (long k = 0; k < np; ++k) m.sameNormal[size_t(k)] = k;
    m.triangles.clear();
    for (size_t k = 0; k < faces.size(); ++k) {
        const std::vector<long>& f = faces[k];
        std::vector<long> made(f.size(), -1);
        auto copy = [&](size_t j) {  // corner j of face k, as a point of its own (once)
            if (made[j] >= 0) return made[j];
            m.points.push_back(m.points[size_t(f[j])]);
            m.uvs.push_back(uvs[size_t(corners[k][j])]);
            m.sameNormal.push_back(f[j]);
            return made[j] = long(m.points.size()) - 1;
        };
        for (size_t j = 1; j + 1 < f.size(); ++j) {
            if (std::max({f[0], f[j], f[j + 1]}) >= np) continue;
            if (std::min({f[0], f[j], f[j + 1]}) < 0) m.triangles.push_back({f[0], f[j], f[j + 1]});  // refused, as it was
            else m.triangles.push_back({copy(0), copy(j), copy(j + 1)});
        }
    }
}

// TriangleSet, QuadSet, FaceSet: each face a fan from its first point, the triangles whose
// points are there (an index below 0 is kept: the drawing refuses it, as it did).
ShapeMesh faceSet(PyObject* obj) {
    ShapeMesh m;
    bool whole = true;
    const Ref list(attributeOr(obj, "pointList", PyTuple_New(0)));
    const Ref seq(PySequence_Fast(list.p, "points"));
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) {
        Py_ssize_t n = 0;
        m.points.push_back(upToThree(PySequence_Fast_GET_ITEM(seq.p, k), num0, n));
        whole = whole && n == 3;
    }
    const Ref faces(attributeOr(obj, "indexList", PyTuple_New(0)));
    const Ref fseq(PySequence_Fast(faces.p, "faces"));
    std::vector<std::vector<long>> kept;
    for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(fseq.p); ++k) {
        const Ref face(PySequence_Fast(PySequence_Fast_GET_ITEM(fseq.p, k), "face"));
        std::vector<long> f;
        for (Py_ssize_t j = 0; j < PySequence_Fast_GET_SIZE(face.p); ++j) {
            long v = 0;
            if (!pynum::intOf(PySequence_Fast_GET_ITEM(face.p, j), v)) raise();
            f.push_back(v);
        }
        for (size_t j = 1; j + 1 < f.size(); ++j)
            if (std::max({f[0], f[j], f[j + 1]}) < long(m.points.size())) m.triangles.push_back({f[0], f[j], f[j + 1]});
        kept.push_back(std::move(f));
    }
    if (m.triangles.empty()) return {};
    if (!whole) raise();  // a point of fewer than three numbers, refused by the drawing
    const Ref uv(attributeOr(obj, "texCoordList", none())), uvIndex(attributeOr(obj, "texCoordIndexList", none()));  // (u, v) a point
    const std::vector<std::array<float, 2>> uvs = uv.p != Py_None ? uvList(uv.p) : std::vector<std::array<float, 2>>{};
    if (uvIndex.p == Py_None && uvs.size() == m.points.size()) m.uvs = uvs;  // never a reason not to draw it
    else if (uvIndex.p != Py_None && !uvs.empty()) cornerUvs(m, kept, uvs, uvIndex.p);
    PyErr_Clear();
    return result(std::move(m));
}

// A NurbsPatch (its points at (i / 10, j / 10), from its _grid) or a BezierPatch (a
// NurbsPatch of its control points, the degrees their counts - 1), two triangles a cell.
ShapeMesh patch(PyObject* obj, bool bezier) {
    const long n = 10;
    std::vector<V3> points;
    if (!bezier) {
        const Ref grid(PyObject_CallMethod(obj, "_grid", "l", n));
        const Ref seq(PySequence_Fast(grid.p, "points"));
        for (Py_ssize_t k = 0; k < PySequence_Fast_GET_SIZE(seq.p); ++k) {
            std::vector<double> q;  // what the drawing took: three numbers
            if (!pynum::numbers(PySequence_Fast_GET_ITEM(seq.p, k), q) || q.size() != 3) raise();
            points.push_back({q[0], q[1], q[2]});
        }
    } else {
        const Ref rows(attributeOr(obj, "ctrlPointMatrix", none()));
        const Py_ssize_t nu = PyObject_Length(rows.p);
        if (nu < 0) raise();
        const Ref first(PySequence_GetItem(rows.p, 0));
        const Py_ssize_t nv = PyObject_Length(first.p);
        if (nv < 0) raise();
        for (const curves::Point& q : patchGrid(rows.p, int(nu - 1), int(nv - 1), int(n))) points.push_back(q);
    }
    ShapeMesh m = gridMesh(std::move(points), n);
    m.uvs = pglmath::gridTexCoords(m.points, n);
    return m;
}

// [SECTION] The crown (AsymmetricHull)

// The hull's fields: as the Python meshing read them (num(getattr(obj, f, d), d), the points
// tuple(v) padded with zeros, num(x, 0) each), or, `lenient`, as the drawing's own reading of a
// hull given alone read them (any error: the default; a point not all numbers: zeros).
struct HullReader {
    PyObject* obj;
    bool lenient;

    double number(const char* name, double fallback) const {
        if (!lenient) return field(obj, name, fallback);
        PyObject* v = PyObject_GetAttrString(obj, name);
        double x = fallback;
        if (!v || !pynum::floatOf(v, x)) x = fallback;
        Py_XDECREF(v);
        PyErr_Clear();
        return x;
    }
    V3 at(const char* name, V3 fallback) const {
        if (!lenient) {
            const Ref v(attributeOr(obj, name, none()));
            if (v.p == Py_None) return fallback;
            Py_ssize_t n = 0;
            return upToThree(v.p, num0, n);
        }
        PyObject* v = PyObject_GetAttrString(obj, name);
        V3 out = fallback;
        if (v && v != Py_None) {
            std::vector<double> xyz;
            if (!pynum::numbers(v, xyz)) xyz.clear();
            out = {0, 0, 0};
            for (size_t k = 0; k < 3 && k < xyz.size(); ++k) out[k] = xyz[k];
        }
        Py_XDECREF(v);
        PyErr_Clear();
        return out;
    }
    int count(const char* name, double fallback) const {  // int(max(-1e9, min(1e9, v))), NaN as Python's min takes it
        const double v = number(name, fallback);
        return int(std::isnan(v) ? 1e9 : std::clamp(v, -1e9, 1e9));
    }
};

ShapeMesh hull(PyObject* obj, bool lenient) {
    const HullReader r{obj, lenient};
    AsymmetricHull h;
    h.negXRadius = r.number("negXRadius", 0.5), h.posXRadius = r.number("posXRadius", 0.5);
    h.negYRadius = r.number("negYRadius", 0.5), h.posYRadius = r.number("posYRadius", 0.5);
    h.negXHeight = r.number("negXHeight", 0), h.posXHeight = r.number("posXHeight", 0);
    h.negYHeight = r.number("negYHeight", 0), h.posYHeight = r.number("posYHeight", 0);
    h.bottom = r.at("bottom", {0, 0, -0.5}), h.top = r.at("top", {0, 0, 0.5});
    h.bottomShape = r.number("bottomShape", 2), h.topShape = r.number("topShape", 2);
    h.slices = r.count("slices", 4), h.stacks = r.count("stacks", 4);
    const HullMesh hm = meshOf(h);
    ShapeMesh m = mesh();
    m.points = hm.points;
    for (const auto& t : hm.triangles) m.triangles.push_back({long(t[0]), long(t[1]), long(t[2])});
    return m;
}

// [SECTION] The shape's kind, and shapeMesh

bool oneOf(std::string_view name, std::initializer_list<std::string_view> names) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The shape's mesh by its class's name, in the order the Python meshing asked.
ShapeMesh of(PyObject* obj, int depth) {
    if (depth > 32) return {};
    const std::string_view name(Py_TYPE(obj)->tp_name);
    if (PyList_Check(obj) || PyTuple_Check(obj) || name == "Scene" || name == "Group") return group(obj, name == "Group", depth);
    if (name == "Shape") return shapeOf(obj, depth);
    if (name == "Polyline") {
        const Ref list(attributeOr(obj, "pointList", none()));
        return polyline(list.p);
    }
    if (oneOf(name, {"Polyline2D", "NurbsCurve", "NurbsCurve2D", "BezierCurve2D", "BezierCurve"})) {
        const Ref points(PyObject_CallMethod(obj, "points", nullptr));
        return polyline(points.p);
    }
    if (name == "PointSet") return pointSet(obj);
    if (oneOf(name, {"Scaled", "Translated", "AxisRotated", "EulerRotated", "Oriented"})) return transformed(obj, name, depth);
    if (name == "Box") return box(obj);
    const long slices = count(obj, "slices", 8, 3, 64);  // read of every other shape first
    if (oneOf(name, {"Sphere", "Cylinder", "Cone", "Frustum", "Paraboloid", "Disc"})) return solid(obj, name, slices);
    if (name == "AsymmetricHull") return hull(obj, false);
    if (oneOf(name, {"TriangleSet", "QuadSet", "FaceSet"})) return faceSet(obj);
    if (name == "NurbsPatch" || name == "BezierPatch") return patch(obj, name == "BezierPatch");
    return {};  // text, None, what PlantGL draws and Sprout does not
}

}  // namespace
}  // namespace meshing

using meshing::Raises;

ShapeMesh shapeMesh(PyObject* obj) {
    try {
        return meshing::of(obj, 0);
    } catch (Raises&) {
    } catch (py::error_already_set&) {
    } catch (std::exception&) {  // a patch's C++ refusing what the Python refused too
    }
    if (PyErr_Occurred()) PyErr_Clear();
    return {};
}

ShapeMesh welded(const ShapeMesh& mesh) {
    if (mesh.sameNormal.size() != mesh.points.size()) return mesh;
    ShapeMesh out = mesh;
    out.points.clear(), out.colours.clear(), out.uvs.clear(), out.sameNormal.clear();
    out.triangles.clear(), out.segments.clear();
    std::vector<long> index(mesh.points.size(), -1);
    const long n = long(mesh.points.size());
    for (long k = 0; k < n; ++k)
        if (mesh.sameNormal[size_t(k)] == k || mesh.sameNormal[size_t(k)] < 0 || mesh.sameNormal[size_t(k)] >= n) {
            index[size_t(k)] = long(out.points.size());
            out.points.push_back(mesh.points[size_t(k)]);
            if (mesh.colours.size() == mesh.points.size()) out.colours.push_back(mesh.colours[size_t(k)]);
        }
    auto at = [&](long k) { return k >= 0 && k < n ? index[size_t(index[size_t(k)] >= 0 ? k : mesh.sameNormal[size_t(k)])] : k; };
    for (const auto& t : mesh.triangles) out.triangles.push_back({at(t[0]), at(t[1]), at(t[2])});
    for (const auto& e : mesh.segments) out.segments.push_back({at(e[0]), at(e[1])});
    return out;
}

ShapeMesh hullMesh(PyObject* shape) {
    try {
        return meshing::hull(shape, true);
    } catch (Raises&) {
    } catch (std::exception&) {
    }
    if (PyErr_Occurred()) PyErr_Clear();
    return {};
}

}  // namespace sprout::lpy
