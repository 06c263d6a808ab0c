// clover (VLab's ENVIRO/clover): light on a ground grid shaded by the leaves the plant lays on
// it (the Clover object). ?E(0[, x]) or ?E(q) asks the light where the turtle stands: answered
// light/255 * transmittance^leaves there (and, with two parameters, the image's red/128 as the
// second), after the whole pass; ?E(1, area) lays a leaf disc of that area there, ?E(2, area)
// (any other first value) takes one away, at once. Leaves stay from step to step (unless
// `remove old leaves: on`). Specification: `grid size: NX NY`, `grid position: X Y`, `grid range:
// W H`, `input image: FILE.rgb` (its green channel is the light, red the ratio), `transmittance:
// T` (0.6), `z is up: no` (then x and z are the ground), `verbose`.
#include <cmath>
#include <cstdint>

#include "core/environment/cpfg_programs/spec_file.hpp"

namespace sprout::cpfgprog {
namespace {

constexpr std::int64_t kMaxCells = 64'000'000;

struct Cell {
    unsigned char objects = 0, light = 255, ratio = 0;
};

struct Clover : EnvironmentProgram {
    int size[2] = {512, 512};
    float pos[2] = {-1, -1}, range[2] = {2, 2};
    float table[256];  // transmittance^i
    bool removeOldLeaves = false, zIsUp = true;
    std::vector<Cell> initial;  // the grid as the image makes it
    std::unique_ptr<ProgramRun> start() const override;
};

class CloverRun : public ProgramRun {
public:
    explicit CloverRun(const Clover& p) : m_p(p), m_grid(p.initial) {}
    void pass(std::vector<ProgramQuery>& queries) override {
        if (m_p.removeOldLeaves)
            for (Cell& c : m_grid) c.objects = 0;
        std::vector<std::pair<ProgramQuery*, std::array<float, 2>>> asked;
        for (ProgramQuery& q : queries) {
            if (q.params.empty() || q.position.count < (m_p.zIsUp ? 2 : 3)) continue;
            float p[2] = {q.position.v[0], m_p.zIsUp ? q.position.v[1] : q.position.v[2]};
            if (q.params.size() == 1 || q.params[0] == 0) {
                asked.push_back({&q, {p[0], p[1]}});
                continue;
            }
            const int add = q.params[0] == 1 ? 1 : -1;
            if (q.params[1] < 0.0000001f) continue;
            const float radius = float(std::sqrt(double(q.params[1]) / 3.14159265358979323846));
            int node[2], range[2];
            for (int c = 0; c < 2; ++c) {
                node[c] = toInt(std::floor((p[c] - m_p.pos[c]) / m_p.range[c] * float(m_p.size[c])));
                range[c] = toInt(radius / m_p.range[c] * float(m_p.size[c]) + 1);
            }
            // The disc's cells, only those on the grid visited (a huge leaf stays quick).
            const int y0 = std::max(-range[1], -node[1]), y1 = std::min(range[1], m_p.size[1] - node[1]);
            const int x0 = std::max(-range[0], -node[0]), x1 = std::min(range[0], m_p.size[0] - node[0]);
            // clover.c's int products, in 64 bits: the same numbers where they fit (a disc or a
            // grid over 46,340 cells across overflowed them).
            const auto square = [](int v) { return float(std::int64_t(v) * v); };
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    if (!(square(x) / square(range[0]) + square(y) / square(range[1]) <= 1)) continue;
                    Cell* cell = at(node[0] + x, node[1] + y);
                    if (cell && ((add == 1 && cell->objects < 255) || (add == -1 && cell->objects > 0)))
                        cell->objects = (unsigned char)(cell->objects + add);
                }
        }
        for (auto& [q, p] : asked) {
            int node[2];
            for (int c = 0; c < 2; ++c) node[c] = toInt(std::floor((p[size_t(c)] - m_p.pos[c]) / m_p.range[c] * float(m_p.size[c])));
            const Cell* cell = at(node[0], node[1]);
            const float light = cell ? float(double(float(cell->light)) / 255.0 * double(m_p.table[cell->objects])) : 0.0f;
            if (q->params.size() >= 2)
                q->reply({light, cell ? float(double(float(cell->ratio)) / 128.0) : 0.0f});
            else
                q->reply({light});
        }
    }

private:
    Cell* at(int x, int y) {
        if (x < 0 || x >= m_p.size[0] || y < 0 || y >= m_p.size[1]) return nullptr;
        return &m_grid[size_t(y) * size_t(m_p.size[0]) + size_t(x)];
    }
    const Clover& m_p;
    std::vector<Cell> m_grid;
};

std::unique_ptr<ProgramRun> Clover::start() const { return std::make_unique<CloverRun>(*this); }

// An SGI image (.rgb, as VLab's libs/image reads it): channel `z` of each row, bottom row first.
struct SgiImage {
    int xsize = 0, ysize = 0, zsize = 0;
    std::vector<std::vector<std::uint8_t>> rows;  // [z * ysize + y]
};

bool readSgi(const std::string& bytes, SgiImage& img, std::string& error) {
    auto u8 = [&](size_t at) { return std::uint8_t(bytes[at]); };
    auto u16 = [&](size_t at) { return unsigned(u8(at)) << 8 | u8(at + 1); };
    auto u32 = [&](size_t at) { return std::uint32_t(u16(at)) << 16 | u16(at + 2); };
    if (bytes.size() < 512 || u16(0) != 0x01da) {
        error = "expected an SGI image (.rgb: it begins with the number 474 and a 512-byte header)";
        return false;
    }
    const bool rle = u8(2) == 1;
    if (u8(3) != 1) {
        error = "expected an SGI image of one byte a channel (this one has " + std::to_string(u8(3)) + ")";
        return false;
    }
    img.xsize = int(u16(6));
    img.ysize = int(u16(8));
    img.zsize = u16(4) < 3 ? 1 : int(u16(10));
    if (img.xsize == 0 || img.ysize == 0 || img.zsize == 0) {
        error = "the SGI image has no pixels";
        return false;
    }
    const size_t count = size_t(img.ysize) * size_t(img.zsize);
    img.rows.assign(count, std::vector<std::uint8_t>(size_t(img.xsize), 0));
    for (size_t r = 0; r < count; ++r) {
        std::vector<std::uint8_t>& row = img.rows[r];
        if (!rle) {
            const size_t at = 512 + r * size_t(img.xsize);
            if (at + size_t(img.xsize) > bytes.size()) {
                error = "the SGI image ends before its pixels do (truncated)";
                return false;
            }
            for (size_t x = 0; x < row.size(); ++x) row[x] = u8(at + x);
            continue;
        }
        if (512 + 8 * count > bytes.size()) {
            error = "the SGI image ends inside its table of rows (truncated)";
            return false;
        }
        size_t at = u32(512 + 4 * r), end = at + u32(512 + 4 * count + 4 * r);
        if (end > bytes.size() || end < at) {
            error = "row " + std::to_string(r % size_t(img.ysize) + 1) + " of channel " + std::to_string(r / size_t(img.ysize) + 1) +
                    " of the SGI image lies beyond the file's end (truncated)";
            return false;
        }
        size_t x = 0;
        while (at < end) {
            const std::uint8_t pixel = u8(at++);
            int n = pixel & 0x7f;
            if (!n) break;
            if (pixel & 0x80) {
                while (n-- && at < end && x < row.size()) row[x++] = u8(at++);
            } else if (at < end) {
                const std::uint8_t v = u8(at++);
                while (n-- && x < row.size()) row[x++] = v;
            }
        }
    }
    return true;
}

}  // namespace

