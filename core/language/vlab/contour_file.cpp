// cpfg's contours (cpfg/general.c): `.con` files in the first format and `cver 1 1` to `1 3`,
// `.cset` contour sets (VLab's gallery), the cross-section cpfg samples from one (MakeContour:
// a uniform B-spline resampled by arc length, in floats, in cpfg's order of operations), and
// the table a grammar carries (CurveTables).
//
// Index of this file:
//   [SECTION] Sampling (evaluate_spline, MakeContour)
//   [SECTION] Reading a contour
//   [SECTION] Contour sets, files
//   [SECTION] CurveTables

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/line_reader.hpp"

namespace sprout {

using vlab_detail::LineReader;
using vlab_detail::Word;

namespace {

// [SECTION] Sampling (evaluate_spline, MakeContour)

const float kBSpline[4][4] = {{-1.0f / 6.0f, 3.0f / 6.0f, -3.0f / 6.0f, 1.0f / 6.0f},
                              {3.0f / 6.0f, -6.0f / 6.0f, 3.0f / 6.0f, 0.0f / 6.0f},
                              {-3.0f / 6.0f, 0.0f / 6.0f, 3.0f / 6.0f, 0.0f / 6.0f},
                              {1.0f / 6.0f, 4.0f / 6.0f, 1.0f / 6.0f, 0.0f / 6.0f}};

// cpfg's evaluate_spline: the segment of control points first .. first + 3 (wrapping round).
void evaluate(const std::vector<std::array<float, 3>>& pts, float* res, int dim, float t) {
    const int num = int(pts.size());
    int first = int(std::floor(double(t)));
    first = std::clamp(first, 0, num - 1);
    const float lt = t - float(first);
    float tvec[4];
    tvec[3] = 1.0f;
    for (int i = 2; i >= 0; i--) tvec[i] = tvec[i + 1] * lt;
    float vec[4];
    for (int i = 0; i < 4; i++) {  // Vec4Mat4Mult
        float acc = 0.0f;
        for (int j = 0; j < 4; j++) acc = acc + tvec[j] * kBSpline[j][i];
        vec[i] = acc;
    }
    for (int coord = 0; coord < dim; coord++) {
        int first2 = first;
        res[coord] = vec[0] * pts[size_t(first2)][size_t(coord)];
        for (int i = 1; i < 4; i++) {
            first2 = first2 == num - 1 ? 0 : first2 + 1;
            res[coord] += vec[i] * pts[size_t(first2)][size_t(coord)];
        }
    }
}

}  // namespace

std::vector<std::array<float, 3>> Contour::sampled(int sides) const {
    const int num = int(points.size());
    if (num < (closed ? 3 : 4)) return {};
    sides = std::clamp(sides, 3, 1024);
    const int n = 10;  // points per unit of t
    const float invn = 1.0f / float(n);
    std::vector<float> lengths(size_t(num * n), 0.0f);
    float lastP[3] = {0, 0, 0}, actP[3] = {0, 0, 0};
    float lastlen = 0.0f;
    evaluate(points, lastP, dim, 0.0f);
    const float segments = closed ? float(num) : float(num - 3);
    for (int i = 0; i < segments; i++) {
        float t = float(i);
        for (int j = 0; j < n; j++, t += invn) {
            evaluate(points, actP, dim, t);
            float len = 0;
            for (int c = 0; c < 2; c++) {  // the length in x y only
                lastP[c] -= actP[c];
                len += lastP[c] * lastP[c];
            }
            lastlen = lengths[size_t(i * n + j)] = lastlen + float(std::sqrt(double(len)));
            for (int c = 0; c < dim; c++) lastP[c] = actP[c];
        }
    }
    if (closed) {  // back to the first point: the whole length
        evaluate(points, actP, dim, 0.0f);
        float len = 0;
        for (int c = 0; c < 2; c++) {
            lastP[c] -= actP[c];
            len += lastP[c] * lastP[c];
        }
        lastlen += float(std::sqrt(double(len)));
    }
    const float step = lastlen / float(sides);
    // A closed contour is turned so that its first point lies on the x axis.
    float rot[2][2] = {{1, 0}, {0, 1}};
    if (closed) {
        rot[0][0] = actP[0];
        rot[0][1] = -actP[1];
        float invlen = rot[0][0] * rot[0][0] + rot[0][1] * rot[0][1];
        if (invlen < 0.000000001) {
            rot[0][0] = rot[1][1] = 1;
            rot[1][0] = rot[0][1] = 0;
        } else {
            invlen = 1.0f / float(std::sqrt(double(invlen)));
            rot[0][0] *= invlen;
            rot[0][1] *= invlen;
            rot[1][0] = -rot[0][1];
            rot[1][1] = rot[0][0];
        }
    }
    std::vector<std::array<float, 3>> out(size_t(sides) + 1);
    lastlen = 0.0f;
    int j = 0;
    const int numpoints = closed ? sides : sides + 1;
    const int last = int(segments * float(n) - 1.0f);
    for (int i = 0; i < numpoints; i++) {
        float t = 0;
        if (i == 0) {
            while (lengths[size_t(j)] < 1e-10 / step && j < last) j++;
        } else {
            while (lengths[size_t(j)] < lastlen && j < last) j++;
            int j2 = j - 1;
            while (j2 > 0 && lengths[size_t(j)] - lengths[size_t(j2)] <= 1e-10 / step) j2--;
            j2 = std::max(j2, 0);
            t = float(j2) / float(n);
            const float span = lengths[size_t(j)] - lengths[size_t(j2)];
            if (span != 0) t += (lastlen - lengths[size_t(j2)]) / span / float(n);
        }
        evaluate(points, actP, dim, t);
        for (int c = 0; c < 2; c++) out[size_t(i)][size_t(c)] = actP[0] * rot[0][c] + actP[1] * rot[1][c];
        out[size_t(i)][2] = dim > 2 ? actP[2] : 0.0f;
        lastlen += step;
    }
    if (closed) out[size_t(sides)] = out[0];
    return out;
}

// [SECTION] Reading a contour

namespace {

constexpr long kMaxPoints = 100000;

std::string stemOf(const std::string& fileName) {
    std::string s = std::filesystem::path(fileName).filename().string();
    const size_t dot = s.rfind('.');
    return dot == std::string::npos || dot == 0 ? s : s.substr(0, dot);
}

// The words of the lines from here on, each with its line, as fscanf reads numbers across lines.
struct Token {
    Word word;
    int line;
};
std::optional<float> nextNumber(LineReader& in, std::vector<Token>& pending, const std::string& what) {
    while (pending.empty()) {
        if (!in.skipBlank()) {
            in.error(in.lineNo(), 1, "the file ends where " + what + " was expected");
            return std::nullopt;
        }
        for (const Word& w : vlab_detail::words(in.peek())) pending.push_back({w, in.lineNo()});
        std::reverse(pending.begin(), pending.end());
        in.advance();
    }
    const Token t = pending.back();
    pending.pop_back();
    std::optional<float> v = vlab_detail::floatWord(t.word.text);
    if (!v) in.error(t.line, t.word.col, "expected " + what + " here, not '" + std::string(t.word.text.substr(0, 40)) + "'");
    return v;
}

bool enoughPoints(LineReader& in, int line, const ContourFile& c) {
    double expanded = 0;
    for (const auto& p : c.points) expanded += p[3];
    if (expanded >= (c.closed ? 3 : 4)) return true;
    in.error(line, 1, std::string("a") + (c.closed ? " closed contour needs at least 3" : "n open contour needs at least 4") +
                          " points");
    return false;
}

// The first format: `num dim closed|open`, then num points of dim numbers.
std::optional<ContourFile> readOldContour(LineReader& in, const std::vector<Word>& w, const std::string& stem) {
    const int line = in.lineNo();
    in.advance();
    const std::optional<long> num = w.size() == 3 ? vlab_detail::intWord(w[0].text, 1, kMaxPoints) : std::nullopt;
    const std::optional<long> dim = w.size() == 3 ? vlab_detail::intWord(w[1].text, 2, 3) : std::nullopt;
    if (!num || !dim) {
        in.error(line, w[0].col, "expected 'cver 1 3' or the first format's 'POINTS DIMENSION closed|open' (dimension 2 or 3)");
        return std::nullopt;
    }
    ContourFile c;
    c.name = stem;
    c.version = 0;
    c.closed = w[2].text == "closed";
    c.dim = int(*dim);
    std::vector<Token> pending;
    for (long i = 0; i < *num; ++i) {
        std::array<float, 3> p{0, 0, 0};
        for (long k = 0; k < *dim; ++k) {
            std::optional<float> v = nextNumber(in, pending, "coordinate " + std::to_string(k + 1) + " of point " + std::to_string(i + 1));
            if (!v) return std::nullopt;
            p[size_t(k)] = *v;
        }
        // cuspy joins a point repeated into one of a higher multiplicity
        if (!c.points.empty() && c.points.back()[0] == p[0] && c.points.back()[1] == p[1] && c.points.back()[2] == p[2])
            c.points.back()[3] += 1;
        else
            c.points.push_back({p[0], p[1], p[2], 1});
    }
    if (!enoughPoints(in, line, c)) return std::nullopt;
    return c;
}

// `cver 1 1` .. `1 3` after the version line.
std::optional<ContourFile> readCver(LineReader& in, int version, const std::string& stem) {
    ContourFile c;
    c.version = version;
    auto name = in.keyed("name:", "'name: NAME'");
    if (!name) return std::nullopt;
    c.name = name->empty() ? stem : std::string((*name)[0].text);
    const int pointsLine = in.lineNo();
    auto counts = in.keyed("points:", "'points: CONTROL-POINTS TOTAL'");
    if (!counts) return std::nullopt;
    const std::optional<long> n1 = counts->size() == 2 ? vlab_detail::intWord((*counts)[0].text, 1, kMaxPoints) : std::nullopt;
    const std::optional<long> total = counts->size() == 2 ? vlab_detail::intWord((*counts)[1].text, 1, kMaxPoints) : std::nullopt;
    if (!n1 || !total) {
        in.error(pointsLine, counts->empty() ? 1 : (*counts)[0].col, "expected two counts after 'points:' (the control points, and "
                                                                     "their total with multiplicities), from 1 to 100000");
        return std::nullopt;
    }
    const int typeLine = in.lineNo();
    auto type = in.keyed("type:", version == 101 ? "'type: open|closed'" : "'type: or|oe|cr|ce'");
    if (!type) return std::nullopt;
    const std::string_view t = type->empty() ? std::string_view() : (*type)[0].text;
    if (version == 101) {
        c.closed = t.substr(0, 4) != "open";
    } else {
        if (t.size() < 2 || (t[0] != 'o' && t[0] != 'c') || (t[1] != 'r' && t[1] != 'e')) {
            in.error(typeLine, type->empty() ? 1 : (*type)[0].col, "expected the contour's type after 'type:': or, oe, cr or ce "
                                                                   "(open or closed, regular or end-point interpolating)");
            return std::nullopt;
        }
        c.closed = t[0] == 'c';
        c.endpoint = t[1] == 'e';
        if (t[1] == 'e')
            in.error(typeLine, (*type)[0].col, "end-point interpolating contours are drawn as regular ones, as cpfg does", true);
    }
    if (version == 103) {
        const auto samples = in.keyedInt("samples:", -1000000, 1000000, "SAMPLES");  // cuspy's; cpfg uses `contour sides:`
        if (!samples) return std::nullopt;
        c.samples = int(*samples);
        in.skipBlank();
        if (in.peek().substr(0, 11) == "background:") {  // cuspy's background image
            in.advance();
            if (in.skipBlank() && in.peek().substr(0, 13) == "backgroundXY:") in.advance();
        }
        in.skipBlank();
        if (in.peek().substr(0, 8) == "markers:") {
            std::optional<long> markers = in.keyedInt("markers:", 0, 10000, "COUNT");
            if (!markers) return std::nullopt;
            for (long i = 0; i < *markers && in.skipBlank(); ++i) in.advance();
        }
    }
    std::vector<Token> pending;
    long expanded = 0;
    for (long i = 0; i < *n1; ++i) {
        const std::string what = " of point " + std::to_string(i + 1) + " ('x y z multiplicity')";
        std::array<float, 3> p{0, 0, 0};
        for (size_t k = 0; k < 3; ++k) {
            std::optional<float> v = nextNumber(in, pending, std::string(1, "xyz"[k]) + what);
            if (!v) return std::nullopt;
            p[k] = *v;
        }
        std::optional<float> m = nextNumber(in, pending, "the multiplicity" + what);
        if (!m) return std::nullopt;
        if (*m < 0 || *m > 1000 || *m != std::floor(*m)) {
            in.error(in.lineNo() - 1, 1, "the multiplicity" + what + " must be a whole number from 0 to 1000");
            return std::nullopt;
        }
        expanded += long(*m);
        if (expanded > kMaxPoints) {
            in.error(in.lineNo() - 1, 1, "too many points (more than 100000 with their multiplicities)");
            return std::nullopt;
        }
        c.points.push_back({p[0], p[1], p[2], double(*m)});
    }
    if (expanded != *total)
        in.error(pointsLine, (*counts)[1].col, "the multiplicities add up to " + std::to_string(expanded) + ", not " +
                                                   std::to_string(*total) + " (the points are used as they add up)", true);
    if (!enoughPoints(in, pointsLine, c)) return std::nullopt;
    return c;
}

std::optional<ContourFile> readOneContour(LineReader& in, const std::string& stem) {
    if (!in.skipBlank()) {
        in.error(in.lineNo(), 1, "the file ends where a contour ('cver 1 3') was expected");
        return std::nullopt;
    }
    const int line = in.lineNo();
    const std::vector<Word> w = vlab_detail::words(in.peek());
    if (w[0].text == "version:") {
        in.error(line, w[0].col, "this is a curve file ('version:'; cpfg reads it for a view file's 'curve:' line and "
                                 "curveX/Y/Z), not a contour ('cver 1 3')");
        return std::nullopt;
    }
    if (w[0].text != "cver") return readOldContour(in, w, stem);
    in.advance();
    const std::optional<long> major = w.size() > 1 ? vlab_detail::intWord(w[1].text, 0, 999) : std::nullopt;
    const std::optional<long> minor = w.size() > 2 ? vlab_detail::intWord(w[2].text, 0, 999) : std::nullopt;
    const long version = major && minor ? *major * 100 + *minor : -1;
    if (version != 101 && version != 102 && version != 103) {
        in.error(line, w.size() > 1 ? w[1].col : w[0].col, "unsupported contour format (cpfg reads 'cver 1 1', 'cver 1 2' and 'cver 1 3')");
        return std::nullopt;
    }
    return readCver(in, int(version), stem);
}

}  // namespace

ContourRead readContour(std::string_view text, const std::string& fileName) {
    ContourRead r;
    LineReader in(text, fileName, r.diagnostics);
    r.file = readOneContour(in, stemOf(fileName));
    if (r.file) r.contour = r.file->contour();
    return r;
}

// [SECTION] Contour sets, files

ContourSetRead readContourSet(std::string_view text, const std::string& fileName) {
    ContourSetRead r;
    LineReader in(text, fileName, r.diagnostics);
    in.skipBlank();
    const int line = in.lineNo();
    const std::vector<Word> w = vlab_detail::words(in.peek());
    if (w.size() != 3 || w[0].text != "contourgalleryver" || w[1].text != "1" || w[2].text != "1") {
        in.error(line, w.empty() ? 1 : w[0].col, "expected 'contourgalleryver 1 1' (the first line of a contour set)");
        return r;
    }
    in.advance();
    std::optional<long> items = in.keyedInt("items:", 0, 10000, "COUNT");
    if (!items) return r;
    for (long i = 0; i < *items; ++i) {
        std::optional<ContourFile> c = readOneContour(in, "");
        if (!c) return r;
        r.contours.push_back(c->contour());
        r.files.push_back(std::move(*c));
    }
    return r;
}

ContourRead loadContour(const std::filesystem::path& path) {
    return vlab_detail::fromFile<ContourRead>(path, [&](const std::string& t) { return readContour(t, path.string()); });
}

ContourSetRead loadContourSet(const std::filesystem::path& path) {
    return vlab_detail::fromFile<ContourSetRead>(path, [&](const std::string& t) { return readContourSet(t, path.string()); });
}

Contour ContourFile::contour() const {
    Contour c;
    c.name = name, c.closed = closed, c.dim = dim;
    for (const auto& p : points)
        for (int k = 0; k < int(p[3]); ++k) c.points.push_back({float(p[0]), float(p[1]), float(p[2])});
    return c;
}

std::string writeContour(const ContourFile& c) {
    long total = 0;
    for (const auto& p : c.points) total += long(p[3]);
    std::string out = "cver 1 3\nname: " + c.name + "\npoints: " + std::to_string(c.points.size()) + " " + std::to_string(total) +
                      "\ntype: " + (c.closed ? "c" : "o") + (c.endpoint ? "e" : "r") + "\nsamples: " + std::to_string(c.samples) + "\n";
    for (const auto& p : c.points) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%f %f %f %d\n", p[0], p[1], p[2], int(p[3]));  // (cuspy writes z as 0; cpfg reads it)
        out += buf;
    }
    return out;
}

