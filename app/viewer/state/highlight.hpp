#pragma once
// Syntax highlighting for every language Sprout opens (.lsys, the cpfg / L-Py family,
// Lparser, Fractint, .ifs, .forest): a line at a time, into coloured spans, with what carries
// over from line to line (a cpfg /* comment */). No ImGui: tested on its own.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "app/viewer/state/text_model.hpp"
#include "core/language/file_kind.hpp"

namespace sprout::viewer::editor {

enum class Token : std::uint8_t {
    Plain,
    Comment,
    Setting,      // n:, angle:, Lsystem:, derivation length:, the keys of a scene
    Keyword,      // #define, #include, endlsystem, decomposition, Fractint's Angle / Axiom
    Module,       // module names in axioms, predecessors, contexts and successors
    Bracket,      // [ ] { } ( )
    Number,
    Parameter,    // names inside expressions: formal parameters, defines
    Operator,     // < > : and the operators of expressions
    Arrow,        // -> --> = (Lparser, Fractint)
    Probability,  // the ": 0.5" after a successor
    String,       // a quoted string (an L-Py model's Python)
};

struct Span {
    int begin = 0, end = 0;  // bytes of the line
    Token token = Token::Plain;
};

struct LineState {
    bool inBlockComment = false;  // inside a cpfg /* ... */
};

// Appends the spans of one line (in order, not overlapping; the gaps are plain).
void highlightLine(FileKind kind, std::string_view line, LineState& state, std::vector<Span>& out);

// The bracket matching the one at `at` or just before it (( ) [ ] { }), if any.
std::optional<Pos> matchingBracket(const TextModel& text, Pos at);

}  // namespace sprout::viewer::editor
