#pragma once
// Internals of parse(), shared by parser.cpp (names, modules, numbers, the axiom),
// parser_rules.cpp (rules), parser_run.cpp (the whole text, lint), directives.cpp (the
// `key: value` table) and the cpfg family's files (cpfg/: the Parser owns a CpfgReader that
// makes the family's text its logical lines).
#include <array>
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/cpfg/cpfg_reader.hpp"
#include "core/language/grammar.hpp"
#include "core/language/source.hpp"

namespace sprout::detail {

constexpr int kMaxIterations = 10000;

// Text helpers of the parser's files.

inline size_t utf8Length(unsigned char c) {
    if (c < 0x80) return 1;
    if ((c & 0xE0) == 0xC0) return 2;
    if ((c & 0xF0) == 0xE0) return 3;
    if ((c & 0xF8) == 0xF0) return 4;
    return 1;
}

// Position of the first `token` outside parentheses (and, with `braces`, outside cpfg's
// statement blocks `{ }`), or npos.
inline size_t findTopLevel(std::string_view s, std::string_view token, size_t from = 0, bool braces = false) {
    int depth = 0;
    for (size_t i = from; i < s.size(); ++i) {
        char c = s[i];
        if (c == '(' || (braces && c == '{')) ++depth;
        else if (c == ')' || (braces && c == '}')) depth = std::max(0, depth - 1);
        else if (depth == 0 && s.substr(i, token.size()) == token) return i;
    }
    return std::string_view::npos;
}

inline size_t findLastTopLevel(std::string_view s, char token) {
    int depth = 0;
    size_t found = std::string_view::npos;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (c == '(') ++depth;
        else if (c == ')') depth = std::max(0, depth - 1);
        else if (depth == 0 && c == token) found = i;
    }
    return found;
}

// A Greek letter (U+0391..U+03C9, two bytes in UTF-8) at `i`: ABOP and lecture notes name
// their constants so (α = 30). 2, or 0 for anything else.
inline size_t greekLetterAt(std::string_view s, size_t i) {
    if (i + 1 >= s.size()) return 0;
    const unsigned char a = static_cast<unsigned char>(s[i]), b = static_cast<unsigned char>(s[i + 1]);
    return (a == 0xCE && b >= 0x91) || (a == 0xCF && b <= 0x89) ? 2 : 0;
}

// A character of a name: a letter, a digit or '_'.
inline bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

