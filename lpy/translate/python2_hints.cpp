// Python 2 in an .lpy file, told as such (lpy/translate/python2_hints.hpp). Each case starts from the error
// Python 3 raises for the construct, then checks the line for the construct itself, so a
// Python 3 line with the same error keeps Python's message.
#include "lpy/translate/python2_hints.hpp"

#include <array>
#include <regex>
#include <utility>

namespace sprout::lpy {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// Where `what` first stands in the line outside string literals, or npos.
size_t outside(std::string_view line, std::string_view what) {
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == '\\') ++i;
            else if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (line.substr(i, what.size()) == what) {
            return i;
        }
    }
    return std::string_view::npos;
}

// The line's code: up to a `#` that is not inside a string literal.
std::string_view code(std::string_view line) { return trim(line.substr(0, outside(line, "#"))); }

bool outsideStrings(std::string_view line, std::string_view what) { return outside(line, what) != std::string_view::npos; }

// A statement as the message quotes it: short enough to read in a line of the panel.
std::string shown(std::string_view s) {
    s = trim(s);
    return s.size() <= 60 ? std::string(s) : std::string(s.substr(0, 57)) + "...";
}

std::string said(std::string_view written, std::string_view write) {
    return "`" + shown(written) + "` is Python 2: L-Py 3 does not read it either; write `" + shown(write) + "`";
}

// `print x`, `print x,`, `print >>f, x` (and `exec code`) as Python 3 writes them.
std::optional<std::string> statement(std::string_view line, std::string_view keyword) {
    const std::string_view stmt = code(line);
    if (stmt.substr(0, keyword.size()) != keyword) return std::nullopt;
    std::string rest(trim(stmt.substr(keyword.size())));
    std::string target;
    if (keyword == "print" && rest.substr(0, 2) == ">>") {
        const size_t comma = rest.find(',');
        target = std::string(trim(std::string_view(rest).substr(2, comma == std::string::npos ? std::string::npos : comma - 2)));
        rest = comma == std::string::npos ? std::string() : std::string(trim(std::string_view(rest).substr(comma + 1)));
    }
    std::string args = rest;
    if (keyword == "print" && !args.empty() && args.back() == ',') {
        args.pop_back();
        args = std::string(trim(args)) + ", end=' '";
    }
    if (!target.empty()) args += (args.empty() ? "" : ", ") + ("file=" + target);
    return said(stmt, std::string(keyword) + "(" + args + ")");
}

// Python 2's names and methods, with what Python 3 has instead.
constexpr std::array<std::pair<std::string_view, std::string_view>, 10> kNames{{
    {"xrange", "range"},
    {"raw_input", "input"},
    {"unicode", "str"},
    {"basestring", "str"},
    {"long", "int"},
    {"unichr", "chr"},
    {"reduce", "functools.reduce"},
    {"execfile", "exec(open(path).read())"},
    {"file", "open"},
    {"cmp", "(a > b) - (a < b)"},
}};
constexpr std::array<std::pair<std::string_view, std::string_view>, 4> kMethods{{
    {"iteritems", ".items()"},
    {"itervalues", ".values()"},
    {"iterkeys", ".keys()"},
    {"has_key", "key in d"},
}};

// The quoted name of a NameError's or AttributeError's message: name 'xrange' is not defined.
std::string_view quotedName(std::string_view error, std::string_view before) {
    const size_t at = error.find(before);
    if (at == std::string_view::npos) return {};
    const size_t start = at + before.size();
    const size_t end = error.find('\'', start);
    return end == std::string_view::npos ? std::string_view() : error.substr(start, end - start);
}

}  // namespace

std::string_view lineOf(std::string_view text, int number) {
    size_t start = 0;
    for (int k = 1; k < number; ++k) {
        start = text.find('\n', start);
        if (start == std::string_view::npos) return {};
        ++start;
    }
    const size_t end = text.find('\n', start);
    std::string_view line = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

std::optional<std::string> python2Message(std::string_view error, std::string_view line) {
    const std::string stmt(code(line));
    if (error.find("Missing parentheses in call to 'print'") != std::string_view::npos) return statement(line, "print");
    if (error.find("Missing parentheses in call to 'exec'") != std::string_view::npos) return statement(line, "exec");
    if (error.substr(0, 10) == "NameError:") {
        const std::string_view name = quotedName(error, "name '");
        for (const auto& [old, now] : kNames)
            if (name == old) return said(name, now);
        return std::nullopt;
    }
    if (error.substr(0, 15) == "AttributeError:") {
        const std::string_view name = quotedName(error, "has no attribute '");
        for (const auto& [old, now] : kMethods)
            if (name == old) return said("." + std::string(name) + "()", now);
        return std::nullopt;
    }
    if (error.substr(0, 12) != "SyntaxError:") return std::nullopt;
    std::smatch m;
    static const std::regex exceptComma(R"(^except\s+([^,:]+?)\s*,\s*([A-Za-z_]\w*)\s*:)");
    if (std::regex_search(stmt, m, exceptComma)) return said(m[0].str(), "except " + m[1].str() + " as " + m[2].str() + ":");
    static const std::regex raiseComma(R"(^raise\s+([A-Za-z_][\w.]*)\s*,\s*(.+)$)");
    if (std::regex_search(stmt, m, raiseComma)) return said(m[0].str(), "raise " + m[1].str() + "(" + m[2].str() + ")");
    static const std::regex octal(R"((^|[^\w.])(0[0-7]+)\b)");
    if (error.find("leading zeros") != std::string_view::npos && std::regex_search(stmt, m, octal))
        return said(m[2].str(), "0o" + m[2].str().substr(1));
    if (outsideStrings(stmt, "<>")) {
        std::string now = stmt;
        for (size_t at = now.find("<>"); at != std::string::npos; at = now.find("<>", at)) now.replace(at, 2, "!=");
        return said(stmt, now);
    }
    static const std::regex backquotes(R"(`([^`]+)`)");
    if (outsideStrings(stmt, "`") && std::regex_search(stmt, m, backquotes))
        return "backquotes around `" + shown(m[1].str()) + "` are Python 2: L-Py 3 does not read them either; write `repr(" +
               shown(m[1].str()) + ")`";
    return std::nullopt;
}

}  // namespace sprout::lpy
