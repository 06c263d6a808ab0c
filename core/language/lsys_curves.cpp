// Sprout's own grammars' functions and contours (issue 52): `function:` and `contour:` lines,
// the curves a user shapes in the viewer's curve editor, kept as cpfg keeps a VLab object's
// (core/language/vlab/curve_files.hpp) so that func() and @# use them alike:
//     function: width 0,0.2 0.3,0.5 0.7,0.4 1,0      func(width, x) or func(1, x)
//     contour: 1 closed 1,0.3 1,-0.3 -1,-0.3 -1,0.3   @#(1) (closed unless `open`)
#include <cmath>
#include <string>
#include <vector>

#include "core/language/parser_impl.hpp"

namespace sprout::detail {
namespace {

// `x,y` pairs separated by spaces, each at its place in the line for messages.
std::optional<std::vector<std::array<double, 2>>> pairs(Parser& p, const SourceLine& line, std::string_view text, size_t fewest,
                                                        const char* what) {
    std::vector<std::array<double, 2>> out;
    size_t k = 0;
    while (k < text.size()) {
        while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
        if (k >= text.size()) break;
        size_t e = k;
        while (e < text.size() && text[e] != ' ' && text[e] != '\t') ++e;
        const std::string_view word = text.substr(k, e - k);
        const size_t comma = word.find(',');
        std::array<double, 2> xy{};
        bool ok = comma != std::string_view::npos;
        for (int i = 0; ok && i < 2; ++i) {
            const std::string s(i == 0 ? word.substr(0, comma) : word.substr(comma + 1));
            char* end = nullptr;
            xy[size_t(i)] = std::strtod(s.c_str(), &end);
            ok = !s.empty() && end == s.c_str() + s.size() && std::isfinite(xy[size_t(i)]);
        }
        if (!ok) {
            p.sink().error(line, word, std::string("expected a point 'x,y' (two numbers and a comma) of the ") + what);
            return std::nullopt;
        }
        out.push_back(xy);
        k = e;
    }
    if (out.size() < fewest) {
        p.sink().error(line, text.empty() ? line.text : text,
                       std::string(what[0] == 'o' ? "an " : "a ") + what + " needs at least " + std::to_string(fewest) + " points 'x,y'");
        return std::nullopt;
    }
    return out;
}

std::string_view firstWord(std::string_view& text) {
    size_t k = 0;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
    size_t e = k;
    while (e < text.size() && text[e] != ' ' && text[e] != '\t') ++e;
    const std::string_view w = text.substr(k, e - k);
    text.remove_prefix(e);
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    return w;
}

}  // namespace

CurveTables& Parser::ownCurves() {
    if (!m_ownCurves) {
        m_ownCurves = std::make_shared<CurveTables>();
        m_options.curves = m_ownCurves;  // the rules' expressions see them (func, @#)
        m_g.curves = m_ownCurves;
    }
    return *m_ownCurves;
}

void Parser::addFunction(const SourceLine& line, std::string_view text) {
    if (m_cpfg) {  // cpfg's functions are its object's files, named in the view file
        m_sink.error(line, line.text, "cpfg reads its functions from the object's view file ('function: FILE' there), not the L-system");
        return;
    }
    std::string_view rest = text;
    const std::string_view name = firstWord(rest);
    if (!isIdentifier(name)) {
        m_sink.error(line, name.empty() ? text : name, "expected 'function: NAME x,y x,y ...', a name then the points of y = f(x)");
        return;
    }
    const auto pts = pairs(*this, line, rest, 2, "function");
    if (!pts) return;
    if (pts->front()[0] != 0 || pts->back()[0] != 1) {
        m_sink.error(line, rest, "a function's points go from x = 0 to x = 1 (its first x is 0, its last 1)");
        return;
    }
    for (size_t i = 1; i < pts->size(); ++i)
        if ((*pts)[i][0] < (*pts)[i - 1][0]) {
            m_sink.error(line, rest, "a function's points go along x in order (point " + std::to_string(i + 1) + " goes back)");
            return;
        }
    CurveTables& t = ownCurves();
    for (const CurveFunction& f : t.functions)
        if (f.name() == name) {
            m_sink.error(line, name, "a function '" + std::string(name) + "' is there already");
            return;
        }
    // cpfg's B-spline through the points (its ends repeated, as funcedit's default has them: the
    // curve starts and ends at the points); fewer than 4 points are repeated to 4.
    std::vector<std::array<double, 2>> expanded;
    for (size_t i = 0; i < pts->size(); ++i) {
        const bool end = i == 0 || i + 1 == pts->size();
        for (int k = 0; k < (end ? 3 : 1); ++k) expanded.push_back((*pts)[i]);
    }
    std::vector<CurveFunction> all = t.functions;
    all.emplace_back(std::string(name), std::move(expanded), 0);
    t.setFunctionSet(std::move(all));  // func(NAME, x) as a function set's names, func(k, x) by number
}

void Parser::addContour(const SourceLine& line, std::string_view text) {
    if (m_cpfg) {
        m_sink.error(line, line.text, "cpfg reads its contours from the object's view file ('contour: ID FILE' there), not the L-system");
        return;
    }
    std::string_view rest = text;
    const std::string_view id = firstWord(rest);
    int n = 0;
    for (char c : id) n = std::isdigit(static_cast<unsigned char>(c)) && n < 100000 ? n * 10 + (c - '0') : -1;
    if (id.empty() || n < 1) {
        m_sink.error(line, id.empty() ? text : id, "expected 'contour: ID [open|closed] x,y x,y ...', ID a whole number from 1 (@#(ID))");
        return;
    }
    Contour c;
    c.name = std::string(id);
    c.dim = 2;
    std::string_view after = rest;
    const std::string_view kind = firstWord(after);
    if (kind == "open" || kind == "closed") c.closed = kind == "closed", rest = after;
    const auto pts = pairs(*this, line, rest, c.closed ? 3 : 4, c.closed ? "closed contour" : "open contour");
    if (!pts) return;
    for (const auto& p : *pts) c.points.push_back({float(p[0]), float(p[1]), 0});
    CurveTables& t = ownCurves();
    if (t.contours.count(n)) {
        m_sink.error(line, id, "a contour " + std::string(id) + " is there already");
        return;
    }
    t.contours.emplace(n, std::move(c));
}

}  // namespace sprout::detail
