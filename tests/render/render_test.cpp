// Screenshot tests: real headless renders through OSMesa (no display), checked pixel by pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>
#include <glm/geometric.hpp>

#include "app/cli/load.hpp"
#include "app/headless.hpp"
#include "app/image.hpp"
#include "app/labels.hpp"
#include "app/plant/presets.hpp"
#include "app/snapshot.hpp"
#include "app/render/renderer.hpp"
#include "core/environment/environment_drawing.hpp"
#include "core/language/file_kind.hpp"
#include "core/scene/forest.hpp"
#include "core/scene/ifs.hpp"

namespace sprout {
namespace {

constexpr int kW = 320, kH = 180;

std::shared_ptr<const Grammar> grammarOf(std::string_view text) {
    ParseResult r = parseDetected(text);
    for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, "<test>");
    return r.grammar;
}

Image render(std::shared_ptr<const Grammar> g, SnapshotOptions o = {}) {
    o.width = o.width == 1280 ? kW : o.width;
    o.height = o.height == 720 ? kH : o.height;
    Snapshot shot;
    std::string error;
    EXPECT_TRUE(renderSnapshot(g, o, shot, error)) << error;
    return shot.image;
}

// Plain background and no ground, so every pixel that differs from an empty scene is plant.
SnapshotOptions plain() {
    SnapshotOptions o;
    o.render.ground = false;
    o.render.shadows = false;
    return o;
}

struct Mask {
    int w = 0, h = 0;
    std::vector<std::uint8_t> on;
    int count = 0;
    bool at(int x, int y) const { return on[std::size_t(y * w + x)]; }
};

Mask plantMask(const Image& plant, const Image& empty) {
    Mask m;
    m.w = plant.width;
    m.h = plant.height;
    m.on.resize(std::size_t(m.w * m.h));
    for (std::size_t i = 0; i < m.on.size(); ++i) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d += std::abs(int(plant.rgba[i * 4 + c]) - int(empty.rgba[i * 4 + c]));
        m.on[i] = d > 24;
        m.count += m.on[i];
    }
    return m;
}

// A renderer on a headless context of its own, kW x kH; null (the test fails) without OpenGL.
struct HeadlessRenderer {
    std::unique_ptr<HeadlessContext> context;
    render::Renderer renderer;
};
std::unique_ptr<HeadlessRenderer> headlessRenderer() {
    auto h = std::make_unique<HeadlessRenderer>();
    std::string error;
    h->context = HeadlessContext::create(kW, kH, error);
    if (!h->context || !h->renderer.init(h->context->loader(), error)) {
        ADD_FAILURE() << "no OpenGL: " << error;
        return nullptr;
    }
    return h;
}

Image emptyScene(const SnapshotOptions& o) { return render(grammarOf("axiom: X\n"), o); }

// Pixels of a plant (unlike the empty scene's) in a moving frame and in the still picture,
// and the moving frame's outside the still one's.
struct PlantPixels {
    int inMoving = 0, inWhole = 0, outside = 0;
};
PlantPixels plantPixels(const std::vector<std::uint8_t>& moving, const std::vector<std::uint8_t>& whole, const Image& empty) {
    PlantPixels p;
    for (std::size_t i = 0; i < whole.size(); i += 4) {
        auto differs = [&](const std::vector<std::uint8_t>& img) {
            return std::abs(int(img[i]) - int(empty.rgba[i])) + std::abs(int(img[i + 1]) - int(empty.rgba[i + 1])) +
                       std::abs(int(img[i + 2]) - int(empty.rgba[i + 2])) > 30;
        };
        const bool a = differs(moving), b = differs(whole);
        p.inMoving += a, p.inWhole += b, p.outside += a && !b;
    }
    return p;
}

// A plant derived n steps and drawn, prepared at `detail` with what its moving frames draw
// (Renderer::prepareMoving); false when it does not derive.
bool preparePlant(const std::shared_ptr<const Grammar>& g, int n, render::Quality detail, Geometry& geometry,
                  render::PreparedScene& scene) {
    DeriveResult d = derive(g, n);
    if (!d.outcome.ok()) return false;
    interpret(*d.string, *g, {n, 1, nullptr}, geometry);
    render::Renderer::prepare(geometry, detail, scene);
    render::Renderer::prepareMoving(geometry, scene);
    return true;
}

// A scene prepared as the window's worker prepares it (its proxy for moving frames too),
// drawn headless from the snapshot camera as a moving frame and as the still picture. The
// moving frame must draw the proxy and the still one the scene; the still plant must cover
// 1/wholeShare of the picture, the moving one 1/shownShare of that, and at most a fifth of
// the moving frame's plant may lie outside the still one's. Returns the moving frame's
// triangles.
std::size_t expectMovingFrameOnThePlant(const Geometry& geometry, const render::PreparedScene& scene, int wholeShare,
                                        int shownShare, const char* what) {
    auto headless = headlessRenderer();
    EXPECT_TRUE(headless);
    if (!headless) return 0;
    render::Renderer& renderer = headless->renderer;
    renderer.upload(scene);
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    const render::Camera camera = snapshotCamera(geometry, o);
    render::RenderOptions still = o.render, moving = o.render;
    still.quality = render::Quality::Still;
    moving.quality = render::Quality::Interactive;
    const std::vector<std::uint8_t> a = renderer.renderImage(camera, kW, kH, moving);
    EXPECT_TRUE(renderer.stats().proxy) << "the moving frame draws " << what;
    const std::size_t movingTriangles = renderer.stats().triangles;
    const std::vector<std::uint8_t> b = renderer.renderImage(camera, kW, kH, still);
    EXPECT_FALSE(renderer.stats().proxy) << "the still picture draws the scene";
    const PlantPixels p = plantPixels(a, b, emptyScene(o));
    EXPECT_GT(p.inWhole, kW * kH / wholeShare);
    EXPECT_GT(p.inMoving, p.inWhole / shownShare) << what << " shows the plant";
    EXPECT_LT(p.outside, p.inMoving / 5) << what << " lies where the plant is";
    return movingTriangles;
}

TEST(Render, EveryPresetIsFramedAndNotClipped) {
    SnapshotOptions o = plain();
    Image empty = emptyScene(o);
    for (const auto& name : presetNames()) {
        // Loaded as `sprout render PRESET` loads it (an L-Py preset runs its Python).
        auto loaded = cli::loadGrammar(name);
        ASSERT_TRUE(loaded && loaded->grammar) << name;
        Image img = render(loaded->grammar, o);
        Mask m = plantMask(img, empty);
        double cover = double(m.count) / (kW * kH);
        EXPECT_GT(cover, 0.004) << name << " covers too little of the frame";
        EXPECT_LT(cover, 0.9) << name;
        // Framed: the plant reaches near at least two opposite borders of the frame...
        int minX = kW, maxX = -1, minY = kH, maxY = -1, border = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (m.at(x, y)) {
                    minX = std::min(minX, x);
                    maxX = std::max(maxX, x);
                    minY = std::min(minY, y);
                    maxY = std::max(maxY, y);
                    border += x == 0 || y == 0 || x == kW - 1 || y == kH - 1;
                }
        EXPECT_TRUE(maxY - minY > kH * 0.7 || maxX - minX > kW * 0.7) << name << " is not framed";
        // ...and touches none of them.
        EXPECT_EQ(border, 0) << name << " is clipped at the border";
    }
}

