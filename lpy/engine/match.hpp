#pragma once
// L-Py's rules matched against a string (lpy/engine/match.cpp): a module's pattern (its
// parameters bound as Python values, header constants and predicates checked), the contexts
// left and right of it (skipping branches and the modules a filter ignores), a rule's whole
// header at a position, and the context tests of a running body (InLeftContext ...). With the
// option 'String matching' and the modules' scales (lpy/engine/scales.cpp), contexts are read
// at a pattern module's scale. The Engine owns one; its passes (lpy/engine/passes.cpp) ask it
// whether a rule applies.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/derive/provenance.hpp"
#include "lpy/engine/lstring.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout::lpy {

class Matcher {
public:
    explicit Matcher(const Translation& tr) : m_tr(tr) {}

    // When the model is bound: L-Py's option 'Module inheritance' (rules match derived
    // modules: each class's ancestors, worked out once; none without the option), and a
    // pattern's header constants and predicates evaluated in `ns` (in its repetitions and
    // alternatives too).
    void setInheritance(bool on);
    bool inherits() const { return !m_ancestors.empty(); }
    bool derived(int cls, int base) const {
        if (m_ancestors.empty() || size_t(cls) >= m_ancestors.size()) return false;
        const auto& a = m_ancestors[size_t(cls)];
        return std::find(a.begin(), a.end(), base) != a.end();
    }
    void compile(const PatternModule& p, py::dict& ns);
    // The option 'String matching' and the modules' scales, read again when the context state
    // changed (scales.cpp).
    void readOptions();
    int scaleOf(int cls) const;

    // Whether rule r's header matches at `at` (its predecessor's first module, or last when
    // backward), its variables' values in `args`, where its contexts ended.
    bool matchAt(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, py::tuple& args, long& leftEnd,
                 size_t& rightEnd);
    // L-Py's LsysRule.match / reverse_match: (the position past the match, its values) or False.
    py::object matchRule(size_t rule, const LString& s, long at, bool forward);
    // `InLeftContext(pattern, d)` / `InRightContext` in a rule's body (translation's
    // contextPatterns[index]): matched from where the rule's own context ended, or from the
    // previous such test's end, which then moves past it (so a loop counts a run of modules);
    // the pattern's variables are written into d. Outside a rule's body: an error.
    bool inContext(size_t index, bool left, py::handle dict);
    bool inContext(const ContextPattern& p, bool left, py::handle dict);
    // The same with a pattern made at run time (inLeftContext(p, d), p not written in the
    // call): read once (readContextPattern), its constants and predicates evaluated in `ns`.
    bool inContextText(const std::string& text, bool left, py::handle dict, py::dict& ns);
    // Where a running body's context tests start (set by the engine around the call).
    struct BodyContext {
        const LString* s = nullptr;
        long left = -1;      // the next module to the left to read
        size_t right = 0;    // the next module to the right to read
        int filter = -1;
    };
    BodyContext& body() { return m_body; }
    // A body's context while one body runs, the one before it restored after (a body may
    // call another: a rule applied from a script, a hook that derives).
    class BodyScope {
    public:
        BodyScope(Matcher& m, const BodyContext& now) : m_matcher(m), m_was(m.m_body) { m.m_body = now; }
        ~BodyScope() { m_matcher.m_body = m_was; }
        BodyScope(const BodyScope&) = delete;
        BodyScope& operator=(const BodyScope&) = delete;

    private:
        Matcher& m_matcher;
        BodyContext m_was;
    };

    // The bracket partners of the string a pass rewrites (contexts skip branches by them).
    void matchBrackets(const LString& s);
    bool indexed(const LString& s) const { return m_matchOf == &s; }
    // While a pass reads `s`: the string `$A(a)` patterns bind modules of (a view of it).
    class Reading {
    public:
        Reading(Matcher& m, const LString& s) : m_m(m), m_was(m.m_reading), m_shared(std::move(m.m_readingShared)) {
            m.m_reading = &s;
            m.m_readingShared.reset();
        }
        ~Reading() { m_m.m_reading = m_was, m_m.m_readingShared = std::move(m_shared); }
        Reading(const Reading&) = delete;
        Reading& operator=(const Reading&) = delete;

    private:
        Matcher& m_m;
        const LString* m_was;
        std::shared_ptr<LString> m_shared;
    };
    // While a production pass keeps where contexts matched (derive's `contexts`): the rules'
    // matches go there, the last rule tried's context kept by matchAt.
    ContextMatches*& contexts() { return m_contexts; }
    void keepContexts(std::uint32_t parent) { m_contexts->add(parent, m_left, m_right); }

private:
    bool matchModule(const PatternModule& p, const LModule& m, std::vector<py::object>& bound);
    // `$A(a)`: the module bound whole, a view of the string a pass reads (m_reading).
    py::object nodeOf(const LModule& m);
    // `at`: where the modules matched are added (their indices in s), when kept.
    void bindAlternative(const PatternModule& p, size_t matched, std::vector<py::object>& got, std::vector<py::object>& bound);
    // `stop`: set to the position left of the match, when given.
    bool matchLeft(const std::vector<PatternModule>& ps, const LString& s, long from, int filter, std::vector<py::object>& bound,
                   std::vector<std::uint32_t>* at = nullptr, long* stop = nullptr);
    // A string read left to right, or (the new string of a backward step, built from its
    // end) right to left.
    struct View {
        const LString* s;
        bool reversed = false;
        size_t size() const { return s->size(); }
        const LModule& operator[](size_t j) const { return reversed ? (*s)[s->size() - 1 - j] : (*s)[j]; }
    };
    // Matches `ps` from position j; the position after the match, or npos.
    size_t matchRight(const std::vector<PatternModule>& ps, const View& s, size_t j, int filter, std::vector<py::object>& bound,
                      std::vector<std::uint32_t>* at = nullptr);
    long partnerIn(const View& s, size_t j);
    bool skipped(int cls, int filter) const;
    // The module a left context reads after `pos` at scale `target` (-1: none); the one a
    // right context reads from `pos` (the position after the last module matched; npos: none).
    long predecessorAt(const LString& s, long pos, int target, int filter);
    size_t nextAt(const LString& s, size_t pos, int target, int filter);
    bool multiscale() const { return m_stringMatching >= 2; }

    const Translation& m_tr;
    std::vector<std::vector<int>> m_ancestors;
    std::unordered_map<const PatternArg*, py::object> m_constants, m_predicates;
    std::unordered_map<std::string, ContextPattern> m_textPatterns;  // inContextText's, read once
    BodyContext m_body;
    const LString* m_reading = nullptr;
    std::shared_ptr<LString> m_readingShared;
    std::vector<long> m_match;  // bracket partners of the string being rewritten
    const LString* m_matchOf = nullptr;
    ContextMatches* m_contexts = nullptr;
    std::vector<std::uint32_t> m_left, m_right;
    // Multiscale strings (scales.cpp): the option 'String matching' (0 as a string, 1
    // as an axial tree, 2 multi-level, 3 multiscale; read at each derive) and each class's
    // scale (INT_MAX: none, L-Py's DEFAULT_SCALE).
    int m_stringMatching = 1;
    std::vector<int> m_scale;
    py::object m_lpyModule;  // openalea.lpy, imported once (an import a step was a tenth of a small step)
    // The context state the options were last read from, and its count of changes then
    // ('changes': bumped by the option and scale setters): read again only when either moved.
    py::object m_optionsOf;
    long m_optionsChanges = -1;
};

}  // namespace sprout::lpy
