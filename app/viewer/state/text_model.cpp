#include "app/viewer/state/text_model.hpp"

#include <algorithm>
#include <cctype>

namespace sprout::viewer::editor {
namespace {

constexpr std::size_t kUndoDepth = 500;

bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || continuation(c) || (c & 0x80); }

}  // namespace

std::string TextModel::text() const {
    std::string out;
    for (size_t i = 0; i < m_lines.size(); ++i) {
        if (i) out += '\n';
        out += m_lines[i];
    }
    return out;
}

void TextModel::setText(std::string_view text) {
    m_lines.clear();
    size_t pos = 0;
    for (;;) {
        const size_t nl = text.find('\n', pos);
        m_lines.emplace_back(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
        if (nl == std::string_view::npos) break;
        pos = nl + 1;
    }
    m_cursor = m_anchor = clamp(m_cursor);
    m_typing = false;
    touched();
}

void TextModel::replaceFromOutside(std::string_view text, std::uint64_t gesture) {
    if (text == this->text()) return;
    if (gesture == 0 || gesture != m_gesture) record();  // (record() ends a gesture)
    m_gesture = gesture;
    const Pos cursor = m_cursor;
    setText(text);
    m_cursor = m_anchor = clamp(cursor);
}

Pos TextModel::clamp(Pos p) const {
    p.line = std::clamp(p.line, 0, int(m_lines.size()) - 1);
    p.col = std::clamp(p.col, 0, int(m_lines[size_t(p.line)].size()));
    while (p.col > 0 && p.col < int(m_lines[size_t(p.line)].size()) && continuation(m_lines[size_t(p.line)][size_t(p.col)])) --p.col;
    return p;
}

std::string TextModel::selectedText() const {
    const Pos a = selectionStart(), b = selectionEnd();
    const std::string all = text();
    return all.substr(offsetOf(a), offsetOf(b) - offsetOf(a));
}

void TextModel::setCursor(Pos p, bool select) {
    m_cursor = clamp(p);
    if (!select) m_anchor = m_cursor;
    m_typing = false;
    m_wantCol = -1;
}

void TextModel::selectAll() {
    m_anchor = {0, 0};
    m_cursor = {int(m_lines.size()) - 1, int(m_lines.back().size())};
    m_typing = false;
}

std::size_t TextModel::offsetOf(Pos p) const {
    p = clamp(p);
    std::size_t off = 0;
    for (int i = 0; i < p.line; ++i) off += m_lines[size_t(i)].size() + 1;
    return off + size_t(p.col);
}

Pos TextModel::posOf(std::size_t offset) const {
    Pos p;
    for (; p.line < int(m_lines.size()) - 1 && offset > m_lines[size_t(p.line)].size(); ++p.line) offset -= m_lines[size_t(p.line)].size() + 1;
    p.col = int(std::min(offset, m_lines[size_t(p.line)].size()));
    return clamp(p);
}

void TextModel::record(bool typing) {
    m_redo.clear();
    m_gesture = 0;
    if (typing && m_typing) return;  // typing runs together into one step
    m_undo.push_back({text(), m_cursor, m_anchor});
    if (m_undo.size() > kUndoDepth) m_undo.erase(m_undo.begin());
    m_typing = typing;
}

void TextModel::eraseSelection() {
    if (!hasSelection()) return;
    const Pos a = selectionStart(), b = selectionEnd();
    std::string& first = m_lines[size_t(a.line)];
    first = first.substr(0, size_t(a.col)) + m_lines[size_t(b.line)].substr(size_t(b.col));
    m_lines.erase(m_lines.begin() + a.line + 1, m_lines.begin() + b.line + 1);
    m_cursor = m_anchor = a;
}

void TextModel::insert(std::string_view s) {
    if (s.empty()) return;
    const bool typing = s.size() == 1 && s[0] != '\n' && !hasSelection();
    record(typing);
    eraseSelection();
    std::string& cur = m_lines[size_t(m_cursor.line)];
    const std::string tail = cur.substr(size_t(m_cursor.col));
    cur.resize(size_t(m_cursor.col));
    size_t pos = 0;
    int line = m_cursor.line;
    for (;;) {
        const size_t nl = s.find('\n', pos);
        std::string_view piece = s.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
        if (!piece.empty() && piece.back() == '\r') piece.remove_suffix(1);
        m_lines[size_t(line)] += piece;
        if (nl == std::string_view::npos) break;
        m_lines.insert(m_lines.begin() + line + 1, std::string());
        ++line;
        pos = nl + 1;
    }
    m_cursor = m_anchor = {line, int(m_lines[size_t(line)].size())};
    m_lines[size_t(line)] += tail;
    m_wantCol = -1;
    touched();
}

void TextModel::newline() {
    const std::string& cur = m_lines[size_t(selectionStart().line)];
    const size_t indent = std::min(cur.find_first_not_of(" \t") == std::string::npos ? cur.size() : cur.find_first_not_of(" \t"),
                                   size_t(selectionStart().col));
    insert("\n" + cur.substr(0, indent));  // one undo step, the selection replaced
    m_typing = false;
}

void TextModel::backspace() {
    if (!hasSelection()) {
        if (m_cursor == Pos{0, 0}) return;
        Pos before = m_cursor;
        if (before.col > 0) {
            --before.col;
            while (before.col > 0 && continuation(m_lines[size_t(before.line)][size_t(before.col)])) --before.col;
        } else {
            --before.line;
            before.col = int(m_lines[size_t(before.line)].size());
        }
        m_anchor = before;
    }
    record();
    eraseSelection();
    m_wantCol = -1;
    touched();
}

void TextModel::del() {
    if (!hasSelection()) {
        Pos after = m_cursor;
        if (after.col < int(m_lines[size_t(after.line)].size())) {
            ++after.col;
            while (after.col < int(m_lines[size_t(after.line)].size()) && continuation(m_lines[size_t(after.line)][size_t(after.col)])) ++after.col;
        } else if (after.line + 1 < int(m_lines.size())) {
            ++after.line;
            after.col = 0;
        } else {
            return;
        }
        m_anchor = after;
    }
    record();
    eraseSelection();
    touched();
}

void TextModel::indent(bool outdent) {
    if (!hasSelection() && !outdent) {
        insert("  ");
        return;
    }
    record();
    const int a = selectionStart().line, b = selectionEnd().line - (selectionEnd().col == 0 && selectionEnd().line > a ? 1 : 0);
    for (int i = a; i <= b; ++i) {
        std::string& l = m_lines[size_t(i)];
        if (outdent) l.erase(0, std::min<size_t>(l.find_first_not_of(' ') == std::string::npos ? l.size() : l.find_first_not_of(' '), 2));
        else l.insert(0, "  ");
    }
    m_cursor = clamp(m_cursor);
    m_anchor = clamp(m_anchor);
    touched();
}

void TextModel::toggleComment(std::string_view prefix) {
    record();
    const int a = selectionStart().line, b = selectionEnd().line - (selectionEnd().col == 0 && selectionEnd().line > a ? 1 : 0);
    std::string_view bare = prefix;
    while (!bare.empty() && bare.back() == ' ') bare.remove_suffix(1);
    // Uncomment when every non-blank line is commented; else comment them all.
    bool all = true;
    for (int i = a; i <= b; ++i) {
        const std::string& l = m_lines[size_t(i)];
        const size_t first = l.find_first_not_of(" \t");
        if (first != std::string::npos && l.compare(first, bare.size(), bare) != 0) all = false;
    }
    for (int i = a; i <= b; ++i) {
        std::string& l = m_lines[size_t(i)];
        const size_t first = l.find_first_not_of(" \t");
        if (first == std::string::npos) continue;
        if (all) l.erase(first, l.compare(first, prefix.size(), prefix) == 0 ? prefix.size() : bare.size());
        else l.insert(first, prefix);
    }
    m_cursor = clamp(m_cursor);
    m_anchor = clamp(m_anchor);
    touched();
}

void TextModel::left(bool select, bool word) {
    Pos p = m_cursor;
    if (hasSelection() && !select) p = selectionStart();
    else if (p.col > 0) {
        const std::string& l = m_lines[size_t(p.line)];
        --p.col;
        while (p.col > 0 && continuation(l[size_t(p.col)])) --p.col;
        if (word) {
            while (p.col > 0 && !wordChar(l[size_t(p.col)])) --p.col;
            while (p.col > 0 && wordChar(l[size_t(p.col - 1)])) --p.col;
        }
    } else if (p.line > 0) {
        --p.line;
        p.col = int(m_lines[size_t(p.line)].size());
    }
    setCursor(p, select);
}

void TextModel::right(bool select, bool word) {
    Pos p = m_cursor;
    if (hasSelection() && !select) p = selectionEnd();
    else if (p.col < int(m_lines[size_t(p.line)].size())) {
        const std::string& l = m_lines[size_t(p.line)];
        ++p.col;
        while (p.col < int(l.size()) && continuation(l[size_t(p.col)])) ++p.col;
        if (word) {
            while (p.col < int(l.size()) && wordChar(l[size_t(p.col)])) ++p.col;
            while (p.col < int(l.size()) && !wordChar(l[size_t(p.col)])) ++p.col;
        }
    } else if (p.line + 1 < int(m_lines.size())) {
        ++p.line;
        p.col = 0;
    }
    setCursor(p, select);
}

void TextModel::up(bool select, int lines) {
    const int want = m_wantCol >= 0 ? m_wantCol : m_cursor.col;
    setCursor({m_cursor.line - lines, want}, select);
    m_wantCol = want;
}

void TextModel::down(bool select, int lines) {
    const int want = m_wantCol >= 0 ? m_wantCol : m_cursor.col;
    setCursor({m_cursor.line + lines, want}, select);
    m_wantCol = want;
}

void TextModel::home(bool select) {
    const std::string& l = m_lines[size_t(m_cursor.line)];
    const int first = int(l.find_first_not_of(" \t") == std::string::npos ? l.size() : l.find_first_not_of(" \t"));
    setCursor({m_cursor.line, m_cursor.col == first ? 0 : first}, select);
}

void TextModel::end(bool select) { setCursor({m_cursor.line, int(m_lines[size_t(m_cursor.line)].size())}, select); }

bool TextModel::findNext(std::string_view query, bool caseSensitive) {
    if (query.empty()) return false;
    std::string all = text(), q(query);
    if (!caseSensitive) {
        for (char& c : all) c = char(std::tolower(static_cast<unsigned char>(c)));
        for (char& c : q) c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    const size_t from = offsetOf(selectionEnd());
    size_t at = all.find(q, from);
    if (at == std::string::npos) at = all.find(q);
    if (at == std::string::npos) return false;
    m_anchor = posOf(at);
    m_cursor = posOf(at + q.size());
    m_typing = false;
    return true;
}

// Undo and redo: the state on top of one history comes back, the present goes on the other.
bool TextModel::travel(std::vector<Snapshot>& from, std::vector<Snapshot>& to) {
    if (from.empty()) return false;
    to.push_back({text(), m_cursor, m_anchor});
    Snapshot s = std::move(from.back());
    from.pop_back();
    setText(s.text);
    m_cursor = clamp(s.cursor);
    m_anchor = clamp(s.anchor);
    m_typing = false;
    m_gesture = 0;
    return true;
}

bool TextModel::undo() { return travel(m_undo, m_redo); }
bool TextModel::redo() { return travel(m_redo, m_undo); }

}  // namespace sprout::viewer::editor
