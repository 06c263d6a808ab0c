#pragma once
// A material's light beyond its colour (L-Py's and VLab's materials, a grammar's `material:`):
// its specular colour at its shininess and its emission. The grammar keeps them by palette
// index, the drawing by the colour the turtle gave the surfaces (Geometry::shines).
#include <cstdint>

namespace sprout {

struct Shine {
    std::uint32_t specular = 0;  // 0xRRGGBB00: the highlight's colour
    float shininess = 0.2f;      // 0 to 1: the highlight's exponent 128 x it, as PlantGL gives OpenGL
    std::uint32_t emission = 0;  // 0xRRGGBB00: light of its own, added to what it reflects
    bool plain() const { return specular == 0 && emission == 0; }
    bool operator==(const Shine&) const = default;
};

}  // namespace sprout
