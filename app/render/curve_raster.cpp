#include "app/render/curve_raster.hpp"
#include "core/base/bounded.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sprout::render {

namespace {

// Four samples per pixel, where a 4x multisampled framebuffer takes them (the standard
// pattern): a pixel's coverage is the share of its samples inside some segment, the union of
// all of them, as the ribbons drawn with 4x MSAA give. (Blending per-pixel coverages by their
// maximum left the inside of a dense curve speckled: two strokes a pixel apart each cover a
// pixel between them by 75%, together by all of it.)
constexpr float kSample[4][2] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};

// One segment, extended by half a width at each end as the ribbons are: the samples within
// half a width of it.
void stamp(glm::vec2 a, glm::vec2 b, float half, int w, int h, std::uint8_t* mask) {
    glm::vec2 d = b - a;
    const float len = std::sqrt(d.x * d.x + d.y * d.y);
    const glm::vec2 dir = len > 1e-6f ? d / len : glm::vec2(1, 0);
    a -= dir * half;
    b += dir * half;
    d = b - a;
    const float len2 = d.x * d.x + d.y * d.y, half2 = half * half;
    // Saturated before the image's clamp: a segment far off screen (a deep zoom) or at NaN
    // has pixel coordinates beyond int.
    const int x0 = std::max(0, floorCell<int>(std::min(a.x, b.x) - half));
    const int x1 = std::min(w - 1, floorCell<int>(std::max(a.x, b.x) + half));
    const int y0 = std::max(0, floorCell<int>(std::min(a.y, b.y) - half));
    const int y1 = std::min(h - 1, floorCell<int>(std::max(a.y, b.y) + half));
    for (int y = y0; y <= y1; ++y) {
        std::uint8_t* row = mask + std::size_t(y) * std::size_t(w);
        // Only the pixels of this row near the segment: the part of it within half a width
        // (and a pixel) of the row, widened by as much, not the whole bounding box (a long
        // diagonal chord costs its length, not its length squared).
        int rx0 = x0, rx1 = x1;
        if (std::fabs(d.y) > 1e-6f) {
            const float reach = half + 1.0f;
            float t0 = (float(y) - reach - a.y) / d.y, t1 = (float(y) + 1.0f + reach - a.y) / d.y;
            if (t0 > t1) std::swap(t0, t1);
            t0 = std::clamp(t0, 0.0f, 1.0f);
            t1 = std::clamp(t1, 0.0f, 1.0f);
            const float xa = a.x + d.x * t0, xb = a.x + d.x * t1;
            rx0 = std::max(x0, floorCell<int>(std::min(xa, xb) - reach));
            rx1 = std::min(x1, floorCell<int>(std::max(xa, xb) + reach));
        }
        for (int x = rx0; x <= rx1; ++x) {
            if (row[x] == 15) continue;  // every sample already inked: dense curves fill up early
            std::uint8_t bits = 0;
            for (int k = 0; k < 4; ++k) {
                const float px = float(x) + kSample[k][0], py = float(y) + kSample[k][1];
                float t = len2 > 0 ? ((px - a.x) * d.x + (py - a.y) * d.y) / len2 : 0.0f;
                t = std::clamp(t, 0.0f, 1.0f);
                const float qx = a.x + d.x * t - px, qy = a.y + d.y * t - py;
                if (qx * qx + qy * qy <= half2) bits |= std::uint8_t(1u << k);
            }
            row[x] |= bits;
        }
    }
}

// A short chord (up to 1.25 pixels, the common case in a dense curve) is stamped as a round
// dot at its middle from a table of 5 x 5 sample masks per eighth of a pixel: no geometry per
// pixel (measured: 3x faster than the exact stamp on the quadratic Gosper curve n=5).
class DotStamps {
public:
    explicit DotStamps(float radius) {
        for (int fy = 0; fy < 8; ++fy)
            for (int fx = 0; fx < 8; ++fx)
                for (int y = 0; y < 5; ++y)
                    for (int x = 0; x < 5; ++x) {
                        const float cx = 2.0f + float(fx) / 8.0f, cy = 2.0f + float(fy) / 8.0f;
                        std::uint8_t bits = 0;
                        for (int k = 0; k < 4; ++k) {
                            const float dx = float(x) + kSample[k][0] - cx, dy = float(y) + kSample[k][1] - cy;
                            if (dx * dx + dy * dy <= radius * radius) bits |= std::uint8_t(1u << k);
                        }
                        m_table[fy][fx][y][x] = bits;
                    }
    }
    // False when the dot would cross the image's border (the exact stamp does it then).
    bool stamp(glm::vec2 centre, int w, int h, std::uint8_t* mask) const {
        const float ix = std::floor(centre.x), iy = std::floor(centre.y);
        if (!(ix >= 2 && iy >= 2 && ix + 3 <= float(w) && iy + 3 <= float(h))) return false;  // before any cast
        const int x0 = int(ix) - 2, y0 = int(iy) - 2;
        const int fx = std::min(7, int((centre.x - ix) * 8.0f)), fy = std::min(7, int((centre.y - iy) * 8.0f));
        const std::uint8_t(&k)[5][5] = m_table[fy][fx];
        for (int y = 0; y < 5; ++y) {
            std::uint8_t* row = mask + std::size_t(y0 + y) * std::size_t(w) + std::size_t(x0);
            for (int x = 0; x < 5; ++x) row[x] |= k[y][x];
        }
        return true;
    }

private:
    std::uint8_t m_table[8][8][5][5];
};

