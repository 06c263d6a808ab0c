// The solids a model gives to @g (Box, Sphere, Cylinder, Cone, Frustum, Paraboloid, Disc)
// made into points and triangles, with the same numbers in the same order as the Python
// meshing Sprout had before (so that the drawing is the same), and the texture coordinates
// PlantGL's Discretizer gives them (a Paraboloid has none there, and none here). A ring's
// seam and a cap's ring are copies of the side's points with a texture coordinate of their
// own, sharing the side's normals (ShapeMesh::sameNormal): the shading is as it was.
#include <cmath>

#include "lpy/plantgl/meshing.hpp"

namespace sprout::lpy::meshing {

namespace {

// A ring's texture coordinates: round a band, (i / n, v), or projected on a disc,
// (0.5 + k cos / 2, 0.5 + k sin / 2) (PlantGL's cone and caps).
struct RingUv {
    bool disc = false;
    double v = 0;  // the band's v, or the disc's k
};

std::array<float, 2> ringUv(const RingUv& r, long i, long n) {
    const double a = 2 * M_PI * double(i) / double(n);
    if (r.disc) return {float(0.5 + r.v * std::cos(a) / 2), float(0.5 + r.v * std::sin(a) / 2)};
    return {float(double(i) / double(n)), float(r.v)};
}

// Points (r cos, r sin, z) around the z axis, n of them, and the first again (the seam: a
// copy with u = 1, its normal the first's).
void ring(ShapeMesh& m, double r, double z, long n, const RingUv& uv) {
    const long first = long(m.points.size());
    for (long i = 0; i <= n; ++i) {
        const double a = 2 * M_PI * double(i % n) / double(n);
        m.points.push_back({r * std::cos(a), r * std::sin(a), z});
        m.uvs.push_back(ringUv(uv, i, n));
        m.sameNormal.push_back(i < n ? first + i : first);
    }
}

// Rings of (radius, z) swept about z, with their texture coordinates, and caps (their own
// rings, projected on a disc) at the profile's entries `caps` (-1: the last).
ShapeMesh tube(const std::vector<std::array<double, 2>>& profile, long n, std::initializer_list<int> caps, const std::vector<RingUv>& uvs) {
    ShapeMesh m = mesh();
    const long stride = n + 1;
    for (size_t j = 0; j < profile.size(); ++j) {
        ring(m, profile[j][0], profile[j][1], n, uvs[j]);
        if (j) {
            const long a = long(j - 1) * stride, b = long(j) * stride;
            for (long i = 0; i < n; ++i) {
                m.triangles.push_back({a + i, a + i + 1, b + i + 1});
                m.triangles.push_back({a + i, b + i + 1, b + i});
            }
        }
    }
    for (int j : caps) {
        const size_t at = j >= 0 ? size_t(j) : profile.size() - 1;
        const auto& [r, z] = profile[at];
        if (r > 0) {
            const long c = long(m.points.size()), side = long(at) * stride;
            m.points.push_back({0.0, 0.0, z});
            m.uvs.push_back({0.5f, 0.5f});
            m.sameNormal.push_back(c);
            for (long i = 0; i < n; ++i) {
                m.points.push_back(m.points[size_t(side + i)]);
                m.uvs.push_back(ringUv({true, 1}, i, n));
                m.sameNormal.push_back(side + i);
            }
            for (long i = 0; i < n; ++i) m.triangles.push_back({c, c + 1 + (i + 1) % n, c + 1 + i});
        }
    }
    return m;
}

// A box face's texture coordinates at a corner, as PlantGL's quads have them ((1, 0), (0, 0),
// (0, 1), (1, 1) round each): which of the corner's signs make u and v 1.
std::array<float, 2> boxUv(int axis, int sign, const V3& p) {
    const bool x = p[0] > 0, y = p[1] > 0, z = p[2] > 0;
    if (axis == 2) return sign < 0 ? std::array<float, 2>{float(x), float(y)} : std::array<float, 2>{float(!y), float(!x)};
    if (axis == 0) return {float(sign > 0 ? !y : y), float(z)};
    return {float(sign > 0 ? x : !x), float(z)};
}

}  // namespace

// Six faces of two triangles, half sizes its size (or its first three arguments).
ShapeMesh box(PyObject* obj) {
    const Ref sv(attributeOr(obj, "size", Py_BuildValue("(ddd)", 0.5, 0.5, 0.5)));
    const Ref args(own(PyObject_GetAttrString(obj, "args")));
    const Py_ssize_t nargs = PyObject_Length(args.p);
    if (nargs < 0) raise();
    const Ref chosen(nargs >= 3 ? PySequence_GetSlice(args.p, 0, 3) : Py_NewRef(sv.p));
    Py_ssize_t n = 0;
    const V3 s = sizes(chosen.p, 0.5, n);
    if (n < 3) raise();  // s[2]
    ShapeMesh m = mesh();
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {-1, 1}) {
            const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
            const long base = long(m.points.size());
            for (const auto& [du, dv] : {std::array<int, 2>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                V3 p{0.0, 0.0, 0.0};
                p[size_t(axis)] = sign * s[size_t(axis)], p[size_t(u)] = du * s[size_t(u)], p[size_t(v)] = dv * s[size_t(v)];
                m.points.push_back(p);
                V3 corner{0.0, 0.0, 0.0};  // the corner's signs (a size of 0 keeps them)
                corner[size_t(axis)] = sign, corner[size_t(u)] = du, corner[size_t(v)] = dv;
                m.uvs.push_back(boxUv(axis, sign, corner));
            }
            m.triangles.push_back({base, base + 1, base + 2});
            m.triangles.push_back({base, base + 2, base + 3});
        }
    return m;
}

ShapeMesh solid(PyObject* obj, std::string_view name, long slices) {
    if (name == "Sphere") {
        // PlantGL's sphere: v 0 and 1 at the poles, j / (stacks + 1) at ring j between.
        const double r = field(obj, "radius", 0.5);
        const long stacks = count(obj, "stacks", 8, 2, 64);
        std::vector<std::array<double, 2>> prof;
        std::vector<RingUv> uvs;
        for (long i = 0; i <= stacks; ++i) {
            const double a = M_PI * double(i) / double(stacks);
            prof.push_back({r * std::sin(a), -r * std::cos(a)});
            uvs.push_back({false, i == 0 ? 0.0 : i == stacks ? 1.0 : double(i) / double(stacks + 1)});
        }
        return tube(prof, slices, {}, uvs);
    }
    if (name == "Cylinder" || name == "Cone" || name == "Frustum") {
        // Round the side v runs to the height (a Cylinder's) or to 1 (a Frustum's); a Cone is
        // projected on a disc, its tip the middle.
        const double r = field(obj, "radius", 0.5), h = field(obj, "height", 1);
        const double top = name == "Cylinder" ? r : name == "Cone" ? 0.0 : r * field(obj, "taper", 0.5);
        const std::vector<RingUv> uvs = name == "Cone" ? std::vector<RingUv>{{true, 1}, {true, 0}}
                                                       : std::vector<RingUv>{{false, 0}, {false, name == "Cylinder" ? h : 1.0}};
        return tube({{r, 0.0}, {top, h}}, slices, {0, -1}, uvs);
    }
    if (name == "Paraboloid") {
        const double r = field(obj, "radius", 0.5), h = field(obj, "height", 1), given = field(obj, "shape", 2);
        const double shape = given > 1e-3 ? given : 1e-3;  // max(1e-3, shape)
        const long stacks = count(obj, "stacks", 8, 2, 64);
        std::vector<std::array<double, 2>> prof;
        for (long i = 0; i <= stacks; ++i) {
            const double left = 1 - double(i) / double(stacks);
            prof.push_back({r * std::pow(left > 0.0 ? left : 0.0, 1 / shape), h * double(i) / double(stacks)});
        }
        ShapeMesh m = tube(prof, slices, {0}, std::vector<RingUv>(prof.size()));
        m.uvs.clear();  // PlantGL gives a paraboloid none
        return m;
    }
    if (name == "Disc") {
        const double r = field(obj, "radius", 0.5);
        ShapeMesh m = mesh();
        m.points.push_back({0.0, 0.0, 0.0});
        m.uvs.push_back({0.5f, 0.5f});
        for (long i = 0; i < slices; ++i) {
            const double a = 2 * M_PI * double(i) / double(slices);
            m.points.push_back({r * std::cos(a), r * std::sin(a), 0.0});
            m.uvs.push_back(ringUv({true, 1}, i, slices));
        }
        for (long i = 0; i < slices; ++i) m.triangles.push_back({0, 1 + i, 1 + (i + 1) % slices});
        return m;
    }
    return {};
}

}  // namespace sprout::lpy::meshing
