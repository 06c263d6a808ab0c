#include "app/viewer/window/editor.hpp"
#include "app/plant/text_edit.hpp"

#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#include "core/base/bounded.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace sprout::viewer::editor {
namespace {

float xOf(const std::string& line, int col) {
    return col <= 0 ? 0.0f : ImGui::CalcTextSize(line.data(), line.data() + std::min<size_t>(size_t(col), line.size())).x;
}

// The byte column nearest to x in a line.
int colAt(const std::string& line, float x) {
    int col = 0;
    while (col < int(line.size())) {
        int next = col + 1;
        while (next < int(line.size()) && (static_cast<unsigned char>(line[size_t(next)]) & 0xC0) == 0x80) ++next;
        const float mid = (xOf(line, col) + xOf(line, next)) * 0.5f;
        if (x < mid) break;
        col = next;
    }
    return col;
}


}  // namespace

std::uint32_t Editor::colour(Token t) {
    switch (t) {
        case Token::Plain: return IM_COL32(220, 220, 220, 255);
        case Token::Comment: return IM_COL32(120, 150, 120, 255);
        case Token::Setting: return IM_COL32(120, 180, 255, 255);
        case Token::Keyword: return IM_COL32(200, 140, 255, 255);
        case Token::Module: return IM_COL32(150, 225, 120, 255);
        case Token::Bracket: return IM_COL32(255, 170, 90, 255);
        case Token::Number: return IM_COL32(130, 230, 200, 255);
        case Token::Parameter: return IM_COL32(170, 210, 255, 255);
        case Token::Operator: return IM_COL32(200, 200, 200, 255);
        case Token::Arrow: return IM_COL32(255, 120, 120, 255);
        case Token::Probability: return IM_COL32(255, 200, 120, 255);
        case Token::String: return IM_COL32(230, 205, 150, 255);
    }
    return IM_COL32_WHITE;
}

void Editor::sync(const std::string& text, bool newDocument, std::uint64_t gesture) {
    if (text == m_synced && !newDocument) return;
    if (newDocument) m_model = TextModel(text);
    else if (text != m_model.text()) m_model.replaceFromOutside(text, gesture);
    m_synced = text;
}

void Editor::gotoLineCol(int line, int col) {
    m_model.setCursor({line - 1, col - 1});
    m_focused = true;
    m_scrollToCursor = true;
}

void Editor::highlightAll(FileKind kind) {
    m_kind = kind;
    m_highlighted = m_model.version();
    m_spans.assign(size_t(m_model.lineCount()), {});
    LineState state;
    for (int i = 0; i < m_model.lineCount(); ++i) highlightLine(kind, m_model.line(i), state, m_spans[size_t(i)]);
}

std::string Editor::wordBeforeCursor() const {
    const Pos c = m_model.cursor();
    const std::string& l = m_model.line(c.line);
    int b = c.col;
    while (b > 0 && (std::isalnum(static_cast<unsigned char>(l[size_t(b - 1)])) || l[size_t(b - 1)] == '_')) --b;
    return l.substr(size_t(b), size_t(c.col - b));
}

