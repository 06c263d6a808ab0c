// cpfg's functions (cpfg/splinefun.cpp, splinearr.cpp): `.func` files in both formats, `.fset`
// function sets, and their evaluation, step for step as cpfg's SplineFunction computes it (the
// same B-spline basis, bisection and table), so that func(id, x) gives cpfg's numbers.
//
// Index of this file:
//   [SECTION] Evaluation (SplineFunction::P, N, _Value, _Precompute)
//   [SECTION] Reading a function
//   [SECTION] Function sets, files, diagnostics

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/line_reader.hpp"

namespace sprout {

using vlab_detail::LineReader;
using vlab_detail::Word;

namespace {

// [SECTION] Evaluation (SplineFunction::P, N, _Value, _Precompute)

constexpr int kOrder = 4;            // cubic (cpfg's t = 4)
constexpr int kMaxSamples = 10000;   // a table's size (cpfg has no bound; its editors write 10 to 1000)
constexpr int kMaxPoints = 100000;   // control points, multiplicities expanded
constexpr int kMaxMultiplicity = 1000;

// cpfg's Uk: the open uniform knot vector 0 0 0 0 1 2 ... n-2 n-2 n-2 n-2 (integers).
int knot(int j, int n) {
    if (j < kOrder) return 0;
    if (j > n) return n - kOrder + 2;
    return j - kOrder + 1;
}

// cpfg's N(k, t, u) (Cox-de Boor), in its order of operations.
double basis(int k, int t, double u, int n) {
    if (t == 1) return (knot(k, n) <= u && u < knot(k + 1, n)) ? 1.0 : 0.0;
    double sum = 0.0;
    int div = knot(k + t - 1, n) - knot(k, n);
    if (div != 0) sum = (u - knot(k, n)) / div * basis(k, t - 1, u, n);
    div = knot(k + t, n) - knot(k + 1, n);
    if (div != 0) sum += (knot(k + t, n) - u) / div * basis(k + 1, t - 1, u, n);
    return sum;
}

}  // namespace

CurveFunction::CurveFunction() : m_points{{0, 0}, {0, 0}, {0, 0}, {1, 0}} {}

CurveFunction::CurveFunction(std::string name, std::vector<std::array<double, 2>> points, int samples)
    : m_name(std::move(name)), m_points(std::move(points)) {
    if (m_points.size() < 4) m_points = CurveFunction().m_points;
    // cpfg's _Precompute: the table's values are the curve's, at i / (samples - 1).
    if (samples > 2 && samples <= kMaxSamples) {
        m_table.resize(size_t(samples));
        for (int i = 0; i < samples; i++) m_table[size_t(i)] = curveValue(double(i) / double(samples - 1));
        m_samples = samples;
    }
}

// cpfg's P(d): the curve's point at d in [0, 1] (1 itself is past the last knot span: 0, 0).
std::array<double, 2> CurveFunction::point(double d) const {
    const int n = int(m_points.size()) - 1;
    const double u = d * (n - kOrder + 2);
    double x = 0, y = 0;
    // cpfg sums over every point; only those of u's knot span and the three before it are not
    // 0 (adding an exact 0 changes no sum), so the sum runs over a margin around them.
    const int span = int(std::clamp(std::floor(u), -1.0, double(n)));
    for (int k = std::max(0, span - 1); k <= std::min(n, span + 4); k++) {
        const double b = basis(k, kOrder, u, n);
        x += m_points[size_t(k)][0] * b;
        y += m_points[size_t(k)][1] * b;
    }
    return {x, y};
}

// cpfg's _Value without a table: bisection on the curve's parameter until its x is within
// 0.001 of `v`. cpfg loops for ever when no point is that close (x not from 0 to 1); here
// 200 halvings end it (the parameter stops changing after about 55).
double CurveFunction::curveValue(double v) const {
    if (std::isnan(v)) return v;
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    const double tofind = (v - 0.0) / (1.0 - 0.0);
    double low = 0.0, high = 1.0;
    std::array<double, 2> tst{0, 0};
    for (int counter = 0; counter < 200; ++counter) {
        const double check = (low + high) / 2.0;
        tst = point(check);
        if (tst[0] > tofind) high = check;
        else low = check;
        if (!(std::fabs(tst[0] - tofind) > 0.001)) break;
    }
    return tst[1];
}

// cpfg's GetValue: x clamped to [0, 1], then the table (linear between its entries) or the curve.
double CurveFunction::operator()(double v) const {
    if (std::isnan(v)) return v;
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    if (m_samples <= 2) return curveValue(v);
    const double index = v * (m_samples - 1);
    const int i = int(std::floor(index));
    const double w1 = 1 - index + i;
    const double w2 = index - i;
    if (i >= m_samples - 1) return m_table[size_t(m_samples - 1)];
    return w1 * m_table[size_t(i)] + w2 * m_table[size_t(i) + 1];
}

// [SECTION] Reading a function

namespace {

// `count` lines of `x y [multiplicity]` (cpfg's _Load0101; the first format has no
// multiplicity, `withMultiplicity` false).
bool readPoints(LineReader& in, long count, bool withMultiplicity, std::vector<std::array<double, 3>>& out) {
    long expanded = 0;
    for (long i = 0; i < count; ++i) {
        if (!in.skipBlank()) {
            in.error(in.lineNo(), 1, "the file ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                                         " points (expected 'x y" + (withMultiplicity ? " [multiplicity]'" : "'") + ")");
            return false;
        }
        const int line = in.lineNo();
        const std::vector<Word> w = vlab_detail::words(in.peek());
        in.advance();
        const size_t most = withMultiplicity ? 3 : 2;
        if (w.size() < 2 || w.size() > most) {
            in.error(line, w.empty() ? 1 : w[0].col,
                     std::string("expected a point 'x y") + (withMultiplicity ? " [multiplicity]'" : "'") + " here (point " +
                         std::to_string(i + 1) + " of " + std::to_string(count) + ")");
            return false;
        }
        std::optional<float> x = vlab_detail::floatWord(w[0].text), y = vlab_detail::floatWord(w[1].text);
        if (!x || !y) {
            const Word& bad = x ? w[1] : w[0];
            in.error(line, bad.col, "expected a number here, not '" + std::string(bad.text.substr(0, 40)) + "'");
            return false;
        }
        int multiplicity = 1;
        if (w.size() == 3) {
            std::optional<float> m = vlab_detail::floatWord(w[2].text);
            if (!m || *m < 0 || *m > kMaxMultiplicity) {
                in.error(line, w[2].col, "expected the point's multiplicity here (a whole number from 0 to 1000)");
                return false;
            }
            multiplicity = int(*m);  // cpfg: std::stof, then an int
        }
        out.push_back({double(*x), double(*y), double(multiplicity)});
        if ((expanded += multiplicity) > kMaxPoints) {
            in.error(line, 1, "too many points (more than 100000)");
            return false;
        }
    }
    return true;
}

// `points: N` and the points after it: at least 4 (cpfg's minimum), also once multiplicities
// are counted; false after saying why.
bool readFunctionPoints(LineReader& in, bool withMultiplicity, std::vector<std::array<double, 3>>& points) {
    const int pointsLine = in.lineNo();
    std::optional<long> count = in.keyedInt("points:", 0, kMaxPoints, "COUNT");
    if (!count) return false;
    if (*count < 4) {
        in.error(pointsLine, 1, "a function needs at least 4 points (cpfg: 'not enough points specified')");
        return false;
    }
    if (!readPoints(in, *count, withMultiplicity, points)) return false;
    double expanded = 0;
    for (const auto& p : points) expanded += p[2];
    if (expanded < 4) {
        in.error(pointsLine, 1, "a function needs at least 4 points once multiplicities are counted");
        return false;
    }
    return true;
}

// `fver 1 1` after its first line: name:, samples:, [background: + backgroundXY:],
// [markers: n + n lines], flip:, points: n, the points.
std::optional<FunctionFile> readFver(LineReader& in, const std::string& stem) {
    FunctionFile f;
    auto name = in.keyed("name:", "'name: NAME'");
    if (!name) return std::nullopt;
    f.name = name->empty() ? stem : std::string((*name)[0].text);
    std::optional<long> samples = in.keyedInt("samples:", -1000000, kMaxSamples, "SAMPLES");
    if (!samples) return std::nullopt;
    in.skipBlank();
    if (in.peek().substr(0, 11) == "background:") {  // funcedit's background image: skipped, as cpfg
        in.advance();
        if (in.skipBlank() && in.peek().substr(0, 13) == "backgroundXY:") in.advance();
    }
    in.skipBlank();
    if (in.peek().substr(0, 8) == "markers:") {
        std::optional<long> markers = in.keyedInt("markers:", 0, 10000, "COUNT");
        if (!markers) return std::nullopt;
        for (long i = 0; i < *markers; ++i) {
            if (!in.skipBlank()) break;
            in.advance();
        }
    }
    in.skipBlank();
    if (in.peek().substr(0, 5) == "flip:") {  // the editor's view: cpfg ignores it
        const std::vector<Word> w = vlab_detail::words(in.peek());
        f.flip = w.size() > 1 && w[1].text == "on";
        in.advance();
    }
    if (!readFunctionPoints(in, true, f.points)) return std::nullopt;
    f.samples = int(*samples);
    return f;
}

std::string stemOf(const std::string& fileName) {
    std::string s = std::filesystem::path(fileName).filename().string();
    const size_t dot = s.rfind('.');
    return dot == std::string::npos || dot == 0 ? s : s.substr(0, dot);
}

// One function from `in`'s next line on: `fver 1 1` or `range: l u` (the first format).
std::optional<FunctionFile> readOne(LineReader& in, const std::string& stem, int samples) {
    if (!in.skipBlank()) {
        in.error(in.lineNo(), 1, "the file ends where a function ('fver 1 1') was expected");
        return std::nullopt;
    }
    const int line = in.lineNo();
    const std::vector<Word> w = vlab_detail::words(in.peek());
    if (w[0].text == "range:") {
        in.advance();
        if (w.size() < 3 || !vlab_detail::floatWord(w[1].text) || !vlab_detail::floatWord(w[2].text)) {
            in.error(line, w.size() > 1 ? w[1].col : 1, "expected 'range: LOW HIGH' (two numbers)");
            return std::nullopt;
        }
        FunctionFile f;
        f.name = stem, f.original = true;
        if (!readFunctionPoints(in, false, f.points)) return std::nullopt;
        if (samples > kMaxSamples)
            in.error(line, 1, "the view file's " + std::to_string(samples) + " samples are more than 10000: the curve is "
                              "evaluated without a table", true);
        return f;
    }
    if (w[0].text != "fver") {
        in.error(line, w[0].col, "expected 'fver 1 1' or 'range: 0 1' (the first line of a function)");
        return std::nullopt;
    }
    in.advance();
    const std::optional<long> major = w.size() > 1 ? vlab_detail::intWord(w[1].text, 0, 999) : std::nullopt;
    const std::optional<long> minor = w.size() > 2 ? vlab_detail::intWord(w[2].text, 0, 999) : std::nullopt;
    if (!major || !minor) {
        in.error(line, w.size() > 1 ? w[1].col : w[0].col + 5, "expected the format's version after 'fver' ('fver 1 1')");
        return std::nullopt;
    }
    if (*major * 100 + *minor != 101) {
        in.error(line, w[1].col, "unsupported function format " + std::to_string(*major) + "." + std::to_string(*minor) +
                                     " (cpfg reads 'fver 1 1')");
        return std::nullopt;
    }
    return readFver(in, stem);
}

}  // namespace

FunctionRead readFunction(std::string_view text, const std::string& fileName, int samples) {
    FunctionRead r;
    LineReader in(text, fileName, r.diagnostics);
    if (std::optional<FunctionFile> f = readOne(in, stemOf(fileName), samples)) {
        r.function = f->function(samples);
        r.file = std::move(*f);
    }
    return r;
}

// [SECTION] Function sets, files, diagnostics

FunctionSetRead readFunctionSet(std::string_view text, const std::string& fileName) {
    FunctionSetRead r;
    LineReader in(text, fileName, r.diagnostics);
    in.skipBlank();
    const int line = in.lineNo();
    const std::vector<Word> w = vlab_detail::words(in.peek());
    if (w.size() != 3 || w[0].text != "funcgalleryver") {
        in.error(line, w.empty() ? 1 : w[0].col, "expected 'funcgalleryver 1 1' (the first line of a function set)");
        return r;
    }
    in.advance();
    if (vlab_detail::intWord(w[1].text, 0, 999).value_or(0) * 100 + vlab_detail::intWord(w[2].text, 0, 999).value_or(0) != 101) {
        in.error(line, w[1].col, "unsupported function set format " + std::string(w[1].text) + "." +
                                     std::string(w[2].text) + " (cpfg reads 'funcgalleryver 1 1')");
        return r;
    }
    std::optional<long> items = in.keyedInt("items:", 0, 10000, "COUNT");
    if (!items) return r;
    for (long i = 0; i < *items; ++i) {
        std::optional<FunctionFile> f = readOne(in, "", -1);
        if (!f) return r;
        r.functions.push_back(f->function(-1));
        r.files.push_back(std::move(*f));
    }
    return r;
}

FunctionRead loadFunction(const std::filesystem::path& path, int samples) {
    return vlab_detail::fromFile<FunctionRead>(path, [&](const std::string& t) { return readFunction(t, path.string(), samples); });
}

FunctionSetRead loadFunctionSet(const std::filesystem::path& path) {
    return vlab_detail::fromFile<FunctionSetRead>(path, [&](const std::string& t) { return readFunctionSet(t, path.string()); });
}

CurveFunction FunctionFile::function(int viewSamples) const {
    std::vector<std::array<double, 2>> expanded;
    for (const auto& p : points)
        for (int j = 0; j < int(p[2]); ++j) expanded.push_back({p[0], p[1]});
    return CurveFunction(name, std::move(expanded), original ? viewSamples : samples);
}

namespace {
std::string printed(const char* format, double a, double b) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, a, b);
    return buf;
}
}  // namespace

std::string writeFunction(const FunctionFile& f) {
    std::string out = "fver 1 1\nname: " + f.name + "\nsamples: " + std::to_string(f.samples) + "\nflip: " + (f.flip ? "on" : "off") +
                      "\npoints: " + std::to_string(f.points.size()) + "\n";
    for (const auto& p : f.points) out += printed("%f %f", p[0], p[1]) + " " + std::to_string(int(p[2])) + "\n";
    return out;
}

std::string writeFunctionSet(const std::vector<FunctionFile>& set) {
    std::string out = "funcgalleryver 1 1\nitems: " + std::to_string(set.size()) + "\n";
    for (const FunctionFile& f : set) out += writeFunction(f);
    return out;
}

bool FunctionRead::ok() const { return vlab_detail::noErrors(diagnostics); }
bool FunctionSetRead::ok() const { return vlab_detail::noErrors(diagnostics); }

std::string CurveFileDiagnostic::text() const {
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(col);
    return s + ": " + (warning ? "warning: " : "") + message;
}

}  // namespace sprout
