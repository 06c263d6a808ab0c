// The .lsys parser over a whole text: pasted characters normalized, each line classified
// (setting, rule, section), the warnings of a finished grammar (lint), and the Grammar's own
// questions about itself.
//
// Index of this file:
//   [SECTION] Lines: classified, linted, checked
//   [SECTION] The whole parse
//   [SECTION] The Grammar's questions about itself
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/language/parser_impl.hpp"

namespace sprout {
namespace detail {
// [SECTION] Lines: classified, linted, checked

void Parser::classify(Line& l, Section& section) {
    std::string_view t = trim(l.src.text);
    if (t.empty()) return;
    // cpfg's preprocessor-style directives, before '#' comments.
    for (const char* word : {"#define", "#ignore"}) {
        std::string_view w(word);
        if (t.starts_with(w) && (t.size() == w.size() || isSpace(t[w.size()]) || t[w.size()] == ':')) {
            for (const auto& d : directives())
                if (w.substr(1) == d.name) l.directive = &d;
            l.kind = Line::DirectiveLine;
            l.value = t.substr(w.size());
            if (l.value.starts_with(":")) l.value.remove_prefix(1);  // "#ignore: + -" as well
            l.value = trim(l.value);
            return;
        }
    }
    if (t.starts_with("#") || t.starts_with("//")) return;
    l.section = section;
    if (size_t arrow = findTopLevel(t, "->"); arrow != std::string_view::npos) {
        // "axiom: F -> FF": a setting and a rule run together on one line.
        size_t colon = t.find(':');
        if (colon != std::string_view::npos && colon < arrow) {
            std::string k(trim(t.substr(0, colon)));
            std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
            for (const auto& d : directives())
                if (k == d.name || (k == "iterations" && std::string_view(d.name) == "n")) {
                    m_sink.error(l.src, t.substr(arrow), "'" + k + ":' is a setting and '->' makes a rule: put the rule on a line of its own");
                    return;
                }
        }
        l.kind = Line::Rule;
        return;
    }
    if (classifyNotation(l, t)) return;
    size_t colon = t.find(':');
    std::string_view key = trim(t.substr(0, colon));
    if (colon != std::string_view::npos && isRuleLabel(key)) {
        m_sink.error(l.src, key, "the label '" + std::string(key) + "' has no rule after it: write the rule on the label's line, as in '" +
                                     std::string(key) + ": F -> F[+F]F'");
        return;
    }
    const char* alias = colon == std::string_view::npos ? nullptr : settingAlias(key);
    if (colon == std::string_view::npos || key.empty() || !(isIdentifier(key) || alias)) {
        if (m_options.explorer)  // that tool passes over what it cannot read, and says nothing
            m_sink.warning(l.src, t, "not a rule, a setting or a statement: left out, as L-system Explorer leaves it out");
        else
            m_sink.error(l.src, t, "expected a rule such as 'F -> F+F' or a setting such as 'angle: 90'");
        return;
    }
    std::string_view value = trim(t.substr(colon + 1));
    std::string k(key);
    std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
    if (k == "interpretation" || k == "homomorphism" || k == "productions" || k == "rules" ||
        k == "derivation") {
        if (!value.empty()) m_sink.error(l.src, value, "'" + k + ":' starts a section; put its rules on the next lines");
        section = k == "interpretation" || k == "homomorphism" ? Section::Interpretation : Section::Productions;
        return;
    }
    if (alias && k != alias) {
        k = alias;
        l.key = key;
        m_notation = true;
    }
    l.directive = directiveNamed(k);
    if (!l.directive && isForeignSetting(key)) {
        warnForeign(l.src, key);
        return;
    }
    if (!l.directive) {
        std::vector<std::string> names;
        for (const auto& d : directives()) names.emplace_back(d.name);
        std::string msg = "unknown setting '" + std::string(key) + "'";
        std::string guess = closestMatch(k, names);
        if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
        else msg += " (a rule needs '->')";
        if (m_options.explorer) m_sink.warning(l.src, key, msg + ": left out, as L-system Explorer leaves it out");
        else m_sink.error(l.src, key, msg);
        return;
    }
    l.kind = Line::DirectiveLine;
    l.value = value;
}

void Parser::lint() {
    // A deterministic context-free rule without a condition always applies, so later rules
    // for the same module are dead: say so rather than leave the user wondering.
    for (const RuleSet* rs : {&m_g.rules, &m_g.interpretation, &m_g.decomposition}) {
        // cpfg's stochastic L-system (a `seed:`) chooses among every production that applies,
        // each of weight 1 unless given: none hides another, and weights need not add up to 1.
        // Without `seed:` its probabilities are left out, as cpfg warns.
        if (m_g.cpfgRandom && rs == &m_g.rules) {
            for (const Production& p : rs->productions)
                if (p.stochastic() && !m_g.settings.seedGiven)
                    m_sink.add({p.line, 1, "a probability without 'seed:': left out, as cpfg leaves it out (the first production "
                                           "that applies rewrites; a 'seed:' line makes the L-system stochastic)",
                                Severity::Warning});
            if (m_g.settings.seedGiven) continue;
        }
        for (const auto& list : rs->bySymbol) {
            // Each sub-L-system's productions are their own (the first's lsystem is the one checked).
            const Production* total = nullptr;
            double probSum = 0;
            int probCount = 0;
            bool guarded = false;
            for (auto idx : list) {
                const Production& p = rs->productions[idx];
                if (p.lsystem != rs->productions[list.front()].lsystem) continue;
                if (total) {
                    Diagnostic d{p.line, 1,
                                 "this rule never applies: the rule on line " + std::to_string(total->line) +
                                     " always rewrites '" + m_g.alphabet[p.pred.symbol].name +
                                     "' first (put rules with conditions or contexts before it)",
                                 Severity::Warning};
                    m_sink.add(d);
                    continue;
                }
                bool unconditional = !p.condition && !p.hasContext();
                if (p.probabilityExpr) {
                    guarded = true;  // cpfg's probability of the parameters
                } else if (unconditional && p.stochastic()) {
                    probSum += p.probability;
                    ++probCount;
                } else if (p.stochastic()) {
                    guarded = true;  // the applicable set varies: the sum says nothing
                } else if (unconditional) {
                    total = &p;
                }
            }
            if (probCount > 0 && !guarded && std::abs(probSum - 1.0) > 1e-6 && !(m_g.cpfgRandom && rs == &m_g.rules)) {
                const Production& p = rs->productions[list.front()];
                std::string sum, rest;
                appendNumber(sum, probSum);
                appendNumber(rest, std::round((1 - probSum) * 1e6) / 1e4);
                m_sink.add({p.line, 1,
                            "the probabilities of the rules for '" + m_g.alphabet[p.pred.symbol].name +
                                "' add up to " + sum +
                                (probSum > 1 ? ", not 1: they are used as weights"
                                             : ": the module stays unchanged the other " + rest + "% of the time"),
                            Severity::Warning});
            }
        }
    }
}

// Split into lines; `original` keeps the typed text for column numbers (the .lsys family:
// buildCpfgLines makes a cpfg file's).
void Parser::splitPlainLines() {
    size_t start = 0;
    int number = 1;
    while (start <= m_text.size()) {
        size_t end = m_text.find('\n', start);
        if (end == std::string::npos) end = m_text.size();
        Line l;
        l.src.number = number++;
        l.src.text = std::string_view(m_text).substr(start, end - start);
        l.src.original = std::string_view(m_original).substr(start, end - start);
        if (l.src.text.ends_with('\r')) l.src.text.remove_suffix(1);
        m_lines.push_back(l);
        start = end + 1;
    }
}

// The warnings of normalizePasted, at the lines of their offsets.
void Parser::warnReplaced(const std::vector<std::pair<size_t, std::string>>& replaced) {
    for (const auto& [offset, what] : replaced) {
        for (const auto& l : m_lines) {
            if (l.src.text.data() < m_text.data() || l.src.text.data() > m_text.data() + m_text.size()) continue;
            size_t ls = size_t(l.src.text.data() - m_text.data());
            if (offset >= ls && offset <= ls + l.src.text.size()) {
                m_sink.warning(l.src, l.src.text.substr(offset - ls), what);
                break;
            }
        }
    }
}

// Control characters (a binary file, or a paste gone wrong): one error per line, at the
// first one, and the line is not read further.
void Parser::refuseBinaryLines() {
    int binaryLines = 0;
    for (auto& l : m_lines) {
        // A comment may hold anything but control characters (old files in Latin-1 included).
        const std::string_view t = trim(l.src.text);
        const bool comment = t.starts_with("//") || (t.starts_with("#") && !t.starts_with("#define") && !t.starts_with("#ignore"));
        for (size_t i = 0; i < l.src.text.size(); ++i) {
            unsigned char c = static_cast<unsigned char>(l.src.text[i]);
            if (c >= 0x80 && !comment) {  // a UTF-8 sequence: lead byte and the right number of continuations
                const int len = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
                bool valid = len > 0 && i + size_t(len) <= l.src.text.size();
                for (int k = 1; valid && k < len; ++k) valid = (static_cast<unsigned char>(l.src.text[i + size_t(k)]) & 0xC0) == 0x80;
                if (!valid) {
                    char msg[120];
                    std::snprintf(msg, sizeof msg, "this text is not UTF-8 (byte 0x%02x): save the file as UTF-8", c);
                    if (++binaryLines <= 5) m_sink.error(l.src, l.src.text.substr(i), msg);
                    l.src.text = l.src.text.substr(0, 0);
                    break;
                }
                i += size_t(len) - 1;
                continue;
            }
            if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
                char msg[96];
                std::snprintf(msg, sizeof msg, "unexpected control character (byte 0x%02x): is this a text file?", c);
                if (++binaryLines <= 5) m_sink.error(l.src, l.src.text.substr(i), msg);
                l.src.text = l.src.text.substr(0, 0);
                break;
            }
        }
    }
}

// ?E asked of an environment the grammar does not declare: an error (in L-system
// Explorer's files a warning).
void Parser::checkEnvironmentQuery() {
    if (!m_g.environment.empty() || !m_g.alphabet.findName("?E")) return;
    // Where it is first written, for the message.
    for (const auto& l : m_lines) {
        if (size_t at = l.src.text.find("?E"); at != std::string_view::npos && l.kind != Line::Skip) {
            if (m_options.explorer)  // the page's JavaScript answers it there; the file cannot carry that
                m_sink.warning(l.src, l.src.text.substr(at), "?E asks L-system Explorer's environment, a JavaScript function "
                                                              "of that tool the file does not carry: here ?E keeps the values it "
                                                              "is given (declare one with 'environment: sphere 0 10 0 8')");
            else
                m_sink.error(l.src, l.src.text.substr(at), "?E asks the environment, but the grammar declares none: add a line "
                                                            "such as 'environment: sphere 0 10 0 8'");
            break;
        }
    }
}

// cpfg reads `@o(r)` as two modules, `@` and `o(r)`, so a production for `o` rewrites the `o`
// after an `@` too; Sprout's `@o` is one module. Where a production for a letter X (no context,
// one module) begins its successor with X again (`o(r) --> o(r+0.03)`), the same production is
// added for `@X`, its successor beginning with `@X`: the string cpfg derives.
void Parser::atModules(RuleSet& rules) {
    const size_t count = rules.productions.size();
    for (size_t k = 0; k < count; ++k) {
        const Production& p = rules.productions[k];
        const SymbolInfo& pred = m_g.alphabet[p.pred.symbol];
        if (pred.name.size() != 1 || p.hasContext() || p.successor.symbols.empty() ||
            p.successor.symbols.front() != p.pred.symbol)
            continue;
        const auto at = m_g.alphabet.find("@" + pred.name, pred.arity);
        if (!at) continue;
        Production copy = p;
        copy.pred.symbol = *at;
        copy.pred.name = m_g.alphabet[*at].nameId;
        copy.successor.symbols.front() = *at;
        rules.productions.push_back(std::move(copy));
    }
}

// [SECTION] The whole parse

ParseResult Parser::run() {
    std::vector<std::pair<size_t, std::string>> replaced;
    // Old Mac line ends (a lone CR) end a line too.
    for (size_t i = 0; i < m_text.size(); ++i)
        if (m_text[i] == '\r' && (i + 1 == m_text.size() || m_text[i + 1] != '\n')) m_text[i] = '\n';
    normalizePasted(m_text, replaced, m_cpfg, m_notation);
    if (m_cpfg) {
        m_original = m_text;  // normalising keeps byte positions; comments are blanked in m_text
        m_g.cutInNextStep = true;
        m_g.decomposeAxiom = !m_options.tabContinues;  // cpfg decomposes within its steps only
        m_g.cpfgRandom = m_options.tabContinues;
        m_g.alphabet.floatParameters = m_options.tabContinues;
        for (const SourceLine& src : m_cpfgReader.read(m_text, m_original)) {
            Line l;
            l.src = src;
            m_lines.push_back(std::move(l));
        }
    } else {
        splitPlainLines();
    }
    warnReplaced(replaced);
    refuseBinaryLines();
    if (!m_cpfg && m_notation) joinNotationLines();
    if (!m_cpfg) declareNamedModules();
    Section section = Section::Productions;
    bool ended = false;
    for (auto& l : m_lines) {
        if (m_cpfg) classifyCpfg(l, section, ended);
        else classify(l, section);
    }
    for (int phase = 0; phase <= 2; ++phase) {
        for (auto& l : m_lines) {
            if (l.lsystem > 0 && (l.kind == Line::DirectiveLine || l.section != Section::Productions)) {
                // A sub-L-system's own axiom, derivation length and homomorphism: not used (its
                // productions rewrite the main L-system's string), as in L-system Explorer.
                if (phase == 2 && l.kind != Line::Skip)
                    m_sink.warning(l.src, trim(l.src.text), "a sub-L-system's productions are used; its other lines are not");
                continue;
            }
            if (l.kind == Line::DirectiveLine && l.directive->phase == phase) {
                if (m_cpfg) m_depthSection = l.section;
                applyDirective(*l.directive, l.src, l.value, l.key);
            } else if (l.kind == Line::Rule && phase == 2) {
                m_ruleLsystem = l.lsystem;
                parseRule(l.src, l.section, l.equalsArrow);
            }
            for (const auto& m : l.more)
                if (m.directive->phase == phase) applyDirective(*m.directive, l.src, m.value, m.key);
        }
    }
    if (!m_axiomSet && m_sink.errorCount() == 0)
        m_sink.add({1, 1, "the grammar has no axiom: add a line such as 'axiom: F'", Severity::Error});

    if (m_options.tabContinues) atModules(m_g.rules);
    m_g.rules.index(m_g.alphabet.size());
    m_g.interpretation.index(m_g.alphabet.size());
    m_g.decomposition.index(m_g.alphabet.size());
    m_g.ignored.resize(m_g.alphabet.nameCount(), false);
    if (m_considerSet) {  // cpfg `consider:`: only the listed modules count for contexts
        m_g.ignored.assign(m_g.alphabet.nameCount(), true);
        for (NameId n : m_considered) m_g.ignored[n] = false;
        // cpfg leaves out the brackets it does not list too: its right context then passes
        // them (generate.c); its left context follows them always.
        for (size_t s = 0; s < m_g.alphabet.size() && !m_options.tabContinues; ++s) {
            const auto& sym = m_g.alphabet[SymbolId(s)];
            if (sym.name == "[" || sym.name == "]") m_g.ignored[sym.nameId] = false;
        }
    }
    if (m_cpfg) loadSurfaceFiles();
    checkEnvironmentQuery();
    lint();
    if (m_options.explorer) {
        // L-system Explorer derives once when the file sets no derivation length.
        const bool nSet = std::any_of(m_g.settingsRead.begin(), m_g.settingsRead.end(),
                                      [](const Grammar::ReadSetting& s) { return s.name == "n" || s.name == "iterations"; });
        if (!nSet) m_g.settings.iterations = 1;
        m_g.settings.bracePaths = true;
    }
    m_g.dialect = m_cpfg ? (m_mixed || m_options.explorer ? "L-system Explorer (cpfg family)" : "cpfg")
                  : m_options.explorer ? "L-system Explorer"
                  : m_notation         ? "ABOP notation"
                                       : ".lsys";
    std::stable_sort(m_g.settingsRead.begin(), m_g.settingsRead.end(),
                     [](const Grammar::ReadSetting& a, const Grammar::ReadSetting& b) { return a.line < b.line; });

    ParseResult result;
    result.diagnostics = std::move(m_sink.all());
    if (m_cpfg) m_cpfgReader.placeDiagnostics(result.diagnostics);
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                         return a.line != b.line ? a.line < b.line : a.col < b.col;
                     });
    if (!hasErrors(result.diagnostics)) result.grammar = std::make_shared<const Grammar>(std::move(m_g));
    return result;
}

}  // namespace detail


