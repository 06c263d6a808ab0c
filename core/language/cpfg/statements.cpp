// cpfg statement blocks in productions: `pred : { x = a*2; } x > 1 { y = x+1; } --> F(y)`.
// The blocks hold assignments and if / else; names they assign are the production's locals
// (slots after its formal parameters), visible in the condition and the successor.
//
// Index of this file:
//   [SECTION] The block parser (statements, calls, assignments)
//   [SECTION] Global blocks and arrays
//   [SECTION] Locals and conditions
#include <cctype>

#include "core/language/cpfg/user_files.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout::detail {
namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }

// Index of the bracket closing the one at `open` (same kind), or npos.
size_t matching(std::string_view s, size_t open) {
    const char o = s[open], c = o == '{' ? '}' : o == '(' ? ')' : ']';
    int depth = 0;
    for (size_t i = open; i < s.size(); ++i) {
        if (s[i] == o) ++depth;
        else if (s[i] == c && --depth == 0) return i;
    }
    return std::string_view::npos;
}

size_t skipSpaces(std::string_view s, size_t i) {
    while (i < s.size() && isSpace(s[i])) ++i;
    return i;
}

// [SECTION] The block parser (statements, calls, assignments)

class BlockParser {
public:
    BlockParser(DiagnosticSink& sink, const SourceLine& line, const std::vector<std::string>& params,
                const ExprScope& scope, FileCalls* files)
        : m_sink(sink), m_line(line), m_params(params), m_scope(scope), m_files(files) {}

    bool statements(std::string_view text, std::vector<Statement>& out) {
        size_t i = 0;
        while (true) {
            i = skipSpaces(text, i);
            if (i >= text.size()) return true;
            if (!statement(text, i, out)) return false;
        }
    }

private:
    // The ';' that ends a statement from `i`, outside parentheses (or the end of the block).
    static size_t statementEnd(std::string_view text, size_t i) {
        int depth = 0;
        for (; i < text.size(); ++i) {
            if (text[i] == '"') {  // a string (printf's format) to its closing quote
                for (++i; i < text.size() && text[i] != '"'; ++i)
                    if (text[i] == '\\') ++i;
                if (i >= text.size()) return text.size();
            } else if (text[i] == '(') ++depth;
            else if (text[i] == ')') --depth;
            else if (text[i] == ';' && depth <= 0) break;
        }
        return i;
    }

    // `(test)` at `i` (after `while`): compiled into `out`; `i` moves past the ')'.
    bool test(std::string_view text, size_t& i, const char* word, Expr& out) {
        if (i >= text.size() || text[i] != '(')
            return fail(text.substr(std::min(i, text.size())), std::string("expected '(' after '") + word + "'");
        const size_t close = matching(text, i);
        if (close == std::string_view::npos) return fail(text.substr(i), "this '(' is never closed");
        auto e = compileExpr(text.substr(i + 1, close - i - 1), m_line, m_scope, m_sink);
        if (!e) return false;
        out = std::move(*e);
        i = close + 1;
        return true;
    }

    // The flat index of `a[i][j]`, as a read of it computes it (compileArrayIndex); `misread`
    // the slot cpfg assigns instead, or -1.
    Expr indexOf(std::string_view element, const GlobalArray& array, int& misread) {
        // The element was compiled as a read already (its mistakes said there): a scratch sink.
        DiagnosticSink scratch;
        auto e = compileArrayIndex(element, array, m_line, m_scope, scratch, &misread);
        return e ? std::move(*e) : Expr::constant(0);
    }

    // The function `text` calls when it is one call and nothing else (`fopen(...)`), or "".
    static std::string_view callOf(std::string_view text) {
        size_t a = skipSpaces(text, 0), b = a;
        while (b < text.size() && isIdentChar(text[b])) ++b;
        const size_t open = skipSpaces(text, b);
        if (b == a || open >= text.size() || text[open] != '(') return {};
        const size_t close = matching(text, open);
        if (close == std::string_view::npos || skipSpaces(text, close + 1) < text.size()) return {};
        return text.substr(a, b - a);
    }

