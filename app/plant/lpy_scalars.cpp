// An L-Py model's scalars created, renamed and deleted in its text (lpy_scalars.hpp).
#include "app/plant/lpy_scalars.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "app/plant/python_text.hpp"

namespace sprout {
namespace {

using namespace python_text;

struct Tuple {
    std::string name;
    size_t open = 0, close = 0;  // '(' and ')'
    bool typed = false;          // ('NAME', 'Type', ...), Studio's form since 1.1
};
struct ScalarList {
    size_t open = 0, close = 0;  // '[' and ']'
    std::vector<Tuple> tuples;
};

// The `scalars = [...]` list of the INITIALISATION part.
std::optional<ScalarList> scalarList(std::string_view t) {
    size_t at = t.find("__initialiseContext__");
    for (at = at == std::string_view::npos ? 0 : at; (at = t.find("scalars", at)) != std::string_view::npos; at += 7) {
        if (at > 0 && isIdent(t[at - 1])) continue;
        size_t k = at + 7;
        if (!eat(t, k, "=")) continue;
        k = skipSpace(t, k);
        if (k >= t.size() || t[k] != '[') continue;
        ScalarList l;
        l.open = k;
        int depth = 0;
        for (size_t i = k; i < t.size(); ++i) {
            const char c = t[i];
            if (c == '\'' || c == '"') {
                const size_t q = t.find(c, i + 1);
                if (q == std::string_view::npos) return std::nullopt;
                i = q;
            } else if (c == '(' || c == '[') {
                if (++depth == 2 && c == '(') l.tuples.push_back(Tuple{"", i, 0, false});
            } else if (c == ')' || c == ']') {
                if (--depth == 0) {
                    l.close = i;
                    break;
                }
                if (depth == 1 && c == ')' && !l.tuples.empty()) l.tuples.back().close = i;
            }
        }
        if (l.close == 0) return std::nullopt;
        for (Tuple& tu : l.tuples) {
            size_t p = skipSpace(t, tu.open + 1);
            if (p >= t.size() || (t[p] != '\'' && t[p] != '"')) continue;
            const size_t q = t.find(t[p], p + 1);
            if (q == std::string_view::npos) continue;
            tu.name = std::string(t.substr(p + 1, q - p - 1));
            size_t r = q + 1;
            tu.typed = eat(t, r, ",") && (r = skipSpace(t, r)) < t.size() && (t[r] == '\'' || t[r] == '"');
        }
        return l;
    }
    return std::nullopt;
}

bool identifier(std::string_view n) {
    if (n.empty() || std::isdigit(static_cast<unsigned char>(n[0]))) return false;
    for (char c : n)
        if (!isIdent(c)) return false;
    static const char* keywords[] = {"False", "None", "True", "and", "as", "def", "class", "for", "if", "in", "is", "lambda", "not", "or",
                                     "return", "while", "import", "from", "with", "yield", "pass", "break", "continue", "global"};
    for (const char* k : keywords)
        if (n == k) return false;
    return true;
}

std::string number(double v, bool integer) {
    if (integer) return std::to_string(std::llround(v));
    std::string s = formatValue(v);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string tupleText(const LpyScalar& s, bool typed) {
    const std::string name = "'" + s.name + "'";
    if (s.kind == LpyScalar::Kind::Category) return "(" + name + (typed ? ", 'Category')" : ", None)");
    const bool integer = s.kind == LpyScalar::Kind::Integer;
    if (s.kind == LpyScalar::Kind::Bool) return typed ? "(" + name + ", 'Bool', " + (s.value != 0 ? "True" : "False") + ")"
                                                      : "(" + name + ", " + (s.value != 0 ? "True" : "False") + ", False, True)";
    const std::string range = number(s.value, integer) + ", " + number(s.min, integer) + ", " + number(s.max, integer);
    if (!typed) return "(" + name + ", " + range + ")";
    return "(" + name + (integer ? ", 'Integer', " + range : ", 'Float', " + range + ", 2") + ")";
}

}  // namespace

std::string addLpyScalar(std::string_view text, const LpyScalar& s, std::string& error) {
    if (!identifier(s.name)) return error = "'" + s.name + "' is not a Python name", "";
    const auto list = scalarList(text);
    if (list)
        for (const Tuple& t : list->tuples)
            if (t.name == s.name) return error = "a scalar " + s.name + " is there already", "";
    for (const LpyScalar& other : lpyScalars(text))
        if (other.name == s.name) return error = "a scalar " + s.name + " is there already", "";
    std::string out(text);
    if (list) {
        const bool typed = list->tuples.empty() || list->tuples.front().typed;
        return out.insert(list->close, std::string(list->tuples.empty() ? "" : ", ") + tupleText(s, typed));
    }
    // No list yet: Studio's lines after the context's first line (the part made when missing).
    const std::string block = "\tscalars = [" + tupleText(s, true) + "]\n\tcontext[\"__scalars__\"] = scalars\n\tfor s in scalars:\n"
                              "\t\tif not s[1] == \"Category\" : context[s[0]] = s[2]\n";
    const size_t def = out.find("def __initialiseContext__(");
    if (def != std::string::npos) {
        const size_t eol = out.find('\n', def);
        if (eol == std::string::npos) return out + "\n" + block;
        return out.insert(eol + 1, block);
    }
    if (!out.empty() && out.back() != '\n') out += '\n';
    return out + "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\ndef __initialiseContext__(context):\n" + block;
}

std::string renameLpyScalar(std::string_view text, std::string_view name, std::string_view newName, std::string& error) {
    if (!identifier(newName)) return error = "'" + std::string(newName) + "' is not a Python name", "";
    const auto list = scalarList(text);
    if (!list) return error = "the model has no scalars", "";
    const Tuple* found = nullptr;
    for (const Tuple& t : list->tuples) {
        if (t.name == newName) return error = "a scalar " + std::string(newName) + " is there already", "";
        if (t.name == name) found = &t;
    }
    if (!found) return error = "no scalar " + std::string(name), "";
    std::string out(text);
    const size_t q = skipSpace(text, found->open + 1) + 1;  // inside the quotes
    return out.replace(q, name.size(), newName);
}

std::string removeLpyScalar(std::string_view text, std::string_view name, std::string& error) {
    const auto list = scalarList(text);
    if (!list) return error = "the model has no scalars", "";
    for (size_t i = 0; i < list->tuples.size(); ++i) {
        const Tuple& t = list->tuples[i];
        if (t.name != name) continue;
        // The tuple and the comma that joins it to the next (the last: to the one before).
        size_t b = t.open, e = t.close + 1;
        if (i + 1 < list->tuples.size()) e = list->tuples[i + 1].open;
        else if (i > 0) b = list->tuples[i - 1].close + 1;
        return std::string(text).erase(b, e - b);
    }
    return error = "no scalar " + std::string(name), "";
}

}  // namespace sprout
