#include "core/scene/ifs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <thread>

#include "core/base/bounded.hpp"
#include "core/base/rng.hpp"

namespace sprout {

IfsParseResult parseIfs(std::string_view text) {
    IfsParseResult r;
    Ifs ifs;
    std::istringstream in{std::string(text)};
    std::string line;
    int number = 0;
    double total = 0;
    while (std::getline(in, line)) {
        ++number;
        if (size_t h = line.find('#'); h != std::string::npos) {
            // '#' starts a comment unless it is a colour value.
            if (line.find("colour") == std::string::npos && line.find("color") == std::string::npos) line.resize(h);
        }
        std::istringstream words(line);
        std::string first;
        if (!(words >> first)) continue;
        if (first == "points:" || first == "seed:") {
            double v = 0;
            const auto whole = (words >> v) ? wholeIn(v, 1, 1'000'000'000'000) : std::nullopt;
            if (!whole) {
                r.diagnostics.push_back({number, 1, "'" + first + "' needs a whole number from 1 to 1e12", Severity::Error});
                continue;
            }
            (first == "points:" ? ifs.points : ifs.seed) = std::uint64_t(*whole);
            continue;
        }
        if (first == "colour:" || first == "color:") {
            std::string hex;
            words >> hex;
            if (!hex.empty() && hex[0] == '#') hex.erase(0, 1);
            if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
                r.diagnostics.push_back({number, 1, "expected a colour such as 'colour: #2f6e2a'", Severity::Error});
                continue;
            }
            ifs.colour = std::uint32_t(std::stoul(hex, nullptr, 16)) << 8 | 0xFF;
            continue;
        }
        std::istringstream values(line);
        AffineMap m;
        if (!(values >> m.a >> m.b >> m.c >> m.d >> m.e >> m.f >> m.p)) {
            r.diagnostics.push_back({number, 1, "expected a map 'a b c d e f p' (7 numbers)", Severity::Error});
            continue;
        }
        if (!(m.p >= 0)) {
            r.diagnostics.push_back({number, 1, "a probability cannot be negative", Severity::Error});
            continue;
        }
        total += m.p;
        ifs.maps.push_back(m);
    }
    if (ifs.maps.empty() && r.diagnostics.empty())
        r.diagnostics.push_back({1, 1, "no maps: write one per line as 'a b c d e f p'", Severity::Error});
    if (!ifs.maps.empty() && !(total > 0))
        r.diagnostics.push_back({1, 1, "the probabilities add up to 0", Severity::Error});
    if (!hasErrors(r.diagnostics)) r.ifs = std::move(ifs);
    return r;
}

namespace {

// Maps chosen through a 65536-entry table: one 16-bit slice of a random number picks a map
// with its probability (to 1/65536), with no search.
std::vector<std::uint8_t> selectionTable(const Ifs& ifs) {
    double total = 0;
    for (const auto& m : ifs.maps) total += m.p;
    std::vector<std::uint8_t> table(65536);
    double acc = 0;
    size_t k = 0;
    for (size_t i = 0; i < table.size(); ++i) {
        double u = (double(i) + 0.5) / double(table.size());
        while (k + 1 < ifs.maps.size() && u > (acc + ifs.maps[k].p) / total) {
            acc += ifs.maps[k].p;
            ++k;
        }
        table[i] = std::uint8_t(k);
    }
    return table;
}

}  // namespace