    // fopen / fscanf with `(args)` (user_files.hpp).
    bool fileCall(std::string_view name, std::string_view parenthesised, Statement& s) {
        if (!m_files) return fail(name, "'" + std::string(name) + "' is not available here");
        const size_t close = parenthesised.empty() ? std::string_view::npos : matching(parenthesised, 0);
        if (close == std::string_view::npos) return fail(parenthesised.empty() ? name : parenthesised, "this '(' is never closed");
        if (skipSpaces(parenthesised, close + 1) < parenthesised.size())
            return fail(parenthesised.substr(close + 1), "expected ';' after '" + std::string(name) + "(...)'");
        const std::string_view args = parenthesised.substr(1, close - 1);
        if (name == "fopen") return compileFopen(*m_files, m_sink, m_line, args, s);
        auto slotOf = [&](std::string_view v) -> std::optional<std::uint16_t> {
            for (size_t k = 0; k < m_params.size(); ++k)
                if (m_params[k] == v) return std::uint16_t(k);
            if (m_scope.globals)
                for (size_t g = 0; g < m_scope.globals->size(); ++g)
                    if ((*m_scope.globals)[g] == v) return std::uint16_t(kGlobalSlot + g);
            return std::nullopt;
        };
        return compileFscanf(*m_files, m_sink, m_line, args, m_scope, slotOf, s);
    }

    bool fail(std::string_view at, std::string message) {
        m_sink.error(m_line, at, std::move(message));
        return false;
    }

