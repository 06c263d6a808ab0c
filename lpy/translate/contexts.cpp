// Contexts tested from inside a rule's body: `InLeftContext(A(x), d)`, `InRightContext(B, d)`,
// and `inLeftContext('A(x)', d)` / `inRightContext(...)` with the pattern as a string literal
// (with a pattern made at run time, the call stays: openalea.lpy's function reads it then).
// As L-Py's parser does (src/cpp/lpy_parser.cpp), the pattern is read when the file is: it
// becomes a ContextPattern of the translation, and the call `__lpy_in_context(index, side,
// d)`, which the engine answers from where the rule's own contexts ended (lpy/engine/engine.hpp).
// A pattern made at run time is read alone by readContextPattern.
// Its own file: the one part of a body's Python that L-Py reads as an lstring besides produce.
#include "lpy/translate/translate_impl.hpp"

namespace sprout::lpy::translate_detail {

void Translator::translateInContexts(std::string& line, int lineNo) {
    struct Form {
        const char* word;
        bool left;
        bool quoted;  // the pattern is a string literal
    };
    for (const Form f : {Form{"InLeftContext", true, false}, Form{"InRightContext", false, false},
                         Form{"inLeftContext", true, true}, Form{"inRightContext", false, true}}) {
        for (size_t from = 0;;) {
            const size_t at = findKeyword(line, f.word, from);
            if (at == std::string::npos) break;
            size_t open = at + std::string_view(f.word).size();
            while (open < line.size() && (line[open] == ' ' || line[open] == '\t')) ++open;
            const size_t close = open < line.size() && line[open] == '(' ? closeParen(line, open) : std::string::npos;
            if (close == std::string::npos) {
                error(lineNo, int(at) + 1, std::string(f.word) + " is called with its pattern and a dict: " + f.word + "(A(x), d)");
                break;
            }
            const std::string_view args = std::string_view(line).substr(open + 1, close - open - 1);
            const std::vector<size_t> commas = topCommas(args);  // the dict follows the last one
            const size_t comma = commas.empty() ? std::string_view::npos : commas.back();
            std::string_view pattern = trim(comma == std::string_view::npos ? args : args.substr(0, comma));
            const std::string dict = comma == std::string_view::npos ? "None" : std::string(trim(args.substr(comma + 1)));
            int col = int(open + 2 + size_t(pattern.data() - args.data()));
            if (f.quoted) {
                // The pattern as a literal is read with the file; one made at run time (a
                // variable) is read when the call runs (openalea.lpy's inLeftContext).
                if (pattern.size() < 2 || (pattern.front() != '\'' && pattern.front() != '"') || pattern.back() != pattern.front()) {
                    from = close;
                    continue;
                }
                pattern = pattern.substr(1, pattern.size() - 2);
                ++col;
            }
            ContextPattern cp;
            cp.modules = patterns(pattern, lineNo, col);
            bindNames(cp.modules, cp.names, lineNo);
            const std::string call = "__lpy_in_context(" + std::to_string(m_out.contextPatterns.size()) + ", " +
                                     (f.left ? "True" : "False") + ", " + dict + ")";
            m_out.contextPatterns.push_back(std::move(cp));
            line = line.substr(0, at) + call + line.substr(close + 1);
            from = at + call.size();
        }
    }
}

ContextPattern Translator::contextPattern(std::string_view text) {
    ContextPattern cp;
    cp.modules = patterns(text, 1, 1);
    bindNames(cp.modules, cp.names, 1);
    return cp;
}

}  // namespace sprout::lpy::translate_detail

namespace sprout::lpy {

ContextPattern readContextPattern(std::string_view text, const ModuleClasses& classes, std::vector<Diagnostic>& diags) {
    translate_detail::Translator t("");
    t.seed(classes);
    ContextPattern cp = t.contextPattern(text);
    diags = t.diagnostics();
    return cp;
}

}  // namespace sprout::lpy
