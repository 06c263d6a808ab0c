#pragma once
// The cpfg / lpfg / L-Py family's text made into the logical lines the Parser classifies:
// C comments blanked, lines continued with '\\' joined, #define and #include read (an
// included file's lines in place of its #include), textual macros put in place, and
// productions written over several lines joined into one. The diagnostics are moved back to
// the lines they were written on at the end (placeDiagnostics). The Parser owns one, hands it
// the text (read), and classifies what it returns (cpfg_classify.cpp).
#include <deque>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/language/expr.hpp"
#include "core/language/grammar.hpp"
#include "core/language/source.hpp"

namespace sprout::detail {

class Parser;

// A cpfg line's words, shared by the reader (which lines make one) and the Parser (what each
// line is); cpfg_lines.cpp.
// The arrow of a production outside parentheses and blocks: cpfg's `-->`, or `->`.
size_t arrowAt(std::string_view s);
bool startsWithWord(std::string_view t, std::string_view word);
// The key of a `key: value` line in canonical form ("derivation length"), or "".
std::string keyOf(std::string_view t, std::string_view& value);
// The cpfg settings Sprout reads, by their cpfg names, and the .lsys directive they set.
const std::map<std::string, std::string>& cpfgKeys();
// `homomorphism`, `decomposition:`, `endlsystem` ...: the section word a line opens, or "".
std::string sectionWord(std::string_view t);
bool isStatementBlockKey(const std::string& key);  // define:, Start:, StartEach:, EndEach:, End:

class CpfgReader {
public:
    // `parser` takes the diagnostics and the numeric #defines (its define()); `store` keeps the
    // texts the lines view into (joined, included, expanded); `macros` gets the function-like
    // #defines the parser's expressions expand.
    CpfgReader(Parser& parser, const ParseOptions& options, std::deque<std::string>& store,
               std::unordered_map<std::string, ExprMacro>& macros)
        : m_parser(parser), m_options(options), m_store(store), m_macros(macros) {}

    // The text's logical lines, in order. `text` gets its comments blanked in place (every
    // byte stays where it was); `original` is the text as given, which the lines' columns show.
    std::vector<SourceLine> read(std::string& text, std::string_view original);
    // Diagnostics of joined productions and included files moved to the lines they were
    // written on, in order of position.
    void placeDiagnostics(std::vector<Diagnostic>& diags) const;

private:
    // Where the pieces of a cpfg logical line came from: a production joined from several
    // lines, or a line of an #included file (reported at the #include, naming the file).
    struct Origin {
        int logical = 0;                  // the line number the parser used
        std::vector<std::pair<size_t, int>> pieces;  // byte offset in the joined text -> physical line
        std::vector<size_t> pieceStart;   // offset of each piece's first byte in its physical line
        std::string includeName;          // non-empty: the line comes from this included file
        int includeLine = 0;              // the #include's line in the grammar
    };

    // Logical lines (cpfg_lines.cpp).
    std::vector<SourceLine> readFile(std::string_view text, const std::string& includeName, int includeLine,
                                     int depth, std::vector<std::string>& stack);
    std::vector<SourceLine> physicalLines(std::string_view text, bool top, int originBase) const;
    void joinTabLines(std::vector<SourceLine>& body);
    void joinLines(std::vector<SourceLine>& body, std::vector<SourceLine>& out);
    void joinStatementBlock(std::vector<SourceLine>& body, size_t i);
    size_t joinProduction(std::vector<SourceLine>& body, size_t i, SourceLine& out);
    // The C preprocessor (cpfg_preprocessor.cpp): comments, continued lines, #define,
    // #include, textual macros.
    static size_t blankComments(std::string& text);
    void joinContinuations(std::vector<SourceLine>& lines, bool top);
    std::vector<SourceLine> preprocess(const std::vector<SourceLine>& lines, bool top, int includeLine, int depth,
                                       std::vector<std::string>& stack);
    void readDefine(const SourceLine& line, std::string_view rest, bool top);
    static bool wholeValue(std::string_view value);  // a #define's value that is one value where put
    bool condition(const SourceLine& line, std::string_view word, std::string_view rest);
    void readInclude(const SourceLine& line, std::string_view t, std::string_view rest, bool top, int includeLine,
                     int depth, std::vector<std::string>& stack, std::vector<SourceLine>& body);
    void putTextMacros(std::vector<SourceLine>& body);
    std::string expandTextMacros(std::string_view text, std::vector<std::string>& active, bool& tooLong) const;

    Parser& m_parser;
    const ParseOptions& m_options;
    std::deque<std::string>& m_store;
    std::unordered_map<std::string, ExprMacro>& m_macros;
    std::string_view m_original;  // the text as given (read)
    std::vector<Origin> m_origins;
    std::vector<std::pair<std::string, std::string>> m_textMacros;  // #define NAME text (not a number)
};

}  // namespace sprout::detail