inline bool isIdentifier(std::string_view s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_' || greekLetterAt(s, 0))) return false;
    for (size_t i = 0; i < s.size();) {
        if (const size_t g = greekLetterAt(s, i)) i += g;
        else if (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_') ++i;
        else return false;
    }
    return true;
}

// ABOP's notation and the web's dialects (notation.cpp).
// The directive a setting's key names ("δ", "delta", "w", "ω", "start", "dlength",
// "derivation length" ...), or nullptr.
const char* settingAlias(std::string_view key);
// Another tool's view or camera setting ("stemsize", "zpos" ...): a warning, never an error.
bool isForeignSetting(std::string_view key);
// A rule label: "p1", "P2", "p" (subscripts are digits by then).
bool isRuleLabel(std::string_view s);
bool webVariable(std::string_view key);  // a web dialect's setting its rules read as a variable
// Characters pasted from PDFs and web pages (dashes, spaces, quotes, arrows, subscripts, LaTeX)
// replaced in place, keeping every byte position; `replaced` gets the warnings to give,
// `notation` is set when the text used ABOP's printed notation.
void normalizePasted(std::string& text, std::vector<std::pair<size_t, std::string>>& replaced, bool cpfg,
                     bool& notation);

// cpfg statement blocks in productions (core/language/cpfg/statements.cpp).
// A block's statements (assignments, if / else) compiled in `scope`, whose params are `params`.
// `files`: fopen and fscanf are read (cpfg/user_files.hpp); null: they are errors.
struct FileCalls;
bool parseStatements(DiagnosticSink& sink, const SourceLine& line, std::string_view text,
                     const std::vector<std::string>& params, const ExprScope& scope, std::vector<Statement>& out,
                     FileCalls* files = nullptr);
// The names a block assigns (`x = ...`), added to `names` once each.
void collectAssigned(std::string_view text, std::vector<std::string>& names);
// `{pre} condition {post}` taken apart; false (and an error) when the blocks are misplaced.
bool splitCpfgCondition(DiagnosticSink& sink, const SourceLine& line, std::string_view text, std::string_view& pre,
                        std::string_view& condition, std::string_view& post);

class Parser;
using DirectiveHandler = std::function<void(Parser&, const SourceLine&, std::string_view value)>;

struct Directive {
    const char* name;
    DirectiveHandler handler;
    int phase = 2;  // 0: module names, 1: defines, 2: everything else (in file order with rules)
};

// The table of `key: value` directives. Adding one is one row here (and a Settings field).
const std::vector<Directive>& directives();
const Directive* directiveNamed(std::string_view name);  // nullptr: no such directive

// A module as written: its name and the raw text of each argument.
struct RawModule {
    std::string_view name;
    std::vector<std::string_view> args;
    bool hasParens = false;
};

class Parser {
public:
    explicit Parser(std::string_view text, const ParseOptions& options = {});
    ParseResult run();

    // Used by directive handlers.
    Grammar& grammar() { return m_g; }
    DiagnosticSink& sink() { return m_sink; }
    const ParseOptions& options() const { return m_options; }  // the include reader, the file's name
    bool tokenize(const SourceLine& line, std::string_view text, std::vector<RawModule>& out);
    std::optional<double> constant(const SourceLine& line, std::string_view text);
    std::optional<Jittered> jittered(const SourceLine& line, std::string_view text);
    // Values separated by commas, or by spaces when there is no comma ("0 -1 0 0.2").
    std::optional<std::vector<double>> numbers(const SourceLine& line, std::string_view text,
                                               size_t minCount, size_t maxCount, const char* example);
    void declareModules(const SourceLine& line, std::string_view names);
    void define(const SourceLine& line, std::string_view text);
    void setAxiom(const SourceLine& line, std::string_view text);
    bool setPlainAxiom(const SourceLine& line, std::string_view text);  // no parameters: the fast way
    // A parameter written as a quoted name ('ctr', "leaf"): the name, without its quotes.
    static std::optional<std::string_view> quotedName(std::string_view arg);
    void setIgnore(const SourceLine& line, std::string_view text);
    // `function: NAME x,y ...` and `contour: ID [open|closed] x,y ...` (lsys_curves.cpp).
    void addFunction(const SourceLine& line, std::string_view text);
    void addContour(const SourceLine& line, std::string_view text);
    CurveTables& ownCurves();  // made on the first, and given to the grammar and its expressions
    void setConsider(const SourceLine& line, std::string_view text);
    void setMaximumDepth(const SourceLine& line, std::string_view text);
    void setSurface(const SourceLine& line, std::string_view text);  // cpfg `surface: s file.s`
    // cpfg's `Start: {...}`, `StartEach:`, `EndEach:`, `End:`: the names they assign become
    // global variables (statements.cpp).
    void readGlobalBlock(const SourceLine& line, const std::string& key, std::string_view body);
    // `array a[3], b[2][4] = {...}` in cpfg's `define:` block: global arrays.
    void defineArrays(const SourceLine& line, std::string_view statement);
    void atModules(RuleSet& rules);  // cpfg's `@` and the letter after it (parser_run.cpp)
    bool cpfg() const { return m_cpfg; }

    enum class Section { Productions, Interpretation, Decomposition };

private:
    struct Line {
        SourceLine src;
        enum Kind { Skip, DirectiveLine, Rule } kind = Skip;
        const Directive* directive = nullptr;
        std::string_view value;
        Section section = Section::Productions;
        std::string_view key;  // the setting's key as written, when another name than the directive's
        // A figure caption "n=5, δ=25.7°": the settings after the first, with their keys.
        struct More {
            const Directive* directive;
            std::string_view value, key;
        };
        std::vector<More> more;
        size_t equalsArrow = std::string_view::npos;  // a rule written "F = FF": where its '=' is
        std::uint8_t lsystem = 0;  // the cpfg sub-L-system the line belongs to (0: the main one)
    };
    // The whole text's steps (parser_run.cpp), before each line is classified.
    void splitPlainLines();
    void warnReplaced(const std::vector<std::pair<size_t, std::string>>& replaced);
    void refuseBinaryLines();
    void checkEnvironmentQuery();
    void classify(Line& line, Section& section);
    void parseRule(const SourceLine& line, Section section, size_t equalsArrow = std::string_view::npos);
    // parseRule's parts (parser_rules.cpp): the line's head, its patterns, the blocks' locals,
    // the successor and its probability.
    void unwrapTutorialRule(std::string_view& head, std::string_view& tail);
    std::string ruleLabel(const SourceLine& line, std::string_view& head, size_t& colon);
    bool parseRulePatterns(const SourceLine& line, std::string_view patterns, std::vector<std::string>& params,
                           Production& prod);
    bool collectBlockLocals(const SourceLine& line, std::string_view preBlock, std::string_view postBlock,
                            std::vector<std::string>& params,
                            std::vector<std::pair<std::string, double>>& globalsAssigned);
    // `scope`: the production's names, which a cpfg probability may read (null: a constant).
    bool splitRuleProbability(const SourceLine& line, std::string_view tail, std::string_view& succText,
                              Production& prod, const ExprScope* scope = nullptr);
    // `key = value` or `key: value` in ABOP's notation; false when the line is none of them.
    bool classifyNotation(Line& l, std::string_view t);
    bool readInRules(std::string_view name) const;
    void warnMixed(const SourceLine& line, std::string_view t);  // once per file (m_mixed)
    // ABOP's notation as a PDF gives it: a successor that goes on over the next lines, and
    // words as modules (`plant -> internode [+ leaf] ...`), declared from the predecessors.
    void joinNotationLines();
    void warnForeign(const SourceLine& line, std::string_view key);  // another tool's setting, left out
    bool isConstantExpr(const SourceLine& line, std::string_view value);
    void declareNamedModules();  // `SetContour("leaf")`: a word before a quoted name is one module
    void applyDirective(const Directive& d, const SourceLine& src, std::string_view value, std::string_view key);
    // cpfg family: what each logical line is (core/language/cpfg/cpfg_classify.cpp); the lines
    // themselves are m_cpfgReader's.
    void classifyCpfg(Line& line, Section& section, bool& ended);
    void loadSurfaceFiles();  // `~s` modules with an `s.s` file beside the grammar
    bool parsePattern(const SourceLine& line, std::string_view text, bool allowBrackets,
                      bool allowWildcard, std::vector<std::string>& params,
                      std::vector<PatternModule>& out);
    bool parseSuccessor(const SourceLine& line, std::string_view text,
                        const std::vector<std::string>& params, Successor& out, int net);
    std::optional<SymbolId> symbolFor(const SourceLine& line, std::string_view name, int arity);
    bool checkBrackets(const SourceLine& line, std::string_view text,
                       const std::vector<RawModule>& mods, int net);
    void lint();
    size_t nameLength(std::string_view s, size_t pos) const;

    std::string m_text;  // normalised copy; lines view into it
    std::string m_original;
    std::vector<Line> m_lines;
    std::vector<std::string> m_moduleNames;  // declared multi-letter names, longest first
    std::array<bool, 256> m_nameStart{};      // first bytes of those names: others are one character
    void indexModuleNames();
    DiagnosticSink m_sink;
    Grammar m_g;
    std::optional<Rng> m_rng;  // rand() outside rules
    bool m_axiomSet = false;
    int m_axiomLine = 0;
    bool m_notation = false;  // the text used ABOP's printed notation (Grammar::dialect)
    bool m_mixed = false;  // a cpfg file with lines of the .lsys family (the web's dialects): said once
    bool m_assignedScanned = false;
    std::unordered_map<std::string, double> m_assignedNames;  // names given a value with '=' (notation.cpp)
    std::array<bool, 128> m_moduleLetters{};                   // one-letter modules written in rules

    bool m_cpfg = false;
    ParseOptions m_options;
    std::shared_ptr<CurveTables> m_ownCurves;  // a .lsys file's own functions and contours
    std::deque<std::string> m_store;  // texts the cpfg lines view into (joined, included, expanded)
    std::unordered_map<std::string, ExprMacro> m_macros;          // function-like #define
    CpfgReader m_cpfgReader{*this, m_options, m_store, m_macros};  // the cpfg family's logical lines
    Section m_depthSection = Section::Productions;  // where `maximum depth:` applies (cpfg)
    bool m_considerSet = false;
    std::uint8_t m_lsystem = 0;      // the sub-L-system being read (classifyCpfg)
    std::uint8_t m_ruleLsystem = 0;  // the sub-L-system of the production parseRule reads
    std::vector<NameId> m_considered;
};

}  // namespace sprout::detail