    // One statement starting at `i` (spaces skipped); `i` moves past it.
    bool statement(std::string_view text, size_t& i, std::vector<Statement>& out) {
        if (text[i] == ';') {
            ++i;
            return true;
        }
        if (text[i] == '{') {
            size_t close = matching(text, i);
            if (close == std::string_view::npos) return fail(text.substr(i), "this '{' is never closed with '}'");
            if (!statements(text.substr(i + 1, close - i - 1), out)) return false;
            i = close + 1;
            return true;
        }
        if (!identStart(text[i]))
            return fail(text.substr(i), "expected a statement such as 'x = a * 2;' or 'if (x > 1) y = 2;'");
        size_t start = i;
        while (i < text.size() && isIdentChar(text[i])) ++i;
        std::string_view name = text.substr(start, i - start);
        i = skipSpaces(text, i);
        if (name == "if") {
            if (i >= text.size() || text[i] != '(') return fail(text.substr(i), "expected '(' after 'if', as in 'if (x > 1) y = 2;'");
            size_t close = matching(text, i);
            if (close == std::string_view::npos) return fail(text.substr(i), "this '(' is never closed");
            Statement s;
            s.kind = Statement::Kind::If;
            auto test = compileExpr(text.substr(i + 1, close - i - 1), m_line, m_scope, m_sink);
            if (!test) return false;
            s.expr = std::move(*test);
            i = skipSpaces(text, close + 1);
            if (i >= text.size()) return fail(text.substr(start), "'if (...)' needs a statement after it");
            if (!statement(text, i, s.then)) return false;
            size_t j = skipSpaces(text, i);
            if (text.substr(j, 4) == "else" && (j + 4 >= text.size() || !isIdentChar(text[j + 4]))) {
                i = skipSpaces(text, j + 4);
                if (i >= text.size()) return fail(text.substr(j), "'else' needs a statement after it");
                if (!statement(text, i, s.otherwise)) return false;
            }
            out.push_back(std::move(s));
            return true;
        }
        if (name == "while") {
            Statement s;
            s.kind = Statement::Kind::While;
            if (!test(text, i, "while", s.expr)) return false;
            i = skipSpaces(text, i);
            if (i >= text.size()) return fail(text.substr(start), "'while (...)' needs a statement after it");
            if (!statement(text, i, s.then)) return false;
            out.push_back(std::move(s));
            return true;
        }
        if (name == "do") {
            Statement s;
            s.kind = Statement::Kind::Do;
            if (i >= text.size()) return fail(text.substr(start), "'do' needs a statement after it");
            if (!statement(text, i, s.then)) return false;
            i = skipSpaces(text, i);
            if (text.substr(i, 5) != "while") return fail(text.substr(i), "expected 'while (...)' after the body of 'do'");
            i = skipSpaces(text, i + 5);
            if (!test(text, i, "while", s.expr)) return false;
            out.push_back(std::move(s));
            return true;
        }
        if (name == "for") return fail(name, "'for' is not part of cpfg's language: write 'while (...) { ... }'");
        if (name == "else") return fail(name, "'else' without an 'if' before it");
        if (i < text.size() && text[i] == '(') {  // a call run for what it does: srand(3); printf(...);
            const size_t end = statementEnd(text, i);
            // cpfg's messages, files written, animation: nothing in the model; its files read
            if (noEffectCall(name) || name == "fscanf" || name == "fopen") {
                Statement s;
                if (!noEffectCall(name) && !fileCall(name, text.substr(i, end - i), s)) return false;
                if (!noEffectCall(name)) out.push_back(std::move(s));
                i = end < text.size() ? end + 1 : end;
                return true;
            }
            Statement s;
            s.kind = Statement::Kind::Eval;
            auto value = compileExpr(text.substr(start, end - start), m_line, m_scope, m_sink);
            if (!value) return false;
            s.expr = std::move(*value);
            out.push_back(std::move(s));
            i = end < text.size() ? end + 1 : end;
            return true;
        }
        Statement s;
        s.kind = Statement::Kind::Assign;
        bool element = false;  // an array's element (or where cpfg assigns instead): s.slot is set
        if (i < text.size() && text[i] == '[') {
            element = true;  // cpfg: `a[i][j] = ...`, an element of a global array
            const GlobalArray* array = nullptr;
            if (m_scope.arrays)
                for (const GlobalArray& a : *m_scope.arrays)
                    if (a.name == name) array = &a;
            if (!array) return fail(name, "'" + std::string(name) + "' is not an array: declare it in 'define: { array " + std::string(name) + "[10]; }'");
            size_t end = i;
            while (end < text.size() && text[end] == '[') {
                const size_t close = matching(text, end);
                if (close == std::string_view::npos) return fail(text.substr(end), "this '[' is never closed with ']'");
                end = skipSpaces(text, close + 1);
            }
            std::string element(text.substr(start, end - start));  // compiled as a read, then made a write
            auto read = compileExpr(element, m_line, m_scope, m_sink);
            if (!read) return false;
            int misread = -1;
            s.index = indexOf(text.substr(start, end - start), *array, misread);
            s.slot = std::uint16_t(kGlobalSlot + array->first);
            s.size = std::uint16_t(array->size());
            if (misread >= 0) {  // cpfg assigns to the index's variable (compileArrayIndex)
                m_sink.warning(m_line, text.substr(start, end - start),
                               "cpfg assigns this value to the variable of the index, not to the array's element "
                               "(its first index begins with a one-operand function or sign): so does Sprout");
                s.slot = std::uint16_t(misread);
                s.size = 0;
            }
            i = end;
        }
        if (i >= text.size() || text[i] != '=' || (i + 1 < text.size() && text[i + 1] == '='))
            return fail(text.substr(start), "expected '=' after '" + std::string(name) + "', as in '" + std::string(name) + " = 1;'");
        ++i;
        const size_t end = statementEnd(text, i);
        size_t slot = 0;
        while (slot < m_params.size() && m_params[slot] != name) ++slot;
        if (element) slot = s.slot;
        if (slot == m_params.size() && m_scope.globals) {  // cpfg's global variable
            size_t g = 0;
            while (g < m_scope.globals->size() && (*m_scope.globals)[g] != name) ++g;
            if (g < m_scope.globals->size()) slot = kGlobalSlot + g;
        }
        s.slot = std::uint16_t(slot);
        if (std::string_view call = callOf(text.substr(i, end - i)); call == "fopen" || call == "fscanf") {
            if (s.size) return fail(text.substr(start), "'" + std::string(call) + "' gives its value to a variable, not to an array's element");
            if (slot == m_params.size()) return fail(text.substr(start), "'" + std::string(name) + "' cannot be assigned here");
            const std::string_view value = text.substr(i, end - i);
            const size_t open = value.find('(');
            const size_t close = matching(value, open);
            if (close == std::string_view::npos) return fail(value.substr(open), "this '(' is never closed");
            if (!fileCall(call, value.substr(open, close - open + 1), s)) return false;
            s.slot = std::uint16_t(slot);
            s.size = 1;  // its value (the file's id, the count read) goes to `slot`
            out.push_back(std::move(s));
            i = end < text.size() ? end + 1 : end;
            return true;
        }
        auto value = compileExpr(text.substr(i, end - i), m_line, m_scope, m_sink);
        if (!value) return false;
        s.expr = std::move(*value);
        out.push_back(std::move(s));
        i = end < text.size() ? end + 1 : end;
        return true;
    }