// Every cpfg-family test file draws a plausible picture at its derivation length: something
// on screen, framed, not the whole frame, and at least two colours of plant (shading); files
// that draw nothing (strings of symbols the turtle ignores) say so with '// picture: none'.
TEST(Render, EveryCpfgTestFileDrawsAPlausiblePicture) {
    namespace fs = std::filesystem;
    SnapshotOptions o = plain();
    Image empty = emptyScene(o);
    int drawn = 0;
    for (const auto& e : fs::directory_iterator(SPROUT_CPFG_DIR)) {
        if (e.path().extension() != ".l" && e.path().extension() != ".lpy") continue;
        const std::string name = e.path().filename().string();
        std::ifstream in(e.path(), std::ios::binary);
        const std::string text(std::istreambuf_iterator<char>(in), {});
        ParseResult r = parseDetected(text, e.path().string());
        ASSERT_TRUE(r.ok()) << name;
        Image img = render(r.grammar, o);
        Mask m = plantMask(img, empty);
        const double cover = double(m.count) / (kW * kH);
        if (text.find("// picture: none") != std::string::npos) {
            EXPECT_LT(cover, 0.001) << name << " says it draws nothing";
            continue;
        }
        ++drawn;
        EXPECT_GT(cover, 0.002) << name << " draws almost nothing";
        EXPECT_LT(cover, 0.9) << name;
        int minX = kW, maxX = -1, minY = kH, maxY = -1;
        std::set<std::uint32_t> shades;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (m.at(x, y)) {
                    minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
                    const std::size_t i = std::size_t(y * kW + x) * 4;
                    shades.insert(std::uint32_t(img.rgba[i] / 16) << 8 | std::uint32_t(img.rgba[i + 1] / 16) << 4 | img.rgba[i + 2] / 16);
                }
        EXPECT_TRUE(maxY - minY > kH * 0.5 || maxX - minX > kW * 0.5) << name << " is not framed";
        EXPECT_GE(shades.size(), 2u) << name << " is one flat colour";
    }
    EXPECT_GE(drawn, 30);
}

// A big planar curve is rasterised on the CPU (app/render/curve_raster.cpp) instead of drawn
// as a ribbon per segment; the two must give the same picture. The dragon curve n=10 (1 k
// segments: ribbons by default) drawn both ways from one geometry, compared pixel by pixel.
// (Denser, at n=14, the raster has up to 16% more ink: where strokes a pixel apart leave a
// sliver between them the analytic union covers what 4x MSAA samples may miss.)
TEST(Render, RasterisedCurveLooksLikeItsRibbons) {
    auto g = grammarOf(*presetText("dragon"));
    DeriveResult d = derive(g, 10);
    ASSERT_TRUE(d.outcome.ok());
    auto geometry = std::make_shared<Geometry>();
    interpret(*d.string, *g, {14, 1, nullptr}, *geometry);
    ASSERT_TRUE(geometry->planarCurve);
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    const render::Camera camera = snapshotCamera(*geometry, o);
    render::PreparedScene ribbons;
    render::Renderer::prepare(*geometry, render::Quality::Still, ribbons, geometry);
    ASSERT_FALSE(ribbons.curve.empty());
    renderer.upload(ribbons);
    const std::vector<std::uint8_t> a = renderer.renderImage(camera, kW, kH, o.render);
    render::PreparedScene raster = ribbons;
    raster.curve.clear();
    raster.curveGeometry = geometry;
    renderer.upload(raster);
    const std::vector<std::uint8_t> b = renderer.renderImage(camera, kW, kH, o.render);
    ASSERT_EQ(a.size(), b.size());
    int inkA = 0, inkB = 0, differ = 0;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        inkA += a[i] + a[i + 1] + a[i + 2] < 3 * 120;
        inkB += b[i] + b[i + 1] + b[i + 2] < 3 * 120;
        differ += std::abs(int(a[i]) - int(b[i])) + std::abs(int(a[i + 1]) - int(b[i + 1])) + std::abs(int(a[i + 2]) - int(b[i + 2])) > 120;
    }
    EXPECT_GT(inkA, kW * kH / 50) << "the curve is drawn";
    EXPECT_NEAR(double(inkB) / inkA, 1.0, 0.12) << "as much ink either way";
    EXPECT_LT(differ, kW * kH / 25) << "the same pixels, up to the edges of the ink";
}

// On a GPU a big curve is drawn as its ribbons, as a small one is (Renderer::bigCurveRibbons;
// on llvmpipe it is rasterised). The dragon curve n=10 with each segment cut into 256 pieces
// (262 k segments, past the raster's threshold) drawn as ribbons is the picture of the uncut
// curve's ribbons.
TEST(Render, BigCurveIsDrawnAsItsRibbonsWhereTheGpuCan) {
    auto g = grammarOf(*presetText("dragon"));
    DeriveResult d = derive(g, 10);
    ASSERT_TRUE(d.outcome.ok());
    auto small = std::make_shared<Geometry>();
    interpret(*d.string, *g, {14, 1, nullptr}, *small);
    auto big = std::make_shared<Geometry>(*small);
    big->cylinders.clear();
    constexpr int kPieces = 256;
    for (const CylinderInstance& c : small->cylinders)
        for (int k = 0; k < kPieces; ++k) {
            CylinderInstance piece = c;
            piece.start = glm::mix(c.start, c.end, float(k) / kPieces);
            piece.end = glm::mix(c.start, c.end, float(k + 1) / kPieces);
            big->cylinders.push_back(piece);
        }
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    EXPECT_FALSE(renderer.bigCurveRibbons()) << "llvmpipe rasterises a big curve";
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    const render::Camera camera = snapshotCamera(*small, o);
    render::PreparedScene reference, scene;
    render::Renderer::prepare(*small, render::Quality::Still, reference, small);
    render::Renderer::prepare(*big, render::Quality::Still, scene, big);
    ASSERT_TRUE(scene.curveGeometry) << "a big curve";
    renderer.upload(reference);
    const std::vector<std::uint8_t> uncut = renderer.renderImage(camera, kW, kH, o.render);
    renderer.upload(scene);
    EXPECT_TRUE(renderer.rasterCurve());
    renderer.renderImage(camera, kW, kH, o.render);
    EXPECT_LT(renderer.stats().triangles, 10u) << "rasterised: one quad";
    renderer.setBigCurveRibbons(true);
    renderer.upload(scene);
    EXPECT_FALSE(renderer.rasterCurve()) << "as ribbons";
    const std::vector<std::uint8_t> ribbons = renderer.renderImage(camera, kW, kH, o.render);
    EXPECT_GE(renderer.stats().triangles, 2 * big->cylinders.size()) << "a quad per segment";
    int inkUncut = 0, inkRibbons = 0, differ = 0;
    for (std::size_t i = 0; i < uncut.size(); i += 4) {
        const bool a = uncut[i] + uncut[i + 1] + uncut[i + 2] < 3 * 120, b = ribbons[i] + ribbons[i + 1] + ribbons[i + 2] < 3 * 120;
        inkUncut += a, inkRibbons += b, differ += a != b;
    }
    EXPECT_GT(inkRibbons, kW * kH / 50) << "the curve is drawn";
    EXPECT_NEAR(double(inkRibbons) / inkUncut, 1.0, 0.03) << "as much ink";
    EXPECT_LT(differ, kW * kH / 200) << "the same pixels";
}

