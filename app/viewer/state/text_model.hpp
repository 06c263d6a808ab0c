#pragma once
// The grammar editor's text model (no ImGui): lines, a cursor and a selection, edits that
// keep the indentation, comment toggling, search, and undo/redo that also covers changes made
// from outside (a slider writing a value into the text). The widget (editor.hpp) draws it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sprout::viewer::editor {

struct Pos {
    int line = 0;  // 0-based
    int col = 0;   // byte offset in the line
    bool operator==(const Pos& o) const { return line == o.line && col == o.col; }
    bool operator!=(const Pos& o) const { return !(*this == o); }
    bool operator<(const Pos& o) const { return line < o.line || (line == o.line && col < o.col); }
};

class TextModel {
public:
    TextModel() : m_lines(1) {}
    explicit TextModel(std::string_view text) { setText(text); }

    // The whole text, lines joined by '\n'.
    std::string text() const;
    // Replaces the text without an undo step (a file opened).
    void setText(std::string_view text);
    // Replaces the text as an edit from outside the editor (a slider): one undo step; the
    // cursor stays on its line. Changes of one gesture (a drag: the same non-zero id, nothing
    // between them) are one step together.
    void replaceFromOutside(std::string_view text, std::uint64_t gesture = 0);

    int lineCount() const { return int(m_lines.size()); }
    const std::string& line(int i) const { return m_lines[size_t(i)]; }
    std::size_t version() const { return m_version; }  // changes with every edit

    Pos cursor() const { return m_cursor; }
    Pos anchor() const { return m_anchor; }
    bool hasSelection() const { return m_cursor != m_anchor; }
    Pos selectionStart() const { return m_cursor < m_anchor ? m_cursor : m_anchor; }
    Pos selectionEnd() const { return m_cursor < m_anchor ? m_anchor : m_cursor; }
    std::string selectedText() const;
    // Moves the cursor (clamped); `select` keeps the anchor where it was.
    void setCursor(Pos p, bool select = false);
    void selectAll();
    // Byte offset in text() of a position, and back.
    std::size_t offsetOf(Pos p) const;
    Pos posOf(std::size_t offset) const;

    // Editing: each is one undo step, except that typed characters run together into one.
    void insert(std::string_view s);
    void newline();    // keeps the current line's indentation
    void backspace();  // the selection, or the character before the cursor
    void del();        // the selection, or the character after the cursor
    void indent(bool outdent);  // Tab / Shift+Tab: the selected lines, or spaces at the cursor
    // Comments or uncomments the selected lines (or the cursor's) with `prefix` ("# ", "// ").
    void toggleComment(std::string_view prefix);

    // Cursor movement; `select` extends the selection.
    void left(bool select, bool word = false);
    void right(bool select, bool word = false);
    void up(bool select, int lines = 1);
    void down(bool select, int lines = 1);
    void home(bool select);  // first non-blank, then column 0
    void end(bool select);

    // The next occurrence of `query` after the cursor (wrapping), selected; false when none.
    bool findNext(std::string_view query, bool caseSensitive = false);

    bool undo();
    bool redo();
    bool canUndo() const { return !m_undo.empty(); }
    bool canRedo() const { return !m_redo.empty(); }

private:
    struct Snapshot {
        std::string text;
        Pos cursor, anchor;
    };
    void record(bool typing = false);  // before an edit: the state to come back to
    bool travel(std::vector<Snapshot>& from, std::vector<Snapshot>& to);
    void eraseSelection();
    void touched() { ++m_version; }
    Pos clamp(Pos p) const;

    std::vector<std::string> m_lines;
    Pos m_cursor, m_anchor;
    std::vector<Snapshot> m_undo, m_redo;
    bool m_typing = false;
    std::uint64_t m_gesture = 0;  // the gesture of the last change from outside: more of it joins its step  // the last edit was typing: more typing joins its undo step
    std::size_t m_version = 0;
    int m_wantCol = -1;     // the column up/down keep to
};

}  // namespace sprout::viewer::editor
