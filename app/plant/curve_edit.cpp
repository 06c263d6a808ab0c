// Editing a curve's control points: the operations the panel's curve editor, the viewer's
// script and Python share (app/plant/curve_edit.hpp).
#include "app/plant/curve_edit.hpp"

#include <algorithm>
#include <cmath>

namespace sprout {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The distance squared from (x, y) to the segment a-b.
double toSegment(const std::array<double, 3>& a, const std::array<double, 3>& b, double x, double y) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = dx * dx + dy * dy;
    const double t = len > 0 ? std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / len, 0.0, 1.0) : 0.0;
    const double px = a[0] + t * dx - x, py = a[1] + t * dy - y;
    return px * px + py * py;
}

}  // namespace

CurvePoints movedPoint(const CurvePoints& pts, const CurveRules& rules, size_t k, double x, double y) {
    CurvePoints out = pts;
    if (k >= out.size()) return out;
    if (rules.function) {
        const double left = k == 0 ? 0 : out[k - 1][0], right = k + 1 == out.size() ? 1 : out[k + 1][0];
        x = k == 0 ? 0 : k + 1 == out.size() ? 1 : std::clamp(x, left, right);
    }
    out[k][0] = x;
    out[k][1] = y;
    return out;
}

std::optional<CurvePoints> insertedPoint(const CurvePoints& pts, const CurveRules& rules, size_t k) {
    if (pts.empty() || k >= pts.size()) return std::nullopt;
    const bool last = k + 1 == pts.size();
    if (last && rules.function) return std::nullopt;  // nothing lies beyond x = 1
    std::array<double, 3> p;
    if (!last || rules.closed) {
        const auto& a = pts[k];
        const auto& b = pts[last ? 0 : k + 1];
        p = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
    } else if (pts.size() >= 2) {  // an open curve's end: on as far again
        const auto& a = pts[k - 1];
        const auto& b = pts[k];
        p = {2 * b[0] - a[0], 2 * b[1] - a[1], b[2]};
    } else {
        p = {pts[0][0] + 1, pts[0][1], pts[0][2]};
    }
    if (rules.newWeight > 0) p[2] = rules.newWeight;
    CurvePoints out = pts;
    out.insert(out.begin() + std::ptrdiff_t(k + 1), p);
    return out;
}

std::optional<CurvePoints> removedPoint(const CurvePoints& pts, const CurveRules& rules, size_t k) {
    if (k >= pts.size() || pts.size() <= std::max<size_t>(rules.fewest, 2)) return std::nullopt;
    if (rules.function && (k == 0 || k + 1 == pts.size())) return std::nullopt;
    CurvePoints out = pts;
    out.erase(out.begin() + std::ptrdiff_t(k));
    return out;
}

std::optional<CurvePoints> weightedPoint(const CurvePoints& pts, size_t k, double w) {
    if (k >= pts.size() || !(w > 0) || !std::isfinite(w)) return std::nullopt;
    CurvePoints out = pts;
    out[k][2] = w;
    return out;
}

size_t nearestSegment(const CurvePoints& pts, const CurveRules& rules, double x, double y) {
    size_t best = 0;
    double bestD = 1e300;
    const size_t segments = pts.size() < 2 ? 0 : rules.closed ? pts.size() : pts.size() - 1;
    for (size_t k = 0; k < segments; ++k) {
        const double d = toSegment(pts[k], pts[(k + 1) % pts.size()], x, y);
        if (d < bestD) bestD = d, best = k;
    }
    return best;
}

std::array<double, 2> snapped(double x, double y, double step) {
    if (!(step > 0)) return {x, y};
    return {std::round(x / step) * step, std::round(y / step) * step};
}

std::optional<CurvePreset> curvePresetNamed(std::string_view name) {
    if (name == "line") return CurvePreset::Line;
    if (name == "arc") return CurvePreset::Arc;
    if (name == "circle") return CurvePreset::Circle;
    if (name == "s" || name == "S") return CurvePreset::S;
    return std::nullopt;
}

std::optional<CurvePoints> presetPoints(CurvePreset preset, const CurveRules& rules, size_t count) {
    if (preset == CurvePreset::Circle && rules.function) return std::nullopt;
    // Enough points for the shape to show: a circle needs 8 round it.
    const size_t least[] = {2, 5, 9, 7};
    const size_t n = std::max({count, rules.fewest, least[int(preset)]});
    CurvePoints out;
    for (size_t i = 0; i < n; ++i) {
        double t = double(i) / double(n - 1), x = 0, y = 0;  // t: 0 .. 1 along the shape
        switch (preset) {
            case CurvePreset::Line: x = t - 0.5, y = rules.function ? t : 0; break;
            case CurvePreset::Arc: x = -0.5 * std::cos(kPi * t), y = 0.5 * std::sin(kPi * t); break;
            case CurvePreset::Circle: {
                const double a = 2 * kPi * (rules.closed ? double(i) / double(n) : t);
                x = 0.5 * std::cos(a), y = 0.5 * std::sin(a);
                break;
            }
            case CurvePreset::S: x = t - 0.5, y = 0.25 * std::sin(2 * kPi * t); break;
        }
        if (rules.function) {  // over x in [0, 1], y in [0, 1]
            x = t;
            if (preset == CurvePreset::Arc) y = std::sin(kPi * t);
            if (preset == CurvePreset::S) y = 0.5 - 0.4 * std::cos(kPi * t);
        }
        auto tidy = [](double v) { return std::fabs(v) < 1e-12 ? 0.0 : v; };  // no 1e-16 in the file
        out.push_back({tidy(x), tidy(y), 1});
    }
    return out;
}

}  // namespace sprout