    DiagnosticSink& m_sink;
    const SourceLine& m_line;
    const std::vector<std::string>& m_params;
    ExprScope m_scope;
    FileCalls* m_files;
};

}  // namespace

bool parseStatements(DiagnosticSink& sink, const SourceLine& line, std::string_view text,
                     const std::vector<std::string>& params, const ExprScope& scope, std::vector<Statement>& out,
                     FileCalls* files) {
    return BlockParser(sink, line, params, scope, files).statements(text, out);
}

// [SECTION] Global blocks and arrays

void Parser::readGlobalBlock(const SourceLine& line, const std::string& key, std::string_view v) {
    std::string_view body = trim(v);
    if (!body.starts_with("{") || !body.ends_with("}"))
        return m_sink.error(line, body, "expected a block of statements in braces, as in '" + key + ": { n = 0; }'");
    body = body.substr(1, body.size() - 2);
    std::vector<std::string> assigned;
    collectAssigned(body, assigned);
    for (const auto& name : assigned) {
        if (m_g.defines.count(name))
            return m_sink.error(line, body, "'" + name + "' is a constant (#define) and cannot be assigned in a block: use another name");
        if (std::find(m_g.globals.begin(), m_g.globals.end(), name) == m_g.globals.end() &&
            std::none_of(m_g.arrays.begin(), m_g.arrays.end(), [&](const GlobalArray& a) { return a.name == name; })) {
            m_g.globals.push_back(name);
            m_g.globalInit.push_back(0);
        }
    }
    if (m_g.globals.size() > 4096) return m_sink.error(line, body, "too many global variables (the limit is 4096)");
    std::vector<Statement>& out = key == "start" ? m_g.startBlock : key == "starteach" ? m_g.startEachBlock
                                : key == "endeach" ? m_g.endEachBlock : m_g.endBlock;
    const std::vector<std::string> none;
    ExprScope scope{&none, &m_g.defines, &m_macros, &m_g.globals, &m_g.arrays, m_options.curves.get()};
    scope.cpfg = m_options.tabContinues;
    FileCalls files{m_g, m_options.include};
    parseStatements(m_sink, line, body, none, scope, out, &files);
}

void Parser::defineArrays(const SourceLine& line, std::string_view text) {
    // Definitions separated by commas outside brackets and braces.
    std::vector<std::string_view> defs;
    int depth = 0;
    size_t from = 0;
    for (size_t k = 0; k <= text.size(); ++k) {
        const char c = k < text.size() ? text[k] : ',';
        if (c == '[' || c == '{' || c == '(') ++depth;
        else if (c == ']' || c == '}' || c == ')') --depth;
        else if (c == ',' && depth <= 0) {
            defs.push_back(trim(text.substr(from, k - from)));
            from = k + 1;
        }
    }
    for (std::string_view def : defs) {
        size_t k = 0;
        while (k < def.size() && isIdentChar(def[k])) ++k;
        GlobalArray a;
        a.name = std::string(def.substr(0, k));
        if (a.name.empty() || !identStart(a.name[0]))
            return m_sink.error(line, def, "expected an array's name and size, as in 'array a[10]'");
        std::int64_t size = 1;
        for (k = skipSpaces(def, k); k < def.size() && def[k] == '[';) {
            const size_t close = matching(def, k);
            if (close == std::string_view::npos) return m_sink.error(line, def.substr(k), "this '[' is never closed with ']'");
            auto n = constant(line, def.substr(k + 1, close - k - 1));
            if (!n) return;
            if (!(*n >= 1 && *n <= 65536)) return m_sink.error(line, def.substr(k), "an array's size must be a whole number from 1 to 65536");
            a.dims.push_back(int(*n));
            size *= std::int64_t(*n);
            if (size > 65536) return m_sink.error(line, def, "the arrays are too big: at most 65000 elements in all");
            k = skipSpaces(def, close + 1);
        }
        if (a.dims.empty()) return m_sink.error(line, def, "expected the size of '" + a.name + "' in brackets, as in '" + a.name + "[10]'");
        if (m_g.globals.size() + size_t(size) > 65536 - kGlobalSlot)
            return m_sink.error(line, def, "the arrays are too big: at most 65000 elements in all");
        std::vector<double> values;
        if (k < def.size() && def[k] == '=') {
            std::string_view init = trim(def.substr(k + 1));
            size_t v = 0;
            while (v < init.size()) {
                while (v < init.size() && (init[v] == '{' || init[v] == '}' || init[v] == ',' || isSpace(init[v]))) ++v;
                size_t e = v;
                int d = 0;
                while (e < init.size() && !(d == 0 && (init[e] == ',' || init[e] == '}' || init[e] == '{'))) {
                    d += init[e] == '(' ? 1 : init[e] == ')' ? -1 : 0;
                    ++e;
                }
                if (e > v) {
                    auto n = constant(line, trim(init.substr(v, e - v)));
                    if (!n) return;
                    values.push_back(*n);
                }
                v = e;
            }
            if (values.size() > size_t(size))
                return m_sink.error(line, init, "'" + a.name + "' holds " + std::to_string(size) + " values, but " +
                                                    std::to_string(values.size()) + " are given");
        } else if (k < def.size()) {
            return m_sink.error(line, def.substr(k), "expected '= {...}' or nothing after the size of '" + a.name + "'");
        }
        a.first = std::uint16_t(m_g.globals.size());
        m_g.globals.push_back(a.name + "[]");  // never an identifier: read through the array
        for (int e = 1; e < size; ++e) m_g.globals.emplace_back();
        for (int e = 0; e < size; ++e) m_g.globalInit.push_back(size_t(e) < values.size() ? values[size_t(e)] : 0.0);
        m_g.arrays.push_back(std::move(a));
    }
}

