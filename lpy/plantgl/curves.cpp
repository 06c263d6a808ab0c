// PlantGL's curves as lpy/plantgl/plantgl_curves.py evaluated them in Python (lpy/plantgl/curves.hpp).
// Each expression keeps the Python's order of operations and its comparisons (Python's
// min(a, b) keeps a unless b < a; `x or 1.0` replaces only a zero), so that the results are
// the same doubles. The file is compiled without contracting a * b + c into one rounding
// (core/CMakeLists.txt), which the Python never does.
#include "lpy/plantgl/curves.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sprout::curves {
namespace {

using Homogeneous = std::array<double, 4>;  // (x*w, y*w, [z*w,] w), w at index dim

// Python's min(a, b) and max(a, b): the first unless the second is smaller (larger).
double pyMin(double a, double b) { return b < a ? b : a; }
double pyMax(double a, double b) { return b > a ? b : a; }

// abs(p2 - p1) of PlantGL's vectors: sqrt(0 + dx*dx + dy*dy [+ dz*dz]); in 2D z is 0 on both
// sides, and adding 0.0 to the non-negative sum changes nothing.
double distance(const Point& a, const Point& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// De Boor (the Python's _de_boor was): a point of the B-spline of homogeneous `points` (dim + 1 numbers
// used) at t, t clamped to the knots' range.
Homogeneous deBoor(const std::vector<Homogeneous>& points, int degree, const std::vector<double>& knots, double t, int dim) {
    const int n = int(points.size()) - 1;
    t = pyMax(knots.at(degree), pyMin(knots.at(n + 1), t));
    int span = degree;
    while (span < n && t >= knots[span + 1]) ++span;
    std::array<Homogeneous, 8> fixed;
    std::vector<Homogeneous> grown;
    Homogeneous* d = fixed.data();
    if (degree + 1 > int(fixed.size())) grown.resize(degree + 1), d = grown.data();
    for (int j = 0; j <= degree; ++j) d[j] = points.at(span - degree + j);
    for (int r = 1; r <= degree; ++r)
        for (int j = degree; j >= r; --j) {
            const int i = j + span - degree;
            const double den = knots.at(i + degree - r + 1) - knots[i];
            const double a = den != 0 ? (t - knots[i]) / den : 0.0;
            for (int c = 0; c <= dim; ++c) d[j][c] = (1 - a) * d[j - 1][c] + a * d[j][c];
        }
    return d[degree];
}

Point divided(const Homogeneous& h, int dim) {
    double w = h[dim];
    if (w == 0) w = 1.0;  // `or 1.0`
    Point p{0.0, 0.0, 0.0};
    for (int c = 0; c < dim; ++c) p[c] = h[c] / w;
    return p;
}

Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

std::array<double, 4> weightedPointAt(const std::vector<std::array<double, 4>>& points, int degree,
                                      const std::vector<double>& knots, double t) {
    if (points.empty() || degree < 0) throw std::out_of_range("no points, or a negative degree");
    std::vector<Homogeneous> h;
    h.reserve(points.size());
    for (const auto& p : points) h.push_back({p[0] * p[3], p[1] * p[3], p[2] * p[3], p[3]});
    // Python's min(max(t, first), last), in the Python's order (deBoor then clamps again: the same t).
    t = pyMin(pyMax(t, knots.at(size_t(degree))), knots.at(points.size()));
    const Homogeneous d = deBoor(h, degree, knots, t, 3);
    if (d[3] == 0) return d;
    return {d[0] / d[3], d[1] / d[3], d[2] / d[3], d[3]};
}

std::vector<double> uniformClampedKnots(int n, int degree) {
    const int inner = n - degree - 1, ends = std::max(0, degree + 1);  // ([0.0] * (degree + 1): none below 0)
    std::vector<double> k(size_t(ends), 0.0);
    for (int i = 0; i < inner; ++i) k.push_back(double(i + 1) / double(inner + 1));
    k.insert(k.end(), size_t(ends), 1.0);
    return k;
}

Nurbs::Nurbs(int dim, int degree, std::vector<double> knots, std::vector<double> ctrl)
    : m_dim(dim), m_degree(degree), m_count(int(ctrl.size()) / (dim + 1)), m_knots(std::move(knots)) {
    if (dim < 2 || dim > 3 || degree < 0 || m_count < 1 || ctrl.size() % (dim + 1) != 0)
        throw std::out_of_range("a NURBS curve needs points of its dimension and a degree of 0 or more");
    // getPointAt reads the points up to index degree and the knots up to count + degree - 1
    // (and the last knot, index count).
    if (m_degree > m_count - 1 || int(m_knots.size()) < m_count + std::max(m_degree, 1))
        throw std::out_of_range("a NURBS curve's degree and knots do not fit its points");
    m_weighted.reserve(ctrl.size());
    for (int j = 0; j < m_count; ++j) {
        const double* p = &ctrl[j * (dim + 1)];
        for (int c = 0; c < dim; ++c) m_weighted.push_back(p[c] * p[dim]);
        m_weighted.push_back(p[dim]);
    }
}

Point Nurbs::pointAt(double u) const { return divided(homogeneousAt(u), m_dim); }

std::array<double, 4> Nurbs::homogeneousAt(double u) const {
    const int p = m_degree, n = m_count - 1, dim = m_dim, stride = dim + 1;
    const std::vector<double>& k = m_knots;
    u = pyMax(firstKnot(), pyMin(lastKnot(), u));
    int span = p;
    while (span < n && u >= k[span + 1]) ++span;
    std::array<Homogeneous, 8> fixed;
    std::vector<Homogeneous> grown;
    Homogeneous* d = fixed.data();
    if (p + 1 > int(fixed.size())) grown.resize(p + 1), d = grown.data();
    for (int j = 0; j <= p; ++j)
        for (int c = 0; c < stride; ++c) d[j][c] = m_weighted[(j + span - p) * stride + c];
    for (int r = 1; r <= p; ++r)  // de Boor, on homogeneous points
        for (int j = p; j >= r; --j) {
            const int i = j + span - p;
            const double den = k[i + p - r + 1] - k[i];
            const double a = den != 0 ? (u - k[i]) / den : 0.0;
            for (int c = 0; c < stride; ++c) d[j][c] = (1 - a) * d[j - 1][c] + a * d[j][c];
        }
    return d[p];
}

Point Nurbs::derivativeAt(double u, int d) const {
    const int dim = m_dim;
    if (d > m_degree || d < 0) return {0.0, 0.0, 0.0};
    u = pyMax(firstKnot(), pyMin(lastKnot(), u));
    std::vector<Homogeneous> ctrl(m_count);
    for (int j = 0; j < m_count; ++j)
        for (int c = 0; c <= dim; ++c) ctrl[j][c] = m_weighted[j * (dim + 1) + c];
    std::vector<double> knots = m_knots;
    int degree = m_degree;
    std::vector<Homogeneous> homogeneous;
    for (int order = 0; order <= d; ++order) {
        homogeneous.push_back(deBoor(ctrl, degree, knots, u, dim));
        if (order == d) break;
        // The derivative's control points: the differences, one degree less.
        std::vector<Homogeneous> next(ctrl.size() - 1);
        for (size_t i = 0; i + 1 < ctrl.size(); ++i) {
            const double den = knots.at(i + degree + 1) - knots[i + 1];
            for (int c = 0; c <= dim; ++c) next[i][c] = den != 0 ? double(degree) * (ctrl[i + 1][c] - ctrl[i][c]) / den : 0.0;
        }
        ctrl = std::move(next);
        knots = std::vector<double>(knots.begin() + 1, knots.end() - 1);
        degree -= 1;
    }
    double w = homogeneous[0][dim];
    if (w == 0) w = 1.0;
    // C(k) = (A(k) - sum over i of binom(k, i) w(i) C(k - i)) / w
    std::vector<Point> ders;
    for (int order = 0; order <= d; ++order) {
        Point v{0.0, 0.0, 0.0};
        for (int c = 0; c < dim; ++c) v[c] = homogeneous[order][c];
        for (int i = 1; i <= order; ++i) {
            const double b = i == order ? 1 : order;
            for (int c = 0; c < dim; ++c) v[c] = v[c] - b * homogeneous[i][dim] * ders[order - i][c];
        }
        for (int c = 0; c < dim; ++c) v[c] = v[c] / w;
        ders.push_back(v);
    }
    return ders[d];
}

Point Nurbs::normalAt(double u) const {
    const Point t = derivativeAt(u, 1), n = derivativeAt(u, 2);
    const double length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    if (!(length > 0)) return {0.0, 0.0, 0.0};
    const double l4 = std::pow(length, 4.0);  // Python's length ** 4
    Point r = cross(cross(t, n), t);
    for (double& c : r) c = c / l4;
    if (m_dim == 2) r[2] = 0.0;
    return r;
}

double Nurbs::length(double begin, double end, double stride) const {
    const double fk = firstKnot(), lk = lastKnot();
    if (begin < fk) begin = fk;
    if (end > lk) end = lk;
    const double du = (lk - fk) / stride;
    const double beginI = std::trunc((begin - fk) / du) * du + fk, endI = std::trunc((end - fk) / du) * du + fk;
    Point p1 = pointAt(beginI);
    double length = 0.0;
    if (begin - beginI > 1e-5) length -= distance(p1, pointAt(begin));
    double u = beginI + fk + du;  // (PlantGL's: the first knot counted twice)
    while (u <= endI) {
        const Point p2 = pointAt(u);
        length += distance(p1, p2);
        p1 = p2;
        u += du;
    }
    if (end - endI > 1e-5) length += distance(p1, pointAt(end));
    return length;
}

std::vector<std::array<double, 2>> Nurbs::strideSteps(int stride, bool stayOnZero) const {
    const double fk = firstKnot(), lk = lastKnot(), du = (lk - fk) / stride;
    Point p1 = pointAt(fk);
    double u = fk + du;
    std::vector<std::array<double, 2>> steps;
    steps.reserve(size_t(std::max(0, stride)));
    for (int s = 0; s < stride; ++s) {
        const Point p2 = pointAt(u);
        const double n = distance(p1, p2);
        if (n > 0 || !stayOnZero) p1 = p2;
        steps.push_back({u, n});
        u += du;
    }
    return steps;
}

std::vector<std::array<double, 2>> Nurbs::arcLengthToU(int stride) const {
    const double fk = firstKnot(), lk = lastKnot(), total = length(fk, lk, stride);
    double length = 0.0;
    std::vector<std::array<double, 2>> points{{0.0, fk}};
    for (const auto& [u, n] : strideSteps(stride, true))
        if (n > 0) {  // (a step that does not move is left out)
            length += n;
            points.push_back({length / total, u});
        }
    points.back() = {1.0, lk};
    return points;
}

std::vector<std::array<double, 2>> Nurbs::uToArcLength(int stride) const {
    const double fk = firstKnot(), lk = lastKnot(), total = length(fk, lk, stride);
    double length = 0.0;
    std::vector<std::array<double, 2>> points{{fk, 0.0}};
    for (const auto& [u, n] : strideSteps(stride, false)) {
        length += n;
        points.push_back({u, length / total});
    }
    points.back() = {lk, 1.0};
    return points;
}

std::vector<Point> Nurbs::sample(int n) const {
    const double a = firstKnot(), b = lastKnot();
    std::vector<Point> out;
    for (int i = 0; i < n; ++i) out.push_back(pointAt(a + (b - a) * i / (n - 1)));
    return out;
}

Polyline2D::Polyline2D(std::vector<std::array<double, 2>> points) : m_points(std::move(points)) {
    if (m_points.empty()) throw std::out_of_range("a polyline needs a point");
}

Point Polyline2D::pointAt(double u) const {
    const auto& pts = m_points;
    if (pts.size() == 1) return {pts[0][0], pts[0][1], 0.0};
    const double last = double(pts.size() - 1);
    u = pyMax(0.0, pyMin(last, u));
    if (std::fabs(u) < 1e-5) u = 0.0;
    else if (std::fabs(u - last) < 1e-5) u = last;
    const size_t i = size_t(u);
    if (double(i) == u) return {pts[i][0], pts[i][1], 0.0};
    const auto &a = pts[i], &b = pts[i + 1];
    const double up = double(i + 1) - u, down = u - double(i);
    return {a[0] * up + b[0] * down, a[1] * up + b[1] * down, 0.0};
}

namespace {
// The Python's QuantisedFunction: the y where the curve's x is within 1e-5 of `x`, by
// bisection (200 halvings at most: PlantGL would loop for ever on a curve whose x never gets
// there).
template <class Curve>
double valueAt(const Curve& curve, double x, double low, double high, const Point& first, const Point& last) {
    if (x == first[0]) return first[1];
    if (x == last[0]) return last[1];
    Point p{};
    for (int k = 0; k < 200; ++k) {
        const double check = (low + high) / 2.0;
        p = curve.pointAt(check);
        if (p[0] > x) high = check;
        else low = check;
        if (!(std::fabs(p[0] - x) > 1e-5)) break;
    }
    return p[1];
}

template <class Curve>
Quantised quantiseCurve(const Curve& curve, int sampling) {
    const int n = std::max(3, sampling);
    const double a = curve.firstKnot(), b = curve.lastKnot();
    const Point first = curve.pointAt(a), last = curve.pointAt(b);
    Quantised q;
    q.firstx = first[0];
    q.lastx = last[0];
    const double extent = q.lastx - q.firstx;
    q.values.reserve(n);
    for (int i = 0; i < n; ++i) q.values.push_back(valueAt(curve, extent * i / (n - 1) + q.firstx, a, b, first, last));
    return q;
}
}  // namespace

Quantised quantise(const Nurbs& curve, int sampling) { return quantiseCurve(curve, sampling); }
Quantised quantise(const Polyline2D& curve, int sampling) { return quantiseCurve(curve, sampling); }

double Quantised::operator()(double x) const {
    const long n = long(values.size());
    x = pyMin(pyMax(x, firstx), lastx);
    const double index = lastx != firstx ? double(n - 1) * (x - firstx) / (lastx - firstx) : 0.0;
    if (!std::isfinite(index)) throw std::domain_error("a quantised function read at no number");
    const long floor = long(std::floor(index));
    const double diff = index - double(floor);
    // Python's indexing: from the end for a negative index
    auto at = [&](long i) { return values.at(size_t(i < 0 ? i + n : i)); };
    if (floor >= n - 1 || std::fabs(diff) < 1e-5) return at(std::min(floor, n - 1));
    return (1 - diff) * at(floor) + diff * at(floor + 1);
}

NurbsPatch::NurbsPatch(std::vector<std::vector<double>> rows, int udegree, int vdegree, std::vector<double> uknots,
                       std::vector<double> vknots)
    : m_udegree(udegree), m_uknots(std::move(uknots)) {
    if (rows.empty()) throw std::out_of_range("a NURBS patch needs points");
    for (std::vector<double>& row : rows) {
        const int n = int(row.size() / 4), degree = std::max(1, std::min(vdegree, n - 1));
        m_rows.emplace_back(3, degree, vknots.empty() ? uniformClampedKnots(n, degree) : vknots, std::move(row));
    }
}

std::vector<double> NurbsPatch::column(double v) const {
    std::vector<double> column;
    for (const Nurbs& c : m_rows) {  // in homogeneous coordinates, as PlantGL's: the weight kept
        const Homogeneous h = c.homogeneousAt(c.firstKnot() + (c.lastKnot() - c.firstKnot()) * v);
        const Point q = divided(h, 3);
        column.insert(column.end(), {q[0], q[1], q[2], h[3] == 0 ? 1.0 : h[3]});
    }
    return column;
}

Nurbs NurbsPatch::along(const std::vector<double>& column) const {
    const int n = int(column.size() / 4), degree = std::max(1, std::min(m_udegree, n - 1));
    return Nurbs(3, degree, m_uknots.empty() ? uniformClampedKnots(n, degree) : m_uknots, column);
}

Point NurbsPatch::pointAt(double u, double v) const {
    const Nurbs cu = along(column(v));
    return cu.pointAt(cu.firstKnot() + (cu.lastKnot() - cu.firstKnot()) * u);
}

std::vector<Point> NurbsPatch::grid(int n) const {
    std::vector<Nurbs> columns;  // the curve along u at each v = j / n
    for (int j = 0; j <= n; ++j) columns.push_back(along(column(double(j) / double(n))));
    std::vector<Point> out;
    for (int i = 0; i <= n; ++i) {
        const double u = double(i) / double(n);
        for (const Nurbs& cu : columns) out.push_back(cu.pointAt(cu.firstKnot() + (cu.lastKnot() - cu.firstKnot()) * u));
    }
    return out;
}

NurbsVolume::NurbsVolume(Grid ctrl, std::array<int, 3> degrees, std::array<std::vector<double>, 3> knots)
    : m_ctrl(std::move(ctrl)), m_degrees(degrees), m_knots(std::move(knots)) {}

Point NurbsVolume::pointAt(double u, double v, double w) const {
    std::vector<Homogeneous> planes, row, line;
    for (const auto& plane : m_ctrl) {
        row.clear();
        for (const auto& points : plane) {
            line.clear();
            for (const auto& p : points) line.push_back({p[0] * p[3], p[1] * p[3], p[2] * p[3], p[3]});
            row.push_back(deBoor(line, m_degrees[2], m_knots[2], w, 3));
        }
        planes.push_back(deBoor(row, m_degrees[1], m_knots[1], v, 3));
    }
    return divided(deBoor(planes, m_degrees[0], m_knots[0], u, 3), 3);
}

}  // namespace sprout::curves
