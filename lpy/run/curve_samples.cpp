// lpy.hpp's curveSamples: an L-Py model's 2D curve evaluated by PlantGL's arithmetic
// (lpy/plantgl/curves.hpp), for the panel's curve editor; with or without Python.
#include <algorithm>

#include "lpy/lpy.hpp"
#include "lpy/plantgl/curves.hpp"

namespace sprout::lpy {

std::vector<std::array<double, 2>> curveSamples(int kind, int degree, const std::vector<std::array<double, 3>>& ctrl, int samples) {
    std::vector<std::array<double, 2>> out;
    const int n = int(ctrl.size());
    if (n < 2) return out;
    if (kind == 2) {
        for (const auto& p : ctrl) out.push_back({p[0], p[1]});
        return out;
    }
    const int d = kind == 1 ? n - 1 : std::max(1, std::min(degree, n - 1));
    std::vector<double> flat;
    for (const auto& p : ctrl) flat.insert(flat.end(), {p[0], p[1], p[2]});
    try {
        const curves::Nurbs curve(2, d, curves::uniformClampedKnots(n, d), std::move(flat));
        samples = std::max(2, samples);
        const double a = curve.firstKnot(), b = curve.lastKnot();
        for (int i = 0; i < samples; ++i) {
            const curves::Point p = curve.pointAt(a + (b - a) * i / (samples - 1));
            out.push_back({p[0], p[1]});
        }
    } catch (const std::exception&) {
        out.clear();
    }
    return out;
}

std::vector<std::vector<std::array<double, 3>>> patchSamples(const std::vector<std::vector<std::array<double, 4>>>& rows, int udegree,
                                                             int vdegree, int samples) {
    std::vector<std::vector<std::array<double, 3>>> out;
    const int nu = int(rows.size()), nv = rows.empty() ? 0 : int(rows.front().size());
    if (nu < 2 || nv < 2) return out;
    const int du = std::clamp(udegree, 1, nu - 1), dv = std::clamp(vdegree, 1, nv - 1);
    const std::vector<double> ku = curves::uniformClampedKnots(nu, du), kv = curves::uniformClampedKnots(nv, dv);
    samples = std::max(2, samples);
    try {
        for (int i = 0; i < samples; ++i) {
            const double u = ku[size_t(du)] + (ku[ku.size() - 1 - size_t(du)] - ku[size_t(du)]) * i / (samples - 1);
            std::vector<std::array<double, 3>> line;
            for (int j = 0; j < samples; ++j) {
                const double v = kv[size_t(dv)] + (kv[kv.size() - 1 - size_t(dv)] - kv[size_t(dv)]) * j / (samples - 1);
                std::vector<std::array<double, 4>> column;  // each row at v, then those at u
                for (const auto& row : rows) {
                    if (int(row.size()) != nv) return {};
                    column.push_back(curves::weightedPointAt(row, dv, kv, v));
                }
                const auto p = curves::weightedPointAt(column, du, ku, u);
                line.push_back({p[0], p[1], p[2]});
            }
            out.push_back(std::move(line));
        }
    } catch (const std::exception&) {
        out.clear();
    }
    return out;
}

}  // namespace sprout::lpy
