// What each of the cpfg family's logical lines is (cpfg manual; L-Py documentation):
// `Lsystem:` ... `endlsystem`, sub-L-systems, `derivation length:`, `consider:`, the
// homomorphism and decomposition sections with `maximum depth:`, L-Py's `module` lines, and
// the cpfg family's own settings as directive rows. Settings of other tools are warnings: the
// file still opens. The lines themselves come from the CpfgReader (cpfg_lines.cpp).
#include <algorithm>
#include <cmath>

#include "core/base/bounded.hpp"
#include "core/language/cpfg/cpfg_reader.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout::detail {
namespace {

// [SECTION] The cpfg family's own settings

void considerHandler(Parser& p, const SourceLine& l, std::string_view v) { p.setConsider(l, v); }
void surfaceHandler(Parser& p, const SourceLine& l, std::string_view v) { p.setSurface(l, v); }
void depthHandler(Parser& p, const SourceLine& l, std::string_view v) { p.setMaximumDepth(l, v); }
void angleFactorHandler(Parser& p, const SourceLine& l, std::string_view v) {
    auto f = p.constant(l, v);
    if (!f) return;
    if (!(*f > 0)) return p.sink().error(l, v, "the angle factor divides 360 degrees: it must be above 0");
    p.grammar().settings.angle = {360.0 / *f, 0};
}
void defineBlockHandler(Parser& p, const SourceLine& l, std::string_view v) {
    // cpfg's `define: { a = 1; b = a * 2; }`: each assignment is a constant (a slider).
    std::string_view body = trim(v);
    if (body.starts_with("{")) body.remove_prefix(1);
    if (body.ends_with("}")) body.remove_suffix(1);
    size_t start = 0;
    while (start < body.size()) {
        size_t end = body.find(';', start);
        if (end == std::string_view::npos) end = body.size();
        std::string_view stmt = trim(body.substr(start, end - start));
        if (stmt.starts_with("array") && stmt.size() > 5 && isSpace(stmt[5])) {
            p.defineArrays(l, stmt.substr(5));
        } else if (!stmt.empty()) {
            p.define(l, stmt);
        }
        start = end + 1;
    }
}

const Directive kConsider{"consider", considerHandler};
const Directive kSurface{"surface", surfaceHandler, 0};  // before rules: it names a module
const Directive kMaximumDepth{"maximum depth", depthHandler};
const Directive kAngleFactor{"angle factor", angleFactorHandler};
const Directive kDefineBlock{"define", defineBlockHandler, 1};
// L-system Explorer's global blocks (its `.ls` files, whose variables are not cpfg's): not
// run. Said once per block, with what it changes.
void explorerGlobalBlock(Parser& p, const SourceLine& l, std::string_view v) {
    std::string_view t = trim(l.text);
    const std::string_view word = trim(t.substr(0, t.find(':')));
    std::vector<std::string> names;
    std::string_view body = trim(v);
    if (body.starts_with("{")) body.remove_prefix(1);
    if (body.ends_with("}")) body.remove_suffix(1);
    size_t start = 0;
    while (start < body.size()) {  // `name = ...;` statements: the names they assign
        size_t end = body.find(';', start);
        if (end == std::string_view::npos) end = body.size();
        std::string_view stmt = trim(body.substr(start, end - start));
        const size_t eq = stmt.find('=');
        if (eq != std::string_view::npos && eq > 0 && (eq + 1 == stmt.size() || stmt[eq + 1] != '=') &&
            std::string_view("<>!=").find(stmt[eq - 1]) == std::string_view::npos) {
            std::string name(trim(stmt.substr(0, eq)));
            name = name.substr(0, name.find_first_of(".[ "));
            if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        }
        start = end + 1;
    }
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    p.sink().warning(l, word, "'" + std::string(word) + ":' blocks are not run" +
                                  (list.empty() ? std::string() : " (this one sets " + list + ")") +
                                  ": the rules use the values set before the axiom");
}
// `Start: {...}`, `StartEach:`, `EndEach:`, `End:` (cpfg's global blocks): their statements
// run around the derivation and its steps.
void globalBlockHandler(Parser& p, const SourceLine& l, std::string_view v) {
    if (p.options().explorer) return explorerGlobalBlock(p, l, v);
    std::string_view t = trim(l.text);
    std::string_view value;
    std::string key = keyOf(t, value);
    key.erase(std::remove(key.begin(), key.end(), ' '), key.end());
    p.readGlobalBlock(l, key, v);
}
const Directive kGlobalBlock{"global block", globalBlockHandler};

}  // namespace

// [SECTION] What each line is

