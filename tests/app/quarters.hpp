#pragma once
// A test image of four coloured quarters, and which quarter a pixel of a picture shows: how
// the textures tests see where an image lies on a surface.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "app/image.hpp"

namespace sprout_test::quarters {

// The image: top left red, top right green, bottom left blue, bottom right yellow (16 x 16).
// At (u, v), v = 0 the image's bottom: (0.25, 0.25) blue, (0.75, 0.25) yellow, (0.25, 0.75)
// red, (0.75, 0.75) green.
enum Quarter { Blue, Yellow, Red, Green, None };
inline const char* kNames[] = {"blue", "yellow", "red", "green", "none"};

inline sprout::Image quarters() {
    sprout::Image i;
    i.width = i.height = 16;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const bool right = x >= 8, bottom = y >= 8;
            const std::uint8_t r = (!bottom && !right) || (bottom && right) ? 255 : 0;
            const std::uint8_t g = right ? 255 : 0, b = bottom && !right ? 255 : 0;
            i.rgba.insert(i.rgba.end(), {r, g, b, std::uint8_t(255)});
        }
    return i;
}

inline Quarter classify(const sprout::Image& i, int x, int y) {
    const std::size_t k = (std::size_t(y) * std::size_t(i.width) + std::size_t(x)) * 4;
    const int r = i.rgba[k], g = i.rgba[k + 1], b = i.rgba[k + 2];
    const int hi = std::max({r, g, b});
    if (hi < 60) return None;
    const bool R = r > hi / 2, G = g > hi / 2, B = b > hi / 2;
    if (R && G && !B) return Yellow;
    if (R && !G && !B) return Red;
    if (!R && G && !B) return Green;
    if (!R && !G && B) return Blue;
    return None;
}

// The quarter of the image at (u, v), repeated outside [0, 1].
inline Quarter quarterAt(double u, double v) {
    u -= std::floor(u), v -= std::floor(v);
    return v < 0.5 ? (u < 0.5 ? Blue : Yellow) : (u < 0.5 ? Red : Green);
}

}  // namespace sprout_test::quarters
