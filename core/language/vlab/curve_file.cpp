// cpfg's curves (cpfg/curveXYZ.cpp, curveXYZc.cpp): the files of a view file's `curve:` lines,
// read line by line as CCurveXYZ::readCurve reads them, and evaluated step for step as
// calcPValue, createAPoints and calcAValue compute them (the same bases, the same order of
// operations, in doubles), so that curveX/Y/Z(id, t) and curveGAL(id) give cpfg's numbers.
//
// Index of this file:
//   [SECTION] Evaluation (calcPValue, createPPoints, createAPoints, calcAValue)
//   [SECTION] Reading a curve file (readCurve, openCurve)
//   [SECTION] What a grammar calls (CurveCXS, CurveCYS, CurveCZS, CurveGAL)

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/line_reader.hpp"

namespace sprout {

namespace {

// [SECTION] Evaluation (calcPValue, createPPoints, createAPoints, calcAValue)

using P3 = std::array<double, 3>;

// cpfg's Bi1 ... Bi4: the uniform cubic B-spline basis on the knots ti(i) = i.
double bi1(int i, double t) { return (double(i) <= t && t < double(i + 1)) ? 1.0 : 0.0; }
double bi2(int i, double t) {
    return (t - i) / (double(i + 1) - i) * bi1(i, t) + (double(i + 2) - t) / (double(i + 2) - (i + 1)) * bi1(i + 1, t);
}
double bi3(int i, double t) {
    return (t - i) / (double(i + 2) - i) * bi2(i, t) + (double(i + 3) - t) / (double(i + 3) - (i + 1)) * bi2(i + 1, t);
}
double bi4(int i, double t) {
    return (t - i) / (double(i + 3) - i) * bi3(i, t) + (double(i + 4) - t) / (double(i + 4) - (i + 1)) * bi3(i + 1, t);
}

// cpfg's uk and Nk1 ... Nk4: the cubic B-spline basis on the clamped knots 0 0 0 0 1 2 ...
// n-3 n-3 n-3 n-3 (n: the points).
double uk(int k, int n) { return k < 4 ? 0.0 : k > n - 1 ? double(n) - 3.0 : double(k) - 3.0; }
double nk(int order, int k, double u, int n) {
    if (order == 1) return (uk(k, n) <= u && u < uk(k + 1, n)) ? 1.0 : 0.0;
    double result = 0.0;
    const int d = order - 1;
    if (uk(k + d, n) - uk(k, n) != 0.0) result += (u - uk(k, n)) / (uk(k + d, n) - uk(k, n)) * nk(d, k, u, n);
    if (uk(k + order, n) - uk(k + 1, n) != 0.0)
        result += (uk(k + order, n) - u) / (uk(k + order, n) - uk(k + 1, n)) * nk(d, k + 1, u, n);
    return result;
}

// One coordinate of the Bezier surface's point (cpfg's calcPValue for eBEZIERSURFACE, patch 0),
// its products and sums in cpfg's order.
double patch(const std::vector<P3>& q, int c, double t, double s) {
    auto row = [&](int r) {
        const double p0 = q[size_t(r * 4)][size_t(c)], p1 = q[size_t(r * 4 + 1)][size_t(c)],
                     p2 = q[size_t(r * 4 + 2)][size_t(c)], p3 = q[size_t(r * 4 + 3)][size_t(c)];
        return t * t * t * (-1 * p0 + 3 * p1 - 3 * p2 + p3) + t * t * (3 * p0 - 6 * p1 + 3 * p2) +
               t * (-3 * p0 + 3 * p1) + 1 * (p0);
    };
    return (-1 * s * s * s + 3 * s * s - 3 * s + 1) * row(0) + (3 * s * s * s - 6 * s * s + 3 * s) * row(1) +
           (-3 * s * s * s + 3 * s * s) * row(2) + (s * s * s) * row(3);
}

// cpfg's CCurveXYZ::init(eBEZIERSURFACE): 16 points, x = i % 4 - 1.5, y = i / 4 - 1.5.
std::vector<CurveXYZ::Point> grid() {
    std::vector<CurveXYZ::Point> g(16);
    for (int i = 0; i < 16; ++i) g[size_t(i)].p = {double(i % 4) - 1.5, double(i / 4) - 1.5, 0.0};
    return g;
}

}  // namespace

CurveXYZ::CurveXYZ(int samples) : CurveXYZ("", Type::BezierSurface, grid(), samples) {}

CurveXYZ::CurveXYZ(std::string name, Type type, const std::vector<Point>& points, int samples)
    : m_name(std::move(name)), m_type(type), m_samples(std::clamp(samples, 2, kMaxSamples)), m_filePoints(points) {
    // createPPoints: each point repeated by its multiplicity; a closed curve's first three
    // points again at its end; a phantom curve's ends mirrored (2 P1 - P2).
    size_t size = 0, offset = type == Type::Phantom ? 1 : 0;
    for (const Point& p : points) size += size_t(std::max(0, p.multiplicity));
    size += type == Type::Closed ? 3 : type == Type::Phantom ? 2 : 0;
    m_points.assign(size, P3{0, 0, 0});
    size_t at = 0;
    for (const Point& p : points)
        for (int j = 0; j < p.multiplicity; ++j) m_points[offset + at++] = p.p;
    if (type == Type::Closed)
        for (size_t i = 0; i < 3; ++i) m_points[size - 3 + i] = m_points[i];
    if (type == Type::Phantom && size >= 3)
        for (size_t c = 0; c < 3; ++c) {
            m_points[0][c] = 2 * m_points[1][c] - m_points[2][c];
            m_points[size - 1][c] = 2 * m_points[size - 2][c] - m_points[size - 3][c];
        }
    // createAPoints: the polyline through `samples` points at even parameters, its length
    // up to each of them over the whole.
    m_arc.assign(size_t(m_samples), 0.0);
    P3 last{0, 0, 0};
    for (int i = 0; i < m_samples; ++i) {
        const P3 p = atParameter(i / double(m_samples - 1));
        if (i > 0) {
            const double dx = p[0] - last[0], dy = p[1] - last[1], dz = p[2] - last[2];
            m_length += std::sqrt(dx * dx + dy * dy + dz * dz);
        }
        m_arc[size_t(i)] = m_length;
        last = p;
    }
    for (double& l : m_arc) l = l / m_length;
}

P3 CurveXYZ::atParameter(double t, double s) const {
    const int n = int(m_points.size());
    P3 h{0, 0, 0};
    t = t > 0 ? std::min(t, 1.0) : 0.0;  // in [0, 1] as cpfg's callers give it (and never NaN here)
    const std::vector<P3>& q = m_points;
    if (m_type == Type::BezierSurface) {
        if (15 < n)
            for (int c = 0; c < 3; ++c) h[size_t(c)] = patch(q, c, t, s);
    } else if (m_type == Type::Bezier) {
        if (3 < n) {  // segments of 4 points, each sharing its first with the one before
            const int segments = 1 + (n - 4) / 3;
            const int c = std::min(segments - 1, int(t / (1.000001 / double(segments))));
            const size_t i = size_t(c) * 3;
            t = (t - double(c) * (1.0 / double(segments))) * double(segments) / 1.000001;
            for (size_t k = 0; k < 3; ++k)
                h[k] = q[i][k] * nk(4, 0, t, 4) + q[i + 1][k] * nk(4, 1, t, 4) + q[i + 2][k] * nk(4, 2, t, 4) +
                       q[i + 3][k] * nk(4, 3, t, 4);
        }
    } else if (m_type == Type::Endpoint) {
        if (3 < n) {
            t = t * (double(n) - 3.000001);
            // cpfg sums over every point; only those of t's knot span and the three before it
            // are not 0 (adding an exact 0 changes no sum), so the sum runs around them.
            const int span = int(t) + 3;
            for (int i = std::max(0, span - 4); i <= std::min(n - 1, span + 1); ++i) {
                const double b = nk(4, i, t, n);
                for (size_t k = 0; k < 3; ++k) h[k] += q[size_t(i)][k] * b;
            }
        }
    } else if (3 < n) {  // the uniform B-spline (open, closed and phantom)
        const int i = 3 + int(t * (n - 3.000001));
        t = 3.0 + t * (double(n) - 3.000001);
        const size_t u = size_t(i);
        for (size_t k = 0; k < 3; ++k)
            h[k] = q[u - 3][k] * bi4(i - 3, t) + q[u - 2][k] * bi4(i - 2, t) + q[u - 1][k] * bi4(i - 1, t) +
                   q[u][k] * bi4(i, t);
    }
    return h;
}

P3 CurveXYZ::at(double t) const {
    if (std::isnan(t)) return {t, t, t};
    t = t < 0 ? 0.0 : t > 1 ? 1.0 : t;  // CurveCXS: "Parameter %f not defined, 0 used instead"
    if (m_type == Type::BezierSurface) {
        // calcAValue for a surface: each row of the patch is made the first 4 points of a
        // Bezier curve of 16 (the other 12 those of cpfg's grid, which its scratch curve keeps),
        // and measured; the points at t along them make a last such curve, taken at s = 0.
        if (m_points.size() < 16) return {0, 0, 0};  // cpfg reads past its points
        std::vector<Point> scratch = grid();
        P3 rows[4];
        for (size_t j = 0; j < 4; ++j) {
            for (size_t k = 0; k < 4; ++k) scratch[k].p = m_points[j * 4 + k];
            rows[j] = CurveXYZ("", Type::Bezier, scratch, m_samples).at(t);
        }
        for (size_t j = 0; j < 4; ++j) scratch[j].p = rows[j];
        return CurveXYZ("", Type::Bezier, scratch, m_samples).at(0);
    }
    // cpfg divides by the length: when it is 0 (every sample in one place) its fractions are
    // NaN and it reads outside its points; here the parameter is t itself.
    if (!(m_length > 0) || !std::isfinite(m_length)) return atParameter(t);
    int min = 0, max = m_samples - 1;
    while (max - min > 1) {
        const int med = (min + max) / 2;
        if (m_arc[size_t(med)] > t) max = med;
        else min = med;
    }
    // Two samples in one place (t = 1 past a still end): cpfg's 0 / 0; here the later one.
    const double lo = m_arc[size_t(min)], hi = m_arc[size_t(max)];
    const double fraction = hi - lo != 0 ? (t - lo) / (hi - lo) : 1.0;
    return atParameter((min + fraction) / (m_samples - 1));
}

// [SECTION] Reading a curve file (readCurve, openCurve)

namespace {

using vlab_detail::Word;

// Words as sscanf's %s finds them (split at every isspace character, '\r' too).
std::vector<Word> cWords(std::string_view line, size_t from) {
    std::vector<Word> out;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; };
    size_t i = from;
    while (i < line.size()) {
        while (i < line.size() && space(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !space(line[i])) ++i;
        if (i > start) out.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return out;
}

// A number as atof reads a word, the whole word (a wrong file is an error here, not cpfg's 0).
std::optional<double> number(std::string_view w) {
    if (!w.empty() && w[0] == '+') w.remove_prefix(1);
    double v = 0;
    const auto r = std::from_chars(w.data(), w.data() + w.size(), v, std::chars_format::general);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

constexpr long kMaxPoints = 100000;  // control points, multiplicities counted (cpfg has no bound)
constexpr int kMaxLevels = 20;       // cpfg's _cmax: curves inside points inside curves

class CurveReader {
public:
    CurveReader(const std::string& file, std::vector<CurveFileDiagnostic>& out) : m_file(file), m_out(out) {}

    // Each line as cpfg's openCurve gives it to readCurve: up to its '\n', NUL ending it.
    void read(std::string_view text) {
        if (text.empty()) return fail(0, 0, "the file is empty (a curve file: 'points: N', 'dimension: 4', "
                                            "'type: bspline', then the points, as cuspy writes them)");
        size_t i = 0;
        for (int line = 1; i < text.size() && !m_failed; ++line) {
            size_t end = text.find('\n', i);
            if (end == std::string_view::npos) end = text.size();
            std::string_view l = text.substr(i, end - i);
            l = l.substr(0, l.find('\0'));
            command(l, line);
            i = end + 1;
        }
        if (m_failed) return;
        if (m_levels.empty())
            fail(0, 0, "the file has no 'points: N' line (a curve file: 'points: N', 'dimension: 4', "
                       "'type: bspline', then the points, as cuspy writes them)");
        else if (m_read < m_levels[0].size)
            fail(m_pointsLine, 1, "the file ends after " + std::to_string(m_read) + " of the " +
                                      std::to_string(m_levels[0].size) + " points this line declares");
    }

    CurveXYZ::Type type = CurveXYZ::Type::BSpline;
    std::vector<CurveXYZ::Point> points;  // the curve's (level 0), unread ones at 0, 0, 0

private:
    struct Level {
        long size = 0, index = -1;
        int dim = 2;
    };

    void fail(int line, int col, std::string message) {
        m_out.push_back({m_file, line, col, std::move(message)});
        m_failed = true;
    }

    // `count` numbers after the label, as sscanf("label %f %f %f") wants them.
    // `end`: the column after the line's last character.
    bool numbers(const std::vector<Word>& w, size_t count, const char* label, const char* what, int line, int end) {
        for (size_t k = 0; k < count; ++k)
            if (k >= w.size() || !number(w[k].text)) {
                fail(line, k < w.size() ? w[k].col : end, std::string("expected ") + what + " after '" + label + "'");
                return false;
            }
        return true;
    }

    void command(std::string_view l, int line) {
        static const char* const labels[] = {"//",    "version:", "contact:", "end:", "heading:",   "up:",
                                             "size:", "points:",  "range:",   "dim:", "dimension:", "type:"};
        size_t which = 0;
        while (which < std::size(labels) && l.substr(0, std::strlen(labels[which])) != labels[which]) ++which;
        if (which == std::size(labels)) return point(l, line);
        const char* label = labels[which];
        const std::vector<Word> w = cWords(l, std::strlen(label));
        const int col = int(std::strlen(label)) + 2;
        switch (which) {
            case 0: return;
            case 1:
                if (w.empty()) fail(line, col, "expected the format's version after 'version:' (cuspy writes 'version: 1.4')");
                return;
            case 2: case 3: case 4: case 5: numbers(w, 3, label, "three numbers", line, int(l.size()) + 1); return;
            case 6: numbers(w, 1, label, "a number", line, int(l.size()) + 1); return;
            case 8: numbers(w, 2, label, "two numbers", line, int(l.size()) + 1); return;
            case 7: return pointsCommand(w, line, col);
            default: break;
        }
        if (m_levels.empty()) return fail(line, 1, std::string("expected 'points: N' before '") + label + "' (it concerns the curve read last)");
        if (which == 11) {
            if (w.empty()) return fail(line, col, "expected a type after 'type:' (bspline, bspline-closed, bspline-endpoint, "
                                                  "bspline-phantom, bezier or bezier-surface)");
            const std::string_view t = w[0].text;
            const CurveXYZ::Type type = t == "bezier-surface" ? CurveXYZ::Type::BezierSurface
                                        : t == "bezier"          ? CurveXYZ::Type::Bezier
                                        : t == "bspline-phantom"  ? CurveXYZ::Type::Phantom
                                        : t == "bspline-endpoint" ? CurveXYZ::Type::Endpoint
                                        : t == "bspline-closed"   ? CurveXYZ::Type::Closed
                                                                  : CurveXYZ::Type::BSpline;  // cpfg: any other word
            if (m_levels.size() == 1) this->type = type;
            return;
        }
        const std::optional<long> dim = w.empty() ? std::nullopt : vlab_detail::intWord(w[0].text, 2, 4);
        if (!dim) return fail(line, w.empty() ? col : w[0].col, std::string("expected the numbers a point has after '") + label +
                                                                   "' (2: x y, 3: x y z, 4: x y z multiplicity)");
        m_levels.back().dim = int(*dim);
    }

    // `points: N`: the curve's points follow; inside it, the curve of the point read last.
    void pointsCommand(const std::vector<Word>& w, int line, int col) {
        const std::optional<long> n = w.empty() ? std::nullopt : vlab_detail::intWord(w[0].text, 0, kMaxPoints);
        if (!n) return fail(line, w.empty() ? col : w[0].col, "expected the number of points after 'points:' (0 to 100000)");
        if (!m_levels.empty() && m_levels.back().index < 0)
            return fail(line, 1, "expected a point before a second 'points:' (cpfg makes it the curve of the point before it)");
        if (int(m_levels.size()) >= kMaxLevels) return fail(line, 1, "curves inside points nested more than 20 deep");
        if (m_levels.empty()) {
            points.assign(size_t(*n), CurveXYZ::Point{});
            m_total = *n;
            m_pointsLine = line;
        }
        m_levels.push_back({*n, -1, 2});
    }

    // A line with no ':' (and over 2 characters): the next point, `dimension:` numbers of it.
    void point(std::string_view l, int line) {
        if (l.size() <= 2 || l.find(':') != std::string_view::npos) return;  // cpfg skips it
        const std::vector<Word> w = cWords(l, 0);
        if (m_levels.empty()) return fail(line, w.empty() ? 1 : w[0].col, "expected 'points: N' before the first point");
        const size_t count = std::min<size_t>(w.size(), 4);  // sscanf("%s %s %s %s")
        if (int(count) != m_levels.back().dim)
            return fail(line, w.empty() ? 1 : w[0].col, "expected a point of " + std::to_string(m_levels.back().dim) +
                                                            " numbers here (x y, x y z or x y z multiplicity, as 'dimension:' says)");
        while (++m_levels.back().index >= m_levels.back().size) {  // this curve is whole: its parent's next point
            m_levels.pop_back();
            if (m_levels.empty())
                return fail(line, w[0].col, "more points than the 'points: N' of line " + std::to_string(m_pointsLine) + " declares");
        }
        const int dim = m_levels.back().dim;
        if (size_t(dim) > count) return fail(line, w[0].col, "expected a point of " + std::to_string(dim) + " numbers here");
        CurveXYZ::Point p;
        for (int k = 0; k < dim; ++k) {
            const std::optional<double> v = number(w[size_t(k)].text);
            if (!v) return fail(line, w[size_t(k)].col, "expected a number here, not '" + std::string(w[size_t(k)].text.substr(0, 40)) + "'");
            if (k < 3) p.p[size_t(k)] = *v;
            else if (*v >= 0 && *v < 1001) p.multiplicity = int(*v);  // cpfg: int(atof(...))
            else return fail(line, w[3].col, "expected the point's multiplicity here (a whole number from 0 to 1000)");
        }
        if (m_levels.size() > 1) return;  // a point of a point's curve: cpfg keeps it aside
        m_total += p.multiplicity - 1;
        if (m_total > kMaxPoints) return fail(line, w[3].col, "too many points (more than 100000, multiplicities counted)");
        points[size_t(m_levels[0].index)] = p;
        m_read = m_levels[0].index + 1;
    }

    const std::string& m_file;
    std::vector<CurveFileDiagnostic>& m_out;
    std::vector<Level> m_levels;  // cpfg's _ccurve, _cpoint, _cdimen up to _clevel
    long m_total = 0, m_read = 0;
    int m_pointsLine = 0;
    bool m_failed = false;
};

}  // namespace

CurveRead readCurve(std::string_view text, const std::string& fileName, int samples) {
    CurveRead r;
    CurveReader in(fileName, r.diagnostics);
    in.read(text);
    r.curve = CurveXYZ(fileName, in.type, in.points, samples);
    return r;
}

CurveRead loadCurve(const std::filesystem::path& path, int samples) {
    errno = 0;
    const std::optional<std::string> text = readFile(path);
    if (text) return readCurve(*text, path.string(), samples);
    const int err = errno;
    CurveRead r;
    r.curve = CurveXYZ(samples);  // cpfg keeps the first curve it makes, the grid's surface
    r.diagnostics.push_back({path.string(), 0, 0, std::string("cannot read the file: ") + (err ? std::strerror(err) : "unknown error")});
    return r;
}

bool CurveRead::ok() const { return vlab_detail::noErrors(diagnostics); }

// [SECTION] What a grammar calls (CurveCXS, CurveCYS, CurveCZS, CurveGAL)

std::optional<CurveCall> curveCallNamed(std::string_view name) {
    if (name == "func") return CurveCall::Func;
    if (name == "curveX") return CurveCall::CurveX;
    if (name == "curveY") return CurveCall::CurveY;
    if (name == "curveZ") return CurveCall::CurveZ;
    if (name == "curveGAL") return CurveCall::CurveLength;
    return std::nullopt;
}

double CurveTables::call(CurveCall c, double id, double x) const {
    if (c == CurveCall::Func) return func(id, x);
    if (!(id >= 1 && id < double(curves.size()) + 1)) return 0.0;  // cpfg: "Curve id >= count" and 0
    const CurveXYZ& curve = curves[size_t(int(id)) - 1];
    if (c == CurveCall::CurveLength) return curve.length();
    return curve.at(x)[size_t(c) - size_t(CurveCall::CurveX)];
}

std::string CurveTables::idProblem(CurveCall c, double id) const {
    const size_t n = c == CurveCall::Func ? functions.size() : curves.size();
    if (id >= 1 && id < double(n) + 1) return "";
    static const char* const names[] = {"func", "curveX", "curveY", "curveZ", "curveGAL"};
    const char* what = c == CurveCall::Func ? "function" : "curve";
    char shown[32];
    std::snprintf(shown, sizeof shown, "%g", id);
    return std::string(names[size_t(c)]) + "(" + shown + (c == CurveCall::CurveLength ? ")" : ", ...)") + ": there " +
           (n == 1 ? "is " : "are ") + std::to_string(n) + " " + what + (n == 1 ? "" : "s") +
           " (numbered from 1): it gives 0, as in cpfg";
}

std::string writeCurve(const CurveXYZ& c) {
    static const char* types[] = {"bspline", "bspline-closed", "bspline-endpoint", "bspline-phantom", "bezier", "bezier-surface"};
    std::string out = "version: 1.4\ncontact: 0 0 0\nend: 0 0 0\nheading: 0 1 0\nup: 0 0 -1\nsize: 1\npoints: " +
                      std::to_string(c.filePoints().size()) + "\nrange: 0.0 1.0\ndimension: 4\ntype: " + types[int(c.type())] + "\n";
    for (const CurveXYZ::Point& p : c.filePoints()) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "%f %f %g %d\n", p.p[0], p.p[1], p.p[2], p.multiplicity);
        out += buf;
    }
    return out;
}

}  // namespace sprout
