#include "app/plant/text_edit.hpp"

#include "core/language/environment_spec.hpp"
#include "core/language/grammar.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

namespace sprout {
namespace {

struct Line {
    size_t begin, end;  // [begin, end) without the newline
};

std::vector<Line> lines(std::string_view text) {
    std::vector<Line> out;
    size_t pos = 0;
    while (pos <= text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        out.push_back({pos, end});
        if (end == text.size()) break;
        pos = end + 1;
    }
    return out;
}

std::string_view trimLeft(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}


// The setting a key names, in whatever notation it is written ("δ" and "delta" are "angle",
// "dlength" and cpfg's "derivation length" are "n", as the parser reads them).
std::string settingOf(std::string_view key) {
    if (const char* named = settingNamed(key)) return std::string_view(named) == "iterations" ? "n" : named;
    std::string k(key);
    std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return k == "iterations" ? "n" : k;
}

// The offset of the value after "key:" or "key =" on this line, the key written any way the
// parser reads it (any case: cpfg writes `Axiom:`), or npos.
size_t valueStartOfPart(std::string_view line, std::string_view key) {
    if (line.find("->") != std::string_view::npos) return std::string_view::npos;
    const std::string_view t = trimLeft(line);
    const size_t sep = t.find_first_of(":=");
    if (sep == std::string_view::npos || (t[sep] == '=' && t.substr(sep, 2) == "==")) return std::string_view::npos;
    std::string_view written = t.substr(0, sep);
    while (!written.empty() && (written.back() == ' ' || written.back() == '\t')) written.remove_suffix(1);
    if (written.empty() || settingOf(written) != settingOf(key)) return std::string_view::npos;
    size_t off = size_t(t.data() - line.data()) + sep + 1;
    while (off < line.size() && line[off] == ' ') ++off;
    return off;
}

// Also inside a figure caption "n=5, δ=25.7°", after a comma.
size_t valueStart(std::string_view line, std::string_view key) {
    if (size_t off = valueStartOfPart(line, key); off != std::string_view::npos) return off;
    if (key != "n" && key != "iterations" && key != "angle") return std::string_view::npos;
    for (size_t comma = line.find(','); comma != std::string_view::npos; comma = line.find(',', comma + 1))
        if (size_t off = valueStartOfPart(line.substr(comma + 1), key); off != std::string_view::npos) return comma + 1 + off;
    return std::string_view::npos;
}

}  // namespace

bool startsWithNoCase(std::string_view s, std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[i])) != std::tolower(static_cast<unsigned char>(prefix[i]))) return false;
    return true;
}

