// The grammar editor without a window: its text model (edits, indentation, comments, search,
// undo across outside changes) and its highlighting on every language Sprout opens.
#include <gtest/gtest.h>

#include "app/viewer/state/highlight.hpp"
#include "app/viewer/state/text_model.hpp"

namespace sprout::viewer::editor {
namespace {

TEST(TextModel, TypingEditsAndUndoesAsOneStep) {
    TextModel t("n: 3\naxiom: F\n");
    t.setCursor({1, 8});
    for (char c : std::string("+F")) t.insert(std::string(1, c));
    EXPECT_EQ(t.text(), "n: 3\naxiom: F+F\n");
    t.newline();
    t.insert("F -> FF");
    EXPECT_EQ(t.text(), "n: 3\naxiom: F+F\nF -> FF\n");
    EXPECT_TRUE(t.undo());  // the pasted rule
    EXPECT_TRUE(t.undo());  // the new line
    EXPECT_EQ(t.text(), "n: 3\naxiom: F+F\n");
    EXPECT_TRUE(t.undo());  // "+F" typed: one step
    EXPECT_EQ(t.text(), "n: 3\naxiom: F\n");
    EXPECT_FALSE(t.undo());
    EXPECT_TRUE(t.redo());
    EXPECT_EQ(t.text(), "n: 3\naxiom: F+F\n");
    // A slider writes into the text from outside: one undo step too, and the cursor stays.
    t.setCursor({1, 2});
    t.replaceFromOutside("n: 5\naxiom: F+F\n");
    EXPECT_EQ(t.cursor(), (Pos{1, 2}));
    EXPECT_TRUE(t.undo());
    EXPECT_EQ(t.text(), "n: 3\naxiom: F+F\n");
}

// Issue 52: the changes of one drag in the panel (one gesture id) are one undo step; another
// gesture, or an edit between, starts another.
TEST(TextModel, ADragIsOneUndoStep) {
    TextModel t("a = (0, 0)\n");
    t.replaceFromOutside("a = (0, 1)\n", 7);
    t.replaceFromOutside("a = (0, 2)\n", 7);
    t.replaceFromOutside("a = (0, 3)\n", 7);
    t.replaceFromOutside("a = (1, 3)\n", 8);  // another drag
    t.replaceFromOutside("a = (2, 3)\n");     // a change of no gesture: a step of its own
    t.replaceFromOutside("a = (2, 4)\n", 8);  // the old drag's id after it: a step again
    ASSERT_TRUE(t.undo());
    EXPECT_EQ(t.text(), "a = (2, 3)\n");
    ASSERT_TRUE(t.undo());
    EXPECT_EQ(t.text(), "a = (1, 3)\n");
    ASSERT_TRUE(t.undo());
    EXPECT_EQ(t.text(), "a = (0, 3)\n");
    ASSERT_TRUE(t.undo());
    EXPECT_EQ(t.text(), "a = (0, 0)\n") << "the three moves of one drag, undone together";
    EXPECT_FALSE(t.undo());
    ASSERT_TRUE(t.redo());
    EXPECT_EQ(t.text(), "a = (0, 3)\n");
    // After an undo the same id starts a new step.
    t.replaceFromOutside("a = (5, 5)\n", 7);
    t.replaceFromOutside("a = (6, 6)\n", 7);
    ASSERT_TRUE(t.undo());
    EXPECT_EQ(t.text(), "a = (0, 3)\n");
}

TEST(TextModel, NewlineKeepsIndentationAndBackspaceJoinsLines) {
    TextModel t("A -->\n    F [ +A ]");
    t.setCursor({1, 12});
    t.newline();
    t.insert("B");
    EXPECT_EQ(t.text(), "A -->\n    F [ +A ]\n    B");
    t.setCursor({2, 0});
    t.backspace();
    EXPECT_EQ(t.text(), "A -->\n    F [ +A ]    B");
    EXPECT_EQ(t.cursor(), (Pos{1, 12}));
    t.del();
    EXPECT_EQ(t.text(), "A -->\n    F [ +A ]   B");
    // UTF-8: one arrow is one character to the cursor.
    TextModel u("A \xE2\x86\x92 B");
    u.setCursor({0, 5});
    u.left(false);
    EXPECT_EQ(u.cursor(), (Pos{0, 2}));
    u.right(true);
    EXPECT_EQ(u.selectedText(), "\xE2\x86\x92");
    u.backspace();
    EXPECT_EQ(u.text(), "A  B");
}

TEST(TextModel, CommentToggleAndIndentOverTheSelection) {
    TextModel t("n: 3\naxiom: F\nF -> FF\n");
    t.setCursor({1, 0});
    t.setCursor({2, 3}, true);
    t.toggleComment("# ");
    EXPECT_EQ(t.text(), "n: 3\n# axiom: F\n# F -> FF\n");
    t.toggleComment("# ");
    EXPECT_EQ(t.text(), "n: 3\naxiom: F\nF -> FF\n");
    t.indent(false);
    EXPECT_EQ(t.text(), "n: 3\n  axiom: F\n  F -> FF\n");
    t.indent(true);
    EXPECT_EQ(t.text(), "n: 3\naxiom: F\nF -> FF\n");
    TextModel c("A --> B\n  C --> D");
    c.selectAll();
    c.toggleComment("// ");
    EXPECT_EQ(c.text(), "// A --> B\n  // C --> D");
}

TEST(TextModel, FindWrapsAndSelects) {
    TextModel t("axiom: X\nX -> F[+X]\nF -> FF\n");
    ASSERT_TRUE(t.findNext("x ->"));
    EXPECT_EQ(t.selectionStart(), (Pos{1, 0}));
    EXPECT_EQ(t.selectedText(), "X ->");
    ASSERT_TRUE(t.findNext("ff"));
    EXPECT_EQ(t.selectionStart(), (Pos{2, 5}));
    ASSERT_TRUE(t.findNext("axiom"));  // wraps to the top
    EXPECT_EQ(t.selectionStart(), (Pos{0, 0}));
    EXPECT_FALSE(t.findNext("nowhere"));
    EXPECT_EQ(t.posOf(t.offsetOf({1, 4})), (Pos{1, 4}));
}

std::string spans(FileKind kind, std::string_view line, LineState& state) {
    std::vector<Span> out;
    highlightLine(kind, line, state, out);
    static const char* names[] = {"plain", "comment", "setting", "keyword", "module", "bracket", "number",
                                  "parameter", "operator", "arrow", "probability", "string"};
    std::string s;
    for (const Span& sp : out)
        s += std::string(s.empty() ? "" : " ") + names[int(sp.token)] + ":" +
             std::string(line.substr(size_t(sp.begin), size_t(sp.end - sp.begin)));
    return s;
}

std::string spans(FileKind kind, std::string_view line) {
    LineState state;
    return spans(kind, line, state);
}

TEST(Highlight, LsysSettingsRulesConditionsProbabilities) {
    EXPECT_EQ(spans(FileKind::Lsys, "angle: 22.5  # degrees"), "setting:angle: number:22.5 comment:# degrees");
    EXPECT_EQ(spans(FileKind::Lsys, "axiom: F(1) [ +A ]"),
              "setting:axiom: module:F bracket:( number:1 bracket:) bracket:[ module:+ module:A bracket:]");
    EXPECT_EQ(spans(FileKind::Lsys, "B < A(x) : x > 1 -> A(x*2) : 0.5"),
              "module:B operator:< module:A bracket:( parameter:x bracket:) operator:: parameter:x operator:> number:1 "
              "arrow:-> module:A bracket:( parameter:x operator:* number:2 bracket:) probability:: 0.5");
    EXPECT_EQ(spans(FileKind::Lsys, "environment: sphere 0 5 0 R"),
              "setting:environment: parameter:sphere number:0 number:5 number:0 parameter:R");
}

TEST(Highlight, CpfgCommentsOverLinesDefinesAndKeywords) {
    LineState state;
    EXPECT_EQ(spans(FileKind::Cpfg, "#define LEN 2 /* a note", state), "keyword:#define parameter:LEN number:2 comment:/* a note");
    EXPECT_TRUE(state.inBlockComment);
    EXPECT_EQ(spans(FileKind::Cpfg, "   still a note */ A --> B", state), "comment:   still a note */ module:A arrow:--> module:B");
    EXPECT_FALSE(state.inBlockComment);
    EXPECT_EQ(spans(FileKind::Cpfg, "derivation length: 4 // steps", state), "setting:derivation length: number:4 comment:// steps");
    EXPECT_EQ(spans(FileKind::Cpfg, "endlsystem", state), "keyword:endlsystem");
    EXPECT_EQ(spans(FileKind::Cpfg, "A(x) : {y = x+1;} x > 0 --> F(y)", state),
              "module:A bracket:( parameter:x bracket:) operator:: bracket:{ parameter:y operator:= parameter:x operator:+ number:1 "
              "operator:; bracket:} parameter:x operator:> number:0 arrow:--> module:F bracket:( parameter:y bracket:)");
}

// An L-Py model: its L-system lines as the cpfg family's, the rest as Python.
TEST(Highlight, LpyPythonAroundTheLsystem) {
    EXPECT_EQ(spans(FileKind::Lpy, "def grow(x):  # a # comment"),
              "keyword:def parameter:grow bracket:( parameter:x bracket:) operator:: comment:# a # comment");
    EXPECT_EQ(spans(FileKind::Lpy, "name = 'a#b' if x // 2 else None"),
              "parameter:name operator:= string:'a#b' keyword:if parameter:x operator:/ operator:/ number:2 keyword:else keyword:None");
    EXPECT_EQ(spans(FileKind::Lpy, "    nproduce F(l) [ +A ]"),
              "keyword:nproduce module:F bracket:( parameter:l bracket:) bracket:[ module:+ module:A bracket:]");
    EXPECT_EQ(spans(FileKind::Lpy, "Axiom: A(1)"), "setting:Axiom: module:A bracket:( number:1 bracket:)");
    EXPECT_EQ(spans(FileKind::Lpy, "derivation length: N + 1"), "setting:derivation length: parameter:N operator:+ number:1");
    EXPECT_EQ(spans(FileKind::Lpy, "A(x) --> B(x)"), "module:A bracket:( parameter:x bracket:) arrow:--> module:B bracket:( parameter:x bracket:)");
    EXPECT_EQ(spans(FileKind::Lpy, "production:"), "keyword:production operator::");
}

TEST(Highlight, LparserFractintIfsForest) {
    EXPECT_EQ(spans(FileKind::Lparser, "F=F[+F]F"), "module:F arrow:= module:F bracket:[ module:+ module:F bracket:] module:F");
    EXPECT_EQ(spans(FileKind::Lparser, "20 # recursion"), "number:20 comment:# recursion");
    EXPECT_EQ(spans(FileKind::Fractint, "Dragon { ; a curve"), "setting:Dragon bracket:{ comment:; a curve");
    EXPECT_EQ(spans(FileKind::Fractint, "  Angle 8"), "keyword:Angle number:8");
    EXPECT_EQ(spans(FileKind::Fractint, "  Axiom FX"), "keyword:Axiom module:FX");
    EXPECT_EQ(spans(FileKind::Ifs, "0.85 0.04 -0.04 0.85 0 1.6 0.85"),
              "number:0.85 number:0.04 operator:- number:0.04 number:0.85 number:0 number:1.6 number:0.85");
    EXPECT_EQ(spans(FileKind::Forest, "species: tree_4_3 0.5 # half"), "setting:species: parameter:tree_4_3 number:0.5 comment:# half");
}

TEST(Highlight, MatchingBracketsAcrossLines) {
    TextModel t("A --> F [ +(30)\n  B ] C");
    EXPECT_EQ(matchingBracket(t, {0, 8}), (Pos{1, 4}));  // at the [
    EXPECT_EQ(matchingBracket(t, {1, 5}), (Pos{0, 8}));  // just after the ]
    EXPECT_EQ(matchingBracket(t, {0, 11}), (Pos{0, 14}));
    EXPECT_FALSE(matchingBracket(t, {0, 1}));
}

}  // namespace
}  // namespace sprout::viewer::editor
