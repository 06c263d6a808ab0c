// An L-Py model's NURBS patches, read and written in its text (lpy_patches.hpp).
#include "app/plant/lpy_patches.hpp"

#include <algorithm>
#include <optional>

#include "app/plant/python_text.hpp"

namespace sprout {
namespace {

using namespace python_text;

// `(x, y, z, w)` at k (k moves past it), or nothing.
std::optional<std::array<double, 4>> point4(std::string_view t, size_t& k) {
    k = skipSpace(t, k);
    if (k >= t.size() || t[k] != '(') return std::nullopt;
    const size_t close = t.find(')', k);
    if (close == std::string_view::npos) return std::nullopt;
    std::array<double, 4> p{0, 0, 0, 1};
    size_t b = k + 1;
    for (int i = 0; i < 4; ++i) {
        size_t comma = i < 3 ? t.find(',', b) : close;
        if (comma == std::string_view::npos || comma > close) return std::nullopt;
        const auto v = number(t.substr(b, comma - b));
        if (!v) return std::nullopt;
        p[size_t(i)] = *v;
        b = comma + 1;
    }
    k = close + 1;
    return p;
}

// `[[(..), ..], [..]]` from `open`: the rows, and where the outer ']' is.
std::optional<std::vector<std::vector<std::array<double, 4>>>> matrix(std::string_view t, size_t open, size_t& close) {
    std::vector<std::vector<std::array<double, 4>>> rows;
    size_t k = open + 1;
    while (true) {
        k = skipSpace(t, k);
        if (k >= t.size()) return std::nullopt;
        if (t[k] == ']') break;
        if (t[k] == ',') {
            ++k;
            continue;
        }
        if (t[k] != '[') return std::nullopt;
        std::vector<std::array<double, 4>> row;
        ++k;
        while (true) {
            k = skipSpace(t, k);
            if (k >= t.size()) return std::nullopt;
            if (t[k] == ']') {
                ++k;
                break;
            }
            if (t[k] == ',') {
                ++k;
                continue;
            }
            auto p = point4(t, k);
            if (!p) return std::nullopt;
            row.push_back(*p);
        }
        if (!rows.empty() && row.size() != rows.front().size()) return std::nullopt;  // a matrix: rows of one length
        rows.push_back(std::move(row));
    }
    close = k;
    return rows;
}

int degreeAfter(std::string_view t, size_t from, size_t callEnd, std::string_view key, int otherwise) {
    for (size_t d = from; (d = t.find(key, d)) != std::string_view::npos && d < callEnd; d += key.size()) {
        size_t v = d + key.size();
        if (!eat(t, v, "=")) continue;
        v = skipSpace(t, v);
        size_t e = v;
        while (e < callEnd && std::isdigit(static_cast<unsigned char>(t[e]))) ++e;
        if (auto n = number(t.substr(v, e - v))) return int(std::clamp(*n, 0.0, 1000.0));  // clamped to the points after
    }
    return otherwise;
}

}  // namespace

std::vector<LpyPatch> lpyPatches(std::string_view text) {
    std::vector<LpyPatch> out;
    for (size_t at = text.find("NurbsPatch"); at != std::string_view::npos; at = text.find("NurbsPatch", at + 10)) {
        // NAME = [pgl.]NurbsPatch(
        size_t k = at + 10;
        if (!eat(text, k, "(")) continue;
        const size_t call = k - 1, callEnd = closing(text, call);
        if (callEnd == std::string_view::npos) continue;
        size_t b = at;
        if (b >= 4 && text.substr(b - 4, 4) == "pgl.") b -= 4;
        while (b > 0 && (text[b - 1] == ' ' || text[b - 1] == '\t')) --b;
        if (b == 0 || text[b - 1] != '=') continue;
        size_t e = b - 1;
        while (e > 0 && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
        size_t n = e;
        while (n > 0 && isIdent(text[n - 1])) --n;
        if (n == e) continue;
        eat(text, k, "pgl.");
        eat(text, k, "Point4Matrix(");
        const size_t open = skipSpace(text, k);
        if (open >= callEnd || text[open] != '[') continue;
        size_t close = 0;
        auto rows = matrix(text, open, close);
        if (!rows || rows->size() < 2 || rows->front().size() < 2) continue;
        LpyPatch p;
        p.name = std::string(text.substr(n, e - n));
        p.rows = std::move(*rows);
        p.begin = open, p.end = close + 1;
        p.line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(n), '\n'));
        p.udegree = std::clamp(degreeAfter(text, close, callEnd, "udegree", 3), 1, int(p.rows.size()) - 1);
        p.vdegree = std::clamp(degreeAfter(text, close, callEnd, "vdegree", 3), 1, int(p.rows.front().size()) - 1);
        out.push_back(std::move(p));
    }
    return out;
}