// [SECTION] Locals and conditions

void collectAssigned(std::string_view text, std::vector<std::string>& names) {
    for (size_t i = 0; i < text.size();) {
        if (!identStart(text[i]) || (i > 0 && (isIdentChar(text[i - 1]) || text[i - 1] == '.'))) {
            ++i;
            continue;
        }
        size_t start = i;
        while (i < text.size() && isIdentChar(text[i])) ++i;
        std::string name(text.substr(start, i - start));
        size_t j = skipSpaces(text, i);
        // `x = ...`, or fscanf's `&x` (not `a &&x`)
        const bool assigned = j < text.size() && text[j] == '=' && (j + 1 >= text.size() || text[j + 1] != '=');
        size_t before = start;
        while (before > 0 && isSpace(text[before - 1])) --before;
        const bool address = before > 0 && text[before - 1] == '&' && (before < 2 || text[before - 2] != '&');
        if ((assigned || address) && name != "if" && name != "else" && std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    }
}

bool splitCpfgCondition(DiagnosticSink& sink, const SourceLine& line, std::string_view text, std::string_view& pre,
                        std::string_view& condition, std::string_view& post) {
    pre = post = {};
    std::string_view t = trim(text);
    if (t.starts_with("{")) {
        size_t close = matching(t, 0);
        if (close == std::string_view::npos) {
            sink.error(line, t, "this '{' is never closed with '}'");
            return false;
        }
        pre = t.substr(1, close - 1);
        if (trim(pre).empty()) pre = t.substr(1, 0);
        t = trim(t.substr(close + 1));
        if (t.starts_with(":")) t = trim(t.substr(1));  // `{ ... }: a == V` (L-system Explorer's files)
    }
    if (t.ends_with("}")) {
        int depth = 0;
        size_t open = std::string_view::npos;
        for (size_t k = t.size(); k-- > 0;) {
            if (t[k] == '}') ++depth;
            else if (t[k] == '{' && --depth == 0) {
                open = k;
                break;
            }
        }
        if (open == std::string_view::npos) {
            sink.error(line, t.substr(t.size() - 1), "this '}' closes a block that was never opened with '{'");
            return false;
        }
        post = t.substr(open + 1, t.size() - open - 2);
        t = trim(t.substr(0, open));
    }
    if (size_t brace = t.find_first_of("{}"); brace != std::string_view::npos) {
        sink.error(line, t.substr(brace), "a block '{ ... }' goes before or after the condition, not inside it");
        return false;
    }
    condition = t;
    // An empty block is still a block: keep a non-null view so the caller sees it.
    if (pre.data() && trim(pre).empty()) pre = {};
    if (post.data() && trim(post).empty()) post = {};
    return true;
}

}  // namespace sprout::detail
