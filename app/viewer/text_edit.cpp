#include "app/viewer/text_edit.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

namespace sprout::viewer {
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

bool startsWithNoCase(std::string_view s, std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[i])) != std::tolower(static_cast<unsigned char>(prefix[i]))) return false;
    return true;
}

// The offset of the value after "key:" on this line (any case: cpfg writes `Axiom:`), or npos.
// `n` is also `iterations` and cpfg's `derivation length`.
size_t keyValueStart(std::string_view line, std::string_view key) {
    std::string_view t = trimLeft(line);
    if (!startsWithNoCase(t, key)) return std::string_view::npos;
    std::string_view rest = trimLeft(t.substr(key.size()));
    if (!rest.starts_with(":") || line.find("->") != std::string_view::npos) return std::string_view::npos;
    size_t off = size_t(rest.data() - line.data()) + 1;
    while (off < line.size() && line[off] == ' ') ++off;
    return off;
}

size_t valueStart(std::string_view line, std::string_view key) {
    if (key != "n" && key != "iterations") return keyValueStart(line, key);
    for (std::string_view alias : {"n", "iterations", "derivation length"})
        if (size_t off = keyValueStart(line, alias); off != std::string_view::npos) return off;
    return std::string_view::npos;
}

}  // namespace

std::string formatValue(double v) {
    if (std::fabs(v - std::round(v)) < 1e-9) return std::to_string(static_cast<long long>(std::llround(v)));
    char buf[32];
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
        // Keep a jitter (`angle: 22 ~ 4`) and a trailing carriage return.
        std::string_view old = line.substr(v);
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
        if (t.starts_with("#define")) rest = trimLeft(t.substr(7));
        else if (size_t v = valueStart(line, "define"); v != std::string_view::npos) rest = line.substr(v);
        else continue;
        if (rest.starts_with(":")) rest = trimLeft(rest.substr(1));
        if (!rest.starts_with(name)) continue;
        std::string_view after = rest.substr(name.size());
        if (!after.empty() && (std::isalnum(static_cast<unsigned char>(after[0])) || after[0] == '_')) continue;
        size_t valueAt = size_t(after.data() - line.data());
        std::string_view a = trimLeft(after);
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

}  // namespace sprout::viewer
