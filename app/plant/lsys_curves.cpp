// A `.lsys` grammar's functions and contours, read and written in its text (lsys_curves.hpp).
#include "app/plant/lsys_curves.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sprout {
namespace {

std::string_view word(std::string_view t, size_t& k) {
    while (k < t.size() && (t[k] == ' ' || t[k] == '\t')) ++k;
    const size_t b = k;
    while (k < t.size() && t[k] != ' ' && t[k] != '\t') ++k;
    return t.substr(b, k - b);
}

}  // namespace

std::vector<LsysCurve> lsysCurves(std::string_view text) {
    std::vector<LsysCurve> out;
    size_t start = 0;
    for (int line = 1; start <= text.size(); ++line) {
        size_t eol = text.find('\n', start);
        if (eol == std::string_view::npos) eol = text.size();
        std::string_view l = text.substr(start, eol - start);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        size_t k = 0;
        while (k < l.size() && (l[k] == ' ' || l[k] == '\t')) ++k;
        const bool function = l.substr(k, 9) == "function:", contour = l.substr(k, 8) == "contour:";
        if (function || contour) {
            LsysCurve c;
            c.function = function;
            c.line = line;
            k += function ? 9 : 8;
            c.name = std::string(word(l, k));
            size_t pointsAt = k;
            if (contour) {
                size_t after = k;
                const std::string_view kind = word(l, after);
                if (kind == "open" || kind == "closed") c.closed = kind == "closed", pointsAt = after;
            }
            while (pointsAt < l.size() && (l[pointsAt] == ' ' || l[pointsAt] == '\t')) ++pointsAt;
            // The points, up to a comment.
            size_t endAt = l.find('#', pointsAt);
            if (endAt == std::string_view::npos) endAt = l.size();
            while (endAt > pointsAt && (l[endAt - 1] == ' ' || l[endAt - 1] == '\t')) --endAt;
            bool ok = !c.name.empty();
            for (size_t p = pointsAt; ok && p < endAt;) {
                const std::string_view w = word(l.substr(0, endAt), p);
                if (w.empty()) break;
                const size_t comma = w.find(',');
                if (comma == std::string_view::npos) {
                    ok = false;
                    break;
                }
                const std::string xs(w.substr(0, comma)), ys(w.substr(comma + 1));
                char *ex = nullptr, *ey = nullptr;
                const double x = std::strtod(xs.c_str(), &ex), y = std::strtod(ys.c_str(), &ey);
                ok = !xs.empty() && !ys.empty() && ex == xs.c_str() + xs.size() && ey == ys.c_str() + ys.size() && std::isfinite(x) && std::isfinite(y);
                if (ok) c.points.push_back({x, y, 1});
            }
            if (ok && c.points.size() >= 2) {
                c.begin = start + pointsAt, c.end = start + endAt;
                out.push_back(std::move(c));
            }
        }
        if (eol >= text.size()) break;
        start = eol + 1;
    }
    return out;
}

std::string setLsysCurvePoints(std::string_view text, const LsysCurve& c, const std::vector<std::array<double, 3>>& points) {
    std::string list;
    for (const auto& p : points) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%g,%g", list.empty() ? "" : " ", p[0], p[1]);
        list += buf;
    }
    std::string out(text);
    if (c.begin <= c.end && c.end <= out.size()) out.replace(c.begin, c.end - c.begin, list);
    return out;
}

}  // namespace sprout
