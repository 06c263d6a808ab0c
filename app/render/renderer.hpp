#pragma once
// The OpenGL 3.3 core renderer, one code path for the window and for headless rendering:
// it takes a context that is already current and a proc loader, keeps the plant's
// instance data on the GPU, and draws into whatever framebuffer it is given (multisampled
// internally, resolved into the target). No GL types leak out of this header.
#include <atomic>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/mesh/bake.hpp"
#include "app/render/camera.hpp"
#include "core/turtle/geometry.hpp"

namespace sprout::render {

using ProcAddress = void (*)();
using ProcLoader = ProcAddress (*)(const char* name);

enum class Quality {
    Still,        // screenshots and renders: full mesh detail
    Interactive,  // the window while it moves: coarser meshes for big plants
};

// The viewer edits plants with more stems than this at Interactive detail (its still view
// too: a big plant's picture in the window); pictures and exports take Still detail.
constexpr std::size_t kViewerDetailStems = 20000;
// The detail the viewer draws a plant of `stems` stems at.
inline Quality viewerDetail(std::size_t stems) { return stems > kViewerDetailStems ? Quality::Interactive : Quality::Still; }

struct RenderOptions {
    Quality quality = Quality::Still;
    glm::vec3 sunDirection{-0.45f, 0.85f, 0.35f};  // towards the sun
    float sunIntensity = 1.0f;
    bool shadows = true;
    bool ground = true;
    glm::vec3 backgroundTop{0.62f, 0.76f, 0.90f};
    glm::vec3 backgroundBottom{0.95f, 0.95f, 0.92f};
    glm::vec3 groundColour{0.58f, 0.55f, 0.45f};
    glm::vec3 curveInk{0.13f, 0.27f, 0.16f};
    // Lines drawn without multisampling, in moving frames and past kQuickLines lines in still
    // ones: a software rasteriser pays twice for a multisampled line (the n=10 fractal plant's
    // 650 k lines: 142 ms against 66 on llvmpipe at 1440x860). The picture differs only along
    // the thinnest stems, stepped instead of smoothed (1.8% of its pixels by more than 30 of
    // 765). The window's view on software GL sets it, and `sprout render --detail viewer`;
    // other pictures rendered to files do not.
    bool quickLines = false;
};

struct RenderStats {
    std::size_t cylinders = 0, surfaces = 0, triangles = 0;
    std::size_t levels[4] = {0, 0, 0, 0};  // stems drawn as fine mesh, coarse mesh, prism, line
    bool curve = false;                 // drawn as a 2D curve
    bool curveMoved = false;            // a big curve's last raster moved while dragged, not made anew
    bool proxy = false;                 // a big scene drawn as its sketch while the view moves
    bool shadowPass = false;            // the shadow map was drawn for this picture
    std::size_t overlayDrawn = 0;       // the environment's triangles drawn, all its passes together
};

// A plant baked for drawing (CPU only, no GL): made on any thread, uploaded by the thread
// that owns the context. The viewer prepares on its worker so that a big plant's arrival
// costs the window only buffer copies.
struct PreparedScene {
    mesh::BakedMesh baked;                     // stems, leaves, petals, spheres, polygons
    // The translucent triangles (a vertex's alpha below 255: a material's transparency), last
    // in baked.indices in the order they came: drawn after the rest, back to front, blended.
    std::size_t translucent = 0;
    // The first triangles that are closed stems (tubes with their caps, wound outwards): drawn
    // with back faces culled, which no view of a closed tube shows (half of a stem's triangles
    // on a software rasteriser, the picture the same). 0: none culled.
    std::size_t closedStems = 0;
    // The opaque triangles of shining materials (Geometry::shines), grouped after the others.
    std::vector<mesh::ShineRange> shines;
    // The opaque triangles with an image (Geometry::textures, baked.texcoords), grouped by image
    // after the others and before the translucent ones; the images' paths.
    std::vector<mesh::TextureRange> textured;
    std::vector<std::string> textures;
    std::vector<float> lines;            // the thinnest stems: x y z colour, two per line
    std::vector<CylinderInstance> curve; // planar curves: ribbons drawn from these
    // A big planar curve (over 200 k segments): drawn from the geometry's own segments,
    // rasterised on the CPU at the picture's size instead of a ribbon per segment
    // (app/render/curve_raster.hpp). Shared with the geometry's owner, or borrowed from it.
    std::shared_ptr<const Geometry> curveGeometry;
    std::size_t levels[4] = {0, 0, 0, 0};
    std::size_t cylinders = 0, surfaces = 0;
    Bounds bounds;
    bool planarCurve = false;
    Quality detail = Quality::Still;
    // What a moving frame draws instead of the scene (Renderer::prepareMoving, the window's);
    // the full scene is drawn again when the view stops. A big scene's sketch: lines (as `lines`) for its main branches and an even
    // share of the rest, at most kProxyLines, when the scene has more triangles and lines than
    // that. A scene with many triangles (over kProxyTriangles): its bake at interactive
    // detail with leaves, petals and spheres of 12 to 48 triangles, triangles and lines,
    // when that halves its triangles (a software rasteriser pays for long thin triangles: a
    // 6 k-stem plant moved at 25-35 ms a frame, 10 ms so; llvmpipe transforms vertices on one
    // thread: the L-Py flowering plant's 23 k triangles, 2.6 k so), or that bake's sketch.
    // A curve of ribbons past kCurveSketch segments: a line for each segment, drawn in ink (a
    // ribbon is two triangles from a buffer texture: 16-32 k of them took 10 ms a moving frame
    // on llvmpipe at a quarter of the pixels each way).
    std::vector<float> proxy;
    mesh::BakedMesh proxyBaked;
    static constexpr std::size_t kProxyLines = 30000;
    static constexpr std::size_t kProxyTriangles = 4000;
    // The triangles a moving bake aims at (a clustered mesh on coarser grids, leaves of 6
    // triangles, past it): llvmpipe spends about 0.3 us a triangle on one thread, and 21-23 k
    // triangles held `lpy_stochastic_shrub` and the ternary GC tree at 10 ms a moving frame at
    // the smallest resolution.
    static constexpr std::size_t kMovingTriangles = 12000;
    static constexpr std::size_t kCurveSketch = 4000;
};

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Loads GL through `loader`, compiles the shaders and creates the meshes. Needs a
    // current OpenGL 3.3 core context; false with a message when it cannot.
    bool init(ProcLoader loader, std::string& error);
    // Whether the context draws on the CPU (Mesa's llvmpipe or softpipe): what costs there
    // differs (RenderOptions::quickLines).
    bool software() const { return m_software; }
    // Times the ground's shadow texture for moving frames on software GL was made (tests).
    int groundShadowTextures() const;
    // Whether it is made from the shadow map made last (tests).
    bool groundShadowCurrent() const;
    // The context's GL_RENDERER and GL_VERSION strings ("llvmpipe (LLVM 15.0.6, 256 bits)").
    const std::string& glRenderer() const { return m_glRenderer; }
    const std::string& glVersion() const { return m_glVersion; }
    // Copies the plant to the GPU, baked into triangles and lines at the current detail. A big
    // planar curve is drawn from `geometry` itself: it must stay alive until the next upload.
    void upload(const Geometry& geometry);
    void upload(const PreparedScene& scene);
    // A big scene a piece per frame, so that no frame waits for all of it (a 1.57 M-segment
    // plant is some 150 MB of buffers): beginUpload sizes the GPU buffers (and uploads at once
    // what fits in `bytesPerFrame`; true then), continueUpload copies up to `bytes` more each
    // frame and swaps the new scene in when it is whole (true). The scene on screen is drawn
    // until then.
    bool beginUpload(std::shared_ptr<const PreparedScene> scene, std::size_t bytesPerFrame);
    bool continueUpload(std::size_t bytes);
    bool uploading() const;
    // The texture images that could not be read since the last call (each named once, with
    // why), for the window to say; their surfaces are drawn in their colour.
    std::vector<std::string> takeTextureProblems();
    // Whether a staged upload writes into buffers mapped once, persistently (GL 4.4's or
    // ARB_buffer_storage's immutable storage): a piece is then a copy into the mapping, with
    // no call into GL and no copy or wait of the driver's. On where the context has it (Mesa's
    // llvmpipe and GPU drivers do); switched off, the pieces go by glBufferSubData.
    bool persistentUploads() const;
    void setPersistentUploads(bool on);
    // Whether a big planar curve (PreparedScene::curveGeometry) of up to kGpuCurveRibbons
    // segments is drawn as a ribbon per segment, as a small one is, instead of rasterised on
    // the CPU: on a GPU, where every moving frame is then the still picture; not on a software
    // rasteriser. Read at upload; off where the segments do not fit a buffer texture or the
    // GPU's memory. Past the cap the raster is quicker on a GPU too: an H100 drew the 9.8 M
    // ribbons of the quadratic Gosper curve n=5 in 31 ms a frame (its raster, moved as a
    // picture, 4 ms) after a 310 ms upload.
    static constexpr std::size_t kGpuCurveRibbons = 1'000'000;
    bool bigCurveRibbons() const;
    void setBigCurveRibbons(bool on);
    // What is drawn with the plant, translucent, after it: the environment
    // (core/environment/environment_drawing.hpp). An empty mesh draws nothing.
    void setOverlay(const Mesh& mesh);
    // Picked stems and leaves (opaque colours), drawn last and through everything in front.
    void setHighlight(const Mesh& mesh);
    // Bakes a plant at the given detail; thread-safe, no GL.
    // `owner`, when given, is shared by the scene for a big planar curve; without it the scene
    // borrows `geometry`, which must then outlive it.
    // `coarseness` (a moving frame's bake: prepareMoving): 1, leaves, petals and spheres of 12,
    // 12 and 48 triangles; 2, of 6, 6 and 24 (an outline of six points).
    static void prepare(const Geometry& geometry, Quality detail, PreparedScene& out,
                        std::shared_ptr<const Geometry> owner = {}, int coarseness = 0);
    // What a moving frame draws instead of `scene` (prepared from `geometry`): its sketch or a
    // coarser bake, when drawing it whole would cost more than kProxyLines primitives or
    // kProxyTriangles full-detail triangles; nothing else. Thread-safe, no GL.
    static void prepareMoving(const Geometry& geometry, PreparedScene& scene);
    // A plant as the window shows it: at the viewer's detail for its size, with what its
    // moving frames draw (prepare, then prepareMoving). Thread-safe, no GL.
    static void prepareForViewer(const Geometry& geometry, PreparedScene& out, std::shared_ptr<const Geometry> owner = {});
    // Detail of the next upload: Interactive draws more thin stems as lines (the window on a
    // big plant); Still (the default) is for pictures.
    void setDetail(Quality detail);
    // Draws a width x height image into framebuffer `target` (0: the window's or OSMesa's
    // default framebuffer), its lower-left corner at (x, y) there.
    void draw(const Camera& camera, int width, int height, const RenderOptions& options, unsigned target = 0,
              int x = 0, int y = 0);
    // The same picture a piece per frame, so that a frame waits for at most a piece of a big
    // scene (the window's still view on software GL): beginDraw works out the camera,
    // continueDraw draws up to `primitives` more triangles, lines and curve segments (or rows
    // of the sky and ground; the shadow map first, then the picture) and resolves it into the target when it is whole
    // (true then). The target keeps what it held until then; the pixels are those of draw().
    // draw(), renderImage() and a new scene abandon a picture in pieces.
    void beginDraw(const Camera& camera, int width, int height, const RenderOptions& options, unsigned target = 0,
                   int x = 0, int y = 0);
    bool continueDraw(std::size_t primitives);
    // A piece sized to take about `milliseconds` (waited for with glFinish), from the rate the
    // pieces before drew at; a piece is of one phase: the shadow map, the sky and ground (a
    // band of rows), the plant.
    bool continueDrawFor(double milliseconds);
    bool drawing() const;
    // What the last picture drawn by continueDrawFor took to draw, all pieces together (a big
    // curve's raster included); huge until one of this scene is done.
    double lastPictureMs() const { return m_lastPictureMs; }
    // After a picture in pieces is shown: makes what the moving frames to come take from it
    // (on software GL, the ground's shadow texture from its shadow map), unless a moving
    // frame made it already. True when something was made. Keeps the framebuffer bound and
    // the viewport.
    bool prepareMoving();
    // The scene is a big planar curve, drawn from a raster made at the picture's size.
    bool rasterCurve() const;
    // Draws a small scene once in every way the window draws (still and moving, stems,
    // lines and leaves, shadows and ground, a curve: a software rasteriser compiles each
    // way on its first use, which made the first piece of the first picture take 20-50 ms),
    // at width x height (the still view's size) and half that. Leaves no scene uploaded.
    void warmUp(int width, int height);
    // As warmUp does for the window, for one picture to come (`sprout render`): a small plant and
    // a one-segment curve drawn at its size with its options, into the default framebuffer,
    // while the picture's model runs. Stops between passes once `cancel` is set (the model is
    // done: whatever is left is built by its own picture). Leaves no scene uploaded.
    void prime(int width, int height, const RenderOptions& options, const std::atomic<bool>& cancel);
    // Draws into an offscreen image of any size (screenshots larger than the window).
    std::vector<std::uint8_t> renderImage(const Camera& camera, int width, int height, const RenderOptions& options);
    // The lower-left width x height of an RGBA texture (textureWidth x textureHeight, linear
    // filtering) stretched over targetWidth x targetHeight at (x, y) of framebuffer `target`:
    // the window's view, drawn smaller while it moves. A textured quad, not glBlitFramebuffer:
    // llvmpipe stretched a 505x430 picture over the window's 1140x860 view in 3.0 ms by a
    // blit, 2.3 ms by a quad; and no texel past the picture's edge is read.
    void stretch(unsigned texture, int width, int height, int textureWidth, int textureHeight, unsigned target, int x, int y,
                 int targetWidth, int targetHeight);
    // RGBA pixels of framebuffer `source`, top row first.
    std::vector<std::uint8_t> readPixels(int width, int height, unsigned source = 0) const;