// While the view of a big curve is dragged (interactive quality) the last raster is moved as a
// picture instead of rasterising again; it must land where the new raster would.
TEST(Render, DraggedBigCurveMovesItsLastPicture) {
    auto g = grammarOf(*presetText("dragon"));
    DeriveResult d = derive(g, 19);  // 524 k segments: rasterised
    ASSERT_TRUE(d.outcome.ok());
    auto geometry = std::make_shared<Geometry>();
    interpret(*d.string, *g, {19, 1, nullptr}, *geometry);
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    render::PreparedScene scene;
    render::Renderer::prepare(*geometry, render::Quality::Still, scene, geometry);
    ASSERT_TRUE(scene.curveGeometry);
    renderer.upload(scene);
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    render::Camera camera = snapshotCamera(*geometry, o);
    render::RenderOptions still = o.render, moving = o.render;
    still.quality = render::Quality::Still;
    moving.quality = render::Quality::Interactive;
    renderer.renderImage(camera, kW, kH, still);  // the picture before the drag
    camera.target += glm::vec3(camera.orthoHeight * 0.08f, camera.orthoHeight * -0.05f, 0);
    camera.orthoHeight *= 1.15f;  // panned and zoomed out
    const std::vector<std::uint8_t> dragged = renderer.renderImage(camera, kW, kH, moving);
    EXPECT_TRUE(renderer.stats().curveMoved) << "dragging moves the last picture";
    const std::vector<std::uint8_t> exact = renderer.renderImage(camera, kW, kH, still);
    EXPECT_FALSE(renderer.stats().curveMoved) << "a still view rasterises anew";
    int inkDragged = 0, inkExact = 0, differ = 0;
    for (std::size_t i = 0; i < exact.size(); i += 4) {
        const bool a = dragged[i] + dragged[i + 1] + dragged[i + 2] < 3 * 120, b = exact[i] + exact[i + 1] + exact[i + 2] < 3 * 120;
        inkDragged += a, inkExact += b, differ += a != b;
    }
    EXPECT_GT(inkExact, kW * kH / 20);
    EXPECT_NEAR(double(inkDragged) / inkExact, 1.0, 0.1);
    EXPECT_LT(differ, kW * kH / 30) << "the moved picture is where the curve is";
}

// A big plant while the view moves is drawn as its sketch (its main branches and a share of
// the rest as lines): far fewer primitives, the same place and outline; the still view is the
// whole plant as before.
TEST(Render, BigPlantIsSketchedWhileMoving) {
    auto g = grammarOf(std::string(*presetText("fractal_plant")) + "\nn: 9\n");  // 393 k segments
    Geometry geometry;
    render::PreparedScene scene;
    ASSERT_TRUE(preparePlant(g, 9, render::Quality::Interactive, geometry, scene));
    ASSERT_GT(scene.proxy.size(), 0u);
    EXPECT_TRUE(scene.proxyBaked.indices.empty()) << "lines only";
    EXPECT_LE(scene.proxy.size() / 8, render::PreparedScene::kProxyLines + 1000);
    // Plant pixels: the sketch's lie where the whole plant's are, over its outline.
    expectMovingFrameOnThePlant(geometry, scene, 20, 5, "the sketch");
}

// A curve of many ribbons (past kCurveSketch segments, short of the raster's 200 k) moves as a
// line for each segment, in ink, where its ribbons are; still, as its ribbons. A short curve
// keeps its ribbons while it moves.
TEST(Render, CurveOfManyRibbonsMovesAsItsLines) {
    for (int n : {4, 2}) {
        SCOPED_TRACE("koch_curve_1_9a n=" + std::to_string(n));
        auto g = grammarOf(std::string(*presetText("koch_curve_1_9a")));
        DeriveResult d = derive(g, n);
        ASSERT_TRUE(d.outcome.ok());
        Geometry geometry;
        interpret(*d.string, *g, {n, 1, nullptr}, geometry);
        ASSERT_TRUE(geometry.planarCurve);
        render::PreparedScene scene;
        render::Renderer::prepareForViewer(geometry, scene);
        if (n == 4) {
            ASSERT_GT(geometry.cylinders.size(), render::PreparedScene::kCurveSketch);
            EXPECT_EQ(scene.proxy.size(), 8 * scene.curve.size()) << "a line for each segment";
            EXPECT_EQ(expectMovingFrameOnThePlant(geometry, scene, 200, 3, "the curve's lines"), 0u) << "no ribbons";
        } else {
            ASSERT_LT(geometry.cylinders.size(), render::PreparedScene::kCurveSketch);
            EXPECT_TRUE(scene.proxy.empty()) << "a short curve moves as its ribbons";
        }
    }
}

// The window's still view of a big scene is drawn a piece per frame (beginDraw /
// continueDraw): the pieces make the very pixels of one draw, for a plant with shadows and
// leaves (also with its environment drawn: glass, and a slice of its light), a curve of
// ribbons and a big curve whose raster is made on a thread; until the last piece the target
// keeps what it showed.
TEST(Render, PictureDrawnInPiecesIsThePictureDrawnWhole) {
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    struct Case {
        const char* preset;
        int n;
        std::size_t piece;
        const char* environment = nullptr;  // appended to the preset, drawn
    } cases[] = {{"fractal_plant", 6, 997},
                 {"fractal_plant", 9, 20000},
                 {"fractal_plant", 5, 50, "environment: sphere 0 40 0 25\n"},
                 {"fractal_plant", 5, 50, "environment: light 4 0.3\n"},
                 {"dragon", 10, 101},
                 {"dragon", 19, 5000}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.preset + std::string(" n=") + std::to_string(c.n) + (c.environment ? " with its environment" : ""));
        auto g = grammarOf(std::string(*presetText(c.preset)) + "\n" + (c.environment ? c.environment : ""));
        DeriveResult d = derive(g, c.n);
        ASSERT_TRUE(d.outcome.ok());
        auto geometry = std::make_shared<Geometry>();
        interpret(*d.string, *g, {c.n, 1, nullptr}, *geometry);
        render::PreparedScene scene;
        render::Renderer::prepareForViewer(*geometry, scene, geometry);
        renderer.upload(scene);
        Mesh environment;
        if (c.environment) {
            EnvironmentView slice;
            slice.lightSlice = true;
            ASSERT_TRUE(drawEnvironment(g->environment, *geometry, 1, slice, environment));
            ASSERT_GT(environment.indices.size(), 100u);
        }
        renderer.setOverlay(environment);
        SnapshotOptions o = plain();
        o.width = kW, o.height = kH;
        o.render.shadows = true;
        const render::Camera camera = snapshotCamera(*geometry, o);
        const std::vector<std::uint8_t> whole = renderer.renderImage(camera, kW, kH, o.render);
        // In pieces, into the default framebuffer, which first shows another view (so that
        // a raster made before cannot pass for this one either).
        render::Camera moved = camera;
        moved.yaw += 30;
        moved.target += glm::vec3(0.1f, 0.05f, 0) * (moved.orthographic ? moved.orthoHeight : moved.distance);
        renderer.draw(moved, kW, kH, o.render, 0);
        const std::vector<std::uint8_t> shown = renderer.readPixels(kW, kH, 0);
        ASSERT_NE(shown, whole);
        // Twice: with the shadow map drawn in pieces too (a scene uploaded anew), and with the
        // one the last picture left (the same sun: an orbit's still view skips that pass).
        for (bool fresh : {true, false}) {
            if (fresh) renderer.upload(scene);
            renderer.beginDraw(camera, kW, kH, o.render, 0);
            int pieces = 0;
            while (!renderer.continueDraw(c.piece)) {
                ASSERT_LT(++pieces, 100000);
                if (pieces == 1) {
                    EXPECT_EQ(renderer.readPixels(kW, kH, 0), shown) << "the target keeps its picture until the new one is whole";
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(1));  // as frames do: the raster's thread goes on
            }
            EXPECT_FALSE(renderer.drawing());
            EXPECT_GT(pieces, 2);
            const std::vector<std::uint8_t> pieced = renderer.readPixels(kW, kH, 0);
            ASSERT_EQ(pieced.size(), whole.size());
            std::size_t differ = 0;
            for (std::size_t i = 0; i < whole.size(); ++i) differ += pieced[i] != whole[i];
            EXPECT_EQ(differ, 0u) << (fresh ? "shadow map drawn in pieces" : "shadow map kept");
            if (fresh) renderer.draw(moved, kW, kH, o.render, 0);  // shown again
        }
    }
    // A new draw abandons a picture in pieces.
    renderer.beginDraw(render::Camera(), kW, kH, plain().render, 0);
    renderer.renderImage(render::Camera(), kW, kH, plain().render);
    EXPECT_FALSE(renderer.drawing());
}

