#pragma once
// An L-Py model file read as L-Py reads it (L-Py's src/cpp/lpy_parser.cpp, described in the
// L-Py documentation): the text becomes one Python program with the same line numbers (so a
// traceback names the .lpy line) plus what the derivation needs to know at parse time: the
// module classes, the rules with their headers parsed into patterns, the context filters.
//
// Pure C++ (no Python): the fuzz target and the tests drive it without an interpreter; the
// host (lpy/lpy.hpp) runs what it makes.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout::lpy {

// Module classes: L-Py's predefined modules (with their aliases) first, then the names a
// file declares or uses. A name is found by the longest known name at a position; an unknown
// character becomes a class of its own ("on the fly" declaration, L-Py's default).
class ModuleClasses {
public:
    ModuleClasses();
    // `name` becomes another name of `cls` (`module C=D`); a name already known is kept.
    void alias(std::string_view name, int cls);
    // The class of `name`, adding it when new.
    int intern(std::string_view name);
    int find(std::string_view name) const;  // -1 when unknown
    // L-Py's ModuleClassTable.remove: `name` is found no more (a class's own name gives way to
    // its first alias); or every name of `cls`. False when there was nothing to forget. A
    // class without a name keeps its id for the modules of it that strings hold.
    bool forget(std::string_view name);
    bool forget(int cls);
    bool named(int cls) const { return cls >= 0 && size_t(cls) < m_names.size() && find(m_names[size_t(cls)]) == cls; }
    const std::string& name(int cls) const { return m_names[size_t(cls)]; }
    std::vector<std::string> aliasesOf(int cls) const;  // its other names
    size_t size() const { return m_names.size(); }
    size_t longest() const { return m_longest; }
    // One of L-Py's predefined modules (a file's own modules draw nothing, as in L-Py).
    bool isPredefined(int cls) const { return cls >= 0 && size_t(cls) < m_predefined; }
    // Declared parameter names (`module A(x, y)`), for `m.x` in Python.
    std::vector<std::vector<std::string>> parameterNames;
    // Declared bases (`module B : base = A`, `base = (A, C)`): with L-Py's option 'Module
    // inheritance', a rule for A also matches a B.
    std::vector<std::vector<int>> bases;
    // Declared scales (`module I : scale = 2`) for multiscale strings; -1: none (L-Py's
    // ModuleClass.DEFAULT_SCALE).
    std::vector<int> scales;
    bool used(int cls) const { return cls >= 0 && size_t(cls) < m_hidden.size() && !m_hidden[size_t(cls)]; }
    // The classes `cls` derives from, through any number of declarations.
    std::vector<int> ancestors(int cls) const;
    // Whether `cls` is `base` or derives from it.
    bool derivesFrom(int cls, int base) const;

    // The names of `ids` with their ids, every one but the predefined modules hidden: found by
    // no lookup (a text is read as with a fresh table) until interned again, which keeps its
    // id. How L-Systems of one Python process agree on ids (lpy/api/session.cpp): each translation
    // starts from the names all of them made so far.
    static ModuleClasses seededFrom(const ModuleClasses& ids);
    // Adds `other`'s classes from this table's size on, hidden (`other` started from this
    // table, so its ids are this table's), with their declared parameter names.
    void adopt(const ModuleClasses& other, bool hidden);

    // Fixed ids of the modules the derivation itself looks at.
    static constexpr int kPush = 0, kPop = 1, kCut = 2, kStar = 3, kNone = 4, kSurface = 5;

private:
    std::vector<std::string> m_names;
    std::unordered_map<std::string, int> m_ids;  // names and aliases
    std::vector<bool> m_hidden;                  // per class (seededFrom)
    size_t m_longest = 1;
    size_t m_predefined = 0;
};

// One module of an lstring as written: its class and its argument texts (Python expressions).
struct WrittenModule {
    int cls = 0;
    std::vector<std::string> args;
    bool hasParens = false;
    std::string variable;  // `$v`: the module held in Python variable v (cls is -1)
    bool getModule = false;  // `$A(v)` in a header: a module of class A, bound whole to v (variable)
    int col = 0;           // 1-based column in the line
};

// Tokenises an lstring as L-Py does (longest known name first, an unknown character a class
// of its own, `~c` a surface named c, arguments split at top-level commas). Errors (an
// unbalanced parenthesis, a stray ')') go to `diags` at `line` and the text's columns,
// counted from `col0`.
std::vector<WrittenModule> readLstring(std::string_view text, ModuleClasses& classes, int line, int col0,
                                       std::vector<Diagnostic>& diags);

// One argument of a module in a rule's header.
struct PatternArg {
    enum class Kind : std::uint8_t { Bind, Skip, Rest, Keywords, Equal, Predicate } kind = Kind::Bind;
    std::string name;  // Bind, Rest, Keywords, Predicate: the variable
    std::string expr;  // Equal: the value; Predicate: the test (Python, reading `name`)
};