std::string formatValue(double v) {
    // Whole numbers as integers while a long long holds them exactly; beyond, and for NaN and
    // infinities, %g (llround's result is unspecified past 2^63).
    if (std::fabs(v) < 9e15 && std::fabs(v - std::round(v)) < 1e-9) return std::to_string(static_cast<long long>(std::llround(v)));
    char buf[32];
    if (!(std::fabs(v) < 1e15)) {
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

std::optional<std::string> directiveValue(std::string_view text, std::string_view key) {
    for (const Line& l : lines(text)) {
        std::string_view line = text.substr(l.begin, l.end - l.begin);
        size_t v = valueStart(line, key);
        if (v != std::string_view::npos) return std::string(line.substr(v));
    }
    return std::nullopt;
}

std::string setDirective(std::string_view text, std::string_view key, std::string_view value) {
    for (const Line& l : lines(text)) {
        std::string_view line = text.substr(l.begin, l.end - l.begin);
        size_t v = valueStart(line, key);
        if (v == std::string_view::npos) continue;
        // Keep a jitter (`angle: 22 ~ 4`) and a trailing carriage return; in a caption, the
        // settings after this one.
        std::string_view old = line.substr(v);
        if (size_t comma = old.find(','); comma != std::string_view::npos && (key == "n" || key == "iterations" || key == "angle")) {
            std::string out(text.substr(0, l.begin + v));
            out += value;
            out += text.substr(l.begin + v + comma);
            return out;
        }
        size_t tilde = old.find('~');
        std::string keep = tilde == std::string_view::npos ? "" : " " + std::string(old.substr(tilde));
        if (tilde == std::string_view::npos && old.ends_with('\r')) keep = "\r";
        // A comment after the value stays (cpfg: `derivation length: 5 /* steps */`).
        if (size_t c = std::min(old.find("/*"), old.find("//")); c != std::string_view::npos && tilde == std::string_view::npos)
            keep = " " + std::string(old.substr(c));
        std::string out(text.substr(0, l.begin + v));
        out += value;
        out += keep;
        out += text.substr(l.end);
        return out;
    }
    // No such line: insert it before the axiom (or at the top), where settings are read.
    std::string newLine = std::string(key) + ": " + std::string(value) + "\n";
    for (const Line& l : lines(text)) {
        std::string_view line = text.substr(l.begin, l.end - l.begin);
        if (valueStart(line, "axiom") != std::string_view::npos)
            return std::string(text.substr(0, l.begin)) + newLine + std::string(text.substr(l.begin));
    }
    return newLine + std::string(text);
}

std::string setDefine(std::string_view text, std::string_view name, std::string_view value) {
    for (const Line& l : lines(text)) {
        std::string_view line = text.substr(l.begin, l.end - l.begin);
        std::string_view t = trimLeft(line);
        std::string_view rest;
        bool bare = false;  // ABOP's notation and the web's: `R = 1.456`
        if (t.starts_with("#define")) rest = trimLeft(t.substr(7));
        else if (size_t v = valueStart(line, "define"); v != std::string_view::npos) rest = line.substr(v);
        else rest = t, bare = true;
        if (rest.starts_with(":")) rest = trimLeft(rest.substr(1));
        if (!rest.starts_with(name)) continue;
        std::string_view after = rest.substr(name.size());
        if (!after.empty() && (std::isalnum(static_cast<unsigned char>(after[0])) || after[0] == '_')) continue;
        size_t valueAt = size_t(after.data() - line.data());
        std::string_view a = trimLeft(after);
        if (bare && (!a.starts_with("=") || a.starts_with("=="))) continue;
        if (a.starts_with("=")) valueAt = size_t(a.data() - line.data()) + 1;
        while (valueAt < line.size() && line[valueAt] == ' ') ++valueAt;
        std::string out(text.substr(0, l.begin + valueAt));
        out += value;
        // A comment after the value stays (`#define R 1.5 /* ratio */`).
        std::string_view old = line.substr(valueAt);
        if (size_t c = std::min(old.find("/*"), old.find("//")); c != std::string_view::npos)
            out += " " + std::string(old.substr(c));
        else if (old.ends_with('\r'))
            out += "\r";
        out += text.substr(l.end);
        return out;
    }
    return std::string(text);
}

std::vector<EnvironmentNumber> environmentNumbers(std::string_view text) {
    using Kind = EnvironmentNumber::Kind;
    std::vector<EnvironmentNumber> out;
    int lineNumber = 0;
    for (const Line& l : lines(text)) {
        ++lineNumber;
        std::string_view line = text.substr(l.begin, l.end - l.begin);
        const std::string_view body = trimLeft(line);
        if (!startsWithNoCase(body, "environment:")) continue;
        size_t pos = l.begin + (line.size() - body.size()) + 12;
        size_t stop = l.end;  // comments end the value
        for (std::string_view c : {"#", "//", "/*"}) {
            const size_t at = text.substr(pos, stop - pos).find(c);
            if (at != std::string_view::npos) stop = pos + at;
        }
        struct Token {
            size_t begin, end;
            bool word;
            std::optional<double> number;  // a literal
        };
        std::vector<Token> tokens;
        for (const auto& [b, e] : environmentTokens(text.substr(pos, stop - pos))) {
            const size_t begin = pos + b, end = pos + e;
            const std::string token(text.substr(begin, end - begin));
            Token t{begin, end, std::isalpha(static_cast<unsigned char>(token[0])) != 0, std::nullopt};
            char* rest = nullptr;
            const double v = std::strtod(token.c_str(), &rest);
            if (!t.word && rest && *rest == '\0' && std::isfinite(v)) t.number = v;
            if (t.word && !isEnvironmentKeyword(token)) t.word = false;  // a define's name: an expression
            tokens.push_back(t);
        }
        if (tokens.empty() || !tokens[0].word) continue;
        auto word = [&](size_t k) { return std::string(text.substr(tokens[k].begin, tokens[k].end - tokens[k].begin)); };
        // Names for the numbers of a shape, in order.
        auto shapeNames = [](const std::string& shape) -> std::vector<std::pair<const char*, Kind>> {
            if (shape == "sphere") return {{"centre x", Kind::Position}, {"centre y", Kind::Position}, {"centre z", Kind::Position}, {"radius", Kind::Size}};
            if (shape == "box")
                return {{"x0", Kind::Position}, {"y0", Kind::Position}, {"z0", Kind::Position},
                        {"x1", Kind::Position}, {"y1", Kind::Position}, {"z1", Kind::Position}};
            if (shape == "ellipsoid")
                return {{"centre x", Kind::Position}, {"centre y", Kind::Position}, {"centre z", Kind::Position},
                        {"radius x", Kind::Size},     {"radius y", Kind::Size},     {"radius z", Kind::Size}};
            if (shape == "cylinder")
                return {{"base x", Kind::Position}, {"base y", Kind::Position}, {"base z", Kind::Position},
                        {"radius", Kind::Size},     {"height", Kind::Size}};
            return {};
        };
        // What each number means, following the words before it.
        std::string prefix = word(0), current;
        std::vector<std::pair<const char*, Kind>> names;
        size_t named = 0;
        const std::string first = word(0);
        if (first == "obstacle" && tokens.size() > 1 && tokens[1].word) prefix += " " + word(1), names = shapeNames(word(1));
        else if (first == "ground") names = {{"height", Kind::Position}};
        else if (first == "light") names = {{"voxel size", Kind::Size}, {"shadow", Kind::Shadow}};
        else if (first == "attraction") names = {{"points", Kind::Count}};
        else names = shapeNames(first);
        bool sawSun = false;
        size_t lastEnd = tokens.back().end;
        for (size_t k = 1; k < tokens.size(); ++k) {
            const Token& t = tokens[k];
            if (t.word) {
                const std::string w = word(k);
                if (w == "sun") names = {{"sun azimuth", Kind::Azimuth}, {"sun elevation", Kind::Elevation}}, named = 0, sawSun = true;
                else if (w == "influence") names = {{"influence", Kind::Size}}, named = 0;
                else if (w == "kill") names = {{"kill", Kind::Size}}, named = 0;
                else if (first == "attraction" && k >= 2) {  // the shape after the number of points
                    names = shapeNames(w), named = 0;
                    prefix = "attraction " + w;
                }
                continue;
            }
            const size_t index = named++;
            if (!t.number || index >= names.size()) continue;  // an expression, or one too many
            EnvironmentNumber n;
            n.line = lineNumber;
            n.begin = t.begin, n.end = t.end;
            n.label = (names[index].first == std::string("influence") || names[index].first == std::string("kill") ? "attraction"
                                                                                                                  : prefix) +
                      std::string(" ") + names[index].first;
            n.kind = names[index].second;
            n.value = *t.number;
            out.push_back(n);
        }
        if (first == "light" && !sawSun)
            for (int k = 0; k < 2; ++k) {
                EnvironmentNumber n;
                n.line = lineNumber;
                n.begin = n.end = lastEnd;
                n.label = k == 0 ? "light sun azimuth" : "light sun elevation";
                n.kind = k == 0 ? Kind::Azimuth : Kind::Elevation;
                n.value = k == 0 ? 0 : 90;
                n.sun = k;
                out.push_back(n);
            }
    }
    return out;
}

std::string setEnvironmentNumber(std::string_view text, const EnvironmentNumber& n, double v) {
    std::string value = formatValue(v);
    if (n.sun >= 0) value = " sun " + (n.sun == 0 ? value + " 90" : "0 " + value);
    std::string out(text.substr(0, n.begin));
    out += value;
    out += text.substr(n.end);
    return out;
}

}  // namespace sprout

namespace sprout {
namespace {

// A Python number or bool literal: its value, or nullopt.
std::optional<double> pyLiteral(std::string_view t) {
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    if (t == "True") return 1.0;
    if (t == "False") return 0.0;
    if (t.empty() || t.size() > 40) return std::nullopt;
    std::string s(t);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace

std::vector<LpyScalar> lpyScalars(std::string_view text) {
    std::vector<LpyScalar> out;
    // `scalars = [` in the INITIALISATION part.
    size_t list = text.find("__initialiseContext__");
    for (list = list == std::string_view::npos ? 0 : list; (list = text.find("scalars", list)) != std::string_view::npos; list += 7) {
        size_t k = list + 7;
        while (k < text.size() && text[k] == ' ') ++k;
        if (k < text.size() && text[k] == '=') break;
    }
    if (list == std::string_view::npos) return out;
    const size_t open = text.find('[', list), close = text.find(']', list);
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) return out;
    for (size_t at = open; (at = text.find('(', at)) != std::string_view::npos && at < close;) {
        const size_t end = text.find(')', at);
        if (end == std::string_view::npos || end > close) break;
        // The tuple's fields with their offsets.
        std::vector<std::pair<size_t, size_t>> fields;
        for (size_t b = at + 1;;) {
            size_t comma = text.find(',', b);
            if (comma == std::string_view::npos || comma > end) comma = end;
            fields.emplace_back(b, comma);
            if (comma == end) break;
            b = comma + 1;
        }
        at = end + 1;
        auto field = [&](size_t k) { return text.substr(fields[k].first, fields[k].second - fields[k].first); };
        auto unquote = [](std::string_view f) -> std::optional<std::string> {
            while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
            while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
            if (f.size() < 2 || (f.front() != '\'' && f.front() != '"') || f.back() != f.front()) return std::nullopt;
            return std::string(f.substr(1, f.size() - 2));
        };
        if (fields.size() < 2) continue;
        auto name = unquote(field(0));
        if (!name) continue;
        LpyScalar s;
        s.name = *name;
        size_t v = 1;
        const auto type = unquote(field(1));
        std::string_view second = field(1);
        while (!second.empty() && second.front() == ' ') second.remove_prefix(1);
        while (!second.empty() && second.back() == ' ') second.remove_suffix(1);
        if ((type && *type == "Category") || second == "None") {  // a heading, no value
            s.kind = LpyScalar::Kind::Category;
            out.push_back(std::move(s));
            continue;
        }
        if (type) {  // ('NAME', 'Type', value, min, max[, decimals])
            if (*type == "Integer") s.kind = LpyScalar::Kind::Integer;
            else if (*type == "Float") s.kind = LpyScalar::Kind::Float;
            else if (*type == "Bool") s.kind = LpyScalar::Kind::Bool;
            else continue;  // an Enum: not edited
            v = 2;
        }
        if (fields.size() <= v) continue;
        auto value = pyLiteral(field(v));
        if (!value) continue;
        s.value = *value;
        const std::string_view raw = field(v);
        if (v == 1) s.kind = raw.find("True") != std::string_view::npos || raw.find("False") != std::string_view::npos ? LpyScalar::Kind::Bool
                             : raw.find('.') != std::string_view::npos                                                  ? LpyScalar::Kind::Float
                                                                                                                        : LpyScalar::Kind::Integer;
        if (s.kind != LpyScalar::Kind::Bool) {
            auto lo = fields.size() > v + 1 ? pyLiteral(field(v + 1)) : std::nullopt;
            auto hi = fields.size() > v + 2 ? pyLiteral(field(v + 2)) : std::nullopt;
            s.min = lo ? *lo : std::min(0.0, s.value);
            s.max = hi ? *hi : std::max(1.0, std::fabs(s.value) * 2);
            if (s.max < s.min) std::swap(s.min, s.max);
        }
        // The value's bytes, without the spaces around it.
        s.begin = fields[v].first;
        s.end = fields[v].second;
        while (s.begin < s.end && text[s.begin] == ' ') ++s.begin;
        while (s.end > s.begin && text[s.end - 1] == ' ') --s.end;
        out.push_back(std::move(s));
    }
    return out;
}

std::string setLpyScalar(std::string_view text, const LpyScalar& scalar, double v) {
    if (scalar.kind == LpyScalar::Kind::Category) return std::string(text);  // a heading has no value
    std::string value = scalar.kind == LpyScalar::Kind::Bool      ? (v != 0 ? "True" : "False")
                        : scalar.kind == LpyScalar::Kind::Integer ? std::to_string(std::llround(std::clamp(v, -1e15, 1e15)))
                                                                  : formatValue(v);
    if (scalar.kind == LpyScalar::Kind::Float && value.find_first_of(".e") == std::string::npos) value += ".0";
    std::string out(text);
    if (scalar.end <= out.size() && scalar.begin <= scalar.end) out.replace(scalar.begin, scalar.end - scalar.begin, value);
    return out;
}

}  // namespace sprout