// A scene uploaded a piece per frame (as the window uploads a big plant) draws what the same
// scene uploaded at once draws: through buffers mapped once, persistently (the path taken where
// the context has GL_ARB_buffer_storage, as llvmpipe and GPU drivers do), and through
// glBufferSubData. The scene on screen is drawn until the new one is whole; a second staged
// upload goes into the buffers the first one left, and a whole upload after them replaces
// their immutable storage.
TEST(Render, SceneUploadedInPiecesDrawsAsUploadedWhole) {
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    EXPECT_TRUE(renderer.persistentUploads()) << "llvmpipe has GL_ARB_buffer_storage: the mapped path is the one tested";
    std::shared_ptr<Geometry> geometry[2];
    std::shared_ptr<render::PreparedScene> scene[2];
    for (int k = 0; k < 2; ++k) {
        auto g = grammarOf(std::string(*presetText(k ? "bush_3d" : "fractal_plant")));
        DeriveResult d = derive(g, k ? 3 : 5);
        ASSERT_TRUE(d.outcome.ok());
        geometry[k] = std::make_shared<Geometry>();
        interpret(*d.string, *g, {k ? 3 : 5, 1, nullptr}, *geometry[k]);
        scene[k] = std::make_shared<render::PreparedScene>();
        render::Renderer::prepareForViewer(*geometry[k], *scene[k], geometry[k]);
        ASSERT_GT(scene[k]->baked.indices.size() + scene[k]->lines.size(), 5000u);
    }
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    const render::Camera camera = snapshotCamera(*geometry[0], o);
    std::vector<std::uint8_t> whole[2];
    for (int k = 0; k < 2; ++k) {
        renderer.upload(*scene[k]);
        whole[k] = renderer.renderImage(camera, kW, kH, o.render);
    }
    ASSERT_NE(whole[0], whole[1]);
    auto staged = [&](int k) {
        SCOPED_TRACE(k ? "the second scene, staged" : "the first scene, staged");
        ASSERT_FALSE(renderer.beginUpload(scene[k], 4096)) << "too big for one piece";
        int pieces = 0;
        while (!renderer.continueUpload(4096)) {
            ASSERT_LT(++pieces, 1'000'000);
            if (pieces == 1) {
                EXPECT_EQ(renderer.renderImage(camera, kW, kH, o.render), whole[1 - k]) << "the scene on screen meanwhile";
            }
        }
        EXPECT_GT(pieces, 3);
        EXPECT_FALSE(renderer.uploading());
        EXPECT_EQ(renderer.renderImage(camera, kW, kH, o.render), whole[k]);
    };
    for (bool persistent : {true, false}) {
        SCOPED_TRACE(persistent ? "mapped persistently" : "by glBufferSubData");
        renderer.setPersistentUploads(persistent);
        EXPECT_EQ(renderer.persistentUploads(), persistent);
        renderer.upload(*scene[1]);
        staged(0);
        staged(1);
        renderer.upload(*scene[0]);
        EXPECT_EQ(renderer.renderImage(camera, kW, kH, o.render), whole[0]) << "a whole upload after staged ones";
        // A staged upload left half way and replaced by a whole one.
        ASSERT_FALSE(renderer.beginUpload(scene[1], 4096));
        EXPECT_FALSE(renderer.continueUpload(4096));
        renderer.upload(*scene[1]);
        EXPECT_FALSE(renderer.uploading());
        EXPECT_EQ(renderer.renderImage(camera, kW, kH, o.render), whole[1]);
        staged(0);
    }
}

// Labels (L-Py's @L) are painted into pictures where the camera shows their points: the text
// just right of and above the point, and nothing elsewhere.
TEST(Render, LabelsArePaintedAtTheirPoints) {
    auto g = grammarOf("axiom: F\n");
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    Snapshot shot;
    std::string error;
    ASSERT_TRUE(renderSnapshot(g, o, shot, error)) << error;
    const Image before = shot.image;
    shot.geometry.labels.push_back({{0, 0.5f, 0}, "Label 42", 13, 0xFFFFFFFFu});
    const render::Camera camera = snapshotCamera(shot.geometry, o);
    float x = 0, y = 0;
    ASSERT_TRUE(labelPosition(camera, kW, kH, {0, 0.5f, 0}, x, y));
    EXPECT_NEAR(x, kW / 2.0f, kW / 10.0f) << "the stem's middle is near the picture's";
    paintLabels(shot.image, shot.geometry, camera);
    int inside = 0, outside = 0;
    for (int py = 0; py < kH; ++py)
        for (int px = 0; px < kW; ++px) {
            const std::size_t i = (std::size_t(py) * kW + std::size_t(px)) * 4;
            const bool changed = before.rgba[i] != shot.image.rgba[i] || before.rgba[i + 1] != shot.image.rgba[i + 1];
            const bool inBox = px >= int(x) && px < int(x) + 8 * 8 + 8 && py >= int(y) - 18 && py <= int(y) + 2;
            (inBox ? inside : outside) += changed;
        }
    EXPECT_GT(inside, 60) << "the text's pixels";
    EXPECT_EQ(outside, 0) << "nothing painted elsewhere";
}