std::string writeContourSet(const std::vector<ContourFile>& set) {
    std::string out = "contourgalleryver 1 1\nitems: " + std::to_string(set.size()) + "\n";
    for (const ContourFile& c : set) out += writeContour(c);
    return out;
}

bool ContourRead::ok() const { return contour && vlab_detail::noErrors(diagnostics); }
bool ContourSetRead::ok() const { return vlab_detail::noErrors(diagnostics); }

// [SECTION] CurveTables

void CurveTables::addFunction(CurveFunction f) {
    functions.push_back(std::move(f));
    functionsFromSet = false;
}

void CurveTables::setFunctionSet(std::vector<CurveFunction> set) {
    functions = std::move(set);
    functionsFromSet = true;
}

int CurveTables::functionId(std::string_view name) const {
    if (!functionsFromSet || name.empty()) return 0;
    for (size_t i = 0; i < functions.size(); ++i) {
        std::string_view n = functions[i].name();
        if (n.size() > 5 && n.substr(n.size() - 5) == ".func") n.remove_suffix(5);  // cpfg drops the suffix
        if (n == name) return int(i) + 1;
    }
    return 0;
}

std::vector<std::string> CurveTables::functionNames() const {
    std::vector<std::string> out;
    if (functionsFromSet)
        for (const CurveFunction& f : functions) out.push_back(f.name());
    return out;
}

double CurveTables::func(double id, double x) const {
    if (!(id >= 1 && id < double(functions.size()) + 1)) return 0.0;  // cpfg: "Spline function id ..." and 0
    return functions[size_t(int(id)) - 1](x);
}

std::vector<std::array<float, 2>> CurveTables::section(int id, int sides) const {
    auto it = contours.find(id);
    if (it == contours.end()) return {};
    std::vector<std::array<float, 2>> out;
    for (const std::array<float, 3>& p : it->second.sampled(sides > 0 ? sides : contourSides)) out.push_back({-p[1], p[0]});
    return out;
}

}  // namespace sprout
