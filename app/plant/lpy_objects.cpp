#include "app/plant/lpy_objects.hpp"

#include "app/plant/python_text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace sprout {
namespace {

using namespace python_text;

// The points of `[(x, y[, w]), ...]` between `open` and `close` (the brackets), or none when
// one is not a tuple of two or three numbers.
std::optional<std::vector<std::array<double, 3>>> points(std::string_view t, size_t open, size_t close) {
    std::vector<std::array<double, 3>> out;
    size_t k = open + 1;
    while (true) {
        k = skipSpace(t, k);
        if (k >= close) break;
        if (t[k] == ',') {
            ++k;
            continue;
        }
        if (t[k] != '(') return std::nullopt;
        const size_t end = t.find(')', k);
        if (end == std::string_view::npos || end > close) return std::nullopt;
        std::array<double, 3> p{0, 0, 1};
        int n = 0;
        for (size_t b = k + 1;; ++n) {
            size_t comma = t.find(',', b);
            if (comma == std::string_view::npos || comma > end) comma = end;
            auto v = number(t.substr(b, comma - b));
            if (!v || n > 2) return std::nullopt;
            p[size_t(n)] = *v;
            if (comma == end) break;
            b = comma + 1;
        }
        if (n < 1) return std::nullopt;  // two numbers at least (n counts from 0)
        out.push_back(p);
        k = end + 1;
    }
    return out;
}

// The name of the first panel after `from` that lists `name` (Studio writes each panel after
// its objects: `panel_0 = ({'name': 'Panel 1', ...},[('Curve2D',NAME), ...])`), or "".
std::string panelListing(std::string_view text, std::string_view name, size_t from) {
    for (size_t at = text.find("panel_", from); at != std::string_view::npos; at = text.find("panel_", at + 6)) {
        size_t k = at + 6;
        while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
        if (!eat(text, k, "=") || !eat(text, k, "(")) continue;
        const size_t close = closing(text, k - 1);
        if (close == std::string_view::npos) continue;
        const std::string_view panel = text.substr(k, close - k);
        bool listed = false;
        for (size_t q = panel.find(name); q != std::string_view::npos && !listed; q = panel.find(name, q + 1))
            listed = q > 0 && panel[q - 1] == ',' && (q + name.size() >= panel.size() || !isIdent(panel[q + name.size()]));
        if (!listed) continue;
        const size_t key = panel.find("'name'");
        if (key == std::string_view::npos) return "";
        const size_t open = panel.find('\'', key + 6), end = open == std::string_view::npos ? open : panel.find('\'', open + 1);
        return end == std::string_view::npos ? "" : std::string(panel.substr(open + 1, end - open - 1));
    }
    return "";
}

// Whether the model's panel lists `name` as a function: `('Function', NAME)`.
bool listedAsFunction(std::string_view text, std::string_view name) {
    for (size_t at = 0; (at = text.find("'Function'", at)) != std::string_view::npos; at += 10) {
        size_t k = at + 10;
        if (!eat(text, k, ",")) continue;
        k = skipSpace(text, k);
        if (text.substr(k, name.size()) == name && k + name.size() < text.size() && !isIdent(text[k + name.size()])) return true;
    }
    return false;
}

}  // namespace