// Many lines drawn without multisampling (RenderOptions::quickLines, the window's view on
// software GL) are the same plant: the thinnest stems lose their smoothed edges only. A plant
// with fewer lines than that is drawn as it always is.
TEST(Render, ManyLinesDrawnQuickAreTheSamePlant) {
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    for (int n : {9, 5}) {
        SCOPED_TRACE("fractal_plant n=" + std::to_string(n));
        auto g = grammarOf(std::string(*presetText("fractal_plant")));
        DeriveResult d = derive(g, n);
        ASSERT_TRUE(d.outcome.ok());
        auto geometry = std::make_shared<Geometry>();
        interpret(*d.string, *g, {n, 1, nullptr}, *geometry);
        render::PreparedScene scene;
        render::Renderer::prepareForViewer(*geometry, scene, geometry);
        renderer.upload(scene);
        SnapshotOptions o;
        o.width = kW, o.height = kH;
        const render::Camera camera = snapshotCamera(*geometry, o);
        const std::vector<std::uint8_t> smooth = renderer.renderImage(camera, kW, kH, o.render);
        o.render.quickLines = true;
        const std::vector<std::uint8_t> quick = renderer.renderImage(camera, kW, kH, o.render);
        ASSERT_EQ(quick.size(), smooth.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < quick.size(); i += 4)
            differ += std::abs(int(quick[i]) - int(smooth[i])) + std::abs(int(quick[i + 1]) - int(smooth[i + 1])) +
                          std::abs(int(quick[i + 2]) - int(smooth[i + 2])) >
                      30;
        if (n == 9) {
            ASSERT_GT(scene.lines.size() / 8, 100'000u) << "many lines";
            EXPECT_GT(differ, 0u) << "drawn another way";
            EXPECT_LT(differ, std::size_t(kW * kH) / 20) << "the same plant";
        } else {
            ASSERT_LT(scene.lines.size() / 8, 100'000u);
            EXPECT_EQ(differ, 0u) << "few lines: drawn as always";
        }
    }
}

// A plant of a few thousand stems at full detail has many long thin triangles, which a
// software rasteriser pays for: while the view moves it is drawn from its interactive bake
// (far fewer triangles, thin stems as lines), in the same place; still, whole.
TEST(Render, MidSizePlantMovesAsItsCoarserBake) {
    auto g = grammarOf(std::string(*presetText("fractal_plant")) + "\nn: 6\n");  // 6,048 stems
    Geometry geometry;
    render::PreparedScene scene;
    ASSERT_TRUE(preparePlant(g, 6, render::Quality::Still, geometry, scene));
    ASSERT_GT(scene.baked.indices.size() / 3, render::PreparedScene::kProxyTriangles);
    ASSERT_FALSE(scene.proxyBaked.indices.empty());
    EXPECT_LT(2 * scene.proxyBaked.indices.size(), scene.baked.indices.size());
    EXPECT_LT(expectMovingFrameOnThePlant(geometry, scene, 50, 3, "the coarser bake"), scene.baked.indices.size() / 3 / 2);
}

// A plant drawn as generalized cylinders is one big polygon mesh, with no stems to sketch:
// while the view moves its mesh is clustered on a grid (far fewer triangles), in the same
// place.
TEST(Render, PolygonPlantMovesAsItsClusteredMesh) {
    auto g = grammarOf(std::string(*presetText("cpfg_abop_2_8_ternary_gc")));
    const int n = g->settings.iterations;
    Geometry geometry;
    render::PreparedScene scene;
    ASSERT_TRUE(preparePlant(g, n, render::Quality::Still, geometry, scene));
    ASSERT_GT(geometry.polygons.indices.size() / 3, 100000u);
    ASSERT_FALSE(scene.proxyBaked.indices.empty());
    EXPECT_LT(4 * scene.proxyBaked.indices.size(), scene.baked.indices.size()) << "far fewer triangles";
    EXPECT_LE(scene.proxyBaked.indices.size() / 3, render::PreparedScene::kMovingTriangles) << "on a coarser grid";
    EXPECT_GT(scene.proxyBaked.indices.size() / 3, render::PreparedScene::kMovingTriangles / 4) << "not coarser than that";
    expectMovingFrameOnThePlant(geometry, scene, 50, 3, "the clustered mesh");
}

// A leafy plant: its leaves, petals and spheres are most of its triangles (144, 120 and 320
// each). While the view moves they are drawn from 12 to 48 triangles each (llvmpipe
// transforms vertices on one thread), in the same place; still, whole.
TEST(Render, LeafyPlantMovesWithCoarseLeaves) {
    auto g = grammarOf("n: 6\nangle: 30\nwidth: 0.08\naxiom: A\nA -> F[+~leaf(1.5)A]/(90)[-~petal(1.2)A]@O(0.3)\n");
    Geometry geometry;
    render::PreparedScene scene;
    ASSERT_TRUE(preparePlant(g, 6, render::Quality::Still, geometry, scene));
    ASSERT_GT(geometry.surfaces.size(), 150u);
    ASSERT_FALSE(scene.proxyBaked.indices.empty());
    EXPECT_LT(6 * scene.proxyBaked.indices.size(), scene.baked.indices.size()) << "a sixth of the triangles";
    EXPECT_EQ(scene.proxy.size(), scene.lines.size()) << "its stems as they are";
    expectMovingFrameOnThePlant(geometry, scene, 50, 2, "the coarse leaves");
    // Leaves of 12 triangles past PreparedScene::kMovingTriangles: of 6.
    auto many = grammarOf("n: 9\nangle: 30\nwidth: 0.08\naxiom: A\nA -> F[+~leaf(1.5)A]/(90)[-~leaf(1.2)A]\n");
    ASSERT_TRUE(preparePlant(many, 9, render::Quality::Still, geometry, scene));
    ASSERT_GT(geometry.surfaces.size(), render::PreparedScene::kMovingTriangles / 12);
    ASSERT_FALSE(scene.proxyBaked.indices.empty());
    EXPECT_EQ(scene.proxyBaked.indices.size() / 3, 6 * geometry.surfaces.size()) << "every leaf, its stems as lines";
    expectMovingFrameOnThePlant(geometry, scene, 50, 2, "leaves of 6 triangles");
}

TEST(Render, LeavesAreGreen) {
    auto g = grammarOf("angle: 40\nwidth: 0.05\naxiom: F[+~leaf(3)][-~leaf(3)]F[+~leaf(3)][-~leaf(3)]F\n");
    SnapshotOptions o = plain();
    Image img = render(g, o);
    Mask m = plantMask(img, emptyScene(o));
    int green = 0;
    for (std::size_t i = 0; i < m.on.size(); ++i)
        if (m.on[i]) green += img.rgba[i * 4 + 1] > img.rgba[i * 4] + 10 && img.rgba[i * 4 + 1] > img.rgba[i * 4 + 2] + 10;
    EXPECT_GT(m.count, kW * kH / 20);
    EXPECT_GT(double(green) / m.count, 0.8);
}

TEST(Render, KochCurveIsLeftRightSymmetric) {
    SnapshotOptions o = plain();
    o.width = 321;  // odd: the axis of symmetry is a pixel column
    Image img = render(grammarOf(*presetText("koch")), o);
    Image empty = render(grammarOf("axiom: X\n"), o);
    Mask m = plantMask(img, empty);
    int agree = 0, total = 0;
    for (int y = 0; y < m.h; ++y)
        for (int x = 0; x < m.w; ++x)
            if (m.at(x, y)) {
                ++total;
                // Allow one pixel of rasterisation difference.
                bool mirrored = false;
                for (int dx = -1; dx <= 1; ++dx) {
                    int mx = m.w - 1 - x + dx;
                    if (mx >= 0 && mx < m.w && m.at(mx, y)) mirrored = true;
                }
                agree += mirrored;
            }
    ASSERT_GT(total, 500);
    EXPECT_GT(double(agree) / total, 0.97);
}

// ABOP fig. 1.25: a bush with leaves (n=5), which shades itself and its ground.
constexpr const char* kLeafyBush =
    "n: 5\nangle: 22.5\nwidth: 0.4\naxiom: A\nA -> [&FL!A]/////'[&FL!A]///////'[&FL!A]\n"
    "F -> S/////F\nS -> FL\nL -> [^^{-f+f+f-|-f+f+f}]\n";

TEST(Render, ShadowDarkensTheGroundUnderATree) {
    auto g = grammarOf(kLeafyBush);
    SnapshotOptions lit;
    lit.render.shadows = true;
    SnapshotOptions unlit = lit;
    unlit.render.shadows = false;
    Image a = render(g, lit), b = render(g, unlit);
    // Pixels of the ground that the shadow makes clearly darker.
    int darker = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        int la = a.rgba[i] + a.rgba[i + 1] + a.rgba[i + 2], lb = b.rgba[i] + b.rgba[i + 1] + b.rgba[i + 2];
        darker += la + 60 < lb;
    }
    EXPECT_GT(darker, kW * kH / 200);
}

// Pixels where the sun's shadow changes the picture (lit against unlit, more than 30 of 765).
std::vector<bool> shadowedPixels(render::Renderer& renderer, const render::Camera& camera, const SnapshotOptions& o,
                                 render::Quality quality, bool ground) {
    render::RenderOptions lit = o.render;
    lit.quality = quality;
    lit.ground = ground;
    lit.shadows = true;
    render::RenderOptions unlit = lit;
    unlit.shadows = false;
    const std::vector<std::uint8_t> a = renderer.renderImage(camera, kW, kH, lit), b = renderer.renderImage(camera, kW, kH, unlit);
    std::vector<bool> out(a.size() / 4);
    for (std::size_t i = 0; i < a.size(); i += 4)
        out[i / 4] = std::abs(int(a[i]) - int(b[i])) + std::abs(int(a[i + 1]) - int(b[i + 1])) + std::abs(int(a[i + 2]) - int(b[i + 2])) > 30;
    return out;
}

// The leafy bush of ABOP fig. 1.25 (n=2) uploaded to a headless renderer, and the camera a
// snapshot of kW x kH frames it with.
struct LeafyBushView {
    Geometry geometry;
    std::unique_ptr<HeadlessRenderer> headless = headlessRenderer();
    SnapshotOptions o;
    render::Camera camera;
    LeafyBushView() {
        auto g = grammarOf(kLeafyBush);
        DeriveResult d = derive(g, 2);
        if (d.outcome.ok()) interpret(*d.string, *g, {2, 1, nullptr}, geometry);
        o.width = kW, o.height = kH;
        camera = snapshotCamera(geometry, o);
        if (headless) headless->renderer.upload(geometry);
    }
};

// On a software rasteriser a moving frame lights the plant without the shadow map's lookups
// (thin stems are shaded in whole blocks of pixels, nine lookups each); the ground keeps the
// plant's shadow. The leafy bush shades itself in the still view.
TEST(Render, MovingFrameOnSoftwareGlKeepsTheGroundsShadowNotThePlants) {
    LeafyBushView v;
    ASSERT_FALSE(v.geometry.cylinders.empty());
    ASSERT_TRUE(v.headless);
    render::Renderer& renderer = v.headless->renderer;
    ASSERT_TRUE(renderer.software());
    const SnapshotOptions& o = v.o;
    const render::Camera& camera = v.camera;
    auto differing = [&](render::Quality quality, bool ground) {
        const std::vector<bool> s = shadowedPixels(renderer, camera, o, quality, ground);
        return int(std::count(s.begin(), s.end(), true));
    };
    EXPECT_GT(differing(render::Quality::Still, false), kW * kH / 400) << "the still view: the plant shades itself";
    ASSERT_LT(renderer.stats().triangles, 4000u) << "a small plant (a big one moves with no shadow at all)";
    EXPECT_EQ(differing(render::Quality::Interactive, false), 0) << "moving: no shadow on the plant";
    EXPECT_GT(differing(render::Quality::Interactive, true), kW * kH / 200) << "moving: the ground's shadow";
}

// Moving frames on software GL read the ground's shadow from a texture made with the shadow
// map (once, not per frame): the same shadow on the ground as the still picture's lookups.
TEST(Render, MovingGroundReadsThePlantsShadowFromATextureMadeWithTheMap) {
    LeafyBushView v;
    ASSERT_FALSE(v.geometry.cylinders.empty());
    ASSERT_TRUE(v.headless);
    render::Renderer& renderer = v.headless->renderer;
    ASSERT_TRUE(renderer.software());
    const Geometry& geometry = v.geometry;
    const SnapshotOptions& o = v.o;
    const render::Camera& camera = v.camera;
    // The still view as the window draws it, in pieces: its shadow map, and the texture with it.
    auto stillInPieces = [&] {
        render::RenderOptions lit = o.render;
        lit.ground = lit.shadows = true;
        renderer.beginDraw(camera, kW, kH, lit);  // into the headless context's own image
        while (!renderer.continueDraw(2000)) {
        }
    };
    stillInPieces();
    EXPECT_EQ(renderer.groundShadowTextures(), 0) << "not in the picture's pieces";
    EXPECT_TRUE(renderer.prepareMoving()) << "made from its shadow map once it is shown";
    EXPECT_FALSE(renderer.prepareMoving());
    const std::vector<bool> still = shadowedPixels(renderer, camera, o, render::Quality::Still, true);
    const std::vector<bool> onPlant = shadowedPixels(renderer, camera, o, render::Quality::Still, false);
    EXPECT_EQ(renderer.groundShadowTextures(), 1);
    const std::vector<bool> moving = shadowedPixels(renderer, camera, o, render::Quality::Interactive, true);
    shadowedPixels(renderer, camera, o, render::Quality::Interactive, true);
    EXPECT_EQ(renderer.groundShadowTextures(), 1) << "not made again for each moving frame";
    int ground = 0, both = 0, movingOnly = 0;
    for (std::size_t i = 0; i < still.size(); ++i) {
        if (onPlant[i]) continue;  // the plant's shadow on itself: not drawn while moving
        ground += still[i];
        both += still[i] && moving[i];
        movingOnly += moving[i] && !still[i];
    }
    std::printf("ground shadow: %d pixels still, %d of them moving, %d moving only\n", ground, both, movingOnly);
    ASSERT_GT(ground, kW * kH / 200) << "the still picture's shadow on the ground";
    EXPECT_GT(both, ground * 6 / 10) << "moving, the ground's shadow is where the still one is";
    EXPECT_LT(movingOnly, ground * 4 / 10) << "and not elsewhere";
    // Another plant: its shadow map, and the texture with it, made by a moving frame that
    // comes before the picture is shown, and then not again.
    Geometry taller = geometry;
    for (auto& c : taller.cylinders) c.start.y *= 1.5f, c.end.y *= 1.5f;
    renderer.upload(taller);
    stillInPieces();
    shadowedPixels(renderer, camera, o, render::Quality::Interactive, true);
    EXPECT_EQ(renderer.groundShadowTextures(), 2);
    EXPECT_FALSE(renderer.prepareMoving());
    EXPECT_EQ(renderer.groundShadowTextures(), 2);
    // A picture drawn at once (`sprout render`) makes none: no moving frames follow it.
    renderer.upload(geometry);
    shadowedPixels(renderer, camera, o, render::Quality::Still, true);
    EXPECT_FALSE(renderer.prepareMoving());
    EXPECT_EQ(renderer.groundShadowTextures(), 2);
}

// The environment drawn with the plant: a region is blue-tinted glass around the stem, an
// obstacle is solid stone, and a slice of the light grid is deep blue in the leaves' shade.
TEST(Render, EnvironmentIsDrawnWhenAsked) {
    auto g = grammarOf("n: 0\nenvironment: sphere 0 2 0 1.5\naxiom: F(4) ?E(0,0)\n");
    SnapshotOptions o = plain();
    Image without = render(g, o);
    o.showEnvironment = true;
    Image with = render(g, o);
    int glass = 0;
    for (std::size_t i = 0; i < with.rgba.size(); i += 4) {
        const int d = std::abs(int(with.rgba[i]) - int(without.rgba[i])) + std::abs(int(with.rgba[i + 2]) - int(without.rgba[i + 2]));
        glass += d > 12 && with.rgba[i + 2] > with.rgba[i] + 10;
    }
    EXPECT_GT(glass, kW * kH / 20) << "the sphere tints the picture blue";
    // Moving, on software GL, the glass is lit without the shadow map's lookups: the same tint.
    o.render.quality = render::Quality::Interactive;
    o.render.shadows = true;
    o.render.ground = true;
    Image moving = render(g, o);
    o.render.quality = render::Quality::Still;
    Image still = render(g, o);
    int differ = 0;
    for (std::size_t i = 0; i < still.rgba.size(); i += 4)
        differ += std::abs(int(moving.rgba[i]) - int(still.rgba[i])) + std::abs(int(moving.rgba[i + 1]) - int(still.rgba[i + 1])) +
                      std::abs(int(moving.rgba[i + 2]) - int(still.rgba[i + 2])) > 30;
    EXPECT_LT(differ, kW * kH / 50) << "the moving picture of the glass is the still one";
    o = plain();
    o.showEnvironment = true;
    // A solid obstacle hides what is behind it: the middle of the picture is its stone grey.
    auto stone = grammarOf("n: 0\nenvironment: obstacle box -2 0 -2 2 4 2\naxiom: F(4) ?E(1,0,0,0,0)\n");
    Image box = render(stone, o), bare = render(stone, plain());
    const std::size_t at = (std::size_t(kH / 2) * kW + kW / 2 + kW / 8) * 4;  // beside the stem
    const std::uint8_t *mid = &box.rgba[at], *sky = &bare.rgba[at];
    EXPECT_LT(std::abs(int(mid[0]) - int(mid[1])), 30);
    EXPECT_LT(std::abs(int(mid[1]) - int(mid[2])), 40);
    // The sky there is bluer and brighter than the stone in front of it.
    EXPECT_GT(int(sky[0]) + sky[1] + sky[2] - (int(mid[0]) + mid[1] + mid[2]), 60) << "the stone hides the sky";
    EXPECT_GT(int(sky[2]) - sky[0], int(mid[2]) - mid[0] + 10);
    // A leafy crown over a slice of its light: deep blue cells in its shade.
    auto crown = grammarOf("n: 0\nenvironment: light 0.5 2\naxiom: F(4) [ &(90) ~l(2) ] [ ^(90) ~l(2) ] [ +(90) ~l(2) ] ?E(1)\n");
    o.environmentView.lightSlice = true;
    o.environmentView.sliceHeight = 0.6;
    Image slice = render(crown, o);
    int shade = 0;
    for (std::size_t i = 0; i < slice.rgba.size(); i += 4) shade += slice.rgba[i + 2] > slice.rgba[i] + 60 && slice.rgba[i] < 110;
    EXPECT_GT(shade, 200) << "the shade under the leaves is drawn";
}

// A picture is opaque in every pixel: where the ground fades into the sky and through the
// environment's glass as well (their blending made alpha a*a + (1 - a): 0.75 at the ground's
// rim in a PNG of `sprout render`, shown paler than it is wherever a PNG is laid over white).
TEST(Render, PicturesAreOpaqueWhereTheGroundFadesAndThroughGlass) {
    auto g = grammarOf("n: 0\nenvironment: sphere 0 2 0 1.5\naxiom: F(4) ?E(0,0)\n");
    SnapshotOptions o;
    o.showEnvironment = true;
    for (render::Quality q : {render::Quality::Still, render::Quality::Interactive}) {
        o.render.quality = q;
        const Image img = render(g, o);
        int translucent = 0;
        for (std::size_t i = 3; i < img.rgba.size(); i += 4) translucent += img.rgba[i] != 255;
        EXPECT_EQ(translucent, 0) << "pixels not opaque, quality " << int(q);
    }
}

// The environment's passes draw their own triangles: the opaque ones once, the glass twice
// (its far side, then its near side), where each pass had drawn them all; the picture is the
// same, whole or in pieces (PictureDrawnInPiecesIsThePictureDrawnWhole).
TEST(Render, EnvironmentPassesDrawOnlyTheirOwnTriangles) {
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    render::Renderer& renderer = headless->renderer;
    // A glass crown with its free attraction points, opaque.
    auto g = grammarOf("n: 0\nenvironment: attraction 200 sphere 0 6 0 3 influence 3 kill 0.5\naxiom: F(4)\n");
    DeriveResult d = derive(g, 0);
    ASSERT_TRUE(d.outcome.ok());
    auto geometry = std::make_shared<Geometry>();
    interpret(*d.string, *g, {0, 1, nullptr}, *geometry);
    render::PreparedScene scene;
    render::Renderer::prepareForViewer(*geometry, scene, geometry);
    renderer.upload(scene);
    Mesh environment;
    ASSERT_TRUE(drawEnvironment(g->environment, *geometry, 1, EnvironmentView(), environment));
    std::size_t opaque = 0, glass = 0;
    for (std::size_t t = 0; t < environment.indices.size(); t += 3)
        ++((environment.colours[environment.indices[t]] & 0xffu) == 0xffu ? opaque : glass);
    ASSERT_GT(opaque, 0u);
    ASSERT_GT(glass, 0u);
    renderer.setOverlay(environment);
    SnapshotOptions o = plain();
    const render::Camera camera = snapshotCamera(*geometry, o);
    for (render::Quality q : {render::Quality::Still, render::Quality::Interactive}) {
        o.render.quality = q;
        renderer.renderImage(camera, kW, kH, o.render);
        EXPECT_EQ(renderer.stats().overlayDrawn, opaque + 2 * glass);
    }
    renderer.setOverlay(Mesh());
}

TEST(Render, TwoDimensionalCurvesAreCrispInk) {
    Image img = render(grammarOf(*presetText("koch")), plain());
    int ink = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) ink += img.rgba[i + 1] < 100 && img.rgba[i] < 100;
    EXPECT_GT(ink, 300);  // dark line pixels, not shaded tubes
}