struct PatternModule {
    int cls = 0;              // ModuleClasses::kStar: any module
    bool hasParens = false;   // `A` without parentheses matches only an A without arguments
    std::string anyName;      // `*(name, ...)`: binds the module's name
    std::vector<PatternArg> args;
    bool exactPop = false;    // `=]`: an actual ']' (a ']' skips to the end of the branch)
    // `$A(v)`: a module of class A bound whole (its place in the string, its tree) to v.
    std::string moduleVariable;
    // `x(p, min, max)`: the pattern p repeated greedily (0 to 1000 times; exactly min when
    // only min is given); its variables are bound as lists.
    std::vector<PatternModule> repeat;
    int repeatMin = 0, repeatMax = 1000;
    int repeatVariables = 0;  // how many variables the repeated pattern binds (each a list)
    bool isRepeat() const { return !repeat.empty(); }
    // `or(p1, p2, ...)`: the first alternative that matches (`None`: nothing, always matches);
    // every alternative's variables are bound, None for those of the ones that did not match.
    std::vector<std::vector<PatternModule>> alternatives;
    std::vector<int> alternativeVariables;  // how many each binds
    bool isOr() const { return !alternatives.empty(); }
};

enum class RuleKind : std::uint8_t { Production, Decomposition, Interpretation };

struct Rule {
    RuleKind kind = RuleKind::Production;
    int group = 0;
    int line = 0;
    std::string header;  // as written, for "why this branch?"
    std::vector<PatternModule> left, newLeft, pred, newRight, right;
    std::string function;             // the Python function the body became
    std::vector<std::string> params;  // its parameters, in binding order
    int filter = -1;                  // index into Translation::filters; -1: none
    // A `-->` rule: its successor as written (the native path derives it without Python
    // when every rule of the model is this simple: lpy/engine/native_rules.cpp).
    bool arrow = false;
    std::vector<WrittenModule> successor;
    // Whenever it matches, it makes `successor`: a `-->` rule, or a body of plain statements
    // (no branch, loop, return or raise) whose last is its one `produce` (the growth budget
    // predicts such rules' growth before deriving: Engine::predictGrowth).
    bool alwaysProduces = false;
};

// `consider:` (only these classes count in contexts) or `ignore:` (these are skipped).
struct ContextFilter {
    bool consider = false;
    std::vector<int> classes;
};

// A pattern written in a rule's body, `InLeftContext(A(x), d)` / `InRightContext(...)`, tested
// while the body runs (L-Py's LstringMatcher::inLeftContext): its modules and the names its
// variables bind, in binding order.
struct ContextPattern {
    std::vector<PatternModule> modules;
    std::vector<std::string> names;
};

struct Translation {
    std::string initCode;  // the INITIALISATION part, padded so that its lines are the file's
    std::string mainCode;  // the rest, translated; line i is the file's line i
    ModuleClasses classes;
    std::vector<Rule> rules;  // in file order
    std::vector<ContextFilter> filters;
    std::vector<ContextPattern> contextPatterns;  // __lpy_in_context(index, ...) in the code
    std::vector<int> declared;  // the classes `module` lines declare
    bool axiomIsBlock = false;  // `Axiom:` followed by an indented block: __axiom_block__()
    bool hasAxiom = false;
    std::pair<int, int> derivationLengthAt{0, 0};  // line and column of `derivation length:`
    bool writesCut = false;  // a successor, `produce` or the axiom holds '%'
    std::vector<Diagnostic> diagnostics;
    bool ok() const { return !hasErrors(diagnostics); }
};

// L-Py's first pass (Lsystem::set): a line holding `%pastefile NAME` or `%pastemodule
// PKG.NAME` has the named file's text in place of the rest of the line. `read` gives a file's
// text (module: a dotted module name) or nothing when there is none (an error at the line).
using PasteReader = std::function<std::optional<std::string>(const std::string& name, bool module)>;
std::string pasteFiles(std::string_view text, const PasteReader& read, std::vector<Diagnostic>& diags);

// A model file's bytes as UTF-8 text, decoded as L-Py's Python reads the file: by its coding
// cookie (Latin-1, Windows-1252), otherwise as UTF-8 with any byte that is not UTF-8 read as
// Latin-1 (encoding.cpp). A UTF-8 file comes back as it is, less a byte order mark.
std::string modelTextAsUtf8(std::string_view bytes);

// `seed`: a table whose ids the translation keeps (ModuleClasses::seededFrom).
Translation translate(std::string_view text, const ModuleClasses* seed = nullptr);
// A pattern a rule's body tests while it runs, not written in the call (`inLeftContext(p, d)`
// with p a string made at run time): read as a pattern of the file is, its names given the ids
// of `classes` (a name they lack gets an id no module of the string has).
ContextPattern readContextPattern(std::string_view text, const ModuleClasses& classes, std::vector<Diagnostic>& diags);

}  // namespace sprout::lpy
