// The driver of translate(): the file's lines one by one, its sections (`Axiom:`,
// `production:`, `interpretation:`, groups, `endlsystem`), module declarations and context
// filters; a rule's lines go to rules.cpp. The other parts: lpy/translate/translate_impl.hpp.
#include "lpy/translate/translate.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "lpy/translate/translate_impl.hpp"

namespace sprout::lpy {
namespace translate_detail {

Translation Translator::run() {
    // A UTF-8 byte order mark is not Python.
    if (!m_lines.empty() && m_lines[0].rfind("\xEF\xBB\xBF", 0) == 0) m_lines[0].erase(0, 3);
    // `# -*- lpy version: X -*-` on the first line: L-Py reads format 1.0 only
    // (src/cpp/lpy_parser.cpp LpyParsing::isSupportedFormat).
    if (!m_lines.empty()) {
        const std::string& first = m_lines[0];
        const std::string tag = "# -*- lpy version:";
        if (first.rfind(tag, 0) == 0 && first.find("-*-", tag.size()) != std::string::npos) {
            const std::string v(trim(std::string_view(first).substr(tag.size(), first.find("-*-", tag.size()) - tag.size())));
            char* end = nullptr;
            const double version = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || !(version >= 1.0 && version <= 1.0))
                error(1, 1, "lpy format " + v + " is not one L-Py reads: format 1.0 is");
        }
    }
    size_t initAt = m_lines.size();
    for (size_t i = 0; i < m_lines.size(); ++i)
        if (m_lines[i].find("###### INITIALISATION ######") != std::string::npos) {
            initAt = i;
            break;
        }
    std::string& init = m_out.initCode;
    for (size_t i = 0; i < m_lines.size(); ++i) {
        if (i > initAt) init += m_lines[i];
        init += '\n';
    }
    std::vector<std::string> main(m_lines.begin(), m_lines.begin() + std::ptrdiff_t(initAt));
    translateMain(main);
    for (auto& l : m_outLines) m_out.mainCode += l + '\n';
    return std::move(m_out);
}

void Translator::declareModules(std::string_view rest, int line, size_t index) {
    rest = rest.substr(0, commentStart(rest));  // `module I  # an internode`
    // `module A, B(x,y), C=D : base = E, scale = 2`; of the keys after ':', Sprout reads `base`
    // (one class or a tuple of them); `scale` (multiscale strings) is not read yet.
    int depth = 0;
    size_t colon = std::string_view::npos;
    for (size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '(') ++depth;
        else if (rest[i] == ')') --depth;
        else if (rest[i] == ':' && depth == 0) {
            colon = i;
            break;
        }
    }
    std::vector<int> bases;
    int scale = -1;
    if (colon != std::string_view::npos)
        for (const auto& key : splitArgs(rest.substr(colon + 1, commentStart(rest.substr(colon + 1))))) {
            std::string_view k = trim(key);
            const size_t eq = k.find('=');
            if (eq == std::string_view::npos) continue;
            if (trim(k.substr(0, eq)) == "scale") {  // a whole number (L-Py evaluates it)
                const std::string v(trim(k.substr(eq + 1)));
                char* end = nullptr;
                const long n = std::strtol(v.c_str(), &end, 10);
                if (end != v.c_str() && *end == 0 && n >= 0 && n < 1000) scale = int(n);
                else warning(line, 1, "module scale '" + v + "' is not a whole number: Sprout reads scales written as numbers");
                continue;
            }
            if (trim(k.substr(0, eq)) != "base") continue;
            std::string_view v = trim(k.substr(eq + 1));
            if (v.size() >= 2 && v.front() == '(' && v.back() == ')') v = v.substr(1, v.size() - 2);
            for (const auto& b : splitArgs(v))
                if (!trim(b).empty()) bases.push_back(m_out.classes.intern(trim(b)));
        }
    std::string out;
    for (const auto& decl : splitArgs(rest.substr(0, colon))) {
        std::string_view d = trim(decl);
        if (d.empty()) continue;
        std::string_view name = d;
        std::vector<std::string> params;
        if (size_t eq = d.find('='); eq != std::string_view::npos && d.find('(') > eq) {
            // `C=D`: C is another name of D's class.
            const int target = m_out.classes.intern(trim(d.substr(eq + 1)));
            m_out.classes.alias(trim(d.substr(0, eq)), target);
            m_out.declared.push_back(target);
            continue;
        }
        if (size_t open = name.find('('); open != std::string_view::npos) {
            size_t close = closeParen(name, open);
            if (close == std::string_view::npos) {
                error(line, 1, "the '(' of module " + std::string(name.substr(0, open)) + " is never closed");
                continue;
            }
            params = splitArgs(name.substr(open + 1, close - open - 1));
            name = trim(name.substr(0, open));
        }
        const int cls = m_out.classes.intern(name);
        if (params.size()) m_out.classes.parameterNames[size_t(cls)] = params;
        if (!bases.empty()) m_out.classes.bases[size_t(cls)] = bases;
        if (scale >= 0) m_out.classes.scales[size_t(cls)] = scale;
        m_out.declared.push_back(cls);
        if (isIdentifier(name)) out += std::string(name) + " = __lpy_module_class(" + std::to_string(cls) + "); ";
    }
    m_outLines[index] = out.empty() ? "pass" : out;
}