// The long chords drawn so far, by the pixels of their ends (either direction): an
// open-addressing set of 64-bit keys, at most 2^20 of them (past that a chord is drawn again
// rather than remembered: the set never costs more than 16 MB).
class ChordSet {
public:
    // False when the chord was there already.
    bool insert(glm::vec2 a, glm::vec2 b) {
        if (!(std::fabs(a.x) < 1e8f && std::fabs(a.y) < 1e8f && std::fabs(b.x) < 1e8f && std::fabs(b.y) < 1e8f)) return true;
        auto q = [](float v) {  // its pixel (one instruction, not floor's call)
            return std::uint64_t(std::uint32_t(std::int32_t(v >= 0 ? v : v - 1.0f)));
        };
        std::uint64_t ka = q(a.x) << 32 | q(a.y), kb = q(b.x) << 32 | q(b.y);
        if (ka > kb) std::swap(ka, kb);
        std::uint64_t key = mix(ka * 0x9E3779B97F4A7C15ull ^ mix(kb));
        key |= 1;  // 0 marks an empty slot
        if (m_slots.empty()) m_slots.assign(1u << 12, 0);
        const std::size_t mask = m_slots.size() - 1;
        for (std::size_t i = key & mask;; i = (i + 1) & mask) {
            if (m_slots[i] == key) return false;
            if (m_slots[i] == 0) {
                if (m_count >= kMax) return true;
                m_slots[i] = key;
                if (++m_count * 2 > m_slots.size()) grow();
                return true;
            }
        }
    }

private:
    static constexpr std::size_t kMax = std::size_t(1) << 20;
    static std::uint64_t mix(std::uint64_t x) {
        x ^= x >> 33;
        x *= 0xff51afd7ed558ccdull;
        x ^= x >> 33;
        x *= 0xc4ceb9fe1a85ec53ull;
        return x ^ (x >> 33);
    }
    void grow() {
        std::vector<std::uint64_t> old(m_slots.size() * 2, 0);
        old.swap(m_slots);
        const std::size_t mask = m_slots.size() - 1;
        for (std::uint64_t k : old)
            if (k) {
                std::size_t i = k & mask;
                while (m_slots[i]) i = (i + 1) & mask;
                m_slots[i] = k;
            }
    }
    std::vector<std::uint64_t> m_slots;
    std::size_t m_count = 0;
};

}  // namespace

void rasterizeCurve(const CylinderInstance* segs, std::size_t count, const glm::mat4& viewProj, int w, int h,
                    float lineWidth, std::vector<std::uint8_t>& coverage) {
    coverage.assign(std::size_t(w) * std::size_t(h), 0);
    const float half = lineWidth * 0.5f;
    // World (x, y, 0) to pixels: the orthographic camera of a planar curve is an affine map.
    const float ax = viewProj[0][0] * 0.5f * float(w), bx = viewProj[1][0] * 0.5f * float(w),
                cx = (viewProj[3][0] * 0.5f + 0.5f) * float(w);
    const float ay = viewProj[0][1] * 0.5f * float(h), by = viewProj[1][1] * 0.5f * float(h),
                cy = (viewProj[3][1] * 0.5f + 0.5f) * float(h);
    auto toPixel = [&](const glm::vec3& p) { return glm::vec2(ax * p.x + bx * p.y + cx, ay * p.x + by * p.y + cy); };
    constexpr float kMerge2 = 0.75f * 0.75f;
    // A dot for a chord of about a pixel: half the width, and half the chord on each side.
    const DotStamps dots(std::min(half + 0.25f, 2.4f));
    // A long chord that falls on the pixels of one drawn before, from the same pixel to the same
    // pixel (a curve going over the same edges again and again, its float positions drifting a
    // little each round), is skipped in constant time: those pixels are inked.
    ChordSet drawn;
    auto chord = [&](glm::vec2 a, glm::vec2 b) {
        const glm::vec2 d = b - a;
        const float len2 = d.x * d.x + d.y * d.y;
        if (len2 <= 1.25f * 1.25f && dots.stamp((a + b) * 0.5f, w, h, coverage.data())) return;
        if (len2 >= 4.0f * 4.0f && !drawn.insert(a, b)) return;
        stamp(a, b, half, w, h, coverage.data());
    };  // merge what is shorter than three quarters of a pixel
    glm::vec2 kept(0), pending(0);
    glm::vec3 lastWorld(0);
    bool open = false, hasPending = false;
    for (std::size_t i = 0; i < count; ++i) {
        const CylinderInstance& c = segs[i];
        if (!open || c.start != lastWorld) {  // a new polyline: the turtle moved without drawing
            if (open && hasPending) chord(kept, pending);
            kept = toPixel(c.start);
            open = true;
            hasPending = false;
        }
        const glm::vec2 p = toPixel(c.end);
        lastWorld = c.end;
        const glm::vec2 d = p - kept;
        if (d.x * d.x + d.y * d.y < kMerge2) {  // still within 3/4 pixel of the last point kept
            pending = p;
            hasPending = true;
            continue;
        }
        chord(kept, p);
        kept = p;
        hasPending = false;
    }
    if (open && hasPending) chord(kept, pending);
    // Sample masks to coverage.
    for (std::uint8_t& m : coverage) m = std::uint8_t((__builtin_popcount(m) * 255 + 2) / 4);
}

}  // namespace sprout::render
