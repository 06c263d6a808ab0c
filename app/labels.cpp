#include "app/labels.hpp"

#include <algorithm>
#include <cmath>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <imgui.h>

namespace sprout {
namespace {

// ImGui's default font, made once into an alpha atlas (no ImGui context needed).
struct Font {
    ImFontAtlas atlas;
    ImFont* font = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    Font() {
        font = atlas.AddFontDefault();
        atlas.GetTexDataAsAlpha8(&pixels, &width, &height);
    }
};

const Font& font() {
    static const Font f;
    return f;
}

}  // namespace

bool labelPosition(const render::Camera& camera, int w, int h, const glm::vec3& p, float& x, float& y) {
    const float aspect = float(w) / float(std::max(h, 1));
    const glm::vec4 c = camera.projection(aspect, 1e-3f, 1e6f) * camera.view() * glm::vec4(p, 1.0f);
    if (!(c.w > 1e-9f)) return false;
    x = (c.x / c.w * 0.5f + 0.5f) * float(w);
    y = (0.5f - c.y / c.w * 0.5f) * float(h);
    return std::isfinite(x) && std::isfinite(y);
}

void paintLabels(Image& image, const Geometry& g, const render::Camera& camera) {
    if (g.labels.empty() || image.width <= 0 || image.height <= 0) return;
    const Font& f = font();
    if (!f.font || !f.pixels) return;
    auto blend = [&](int px, int py, std::uint32_t rgba, float alpha) {
        if (px < 0 || py < 0 || px >= image.width || py >= image.height || alpha <= 0) return;
        std::uint8_t* d = &image.rgba[(std::size_t(py) * std::size_t(image.width) + std::size_t(px)) * 4];
        for (int c = 0; c < 3; ++c) {
            const float src = float((rgba >> (24 - 8 * c)) & 0xFF);
            d[c] = std::uint8_t(std::lround(float(d[c]) * (1 - alpha) + src * alpha));
        }
    };
    for (const Geometry::Label& label : g.labels) {
        float x = 0, y = 0;
        if (!labelPosition(camera, image.width, image.height, label.position, x, y)) continue;
        const int scale = std::max(1, int(std::lround(label.size / f.font->FontSize)));
        // Left end at the point, a little to the right and above it (the text's baseline).
        float pen = std::round(x) + 3;
        const float top = std::round(y) - f.font->FontSize * float(scale) - 1;
        for (unsigned char ch : label.text) {
            const ImFontGlyph* glyph = f.font->FindGlyph(ImWchar(ch < 0x80 ? ch : '?'));
            if (!glyph) continue;
            const int u0 = int(std::lround(glyph->U0 * float(f.width))), u1 = int(std::lround(glyph->U1 * float(f.width)));
            const int v0 = int(std::lround(glyph->V0 * float(f.height))), v1 = int(std::lround(glyph->V1 * float(f.height)));
            for (int pass = 0; pass < 2; ++pass)  // the outline, then the text
                for (int ty = v0; ty < v1; ++ty)
                    for (int tx = u0; tx < u1; ++tx) {
                        const float a = float(f.pixels[std::size_t(ty) * std::size_t(f.width) + std::size_t(tx)]) / 255.0f;
                        if (a <= 0) continue;
                        for (int sy = 0; sy < scale; ++sy)
                            for (int sx = 0; sx < scale; ++sx) {
                                const int px = int(pen + glyph->X0 * float(scale)) + (tx - u0) * scale + sx;
                                const int py = int(top + glyph->Y0 * float(scale)) + (ty - v0) * scale + sy;
                                if (pass == 1) {
                                    blend(px, py, label.colour, a);
                                    continue;
                                }
                                for (int oy = -1; oy <= 1; ++oy)
                                    for (int ox = -1; ox <= 1; ++ox)
                                        if (ox || oy) blend(px + ox, py + oy, 0x141414FFu, a * 0.5f);
                            }
                    }
            pen += glyph->AdvanceX * float(scale);
        }
    }
}

}  // namespace sprout
