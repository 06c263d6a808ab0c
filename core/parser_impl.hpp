#pragma once
// Internals of parse(), shared by parser.cpp (lines, rules, module sequences) and
// directives.cpp (the `key: value` table).
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/grammar.hpp"
#include "core/source.hpp"

namespace sprout::detail {

constexpr int kMaxIterations = 10000;

class Parser;
using DirectiveHandler = std::function<void(Parser&, const SourceLine&, std::string_view value)>;

struct Directive {
    const char* name;
    DirectiveHandler handler;
    int phase = 2;  // 0: module names, 1: defines, 2: everything else (in file order with rules)
};

// The table of `key: value` directives. Adding one is one row here (and a Settings field).
const std::vector<Directive>& directives();

// A module as written: its name and the raw text of each argument.
struct RawModule {
    std::string_view name;
    std::vector<std::string_view> args;
    bool hasParens = false;
};

class Parser {
public:
    explicit Parser(std::string_view text);
    ParseResult run();

    // Used by directive handlers.
    Grammar& grammar() { return m_g; }
    DiagnosticSink& sink() { return m_sink; }
    bool tokenize(const SourceLine& line, std::string_view text, std::vector<RawModule>& out);
    std::optional<double> constant(const SourceLine& line, std::string_view text);
    std::optional<Jittered> jittered(const SourceLine& line, std::string_view text);
    // Values separated by commas, or by spaces when there is no comma ("0 -1 0 0.2").
    std::optional<std::vector<double>> numbers(const SourceLine& line, std::string_view text,
                                               size_t minCount, size_t maxCount, const char* example);
    void declareModules(const SourceLine& line, std::string_view names);
    void define(const SourceLine& line, std::string_view text);
    void setAxiom(const SourceLine& line, std::string_view text);
    void setIgnore(const SourceLine& line, std::string_view text);

private:
    struct Line {
        SourceLine src;
        enum Kind { Skip, DirectiveLine, Rule } kind = Skip;
        const Directive* directive = nullptr;
        std::string_view value;
        bool interpretation = false;  // rule in the interpretation: section
    };

    void classify(Line& line, bool& inInterpretation);
    void parseRule(const SourceLine& line, bool interpretation);
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
    DiagnosticSink m_sink;
    Grammar m_g;
    std::optional<Rng> m_rng;  // rand() outside rules
    bool m_axiomSet = false;
    int m_axiomLine = 0;
};

}  // namespace sprout::detail