// Golden images: the presets at 320x180 against tests/golden/<name>.png. A render may differ
// by rasterisation details between CPUs, so the comparison allows a small mean difference.
// Regenerate with: SPROUT_UPDATE_GOLDENS=1 build/tests/render_tests --gtest_filter='Render.Golden*'
TEST(Render, GoldenImages) {
    const std::filesystem::path dir = SPROUT_GOLDEN_DIR;
    const bool update = std::getenv("SPROUT_UPDATE_GOLDENS") != nullptr;
    for (const char* name : {"fractal_plant", "koch", "bush", "dandelion", "fern"}) {
        Image img = render(grammarOf(*presetText(name)));
        const std::string path = (dir / (std::string(name) + ".png")).string();
        std::string error;
        if (update) {
            ASSERT_TRUE(writePng(path, img, error)) << error;
            continue;
        }
        Image golden;
        ASSERT_TRUE(readPng(path, golden, error)) << path << ": " << error;
        ASSERT_EQ(golden.width, img.width);
        ASSERT_EQ(golden.height, img.height);
        double diff = 0;
        int bad = 0;
        for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d += std::abs(int(img.rgba[i + c]) - int(golden.rgba[i + c]));
            diff += d;
            bad += d > 60;
        }
        diff /= double(img.width * img.height * 3);
        EXPECT_LT(diff, 2.0) << name << ": mean difference per channel";
        EXPECT_LT(bad, img.width * img.height / 50) << name << ": pixels that differ a lot";
    }
}

