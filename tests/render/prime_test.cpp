// Renderer::prime (what `sprout render` draws on its GL thread while the model runs) and the
// resolve of the multisampled image: a primed renderer draws the very bytes a fresh one draws.
#include <gtest/gtest.h>

#include <atomic>

#include "app/headless.hpp"
#include "app/plant/presets.hpp"
#include "app/render/renderer.hpp"
#include "app/snapshot.hpp"
#include "core/language/file_kind.hpp"

namespace sprout {
namespace {

constexpr int kW = 320, kH = 240;

Geometry plantOf(const char* preset) {
    ParseResult r = parseDetected(*presetText(preset));
    EXPECT_TRUE(r.grammar) << preset;
    Geometry g;
    if (!r.grammar) return g;
    DeriveResult d = derive(r.grammar, r.grammar->settings.iterations);
    EXPECT_TRUE(d.outcome.ok()) << preset;
    if (d.outcome.ok()) interpret(*d.string, *r.grammar, {r.grammar->settings.iterations, 1, nullptr}, g);
    return g;
}

// `g` drawn into the default framebuffer of a context of its own, as renderGeometry draws it;
// first primed with `primeWith` unless `cancelled` (prime then stops before its first pass).
std::vector<std::uint8_t> picture(const Geometry& g, const render::RenderOptions& o, const render::RenderOptions* primeWith,
                                  bool cancelled = false) {
    std::string error;
    auto context = HeadlessContext::create(kW, kH, error);
    render::Renderer renderer;
    if (!context || !renderer.init(context->loader(), error)) {
        ADD_FAILURE() << "no OpenGL: " << error;
        return {};
    }
    if (primeWith) {
        const std::atomic<bool> cancel{cancelled};
        renderer.prime(kW, kH, *primeWith, cancel);
    }
    renderer.upload(g);
    SnapshotOptions so;
    so.width = kW, so.height = kH;
    renderer.draw(snapshotCamera(g, so), kW, kH, o, 0);
    return renderer.readPixels(kW, kH, 0);
}

TEST(Render, APrimedRendererDrawsTheBytesOfAFreshOne) {
    render::RenderOptions lit, plain;
    plain.shadows = plain.ground = false;
    for (const char* preset : {"bush_3d", "koch", "dandelion"}) {
        const Geometry g = plantOf(preset);
        ASSERT_FALSE(g.cylinders.empty()) << preset;
        for (const render::RenderOptions* o : {&lit, &plain}) {
            const std::vector<std::uint8_t> fresh = picture(g, *o, nullptr);
            ASSERT_EQ(fresh.size(), std::size_t(kW * kH * 4));
            // Primed as the picture is drawn, primed otherwise, and a prime cancelled at once.
            EXPECT_EQ(picture(g, *o, o), fresh) << preset << (o == &lit ? " lit" : " plain") << ", primed alike";
            EXPECT_EQ(picture(g, *o, o == &lit ? &plain : &lit), fresh) << preset << ", primed otherwise";
            EXPECT_EQ(picture(g, *o, o, true), fresh) << preset << ", the prime cancelled";
        }
    }
}

// The picture is resolved from 4 samples: each pixel of a curve's picture (solid ink on the
// sky) is the sky, the ink, or the sky with 1, 2 or 3 of its 4 samples inked, and some edges are
// each of those.
TEST(Render, EachPixelIsTheMeanOfItsFourSamples) {
    render::RenderOptions plain;
    plain.shadows = plain.ground = false;
    const std::vector<std::uint8_t> px = picture(plantOf("koch"), plain, nullptr), sky = picture(Geometry(), plain, nullptr);
    ASSERT_EQ(px.size(), sky.size());
    int inked[5] = {0, 0, 0, 0, 0}, other = 0;
    for (std::size_t i = 0; i + 3 < px.size(); i += 4) {
        int k = 0;
        for (; k <= 4; ++k) {
            bool near = true;
            for (int c = 0; c < 3; ++c) {
                const float want = float(sky[i + std::size_t(c)]) + (plain.curveInk[c] * 255.0f - float(sky[i + std::size_t(c)])) * float(k) / 4.0f;
                near = near && std::abs(float(px[i + std::size_t(c)]) - want) <= 1.0f;
            }
            if (near) break;
        }
        k <= 4 ? ++inked[k] : ++other;
    }
    EXPECT_EQ(other, 0) << "pixels that are no mean of sky and ink samples";
    for (int k = 1; k <= 4; ++k) EXPECT_GT(inked[k], 20) << "pixels with " << k << " of 4 samples inked";
}

}  // namespace
}  // namespace sprout