std::string setLpyPatchPoints(std::string_view text, const LpyPatch& patch, const std::vector<std::vector<std::array<double, 4>>>& rows) {
    std::string m = "[";
    for (size_t r = 0; r < rows.size(); ++r) {
        m += r ? ", [" : "[";
        for (size_t c = 0; c < rows[r].size(); ++c) {
            const auto& p = rows[r][c];
            m += (c ? ", (" : "(") + formatted(p[0]) + ", " + formatted(p[1]) + ", " + formatted(p[2]) + ", " + formatted(p[3]) + ")";
        }
        m += "]";
    }
    m += "]";
    std::string out(text);
    if (patch.begin <= patch.end && patch.end <= out.size()) out.replace(patch.begin, patch.end - patch.begin, m);
    return out;
}

std::optional<std::vector<std::vector<std::array<double, 4>>>> editedPatch(const LpyPatch& patch, PatchEdit edit, size_t k, std::string& error) {
    using Rows = std::vector<std::vector<std::array<double, 4>>>;
    // Columns are rows of the transposed matrix.
    auto transposed = [](const Rows& m) {
        Rows t(m.empty() ? 0 : m.front().size(), std::vector<std::array<double, 4>>(m.size()));
        for (size_t i = 0; i < m.size(); ++i)
            for (size_t j = 0; j < m[i].size() && j < t.size(); ++j) t[j][i] = m[i][j];
        return t;
    };
    const bool columns = edit == PatchEdit::AddColumn || edit == PatchEdit::DeleteColumn;
    Rows m = columns ? transposed(patch.rows) : patch.rows;
    const char* what = columns ? "column" : "row";
    const int degree = columns ? patch.vdegree : patch.udegree;
    if (k >= m.size()) return error = std::string("no ") + what + " " + std::to_string(k), std::nullopt;
    if (edit == PatchEdit::AddRow || edit == PatchEdit::AddColumn) {
        if (m.size() >= 64) return error = std::string("a patch of 64 ") + what + "s takes no more", std::nullopt;
        std::vector<std::array<double, 4>> added(m[k].size());
        for (size_t j = 0; j < added.size(); ++j)
            for (size_t c = 0; c < 4; ++c) {
                const double a = m[k][j][c];
                const double b = k + 1 < m.size() ? m[k + 1][j][c] : 2 * a - m[k - (k > 0 ? 1 : 0)][j][c];
                added[j][c] = c == 3 ? (k + 1 < m.size() ? (a + b) / 2 : a) : (a + b) / 2 + (k + 1 < m.size() ? 0 : (b - a) / 2);
            }
        m.insert(m.begin() + std::ptrdiff_t(k + 1), std::move(added));
    } else {
        if (int(m.size()) - 1 < degree + 1)
            return error = std::string("a patch of degree ") + std::to_string(degree) + " along its " + what + "s keeps at least " +
                           std::to_string(degree + 1) + " of them",
                   std::nullopt;
        m.erase(m.begin() + std::ptrdiff_t(k));
    }
    return columns ? transposed(m) : m;
}

}  // namespace sprout