// A small forest (3x3, no grass) against its golden image.
TEST(Render, GoldenSmallForest) {
    Forest f = *parseForest("scene: forest\ngrid: 3 3\nspacing: 30\nseed: 7\nspecies: tree_4_3 0.5\n"
                            "species: bushy_tree_4_4 0.5\n").forest;
    Snapshot shot;
    ForestStats stats;
    std::string error;
    auto presets = [](const std::string& name) -> std::optional<std::string> {
        auto t = presetText(name);
        return t ? std::optional<std::string>(std::string(*t)) : std::nullopt;
    };
    ASSERT_TRUE(buildForest(f, presets, shot.geometry, stats, error)) << error;
    EXPECT_EQ(stats.plants, 9);
    SnapshotOptions o;
    o.width = kW;
    o.height = kH;
    ASSERT_TRUE(renderGeometry(o, shot, error)) << error;
    const std::string path = (std::filesystem::path(SPROUT_GOLDEN_DIR) / "forest.png").string();
    if (std::getenv("SPROUT_UPDATE_GOLDENS")) {
        ASSERT_TRUE(writePng(path, shot.image, error)) << error;
        return;
    }
    Image golden;
    ASSERT_TRUE(readPng(path, golden, error)) << error;
    ASSERT_EQ(golden.rgba.size(), shot.image.rgba.size());
    int differ = 0;
    for (std::size_t i = 0; i < golden.rgba.size(); i += 4) differ += std::abs(int(golden.rgba[i + 1]) - int(shot.image.rgba[i + 1])) > 60;
    EXPECT_LT(differ, kW * kH / 50);
}