ParseResult parse(std::string_view text) { return detail::Parser(text).run(); }
ParseResult parse(std::string_view text, const ParseOptions& options) { return detail::Parser(text, options).run(); }

// [SECTION] The Grammar's questions about itself

void RuleSet::index(size_t alphabetSize) {
    bySymbol.assign(alphabetSize, {});
    for (size_t i = 0; i < productions.size(); ++i)
        bySymbol[productions[i].pred.symbol].push_back(std::uint32_t(i));
}


bool Grammar::parametric() const {
    if (!axiom.params.empty()) return true;
    for (const RuleSet* rs : {&rules, &interpretation})
        for (const auto& p : rs->productions)
            if (p.slotCount > 0 || !p.successor.args.empty()) return true;
    return false;
}

bool Grammar::hasContext() const {
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const Production& p) { return p.hasContext(); });
}

bool Grammar::stochastic() const {
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const Production& p) { return p.stochastic(); });
}

bool Grammar::hasQueries() const {
    for (size_t s = 0; s < alphabet.size(); ++s)
        if (queryKind(alphabet[SymbolId(s)].name)) return true;
    return false;
}

bool Grammar::needsGeneralEngine() const {
    if (!decomposition.productions.empty() || hasQueries() || !subLsystems.empty()) return true;
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const Production& p) { return p.hasBlocks(); });
}

bool Grammar::usesCut() const {
    auto hasCut = [](const auto& symbols) {
        return std::find(symbols.begin(), symbols.end(), Alphabet::kCut) != symbols.end();
    };
    if (hasCut(axiom.symbols)) return true;
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [&](const Production& p) { return hasCut(p.successor.symbols); });
}

}  // namespace sprout
