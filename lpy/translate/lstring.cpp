// Module classes and lstrings as L-Py reads them: its predefined modules with their aliases
// (turtle_vocabulary.hpp's table), ModuleClasses, readLstring() (an lstring's text into
// modules) and the Python expression an lstring becomes. Its own file: the tokeniser every section and rule goes through.
#include <algorithm>
#include <cctype>

#include "lpy/translate/translate_impl.hpp"
#include "lpy/translate/turtle_vocabulary.hpp"

namespace sprout::lpy {

namespace translate_detail {

// The Python expression for an lstring: a list of class ids, (id, (args,)) tuples, and
// Python objects for `$v`.
std::string pythonLstring(const std::vector<WrittenModule>& mods) {
    std::string out = "[";
    for (const auto& m : mods) {
        if (!m.variable.empty()) {
            out += m.variable;
        } else if (m.args.empty()) {
            out += std::to_string(m.cls);
        } else {
            out += "(" + std::to_string(m.cls) + ",(";
            for (const auto& a : m.args) {
                const std::string_view t = trim(a);
                // `A(**p)`: the dict's values in the order of A's declared parameters.
                if (t.substr(0, 2) == "**") out += "*__lpy_kwargs(" + std::to_string(m.cls) + "," + std::string(t.substr(2)) + "),";
                else out += a + ",";
            }
            out += "))";
        }
        out += ",";
    }
    out += "]";
    return out;
}

}  // namespace translate_detail

using namespace translate_detail;

ModuleClasses::ModuleClasses() {
    // L-Py's predefined modules, each with its aliases (lpy/translate/turtle_vocabulary.hpp).
    for (const TurtleWord& word : kTurtleVocabulary) {
        const int id = int(m_names.size());
        m_names.emplace_back(word.names[0]);
        for (const char* n : word.names) {
            if (!n) break;
            m_ids.emplace(n, id);
            m_longest = std::max(m_longest, std::string_view(n).size());
        }
    }
    parameterNames.resize(m_names.size());
    bases.resize(m_names.size());
    scales.resize(m_names.size(), -1);
    m_hidden.resize(m_names.size());
    m_predefined = m_names.size();
}

ModuleClasses ModuleClasses::seededFrom(const ModuleClasses& ids) {
    ModuleClasses out;
    out.adopt(ids, true);
    return out;
}

void ModuleClasses::adopt(const ModuleClasses& other, bool hidden) {
    if (!hidden)  // what `other` declared of classes this table knew
        for (size_t c = m_predefined; c < std::min(m_names.size(), other.m_names.size()); ++c) {
            if (!other.parameterNames[c].empty()) parameterNames[c] = other.parameterNames[c];
            if (other.scales[c] >= 0) scales[c] = other.scales[c];
        }
    for (size_t c = m_names.size(); c < other.m_names.size(); ++c) {
        m_names.push_back(other.m_names[c]);
        m_ids.insert_or_assign(other.m_names[c], int(c));
        // Hidden names are found by no lookup: the longest name read stays the visible ones'.
        if (!hidden) m_longest = std::max(m_longest, other.m_names[c].size());
        parameterNames.push_back(hidden ? std::vector<std::string>{} : other.parameterNames[c]);
        bases.emplace_back();
        scales.push_back(hidden ? -1 : other.scales[c]);
        m_hidden.push_back(hidden);
    }
}

std::vector<std::string> ModuleClasses::aliasesOf(int cls) const {
    std::vector<std::string> out;
    for (const auto& [name, id] : m_ids)
        if (id == cls && name != m_names[size_t(cls)] && !m_hidden[size_t(id)]) out.push_back(name);
    std::sort(out.begin(), out.end());
    return out;
}

int ModuleClasses::find(std::string_view name) const {
    auto it = m_ids.find(std::string(name));
    return it == m_ids.end() || m_hidden[size_t(it->second)] ? -1 : it->second;
}

bool ModuleClasses::forget(std::string_view name) {
    const int cls = find(name);
    if (cls < 0) return false;
    if (m_names[size_t(cls)] == name) {
        const std::vector<std::string> others = aliasesOf(cls);
        if (!others.empty()) m_names[size_t(cls)] = others.front();
    }
    m_ids.erase(std::string(name));
    return true;
}

bool ModuleClasses::forget(int cls) {
    bool any = false;
    for (auto it = m_ids.begin(); it != m_ids.end();) {
        if (it->second == cls && !m_hidden[size_t(cls)]) {
            it = m_ids.erase(it);
            any = true;
        } else {
            ++it;
        }
    }
    return any;
}

void ModuleClasses::alias(std::string_view name, int cls) {
    if (name.empty() || find(name) >= 0) return;
    m_ids.insert_or_assign(std::string(name), cls);
    m_longest = std::max(m_longest, name.size());
}

int ModuleClasses::intern(std::string_view name) {
    if (auto it = m_ids.find(std::string(name)); it != m_ids.end()) {
        if (m_hidden[size_t(it->second)]) {  // a seeded name, used again: its id
            m_hidden[size_t(it->second)] = false;
            m_longest = std::max(m_longest, name.size());
        }
        return it->second;
    }
    const int id = int(m_names.size());
    m_names.emplace_back(name);
    m_ids.emplace(std::string(name), id);
    m_longest = std::max(m_longest, name.size());
    parameterNames.emplace_back();
    bases.emplace_back();
    scales.push_back(-1);
    m_hidden.push_back(false);
    return id;
}

std::vector<int> ModuleClasses::ancestors(int cls) const {
    // Depth-first over the declarations; a cycle (`module A : base = B`, `module B : base = A`)
    // ends when every class was seen.
    std::vector<int> out, todo{cls};
    std::vector<bool> seen(bases.size(), false);
    while (!todo.empty()) {
        const int c = todo.back();
        todo.pop_back();
        if (c < 0 || size_t(c) >= bases.size() || seen[size_t(c)]) continue;
        seen[size_t(c)] = true;
        for (int b : bases[size_t(c)]) {
            if (b != cls && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
            todo.push_back(b);
        }
    }
    return out;
}

bool ModuleClasses::derivesFrom(int cls, int base) const {
    if (cls == base) return true;
    const std::vector<int> a = ancestors(cls);
    return std::find(a.begin(), a.end(), base) != a.end();
}

std::vector<WrittenModule> readLstring(std::string_view s, ModuleClasses& classes, int line, int col0, std::vector<Diagnostic>& diags) {
    std::vector<WrittenModule> out;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        WrittenModule m;
        m.col = col0 + int(i);
        if (c == ')') {
            diags.push_back({line, m.col, "a ')' with no module before it", Severity::Error});
            ++i;
            continue;
        }
        bool getModule = false;
        if (c == '$' && i + 1 < s.size() && isIdentStart(s[i + 1])) {
            size_t j = i + 1;
            while (j < s.size() && isIdent(s[j])) ++j;
            size_t k = j;
            while (k < s.size() && (s[k] == ' ' || s[k] == '\t')) ++k;
            if (k < s.size() && s[k] == '(') {  // `$A(a)`: a pattern's whole module
                getModule = true;
                ++i;
                m.col = col0 + int(i);
            }
        }
        if (!getModule && c == '$' && i + 1 < s.size() && isIdentStart(s[i + 1])) {
            size_t j = i + 1;
            while (j < s.size() && isIdent(s[j])) ++j;
            m.cls = -1;
            m.variable = std::string(s.substr(i + 1, j - i - 1));
            out.push_back(std::move(m));
            i = j;
            continue;
        }
        if (c == '~' && i + 1 < s.size() && !std::isspace(static_cast<unsigned char>(s[i + 1])) && s[i + 1] != '(') {
            // `~l(2)`: the surface named l.
            m.cls = ModuleClasses::kSurface;
            m.args.push_back(std::string("'") + s[i + 1] + "'");
            i += 2;
        } else {
            size_t len = std::min(classes.longest() + 1, s.size() - i);
            int cls = -1;
            for (; len > 0; --len)
                if ((cls = classes.find(s.substr(i, len))) >= 0) break;
            if (cls < 0) {
                // An unknown character is a class of its own; a UTF-8 sequence stays whole.
                len = 1;
                while (i + len < s.size() && (static_cast<unsigned char>(s[i + len]) & 0xC0) == 0x80) ++len;
                cls = classes.intern(s.substr(i, len));
            }
            m.cls = cls;
            i += len;
        }
        size_t j = i;
        while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
        if (j < s.size() && s[j] == '(') {
            size_t close = closeParen(s, j);
            if (close == std::string_view::npos) {
                diags.push_back({line, col0 + int(j), "this '(' is never closed", Severity::Error});
                break;
            }
            m.hasParens = true;
            for (auto& a : splitArgs(s.substr(j + 1, close - j - 1))) m.args.push_back(std::move(a));
            if (m.args.size() == 1 && m.args[0].empty()) m.args.clear();
            i = close + 1;
        }
        if (getModule) {
            m.getModule = true;
            m.variable = m.args.size() == 1 ? std::string(trim(m.args[0])) : std::string();
            if (m.args.size() != 1 || !isIdentifier(m.variable))
                diags.push_back({line, m.col - 1, "'$" + classes.name(m.cls) + "(...)' binds the module to one name, e.g. $" +
                                                      classes.name(m.cls) + "(m)", Severity::Error});
            m.args.clear();
            m.hasParens = false;
        }
        out.push_back(std::move(m));
    }
    return out;
}

}  // namespace sprout::lpy
