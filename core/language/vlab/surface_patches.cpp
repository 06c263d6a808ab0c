// cpfg's surface files as bezieredit reads and writes them (surface_patches.hpp).
#include "core/language/vlab/surface_patches.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/language/vlab/line_reader.hpp"

namespace sprout {
namespace {

using vlab_detail::Word;

// The file's words with their lines, read in order as fscanf reads them.
class Tokens {
public:
    Tokens(std::string_view text, const std::string& file, std::vector<CurveFileDiagnostic>& out) : m_file(file), m_out(out) {
        int line = 1;
        size_t start = 0;
        for (size_t i = 0; i <= text.size(); ++i) {
            if (i == text.size() || text[i] == '\n') {
                std::string_view l = text.substr(start, i - start);
                if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
                for (const Word& w : vlab_detail::words(l)) m_words.push_back({w, line});
                ++line, start = i + 1;
            }
        }
        m_lastLine = line - 1;
    }
    bool done() const { return m_at >= m_words.size(); }
    std::string_view peek() const { return done() ? std::string_view() : m_words[m_at].first.text; }
    bool fail(const std::string& what) {
        CurveFileDiagnostic d;
        d.file = m_file;
        d.line = done() ? m_lastLine : m_words[m_at].second;
        d.col = done() ? 1 : m_words[m_at].first.col;
        d.message = done() ? "the file ends where " + what + " was expected" : "expected " + what + " here, not '" +
                                                                                   std::string(peek().substr(0, 40)) + "'";
        m_out.push_back(std::move(d));
        return false;
    }
    bool expect(std::string_view word) {
        if (peek() != word) return fail("'" + std::string(word) + "'");
        ++m_at;
        return true;
    }
    bool number(float& v, const std::string& what) {
        const auto f = vlab_detail::floatWord(peek());
        if (!f) return fail(what);
        v = *f;
        ++m_at;
        return true;
    }
    bool word(std::string& w, const std::string& what) {
        if (done()) return fail(what);
        w = std::string(peek());
        ++m_at;
        return true;
    }
    bool vector(const char* key1, const char* key2, std::array<float, 3>& v) {
        if (!expect(key1) || (key2 && !expect(key2))) return false;
        for (int k = 0; k < 3; ++k) {
            const char* axis[] = {"X:", "Y:", "Z:"};
            if (!expect(axis[k]) || !number(v[size_t(k)], std::string("the ") + "xyz"[k] + " of " + key1)) return false;
        }
        return true;
    }
    void problem(int line, const std::string& message) {
        m_out.push_back(CurveFileDiagnostic{m_file, line, 1, message, false});
    }
    int line() const { return done() ? m_lastLine : m_words[m_at].second; }

private:
    std::string m_file;
    std::vector<CurveFileDiagnostic>& m_out;
    std::vector<std::pair<Word, int>> m_words;
    size_t m_at = 0;
    int m_lastLine = 0;
};

constexpr size_t kMaxPatches = 65;  // cpfg's limit

bool readPatch(Tokens& in, SurfacePatch& p) {
    if (!in.word(p.name, "a patch's name")) return false;
    if (p.name.size() > 30) return in.fail("a patch name of at most 30 characters (cpfg's limit)");
    if (in.peek() == "TOP") {
        float top = 0, bottom = 0;
        if (!in.expect("TOP") || !in.expect("COLOR:") || !in.number(top, "the top colour") || !in.expect("DIFFUSE:") ||
            !in.number(p.topDiffuse, "the top diffuse") || !in.expect("BOTTOM") || !in.expect("COLOR:") ||
            !in.number(bottom, "the bottom colour") || !in.expect("DIFFUSE:") || !in.number(p.bottomDiffuse, "the bottom diffuse"))
            return false;
        // cpfg reads them with %d: whole numbers (a float beyond them is no colour it keeps)
        p.topColour = unsigned(std::clamp(top, 0.0f, 4095.0f)), p.bottomColour = unsigned(std::clamp(bottom, 0.0f, 4095.0f));
    }
    const char* keys[] = {"AL:", "A:", "AR:", "L:", "R:", "BL:", "B:", "BR:"};
    for (size_t k = 0; k < 8; ++k)
        if (!in.expect(keys[k]) || !in.word(p.neighbours[k], std::string("the name of the patch at ") + keys[k] + " (~ for none)"))
            return false;
    for (size_t k = 0; k < 16; ++k)
        for (size_t c = 0; c < 3; ++c)
            if (!in.number(p.points[k][c], "coordinate " + std::string(1, "xyz"[c]) + " of control point " + std::to_string(k + 1) + " of " + p.name))
                return false;
    return true;
}

// A float in the shortest of `digits` or 9 significant digits that reads back as itself.
std::string num(float v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, double(v));
    if (std::strtof(buf, nullptr) != v) std::snprintf(buf, sizeof buf, "%.9g", double(v));
    return buf;
}

}  // namespace

