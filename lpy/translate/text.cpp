// Scanning the Python text of an .lpy file: string literals, parentheses, commas, keywords
// and comments, and the file's lines. Its own file: translate()'s other parts all read text
// through these, and none of them knows L-Py.
#include <cctype>

#include "lpy/translate/translate_impl.hpp"

namespace sprout::lpy::translate_detail {

// Skips a Python string literal starting at s[i] (a quote); returns the index after it.
size_t skipString(std::string_view s, size_t i) {
    const char q = s[i];
    const bool triple = i + 2 < s.size() && s[i + 1] == q && s[i + 2] == q;
    i += triple ? 3 : 1;
    while (i < s.size()) {
        if (s[i] == '\\') {
            i += 2;
            continue;
        }
        if (s[i] == q) {
            if (!triple) return i + 1;
            if (i + 2 < s.size() && s[i + 1] == q && s[i + 2] == q) return i + 3;
        }
        if (!triple && s[i] == '\n') return i;
        ++i;
    }
    return s.size();
}

std::string openTripleQuote(std::string_view line) {
    for (size_t i = 0; i < line.size();) {
        const char c = line[i];
        if (c == '#') break;
        if (c == '"' || c == '\'') {
            const bool triple = i + 2 < line.size() && line[i + 1] == c && line[i + 2] == c;
            const size_t end = skipString(line, i);
            if (triple && !(end >= i + 6 && line.substr(end - 3, 3) == std::string(3, c))) return std::string(3, c);
            i = end;
            continue;
        }
        ++i;
    }
    return {};
}

std::vector<size_t> topCommas(std::string_view s) {
    std::vector<size_t> out;
    int depth = 0;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\'' || c == '"') {
            i = skipString(s, i);
            continue;
        }
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') --depth;
        else if (c == ',' && depth == 0) out.push_back(i);
        ++i;
    }
    return out;
}

// Splits the text inside a module's parentheses at top-level commas.
std::vector<std::string> splitArgs(std::string_view s) {
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t comma : topCommas(s)) {
        out.emplace_back(trim(s.substr(start, comma - start)));
        start = comma + 1;
    }
    std::string_view last = trim(s.substr(start));
    if (!last.empty() || !out.empty()) out.emplace_back(last);
    return out;
}

// The index of the ')' closing the '(' at s[open], or npos.
size_t closeParen(std::string_view s, size_t open) {
    int depth = 0;
    for (size_t i = open; i < s.size();) {
        const char c = s[i];
        if (c == '\'' || c == '"') {
            i = skipString(s, i);
            continue;
        }
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') {
            if (--depth == 0) return c == ')' ? i : std::string_view::npos;
        }
        ++i;
    }
    return std::string_view::npos;
}

bool isNumberLiteral(std::string_view s) {
    if (s.empty()) return false;
    size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    bool digit = false;
    for (; i < s.size(); ++i) {
        const char c = s[i];
        if (std::isdigit(static_cast<unsigned char>(c))) digit = true;
        else if (c != '.' && c != 'e' && c != 'E' && c != '-' && c != '+' && c != '_') return false;
    }
    return digit;
}

bool isLiteral(std::string_view s) {
    return isNumberLiteral(s) || s == "None" || s == "True" || s == "False" ||
           (s.size() >= 2 && (s[0] == '\'' || s[0] == '"') && s.back() == s[0]);
}

// Finds `word` as a whole word in a line of Python, outside strings and comments.
size_t findKeyword(std::string_view line, std::string_view word, size_t from) {
    for (size_t i = from; i < line.size();) {
        const char c = line[i];
        if (c == '#') return std::string_view::npos;
        if (c == '\'' || c == '"') {
            i = skipString(line, i);
            continue;
        }
        if (isIdentStart(c)) {
            size_t j = i;
            while (j < line.size() && isIdent(line[j])) ++j;
            if (line.substr(i, j - i) == word && (i == 0 || !isIdent(line[i - 1]))) return i;
            i = j;
            continue;
        }
        ++i;
    }
    return std::string_view::npos;
}

// Where a Python comment starts in a line (outside strings), or the line's end.
size_t commentStart(std::string_view line) {
    for (size_t i = 0; i < line.size();) {
        if (line[i] == '#') return i;
        if (line[i] == '\'' || line[i] == '"') {
            i = skipString(line, i);
            continue;
        }
        ++i;
    }
    return line.size();
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    std::string cur;
    for (char c : text) {
        if (c == '\r') continue;
        if (c == '\n') {
            lines.push_back(std::move(cur));
            cur.clear();
        } else {
            cur.push_back(c);
        }
    }
    lines.push_back(std::move(cur));
    return lines;
}

}  // namespace sprout::lpy::translate_detail

namespace sprout::lpy {

std::string pasteFiles(std::string_view text, const PasteReader& read, std::vector<Diagnostic>& diags) {
    if (text.find("%paste") == std::string_view::npos) return std::string(text);
    std::string out;
    int line = 1;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view l = text.substr(start, end - start);
        size_t at = std::string_view::npos;
        bool module = false;
        for (const char* word : {"%pastefile", "%pastemodule"}) {
            const size_t w = l.find(word);
            const size_t after = w + std::string_view(word).size();
            // (Not in a comment: L-Py pastes there too, which no file means.)
            if (w != std::string_view::npos && l.substr(0, w).find('#') == std::string_view::npos &&
                (after >= l.size() || !translate_detail::isIdent(l[after]))) {
                at = w;
                module = word[6] == 'm';
                break;
            }
        }
        if (at == std::string_view::npos) {
            out.append(l);
        } else {
            const size_t after = at + (module ? 12 : 10);
            std::string name(translate_detail::trim(l.substr(after)));
            if (!name.empty() && name.back() == '\r') name.pop_back();
            out.append(l.substr(0, at));
            std::optional<std::string> pasted = name.empty() ? std::nullopt : read(name, module);
            if (pasted) {
                out += *pasted;
            } else {
                diags.push_back({line, int(at) + 1,
                                 name.empty() ? std::string("invalid file to paste: name one after ") + (module ? "%pastemodule" : "%pastefile")
                                              : (module ? "%pastemodule: no module " : "%pastefile: no file ") + name,
                                 Severity::Error});
            }
        }
        if (end == text.size()) break;
        out += '\n';
        start = end + 1;
        ++line;
    }
    return out;
}

}  // namespace sprout::lpy
