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

}  // namespace sprout::lpy