SurfacePatchesRead readSurfacePatches(std::string_view text, const std::string& fileName) {
    SurfacePatchesRead r;
    Tokens in(text, fileName, r.diagnostics);
    SurfacePatches s;
    float box[6];
    for (float& b : box)
        if (!in.number(b, "the bounding box (six numbers: x, y and z from and to)")) return r;
    if (in.peek() == "PRECISION") {
        float ps = 0, pt = 0;
        if (!in.expect("PRECISION") || !in.expect("S:") || !in.number(ps, "the S precision") || !in.expect("T:") ||
            !in.number(pt, "the T precision"))
            return r;
        s.precision = std::array<int, 2>{int(std::clamp(ps, 0.0f, 100000.0f)), int(std::clamp(pt, 0.0f, 100000.0f))};
    }
    if (!in.vector("CONTACT", "POINT", s.contact) || !in.vector("END", "POINT", s.end) || !in.vector("HEADING", nullptr, s.heading) ||
        !in.vector("UP", nullptr, s.up) || !in.expect("SIZE:") || !in.number(s.size, "the size"))
        return r;
    while (!in.done()) {
        if (s.patches.size() == kMaxPatches) {
            in.fail("the end of the file: cpfg reads at most 65 patches");
            return r;
        }
        SurfacePatch p;
        if (!readPatch(in, p)) return r;
        s.patches.push_back(std::move(p));
    }
    if (s.patches.empty()) {
        in.fail("a patch");
        return r;
    }
    for (const SurfacePatch& p : s.patches)
        for (const std::string& n : p.neighbours)
            if (n != "~" && std::none_of(s.patches.begin(), s.patches.end(), [&](const SurfacePatch& q) { return q.name == n; }))
                in.problem(0, "patch " + p.name + " names a neighbour " + n + " that no patch is (cpfg refuses the surface)");
    r.surface = std::move(s);
    return r;
}

SurfacePatchesRead loadSurfacePatches(const std::filesystem::path& path) {
    return vlab_detail::fromFile<SurfacePatchesRead>(path, [&](const std::string& t) { return readSurfacePatches(t, path.string()); });
}

bool SurfacePatchesRead::ok() const { return surface && vlab_detail::noErrors(diagnostics); }

std::string writeSurfacePatches(const SurfacePatches& s) {
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // bezieredit's box starts at the origin
    for (const SurfacePatch& p : s.patches)
        for (const auto& q : p.points)
            for (size_t c = 0; c < 3; ++c) lo[c] = std::min(lo[c], q[c]), hi[c] = std::max(hi[c], q[c]);
    std::string out = num(lo[0], 6) + " " + num(hi[0], 6) + "\t" + num(lo[1], 6) + " " + num(hi[1], 6) + "\t" + num(lo[2], 6) + " " +
                      num(hi[2], 6) + "\n";
    if (s.precision) out += "PRECISION S: " + std::to_string((*s.precision)[0]) + " T: " + std::to_string((*s.precision)[1]) + "\n";
    auto vec = [&](const char* key, const std::array<float, 3>& v) {
        out += std::string(key) + "X: " + num(v[0], 6) + " Y: " + num(v[1], 6) + " Z: " + num(v[2], 6) + "\n";
    };
    vec("CONTACT POINT  ", s.contact);
    vec("END POINT      ", s.end);
    vec("HEADING        ", s.heading);
    vec("UP             ", s.up);
    out += "SIZE: " + num(s.size, 6) + "\n";
    for (const SurfacePatch& p : s.patches) {
        auto diffuse = [](float v) {  // bezieredit's two digits (0.0, 0.70), more where they would change it
            char buf[64];
            std::snprintf(buf, sizeof buf, "%#.2g", double(v));
            return std::strtof(buf, nullptr) == v ? std::string(buf) : num(v, 9);
        };
        const std::string colour = "TOP COLOR: " + std::to_string(p.topColour) + " DIFFUSE: " + diffuse(p.topDiffuse) +
                                   " BOTTOM COLOR: " + std::to_string(p.bottomColour) + " DIFFUSE: " + diffuse(p.bottomDiffuse) + "\n";
        const auto& n = p.neighbours;
        out += p.name + "\n" + colour + "AL: " + n[0] + " A: " + n[1] + " AR: " + n[2] + "\nL: " + n[3] + " R: " + n[4] + "\nBL: " + n[5] +
               " B: " + n[6] + " BR: " + n[7] + "\n";
        for (size_t row = 0; row < 4; ++row) {
            for (size_t k = row * 4; k < row * 4 + 4; ++k)
                out += num(p.points[k][0], 7) + " " + num(p.points[k][1], 7) + " " + num(p.points[k][2], 7) + "\t";
            out += "\n";
        }
    }
    return out;
}

}  // namespace sprout