void Parser::warnMixed(const SourceLine& line, std::string_view t) {
    if (m_mixed) return;
    m_mixed = true;
    m_sink.warning(line, t, "a line of ABOP's notation or a web tool's in a cpfg file: each line is read as what it is "
                            "(L-system Explorer's dialect, of the cpfg family)");
}

void Parser::classifyCpfg(Line& l, Section& section, bool& ended) {
    std::string_view t = trim(l.src.text);
    l.section = section;
    if (ended && !t.empty()) {
        // After `endlsystem`, `lsystem: 2` starts a sub-L-system: its productions rewrite what
        // stands between `$(2)` and `$`. Anything else there is not read.
        std::string_view value;
        if (keyOf(t, value) != "lsystem") return;
        const auto label = constant(l.src, value);
        if (!label) return;
        if (std::find(m_g.subLsystems.begin(), m_g.subLsystems.end(), *label) != m_g.subLsystems.end()) {
            m_sink.error(l.src, value, "a second sub-L-system with the label " + formatNumber(*label));
            return;
        }
        if (m_g.subLsystems.size() >= 250) {
            m_sink.error(l.src, value, "more than 250 sub-L-systems");
            return;
        }
        m_g.subLsystems.push_back(*label);
        m_lsystem = std::uint8_t(m_g.subLsystems.size());
        ended = false;
        section = Section::Productions;
        return;
    }
    l.lsystem = m_lsystem;
    if (ended || t.empty()) return;
    if (t.starts_with("#ignore")) return classify(l, section);
    if (t.starts_with("#")) return;
    if (arrowAt(t) != std::string_view::npos) {
        l.kind = Line::Rule;
        return;
    }
    // Section keywords stand alone (a word after a ':' is a remark of cpfg's: ignored).
    const std::string head = sectionWord(t);
    if (head == "homomorphism" || head == "interpretation") {
        section = Section::Interpretation;
        return;
    }
    if (head == "decomposition") {
        section = Section::Decomposition;
        return;
    }
    if (head == "production" || head == "productions") {
        section = Section::Productions;
        return;
    }
    if (head == "endlsystem") {
        ended = true;  // what follows (another tool's code, a second L-system) is not read
        return;
    }
    if (head == "ring lsystem") {  // cpfg: the string is a ring, its ends neighbours for contexts
        m_g.ring = true;
        return;
    }
    if (head == "group" || head == "endgroup") {
        m_sink.warning(l.src, t, "production groups are not supported: all productions are used");
        return;
    }
    if (startsWithWord(t, "module")) {  // L-Py: `module Apex(x), Internode`
        std::string names;
        int depth = 0;
        for (char c : t.substr(6)) {
            if (c == '(') ++depth;
            else if (c == ')') --depth;
            else if (depth == 0) names += c;
        }
        m_store.push_back(std::move(names));
        l.kind = Line::DirectiveLine;
        l.value = m_store.back();
        for (const auto& d : directives())
            if (std::string_view(d.name) == "module") l.directive = &d;
        return;
    }
    std::string_view value;
    std::string key = keyOf(t, value);
    if (key.empty()) {
        // Not a cpfg line: read as the .lsys and ABOP notation lines are (`delta=25.7`,
        // `n=5`, `ω: F`), whichever dialect the file's other lines come from (the web's cpfg
        // family mixes them). Said once, at the first such line.
        if (!t.starts_with("//")) warnMixed(l.src, t);
        return classify(l, section);
    }
    l.value = value;
    if (key == "lsystem") return;
    std::string name = key;
    if (auto it = cpfgKeys().find(key); it != cpfgKeys().end()) name = it->second;
    if (key == "consider") l.directive = &kConsider;
    else if (key == "surface") l.directive = &kSurface;
    else if (key == "maximum depth") l.directive = &kMaximumDepth;
    else if (key == "angle factor") l.directive = &kAngleFactor;
    else if (key == "define" && value.starts_with("{")) l.directive = &kDefineBlock;
    else if (isStatementBlockKey(key) && key != "define") l.directive = &kGlobalBlock;
    else
        for (const auto& d : directives())
            if (name == d.name) l.directive = &d;
    if (!l.directive && (settingAlias(key) || isForeignSetting(key))) {
        // A setting of the .lsys family's dialects (`dlength: 10`, `stemsize: 0.1`): as the
        // .lsys reader reads it.
        warnMixed(l.src, t);
        l.value = {};
        return classify(l, section);
    }
    if (!l.directive) {
        m_sink.warning(l.src, trim(l.src.text.substr(0, l.src.text.find(':'))),
                       "'" + std::string(trim(t.substr(0, t.find(':')))) + ":' is not a setting Sprout knows (another tool's?): ignored");
        return;
    }
    l.kind = Line::DirectiveLine;
}

}  // namespace sprout::detail