bool Editor::handleKeys(FileKind kind, const std::vector<std::string>& completions) {
    ImGuiIO& io = ImGui::GetIO();
    const std::size_t before = m_model.version();
    const bool shift = io.KeyShift, ctrl = io.KeyCtrl;
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key); };
    const std::string comment = kind == FileKind::Cpfg ? "// " : kind == FileKind::Fractint ? "; " : "# ";
    bool typed = false;
    if (ctrl) {
        if (pressed(GLFW_KEY_Z)) shift ? m_model.redo() : m_model.undo();
        if (pressed(GLFW_KEY_Y)) m_model.redo();
        if (pressed(GLFW_KEY_A)) m_model.selectAll();
        if (pressed(GLFW_KEY_C) || pressed(GLFW_KEY_X)) {
            if (m_model.hasSelection()) ImGui::SetClipboardText(m_model.selectedText().c_str());
            if (pressed(GLFW_KEY_X)) m_model.backspace();
        }
        if (pressed(GLFW_KEY_V))
            if (const char* clip = ImGui::GetClipboardText()) m_model.insert(clip);
        if (pressed(GLFW_KEY_SLASH)) m_model.toggleComment(comment);
        if (pressed(GLFW_KEY_F)) m_findOpen = true, m_findFocus = true;
        if (pressed(GLFW_KEY_LEFT)) m_model.left(shift, true);
        if (pressed(GLFW_KEY_RIGHT)) m_model.right(shift, true);
        if (pressed(GLFW_KEY_HOME)) m_model.setCursor({0, 0}, shift);
        if (pressed(GLFW_KEY_END)) m_model.setCursor({m_model.lineCount() - 1, 1 << 30}, shift);
    } else {
        for (ImWchar c : io.InputQueueCharacters) {
            if (c < 32 || c == 127) continue;
            char utf8[5] = {};
            ImTextCharToUtf8(utf8, c);
            m_model.insert(utf8);
            typed = true;
        }
        const bool popup = !m_candidates.empty();
        if (pressed(GLFW_KEY_TAB)) {
            if (popup) {  // take the completion
                const std::string word = wordBeforeCursor();
                m_model.insert(m_candidates[size_t(m_candidate)].substr(word.size()));
                m_candidates.clear();
            } else {
                m_model.indent(shift);
            }
        }
        if (pressed(GLFW_KEY_ESCAPE)) m_candidates.clear(), m_findOpen = false;
        if (pressed(GLFW_KEY_ENTER) || pressed(GLFW_KEY_KP_ENTER)) m_model.newline(), m_candidates.clear();
        if (pressed(GLFW_KEY_BACKSPACE)) m_model.backspace();
        if (pressed(GLFW_KEY_DELETE)) m_model.del();
        if (pressed(GLFW_KEY_LEFT)) m_model.left(shift), m_candidates.clear();
        if (pressed(GLFW_KEY_RIGHT)) m_model.right(shift), m_candidates.clear();
        if (pressed(GLFW_KEY_UP)) popup ? void(m_candidate = std::max(0, m_candidate - 1)) : m_model.up(shift);
        if (pressed(GLFW_KEY_DOWN)) popup ? void(m_candidate = std::min(int(m_candidates.size()) - 1, m_candidate + 1)) : m_model.down(shift);
        if (pressed(GLFW_KEY_PAGE_UP)) m_model.up(shift, 20);
        if (pressed(GLFW_KEY_PAGE_DOWN)) m_model.down(shift, 20);
        if (pressed(GLFW_KEY_HOME)) m_model.home(shift);
        if (pressed(GLFW_KEY_END)) m_model.end(shift);
    }
    if (typed) {  // completions of the word being typed
        const std::string word = wordBeforeCursor();
        m_candidates.clear();
        m_candidate = 0;
        if (word.size() >= 2)
            for (const std::string& c : completions)
                if (c.size() > word.size() && startsWithNoCase(c, word) && m_candidates.size() < 8) m_candidates.push_back(c);
    }
    const bool moved = m_model.version() != before;
    if (moved || typed) m_scrollToCursor = true;
    return moved;
}

// The find bar over the text: Enter or "next" finds the next match.
void Editor::drawFindBar() {
    ImGui::SetNextItemWidth(160);
    if (m_findFocus) ImGui::SetKeyboardFocusHere(), m_findFocus = false;
    const bool enter = ImGui::InputText("##find", m_find, sizeof m_find, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("next") || enter) {
        if (m_model.findNext(m_find)) m_scrollToCursor = true;
        if (enter) ImGui::SetKeyboardFocusHere(-1);  // Enter again finds the next
    }
    ImGui::SameLine();
    if (ImGui::Button("x")) m_findOpen = false;
}

// The completions of the word at the cursor, under it.
void Editor::drawCompletions(ImVec2 under) {
    ImGui::SetNextWindowPos(under);
    ImGui::BeginTooltip();
    for (size_t k = 0; k < m_candidates.size(); ++k)
        ImGui::TextColored(int(k) == m_candidate ? ImVec4(1, 0.85f, 0.4f, 1) : ImVec4(0.8f, 0.8f, 0.8f, 1), "%s", m_candidates[k].c_str());
    ImGui::TextDisabled("Tab: take it");
    ImGui::EndTooltip();
}