std::shared_ptr<EnvironmentProgram> makeClover(const std::string&, const std::string& text, const Sink& sink,
                                               const FileReader& read) {
    auto p = std::make_shared<Clover>();
    const std::vector<std::string> keywords{"grid size", "grid position", "verbose", "transmittance", "input image",
                                            "grid range", "remove old leaves", "z is up"};
    float transmittance = 0.6f;
    std::string image;
    int imageLine = 0, sizeLine = 0;
    for (const SpecLine& line : specLines(text)) {
        const std::vector<Token> x = tokensOf(line, "x,; \t:\n"), t = tokensOf(line, ",; \t:\n");
        auto two = [&](auto& target, const char* what) {
            for (size_t c = 0; c < 2 && c < x.size(); ++c) target[c] = decltype(+target[0])(numberOf(x[c], line, sink, what));
            if (x.size() < 2) sink.warning(line.number, "'" + line.keyword + "': expected two numbers (" + what + "), as 'X Y' or 'XxY'");
        };
        if (line.keyword == "grid size") {
            sizeLine = line.number;
            double v[2] = {double(p->size[0]), double(p->size[1])};
            two(v, "cells");
            for (int c = 0; c < 2; ++c) p->size[c] = toInt(v[c]);
        } else if (line.keyword == "grid position") {
            two(p->pos, "the grid's corner");
        } else if (line.keyword == "grid range") {
            two(p->range, "the grid's width and height");
        } else if (line.keyword == "transmittance") {
            if (!t.empty()) transmittance = float(numberOf(t[0], line, sink, "a number (the light a leaf lets through)"));
            if (transmittance == 0) {
                transmittance = 0.0001f;
                sink.warning(line.number, "'transmittance' cannot be 0 (clover takes 0.0001)");
            }
        } else if (line.keyword == "input image") {
            if (!t.empty()) image = t[0].text, imageLine = line.number;
        } else if (line.keyword == "remove old leaves") {
            if (!t.empty()) p->removeOldLeaves = t[0].text == "on" || t[0].text == "yes";
        } else if (line.keyword == "z is up") {
            if (!t.empty() && (t[0].text == "no" || t[0].text == "off")) p->zIsUp = false;
        } else if (line.keyword != "verbose") {
            unknownKeyword(line, keywords, "clover", sink);
        }
    }
    if (p->size[0] < 2 || p->size[1] < 2 || std::int64_t(p->size[0]) * p->size[1] > kMaxCells) {
        sink.error(sizeLine, "'grid size': expected at least 2 x 2 cells and at most " + std::to_string(kMaxCells) + " in all, not " +
                                 std::to_string(p->size[0]) + " x " + std::to_string(p->size[1]));
        return nullptr;
    }
    p->table[0] = 1.0f;
    for (int i = 1; i <= 255; ++i) p->table[i] = transmittance * p->table[i - 1];
    p->initial.assign(size_t(p->size[0]) * size_t(p->size[1]), Cell{});
    if (image.empty()) {
        sink.warning(0, "no 'input image': clover assumes full light everywhere");
        return p;
    }
    std::string why;
    std::optional<std::string> bytes;
    if (image.size() < 4 || image.compare(image.size() - 4, 4, ".rgb") != 0)
        why = "Sprout's clover reads SGI images (.rgb), not " + image;
    else if (!(bytes = read(image, why)))
        why = why.empty() ? image + " cannot be read" : why;
    SgiImage img;
    if (why.empty() && !readSgi(*bytes, img, why)) why = image + ": " + why;
    if (!why.empty()) {
        sink.warning(imageLine, "'input image': " + why + "; full light is taken everywhere");
        return p;
    }
    const float xratio = float(img.xsize - 1) / float(p->size[0] - 1), yratio = float(img.ysize - 1) / float(p->size[1] - 1);
    const int green = img.zsize > 1 ? 1 : 0;
    for (int y = 0; y < p->size[1]; ++y)
        for (int x = 0; x < p->size[0]; ++x) {
            const size_t row = size_t(std::min(toInt(float(y) * yratio), img.ysize - 1)), col = size_t(std::min(toInt(float(x) * xratio), img.xsize - 1));
            Cell& c = p->initial[size_t(y) * size_t(p->size[0]) + size_t(x)];
            c.light = img.rows[size_t(green * img.ysize) + row][col];
            c.ratio = img.rows[row][col];
        }
    return p;
}

}  // namespace sprout::cpfgprog