bool chaosGame(const Ifs& ifs, int width, int height, Density& out, int threads, const std::atomic<bool>* cancel) {
    out.width = width;
    out.height = height;
    out.counts.assign(std::size_t(width) * std::size_t(height), 0);
    out.points = 0;
    if (ifs.maps.empty() || ifs.maps.size() > 255 || width <= 0 || height <= 0) return true;
    const auto table = selectionTable(ifs);
    const AffineMap* maps = ifs.maps.data();

    // Bounds from a short run, fitted to the image's aspect with a 4% margin.
    {
        Rng rng = Rng::forStream(ifs.seed, 0xB0);
        double x = 0, y = 0, x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
        for (int i = 0; i < 200000; ++i) {
            const AffineMap& m = maps[table[rng.next() >> 48]];
            double nx = m.a * x + m.b * y + m.e, ny = m.c * x + m.d * y + m.f;
            x = nx;
            y = ny;
            if (i > 100) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
        }
        if (!(x1 > x0)) x1 = x0 + 1;
        if (!(y1 > y0)) y1 = y0 + 1;
        double w = (x1 - x0) * 1.08, h = (y1 - y0) * 1.08, cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
        if (w / h < double(width) / height) w = h * width / height;
        else h = w * height / width;
        out.minX = cx - w / 2;
        out.maxX = cx + w / 2;
        out.minY = cy - h / 2;
        out.maxY = cy + h / 2;
    }
    const double sx = width / (out.maxX - out.minX), sy = height / (out.maxY - out.minY);
    threads = std::max(1, threads);
    std::vector<std::vector<std::uint32_t>> partial(std::size_t(threads - 1));
    std::atomic<bool> stopped{false};
    auto work = [&](int t, std::uint32_t* counts) {
        Rng rng = Rng::forStream(ifs.seed, std::uint64_t(t) + 1);
        std::uint64_t n = ifs.points / std::uint64_t(threads) + (std::uint64_t(t) < ifs.points % std::uint64_t(threads));
        double x = 0, y = 0;
        for (int i = 0; i < 20; ++i) {  // settle onto the attractor before counting
            const AffineMap& m = maps[table[rng.next() >> 48]];
            double nx = m.a * x + m.b * y + m.e;
            y = m.c * x + m.d * y + m.f;
            x = nx;
        }
        const double minX = out.minX, maxY = out.maxY;
        const unsigned w = unsigned(width), h = unsigned(height);
        while (n) {
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                stopped = true;
                return;
            }
            std::uint64_t chunk = std::min<std::uint64_t>(n, 1 << 20);
            n -= chunk;
            for (std::uint64_t i = 0; i < chunk; ++i) {
                // One random number serves several steps: 16 bits pick each map.
                std::uint64_t bits = rng.next();
                for (int k = 0; k < 4 && (k == 0 || i + 1 < chunk); ++k, bits >>= 16) {
                    if (k) ++i;
                    const AffineMap& m = maps[table[bits & 0xFFFF]];
                    double nx = m.a * x + m.b * y + m.e;
                    y = m.c * x + m.d * y + m.f;
                    x = nx;
                    // Compared as doubles first: a map that is not contractive sends points to
                    // infinity or NaN, which must be skipped, not converted.
                    const double fx = (x - minX) * sx, fy = (maxY - y) * sy;
                    if (fx >= 0 && fy >= 0 && fx < double(w) && fy < double(h)) ++counts[unsigned(fy) * w + unsigned(fx)];
                }
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) {
        partial[std::size_t(t - 1)].assign(out.counts.size(), 0);
        pool.emplace_back(work, t, partial[std::size_t(t - 1)].data());
    }
    work(0, out.counts.data());
    for (auto& th : pool) th.join();
    for (const auto& p : partial)
        for (std::size_t i = 0; i < p.size(); ++i) out.counts[i] += p[i];
    out.points = ifs.points;
    return !stopped;
}

std::vector<std::uint8_t> toneMap(const Density& d, std::uint32_t colour, std::uint32_t background) {
    std::vector<std::uint8_t> rgba(d.counts.size() * 4);
    std::uint32_t peak = 1;
    for (auto c : d.counts) peak = std::max(peak, c);
    const double scale = 1.0 / std::log1p(double(peak));
    auto channel = [](std::uint32_t c, int shift) { return double((c >> shift) & 0xFF); };
    for (std::size_t i = 0; i < d.counts.size(); ++i) {
        // Log density: single hits show, dense areas do not saturate.
        double v = d.counts[i] ? 0.25 + 0.75 * std::log1p(double(d.counts[i])) * scale : 0.0;
        for (int k = 0; k < 3; ++k) {
            int shift = 24 - 8 * k;
            rgba[i * 4 + std::size_t(k)] =
                std::uint8_t(std::lround(channel(background, shift) + (channel(colour, shift) - channel(background, shift)) * v));
        }
        rgba[i * 4 + 3] = 255;
    }
    return rgba;
}

}  // namespace sprout
