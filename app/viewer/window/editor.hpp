#pragma once
// The grammar editor widget, drawn with Dear ImGui 1.86's draw lists (its InputTextMultiline
// has no colours, line numbers or marks): syntax highlighting for every language Sprout opens,
// line numbers, errors and warnings marked on their lines (a gutter dot and an underline, the
// message on hover), the matching bracket at the cursor, undo/redo (Ctrl+Z / Ctrl+Y, also over
// slider edits), find (Ctrl+F, Enter for the next), comment toggling (Ctrl+/), Tab and
// Shift+Tab indentation, new lines keeping their indentation, clipboard, and completion of
// settings, functions and module names (Tab takes the first). The text model is
// viewer/state/text_model.hpp, the colours viewer/state/highlight.hpp (no window: tested alone).
#include <cstdint>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/viewer/state/highlight.hpp"
#include "app/viewer/state/text_model.hpp"

namespace sprout::viewer::editor {

struct Marker {
    int line = 0, col = 0;  // 1-based, as diagnostics are
    bool error = true;      // else a warning
    std::string message;
};

class Editor {
public:
    // Draws the editor `height` pixels tall across the available width. Returns true when the
    // user changed the text (then text() is the new text).
    bool draw(const char* id, float height, FileKind kind, const std::vector<Marker>& markers,
              const std::vector<std::string>& completions);
    // The text as the rest of the viewer changed it (a slider, a file opened): `newDocument`
    // starts a fresh undo history, otherwise it is one undoable step.
    void sync(const std::string& text, bool newDocument, std::uint64_t gesture = 0);  // gesture: TextModel::replaceFromOutside
    std::string text() const { return m_model.text(); }
    TextModel& model() { return m_model; }
    // Puts the cursor at line:col (1-based) and the keyboard focus in the editor.
    void gotoLineCol(int line, int col);
    int cursorOffset() const { return int(m_model.offsetOf(m_model.cursor())); }
    // A line (1-based; 0 none) shown with a band behind it: the rule that made a picked branch.
    void setBandLine(int line) { m_bandLine = line; }
    bool focused() const { return m_focused; }
    // The colour of each token (0xAABBGGRR, ImGui's order).
    static std::uint32_t colour(Token t);

private:
    void highlightAll(FileKind kind);
    bool handleKeys(FileKind kind, const std::vector<std::string>& completions);
    void drawFindBar();
    void drawCompletions(ImVec2 under);
    std::string wordBeforeCursor() const;

    TextModel m_model;
    std::string m_synced;              // the text last handed to or taken from the viewer
    std::size_t m_highlighted = ~std::size_t(0);  // the model version the spans are for
    FileKind m_kind = FileKind::Lsys;
    std::vector<std::vector<Span>> m_spans;
    bool m_focused = false;
    bool m_scrollToCursor = false;
    bool m_findOpen = false;
    char m_find[128] = "";
    bool m_findFocus = false;
    std::vector<std::string> m_candidates;  // completions of the word at the cursor
    int m_candidate = 0;
    bool m_dragging = false;
    int m_bandLine = 0;
};

}  // namespace sprout::viewer::editor