// The Barnsley fern preset (an IFS) against its golden image, with 2 M points.
TEST(Render, GoldenBarnsleyFern) {
    auto parsed = parseIfs(*presetText("barnsley_fern"));
    ASSERT_TRUE(parsed.ifs);
    Ifs ifs = *parsed.ifs;
    ifs.points = 2'000'000;
    Density d;
    ASSERT_TRUE(chaosGame(ifs, kW, kH, d, 2));
    Image img{kW, kH, toneMap(d, ifs.colour, 0xF4F2EAFF), {}};
    const std::string path = (std::filesystem::path(SPROUT_GOLDEN_DIR) / "barnsley_fern.png").string();
    std::string error;
    if (std::getenv("SPROUT_UPDATE_GOLDENS")) {
        ASSERT_TRUE(writePng(path, img, error)) << error;
        return;
    }
    Image golden;
    ASSERT_TRUE(readPng(path, golden, error)) << error;
    ASSERT_EQ(golden.rgba.size(), img.rgba.size());
    int differ = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) differ += std::abs(int(img.rgba[i + 1]) - int(golden.rgba[i + 1])) > 40;
    EXPECT_LT(differ, kW * kH / 100);
}

TEST(Render, PngRoundTripKeepsPixelsAndText) {
    Image img = render(grammarOf(*presetText("koch")), plain());
    img.text = {{"lsys", "axiom: F\nF -> F+F\n"}};
    const std::string path = testing::TempDir() + "sprout_roundtrip.png";
    std::string error;
    ASSERT_TRUE(writePng(path, img, error)) << error;
    Image back;
    ASSERT_TRUE(readPng(path, back, error)) << error;
    EXPECT_EQ(back.rgba, img.rgba);
    ASSERT_EQ(back.text.size(), 1u);
    EXPECT_EQ(back.text[0].second, "axiom: F\nF -> F+F\n");
    EXPECT_FALSE(readPng("/nonexistent.png", back, error));
    std::ofstream(path) << "not a png";
    EXPECT_FALSE(readPng(path, back, error));
    EXPECT_EQ(error, "not a PNG file");
}

}  // namespace
}  // namespace sprout

namespace sprout {
// The closed stems (tubes with their caps) come first in the bake, wound outwards, and are drawn
// with their back faces culled: every one of their triangles faces the way its corners' normals
// do (a stem wound inwards would vanish), and the picture is the one drawn without culling but
// for pixels where two stems meet at the same depth. A translucent scene, regrouped, culls none.
TEST(Render, ClosedStemsAreWoundOutwardsAndDrawnCulledAsTheyLook) {
    Geometry geometry;
    render::PreparedScene scene;
    ASSERT_TRUE(preparePlant(grammarOf("angle: 25\nwidth: 0.3\naxiom: F\nF -> F[+F]F[-F]F\n"), 3, render::Quality::Still, geometry, scene));
    ASSERT_GT(scene.closedStems, 100u);
    ASSERT_LE(3 * scene.closedStems, scene.baked.indices.size());
    int inwards = 0;
    for (std::size_t t = 0; t < scene.closedStems; ++t) {
        const mesh::BakedVertex* v[3];
        for (int k = 0; k < 3; ++k) v[k] = &scene.baked.vertices[scene.baked.indices[3 * t + std::size_t(k)]];
        const glm::vec3 face = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
        if (glm::length(face) > 1e-12f && glm::dot(face, v[0]->normal + v[1]->normal + v[2]->normal) < 0) ++inwards;
    }
    EXPECT_EQ(inwards, 0) << "of " << scene.closedStems << " closed stems' triangles";
    auto headless = headlessRenderer();
    ASSERT_TRUE(headless);
    SnapshotOptions o = plain();
    o.width = kW, o.height = kH;
    const render::Camera camera = snapshotCamera(geometry, o);
    headless->renderer.upload(scene);
    const std::vector<std::uint8_t> culled = headless->renderer.renderImage(camera, kW, kH, o.render);
    render::PreparedScene uncut = scene;
    uncut.closedStems = 0;
    headless->renderer.upload(uncut);
    const std::vector<std::uint8_t> whole = headless->renderer.renderImage(camera, kW, kH, o.render);
    std::size_t differ = 0;
    for (std::size_t i = 0; i + 3 < whole.size(); i += 4)
        differ += std::abs(int(culled[i]) - int(whole[i])) + std::abs(int(culled[i + 1]) - int(whole[i + 1])) +
                      std::abs(int(culled[i + 2]) - int(whole[i + 2])) > 24;
    EXPECT_LT(differ, std::size_t(kW * kH / 1000)) << "pixels differ with the back faces culled";
    const PlantPixels p = plantPixels(culled, whole, emptyScene(o));
    EXPECT_GT(p.inWhole, kW * kH / 50) << "the plant is drawn";

    Geometry glassy;
    render::PreparedScene translucent;
    ASSERT_TRUE(preparePlant(grammarOf("palette: #6b4a2e80\naxiom: ;(0) F[+F]F\n"), 0, render::Quality::Still, glassy, translucent));
    EXPECT_GT(translucent.translucent, 0u);
    EXPECT_EQ(translucent.closedStems, 0u) << "regrouped: none culled";
}
}  // namespace sprout