    const RenderStats& stats() const { return m_stats; }

private:
    void adopt(const PreparedScene& scene);
    struct Impl;
    struct Pass;
    void plan(Pass& pass, const Camera& camera, int width, int height, const RenderOptions& options, unsigned target, int x,
              int y) const;
    bool step(Pass& pass, std::size_t budget, bool wait);
    // step()'s phases in order (renderer_draw.cpp), each drawing its next piece; false when the
    // picture is not done yet.
    struct Piece;
    bool shadowPhase(Piece& piece);
    bool rasterPhase(Pass& pass, bool wait);
    bool backdropPhase(Piece& piece, bool groundShadowTexture);
    bool scenePhase(Piece& piece);
    bool overlayPhase(Piece& piece);
    void drawHighlight(const Pass& pass);
    glm::vec3 groundCentre(const Pass& pass) const;  // the ground disc's centre, under the plant
    int partOf(const Pass& pass) const;
    std::size_t partEnd(const Pass& pass) const;
    std::unique_ptr<Impl> m;
    std::unique_ptr<Pass> m_progress;  // a picture drawn in pieces (beginDraw)
    double m_lastPictureMs = 1e9;
    bool m_software = false;
    std::string m_glRenderer, m_glVersion;
    RenderStats m_stats;
};

}  // namespace sprout::render