bool Editor::draw(const char* id, float height, FileKind kind, const std::vector<Marker>& markers,
                  const std::vector<std::string>& completions) {
    ImGui::PushID(id);
    bool changed = false;
    if (m_findOpen) drawFindBar();
    if (m_highlighted != m_model.version() || kind != m_kind) highlightAll(kind);
    const float lineH = ImGui::GetTextLineHeight();
    const float charW = ImGui::CalcTextSize("0").x;
    const int digits = int(std::log10(std::max(1, m_model.lineCount()))) + 1;
    const float gutter = charW * float(digits) + 14;
    ImGui::BeginChild("##text", ImVec2(-1, height), true, ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_NoMove);
    ImGuiIO& io = ImGui::GetIO();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();  // top-left of line 0 (scrolled)
    const float textX = origin.x + gutter;
    // Content size: the longest line and every line.
    float widest = 0;
    for (int i = 0; i < m_model.lineCount(); ++i) widest = std::max(widest, float(m_model.line(i).size()) * charW);
    ImGui::Dummy(ImVec2(gutter + widest + 40, lineH * float(m_model.lineCount()) + lineH));
    const bool hovered = ImGui::IsWindowHovered();
    // Mouse: click to place the cursor, drag or shift-click to select.
    auto posAtMouse = [&] {
        Pos p;
        // No mouse is -FLT_MAX in ImGui: saturated before the clamp.
        p.line = std::clamp(saturate<int>((io.MousePos.y - origin.y) / lineH), 0, m_model.lineCount() - 1);
        p.col = colAt(m_model.line(p.line), io.MousePos.x - textX);
        return p;
    };
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        m_model.setCursor(posAtMouse(), io.KeyShift);
        m_focused = true;
        m_dragging = true;
        m_candidates.clear();
    } else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !hovered && !(m_findOpen && ImGui::IsAnyItemActive())) {
        m_focused = false;  // a click elsewhere
        m_candidates.clear();
    }
    if (m_dragging && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) m_model.setCursor(posAtMouse(), true);
    } else {
        m_dragging = false;
    }
    if (m_focused && !ImGui::IsAnyItemActive()) {
        changed = handleKeys(kind, completions);
        ImGui::CaptureKeyboardFromApp(true);
        ImGui::GetCurrentContext()->WantTextInputNextFrame = 1;  // the window's shortcuts stay quiet
        if (changed && m_highlighted != m_model.version()) highlightAll(kind);
    }
    // Visible lines.
    const float scrollY = ImGui::GetScrollY();
    const int firstLine = std::max(0, int(scrollY / lineH) - 1);
    const int lastLine = std::min(m_model.lineCount() - 1, int((scrollY + height) / lineH) + 1);
    const Pos selA = m_model.selectionStart(), selB = m_model.selectionEnd();
    const std::optional<Pos> match = m_focused ? matchingBracket(m_model, m_model.cursor()) : std::nullopt;
    for (int i = firstLine; i <= lastLine; ++i) {
        const std::string& line = m_model.line(i);
        const float y = origin.y + float(i) * lineH;
        // Gutter: the line number, dim; red or yellow when the line has a message.
        const Marker* mark = nullptr;
        for (const Marker& m : markers)
            if (m.line == i + 1 && (!mark || (m.error && !mark->error))) mark = &m;
        std::string number = std::to_string(i + 1);
        number.insert(0, size_t(std::max(0, digits - int(number.size()))), ' ');
        dl->AddText(ImVec2(origin.x, y), mark ? (mark->error ? IM_COL32(255, 110, 100, 255) : IM_COL32(255, 200, 90, 255))
                                              : IM_COL32(110, 110, 120, 255),
                    number.c_str());
        if (mark) dl->AddCircleFilled(ImVec2(origin.x + gutter - 6, y + lineH * 0.5f), 3, mark->error ? IM_COL32(255, 80, 70, 255) : IM_COL32(255, 190, 60, 255));
        if (i + 1 == m_bandLine)  // the rule of a picked branch
            dl->AddRectFilled(ImVec2(textX - 2, y), ImVec2(textX + std::max(widest, ImGui::GetWindowWidth()), y + lineH),
                              IM_COL32(120, 90, 30, 150));
        // Selection.
        if (selA != selB && i >= selA.line && i <= selB.line) {
            const float x0 = textX + (i == selA.line ? xOf(line, selA.col) : 0);
            const float x1 = textX + (i == selB.line ? xOf(line, selB.col) : xOf(line, int(line.size())) + charW * 0.5f);
            dl->AddRectFilled(ImVec2(x0, y), ImVec2(x1, y + lineH), IM_COL32(70, 100, 160, 200));
        }
        // Text, a span at a time.
        int at = 0;
        // A span that ends inside a UTF-8 character (the highlighter reads bytes: δ, →, p₁)
        // ends after it, and the next one starts there: each character is drawn whole.
        auto whole = [&](int p) {
            while (p > 0 && p < int(line.size()) && (static_cast<unsigned char>(line[size_t(p)]) & 0xC0) == 0x80) ++p;
            return p;
        };
        auto text = [&](int b, int e, std::uint32_t col) {
            b = whole(b);
            e = whole(e);
            if (e > b) dl->AddText(ImVec2(textX + xOf(line, b), y), col, line.data() + b, line.data() + e);
        };
        if (size_t(i) < m_spans.size())
            for (const Span& s : m_spans[size_t(i)]) {
                text(at, s.begin, colour(Token::Plain));
                text(s.begin, s.end, colour(s.token));
                at = s.end;
            }
        text(at, int(line.size()), colour(Token::Plain));
        // Matching brackets.
        if (match)
            for (Pos p : {*match, m_model.cursor().col > 0 && matchingBracket(m_model, *match) ? *matchingBracket(m_model, *match) : *match})
                if (p.line == i)
                    dl->AddRect(ImVec2(textX + xOf(line, p.col) - 1, y), ImVec2(textX + xOf(line, p.col + 1) + 1, y + lineH),
                                IM_COL32(255, 220, 120, 220));
        // Messages: underlined from their column to the end of the word there; the message on hover.
        for (const Marker& m : markers) {
            if (m.line != i + 1) continue;
            const int c0 = std::clamp(m.col - 1, 0, int(line.size()));
            int c1 = c0;
            while (c1 < int(line.size()) && line[size_t(c1)] != ' ') ++c1;
            if (c1 == c0) c1 = std::min(int(line.size()), c0 + 1);
            const float x0 = textX + xOf(line, c0), x1 = std::max(x0 + charW, textX + xOf(line, c1));
            const std::uint32_t col = m.error ? IM_COL32(255, 80, 70, 255) : IM_COL32(255, 190, 60, 255);
            for (float x = x0; x < x1; x += 4)  // a wavy underline
                dl->AddLine(ImVec2(x, y + lineH - 1), ImVec2(std::min(x + 2, x1), y + lineH + 1), col);
            const bool overWord = io.MousePos.x >= x0 && io.MousePos.x <= x1 && io.MousePos.y >= y && io.MousePos.y < y + lineH + 2;
            const bool overGutter = io.MousePos.x >= origin.x && io.MousePos.x < textX && io.MousePos.y >= y && io.MousePos.y < y + lineH;
            if (hovered && (overWord || overGutter)) ImGui::SetTooltip("%s%s", m.error ? "" : "warning: ", m.message.c_str());
        }
    }
    // The cursor, blinking while focused; the view follows it.
    const Pos c = m_model.cursor();
    const float cx = textX + xOf(m_model.line(c.line), c.col), cy = origin.y + float(c.line) * lineH;
    if (m_focused && std::fmod(ImGui::GetTime(), 1.0) < 0.6) dl->AddLine(ImVec2(cx, cy), ImVec2(cx, cy + lineH), IM_COL32(255, 255, 255, 255), 1.5f);
    if (m_scrollToCursor) {
        m_scrollToCursor = false;
        const float top = float(c.line) * lineH;
        if (top < scrollY) ImGui::SetScrollY(top);
        else if (top + lineH * 2 > scrollY + height) ImGui::SetScrollY(top + lineH * 2 - height);
        const float left = cx - textX, viewW = ImGui::GetWindowWidth() - gutter - 20;
        if (left < ImGui::GetScrollX()) ImGui::SetScrollX(left);
        else if (left > ImGui::GetScrollX() + viewW) ImGui::SetScrollX(left - viewW);
    }
    if (m_focused && !m_candidates.empty()) drawCompletions(ImVec2(cx, cy + lineH));
    ImGui::EndChild();
    ImGui::PopID();
    if (changed) m_synced = m_model.text();
    return changed;
}

}  // namespace sprout::viewer::editor
