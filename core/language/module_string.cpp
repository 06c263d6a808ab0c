#include "core/language/module_string.hpp"

#include <charconv>
#include <cstring>

namespace sprout {

void appendNumber(std::string& out, double v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

void appendModule(std::string& out, const SymbolInfo& symbol, const double* params, const Alphabet* alphabet) {
    out += symbol.name;
    if (symbol.arity == 0) return;
    out += '(';
    for (int k = 0; k < symbol.arity; ++k) {
        if (k) out += ',';
        const double v = params[k];
        if (alphabet && (symbol.nameArgs >> k & 1) && v >= 0 && v < double(alphabet->strings().size()) && v == double(size_t(v))) {
            out += '\'';  // a quoted name, as written
            out += alphabet->strings()[size_t(v)];
            out += '\'';
        } else if (alphabet && alphabet->floatParameters && double(float(v)) == v) {
            char buf[32];
            auto r = std::to_chars(buf, buf + sizeof buf, float(v));
            out.append(buf, r.ptr);
        } else {
            appendNumber(out, v);
        }
    }
    out += ')';
}

std::string toString(const ModuleString& s, const Alphabet& alphabet) {
    std::string out;
    out.reserve(s.size());
    const double* p = s.params.data();
    for (SymbolId id : s.symbols) {
        const SymbolInfo& info = alphabet[id];
        appendModule(out, info, p, &alphabet);
        p += info.arity;
    }
    return out;
}

bool sameString(const ModuleString& a, const ModuleString& b) {
    return a.symbols == b.symbols && a.params.size() == b.params.size() &&
           (a.params.size() == 0 || std::memcmp(a.params.data(), b.params.data(), a.params.size() * sizeof(double)) == 0);
}

}  // namespace sprout
