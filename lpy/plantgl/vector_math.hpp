#pragma once
// PlantGL's vector arithmetic as plantgl_vectors.py computes it (Vector3.normed, Matrix3's
// axisRotation and products), for meshes.cpp: the same numbers in the same order.
#include <array>
#include <cmath>
#include <vector>

namespace sprout::lpy::pglmath {

using V3 = std::array<double, 3>;
using M3 = std::array<V3, 3>;  // rows

// Vector3(v).normed(): divided by its norm where that is above 0.
inline V3 normed(V3 v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n > 0) return {v[0] / n, v[1] / n, v[2] / n};
    return v;
}

// Matrix3.axisRotation(axis, angle), as plantgl_vectors.py computes it.
inline M3 axisRotation(const V3& axis, double angle) {
    const V3 u = normed(axis);
    const double x = u[0], y = u[1], z = u[2];
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - std::cos(angle);
    return {V3{t * x * x + c, t * x * y - s * z, t * x * z + s * y}, V3{t * x * y + s * z, t * y * y + c, t * y * z - s * x},
            V3{t * x * z - s * y, t * y * z + s * x, t * z * z + c}};
}

// Matrix3 * Matrix3 and Matrix3 * vector: each entry sum() of its products, from 0.
inline M3 times(const M3& a, const M3& b) {
    M3 out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[i][j] = 0.0 + a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return out;
}
inline V3 times(const M3& m, const V3& p) {
    V3 out{};
    for (int i = 0; i < 3; ++i) out[i] = 0.0 + m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2];
    return out;
}

// A patch's texture coordinates as PlantGL's Discretizer gives them (gridTexCoord): for the
// (n + 1)^2 points, i outer, u the length along each row j so far over the row's (from 0 to 1),
// v the same along each column.
inline std::vector<std::array<float, 2>> gridTexCoords(const std::vector<V3>& pts, long n) {
    const size_t w = size_t(n + 1);
    std::vector<std::array<float, 2>> uv(pts.size(), {0, 0});
    if (pts.size() != w * w) return {};
    auto dist = [&](size_t a, size_t b) { return std::hypot(pts[a][0] - pts[b][0], pts[a][1] - pts[b][1], pts[a][2] - pts[b][2]); };
    for (int along = 0; along < 2; ++along)
        for (size_t line = 0; line < w; ++line) {
            auto at = [&](size_t k) { return along == 0 ? line * w + k : k * w + line; };
            double total = 0, sofar = 0;
            for (size_t k = 1; k < w; ++k) total += dist(at(k - 1), at(k));
            for (size_t k = 1; k < w; ++k) {
                sofar += dist(at(k - 1), at(k));
                uv[at(k)][size_t(along)] = total > 0 ? float(sofar / total) : 0.0f;
            }
        }
    return uv;
}

}  // namespace sprout::lpy::pglmath