std::vector<LpyCurve> lpyCurves(std::string_view text) {
    std::vector<LpyCurve> out;
    const size_t from = text.find("__initialiseContext__");
    if (from == std::string_view::npos) return out;
    const std::pair<std::string_view, LpyCurve::Kind> kinds[] = {
        {"NurbsCurve2D", LpyCurve::Kind::Nurbs}, {"BezierCurve2D", LpyCurve::Kind::Bezier}, {"Polyline2D", LpyCurve::Kind::Polyline}};
    for (const auto& [word, kind] : kinds) {
        for (size_t at = from; (at = text.find(word, at)) != std::string_view::npos; at += word.size()) {
            size_t k = at + word.size();
            if ((at > 0 && isIdent(text[at - 1])) || (k < text.size() && isIdent(text[k]))) continue;
            // NAME = [pgl.]Kind(
            size_t e = at >= 4 && text.substr(at - 4, 4) == "pgl." ? at - 4 : at;
            while (e > 0 && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
            if (e == 0 || text[e - 1] != '=') continue;
            --e;
            while (e > 0 && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
            size_t n = e;
            while (n > 0 && isIdent(text[n - 1])) --n;
            if (n == e || std::isdigit(static_cast<unsigned char>(text[n]))) continue;
            const size_t call = skipSpace(text, k);
            if (call >= text.size() || text[call] != '(') continue;
            const size_t callEnd = closing(text, call);
            if (callEnd == std::string_view::npos) continue;
            // [ctrlPointList|pointList =] [pgl.]Point[23]Array( [
            k = call + 1;
            size_t field = skipSpace(text, k), fe = field;
            while (fe < text.size() && isIdent(text[fe])) ++fe;
            if (fe > field && (text.substr(field, fe - field) == "ctrlPointList" || text.substr(field, fe - field) == "pointList")) {
                size_t eq = fe;
                if (eat(text, eq, "=")) k = eq;
            }
            eat(text, k, "pgl.");
            if (!eat(text, k, "Point3Array(") && !eat(text, k, "Point2Array(")) {
                // a plain list
            }
            const size_t open = skipSpace(text, k);
            if (open >= callEnd || text[open] != '[') continue;
            const size_t close = text.find(']', open);
            if (close == std::string_view::npos || close > callEnd) continue;
            auto pts = points(text, open, close);
            if (!pts || pts->size() < 2) continue;
            LpyCurve c;
            c.name = std::string(text.substr(n, e - n));
            c.kind = kind;
            c.points = std::move(*pts);
            c.begin = open;
            c.end = close + 1;
            c.line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(n), '\n'));
            // `degree = n` after the list, within the call.
            for (size_t d = close; (d = text.find("degree", d)) != std::string_view::npos && d < callEnd; d += 6) {
                size_t v = d + 6;
                if (!eat(text, v, "=")) continue;
                v = skipSpace(text, v);
                size_t ve = v;
                while (ve < callEnd && std::isdigit(static_cast<unsigned char>(text[ve]))) ++ve;
                if (auto deg = number(text.substr(v, ve - v))) c.degree = int(std::clamp(*deg, 0.0, 1000.0));  // clamped to the points below
                break;
            }
            if (kind == LpyCurve::Kind::Nurbs) c.degree = std::max(1, std::min(c.degree, int(c.points.size()) - 1));
            if (kind == LpyCurve::Kind::Bezier) c.degree = int(c.points.size()) - 1;
            c.function = listedAsFunction(text, c.name);
            c.panel = panelListing(text, c.name, close);
            out.push_back(std::move(c));
        }
    }
    std::sort(out.begin(), out.end(), [](const LpyCurve& a, const LpyCurve& b) { return a.begin < b.begin; });
    return out;
}

const LpyCurve* lastLpyCurve(const std::vector<LpyCurve>& curves, std::string_view name) {
    for (auto c = curves.rbegin(); c != curves.rend(); ++c)
        if (c->name == name) return &*c;
    return nullptr;
}

const LpyCurve* lpyCurveNamed(const std::vector<LpyCurve>& curves, std::string_view key) {
    const size_t hash = key.rfind('#');
    if (hash == std::string_view::npos || hash + 1 >= key.size() ||
        key.find_first_not_of("0123456789", hash + 1) != std::string_view::npos)
        return lastLpyCurve(curves, key);
    const std::string_view name = key.substr(0, hash);
    size_t k = 0;
    for (char ch : key.substr(hash + 1)) k = std::min<size_t>(k * 10 + size_t(ch - '0'), 1u << 20);
    for (const LpyCurve& c : curves)
        if (c.name == name && k-- == 0) return &c;
    return nullptr;
}

std::string lpyCurveKey(const std::vector<LpyCurve>& curves, size_t i) {
    if (i >= curves.size()) return "";
    if (lastLpyCurve(curves, curves[i].name) == &curves[i]) return curves[i].name;
    size_t k = 0;
    for (size_t j = 0; j < i; ++j) k += curves[j].name == curves[i].name;
    return curves[i].name + "#" + std::to_string(k);
}

std::string setLpyCurvePoints(std::string_view text, const LpyCurve& curve, const std::vector<std::array<double, 3>>& points) {
    std::string list = "[";
    for (size_t i = 0; i < points.size(); ++i) {
        if (i) list += ",";
        const auto& p = points[i];
        list += "(" + formatted(p[0]) + ", " + formatted(p[1]);
        if (curve.kind != LpyCurve::Kind::Polyline) list += ", " + formatted(p[2]);
        list += ")";
    }
    list += "]";
    std::string out(text);
    if (curve.begin <= curve.end && curve.end <= out.size()) out.replace(curve.begin, curve.end - curve.begin, list);
    return out;
}

}  // namespace sprout