void Translator::filterLine(std::string_view rest, bool consider, int line, int col) {
    ContextFilter f;
    f.consider = consider;
    for (const auto& w : readLstring(rest, m_out.classes, line, col, m_out.diagnostics))
        if (w.cls >= 0) f.classes.push_back(w.cls);
    if (f.classes.empty()) {
        m_filter = -1;
        return;
    }
    m_filter = int(m_out.filters.size());
    m_out.filters.push_back(std::move(f));
}

// Keywords that end with ':' and a value: `derivation length: e`.
bool Translator::keyword(std::string_view t, std::string_view word, std::string_view& rest) {
    if (t.substr(0, word.size()) != word) return false;
    std::string_view r = trim(t.substr(word.size()));
    if (r.empty() || r[0] != ':') return false;
    rest = trim(r.substr(1));
    return true;
}

void Translator::translateMain(std::vector<std::string>& lines) {
    m_outLines.assign(lines.size(), std::string());
    Mode mode = Mode::Python;
    bool sawProduction = false;
    std::string inString;  // the delimiter of a triple-quoted string still open from a line above
    for (size_t i = 0; i < lines.size(); ++i) {
        const int lineNo = int(i) + 1;
        std::string& line = lines[i];
        std::string_view t = trim(line);
        const int ind = indentOf(line);
        std::string_view rest;
        m_outLines[i] = line;
        if (!inString.empty()) {  // a line of a string's text, kept as it is
            if (line.find(inString) != std::string::npos) inString.clear();
            continue;
        }
        if (mode == Mode::Python) inString = openTripleQuote(line);
        if (t.empty() || t[0] == '#') continue;
        if (keyword(t, "derivation length", rest)) {
            m_outLines[i] = std::string(size_t(mode == Mode::Python ? ind : 0), ' ') + "__derivation_length__ = " + std::string(rest);
            m_out.derivationLengthAt = {int(i) + 1, ind + 1};
            continue;
        }
        if (ind == 0 && (startsWithWord(t, "production") && keyword(t, "production", rest))) {
            mode = Mode::Production;
            sawProduction = true;
            m_group = 0;
            m_outLines[i] = "# " + line;
            if (!rest.empty()) error(lineNo, 13, "nothing may follow 'production:' on its line");
            continue;
        }
        if (mode != Mode::Python) {
            if (keyword(t, "interpretation", rest) || keyword(t, "homomorphism", rest)) {
                mode = Mode::Interpretation;
                m_outLines[i] = "# " + line;
                continue;
            }
            if (keyword(t, "decomposition", rest)) {
                mode = Mode::Decomposition;
                m_outLines[i] = "# " + line;
                continue;
            }
            if (keyword(t, "maximum depth", rest)) {
                if (mode == Mode::Production) error(lineNo, 1, "'maximum depth:' belongs to a decomposition or interpretation section");
                m_outLines[i] = std::string(mode == Mode::Decomposition ? "__decomposition_max_depth__ = " : "__homomorphism_max_depth__ = ") + std::string(rest);
                continue;
            }
            if (startsWithWord(t, "group")) {
                std::string_view g = trim(t.substr(5, commentStart(t) - 5));
                if (!g.empty() && g.back() == ':') g = trim(g.substr(0, g.size() - 1));
                int n = 0;
                bool okNumber = !g.empty() && std::all_of(g.begin(), g.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
                if (okNumber && g.size() < 6) n = std::stoi(std::string(g));
                else error(lineNo, 7, "a group is a whole number from 0 (`group 1:`)");
                m_group = n;
                m_outLines[i] = "# " + line;
                continue;
            }
            if (t == "endgroup") {
                m_group = 0;
                m_outLines[i] = "# " + line;
                continue;
            }
            if (t == "endlsystem") {
                mode = Mode::Python;
                m_outLines[i] = "# " + line;
                continue;
            }
        } else if (t == "endlsystem" || startsWithWord(t, "interpretation") || startsWithWord(t, "homomorphism") || startsWithWord(t, "decomposition")) {
            std::string_view r2;
            if (t == "endlsystem" || keyword(t, "interpretation", r2) || keyword(t, "homomorphism", r2) || keyword(t, "decomposition", r2)) {
                error(lineNo, ind + 1, "'" + std::string(t) + "' comes after 'production:' (L-Py)");
                m_outLines[i] = "# " + line;
                continue;
            }
        }
        if (keyword(t, "consider", rest) || keyword(t, "ignore", rest)) {
            filterLine(rest, t[0] == 'c', lineNo, int(line.find(rest.empty() ? ":" : std::string(rest))) + 1);
            m_outLines[i] = "# " + line;
            continue;
        }
        if (mode == Mode::Python) {
            if (ind == 0 && (keyword(t, "Axiom", rest) || keyword(t, "axiom", rest))) {
                m_out.hasAxiom = true;
                if (rest.empty() && i + 1 < lines.size() && indentOf(lines[i + 1]) > 0) {
                    m_out.axiomIsBlock = true;
                    m_outLines[i] = "def __axiom_block__():";
                    continue;
                }
                const size_t col = line.find(':') + 2;
                const size_t sharp = commentStart(rest);
                // `#(`: cpfg's '#' (width up) as a module; in L-Py '#' starts a comment, and
                // what it leaves ('(0.1)...') is an error there too.
                if (sharp + 1 < rest.size() && rest[sharp + 1] == '(')
                    error(lineNo, int(line.find(rest)) + int(sharp) + 1,
                          "'#(': '#' starts a comment in L-Py, so it is not a module; cpfg's # (width up) is _ in L-Py");
                std::string text(rest.substr(0, sharp));
                auto mods = readLstring(text, m_out.classes, lineNo, int(col), m_out.diagnostics);
                m_outLines[i] = "__axiom__ = " + pythonLstring(mods);
                continue;
            }
            if (startsWithWord(t, "module") && t.size() > 7 && std::isspace(static_cast<unsigned char>(t[6]))) {
                declareModules(t.substr(7), lineNo, i);
                m_outLines[i] = std::string(size_t(ind), ' ') + m_outLines[i];
                continue;
            }
            if (startsWithWord(t, "undeclare")) {
                m_outLines[i] = std::string(size_t(ind), ' ') + "pass";
                continue;
            }
            if (startsWithWord(t, "lpyimport")) {
                error(lineNo, ind + 1, "lpyimport (merging another file's rules) is not provided by Sprout: paste the file with %pastefile");
                m_outLines[i] = std::string(size_t(ind), ' ') + "pass";
                continue;
            }
            if (findKeyword(line, "produce") != std::string::npos || findKeyword(line, "nproduce") != std::string::npos ||
                findKeyword(line, "makestring") != std::string::npos) {
                translateProduces(lines, i);
                m_outLines[i] = lines[i];
            }
            // A function of the file may test contexts (InLeftContext), as rule bodies do.
            translateInContexts(lines[i], lineNo);
            m_outLines[i] = lines[i];
            continue;
        }
        // Rule mode.
        if (ind > 0) {
            error(lineNo, 1, "unexpected indent: an indented line belongs under a rule's header");
            m_outLines[i] = "";
            continue;
        }
        if (startsWithWord(t, "def") || startsWithWord(t, "class") || startsWithWord(t, "import") || startsWithWord(t, "from")) {
            warning(lineNo, 1, "Python at the start of a line in a rule section: read as Python, after it the rules end (write 'endlsystem' first)");
            mode = Mode::Python;
            --i;
            continue;
        }
        i = rule(lines, i, mode);
    }
    if (!sawProduction && !m_out.hasAxiom) warning(0, 0, "no 'Axiom:' and no 'production:': nothing to derive");
}

}  // namespace translate_detail

Translation translate(std::string_view text, const ModuleClasses* seed) {
    translate_detail::Translator t(text);
    if (seed) t.seed(*seed);
    return t.run();
}

}  // namespace sprout::lpy
