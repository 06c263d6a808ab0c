#pragma once
// Private to app/render: the renderer's GL state (Renderer::Impl) and a picture's plan and
// progress (Renderer::Pass), shared by renderer.cpp (set-up), renderer_upload.cpp (the scene
// on the GPU), renderer_draw.cpp (pictures) and renderer_phases.cpp (a picture's passes).
#include <cstddef>
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/mesh/texture_images.hpp"
#include "app/render/gl.hpp"
#include "app/render/renderer.hpp"

namespace sprout::render {
namespace detail {

inline constexpr int kShadowSize = 2048;
inline constexpr int kImageUnit = 5;  // the texture unit of a textured triangle's image
// The ground's shadow texture (Impl::ensureGroundShadow), texels across the ground's square:
// about a pixel of a moving frame's ground each (those are drawn at a quarter to a half of
// the window each way).
inline constexpr int kGroundShadowSize = 256;
// RenderOptions::quickLines: from this many lines in a draw on.
inline constexpr std::size_t kQuickLines = 100'000;

struct Buffers {
    GLuint vao = 0, vbo = 0, ebo = 0;
    bool immutable = false;  // storage of glBufferStorage: made anew to take another size
};

}  // namespace detail

// A uniform of the program in use, by name.
inline void setUniform(GLuint p, const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(glGetUniformLocation(p, name), 1, GL_FALSE, glm::value_ptr(m));
}
inline void setUniform(GLuint p, const char* name, const glm::vec3& v) { glUniform3fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
inline void setUniform(GLuint p, const char* name, const glm::vec2& v) { glUniform2fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
inline void setUniform(GLuint p, const char* name, float v) { glUniform1f(glGetUniformLocation(p, name), v); }
inline void setUniform(GLuint p, const char* name, int v) { glUniform1i(glGetUniformLocation(p, name), v); }

struct Renderer::Impl {
    using Buffers = detail::Buffers;
    GLuint bakedProgram = 0, bakedPlainProgram = 0, bakedVertexLitProgram = 0, bakedDepth = 0, lineProgram = 0, inkLineProgram = 0, curveProgram = 0, backgroundProgram = 0,
           groundProgram = 0, groundPlainProgram = 0, curveRasterProgram = 0, curveImpostorProgram = 0, coverageTexture = 0, overlayProgram = 0,
           overlayPlainProgram = 0, stretchProgram = 0, resolveProgram = 0;
    Buffers overlay;  // the environment drawn with the plant (setOverlay)
    std::size_t overlayIndices = 0;
    // Its triangles as uploaded: the opaque ones first (the first pass), then the translucent
    // ones (the glass's two passes); overlayTriangles as given, for the stats.
    std::size_t overlayOpaque = 0, overlayTranslucent = 0, overlayTriangles = 0;
    // The overlay pass a unit of the Overlay phase falls in (0 opaque, 1 far and 2 near sides
    // of the glass), the triangle it draws, and the end of its pass, in units.
    int overlayPass(std::size_t unit) const {
        return unit < overlayOpaque ? 0 : int(std::min<std::size_t>(1 + (unit - overlayOpaque) / std::max<std::size_t>(overlayTranslucent, 1), 2));
    }
    std::size_t overlayTriangle(std::size_t unit) const {
        return unit < overlayOpaque ? unit : overlayOpaque + (unit - overlayOpaque) % std::max<std::size_t>(overlayTranslucent, 1);
    }
    std::size_t overlayPassEnd(int pass) const { return overlayOpaque + std::size_t(pass) * overlayTranslucent; }
    Buffers highlight;  // picked stems, drawn over everything (setHighlight)
    std::size_t highlightIndices = 0;
    Buffers proxy, proxyMesh;  // what a moving frame draws (PreparedScene::proxy, proxyBaked)
    std::size_t proxyCount = 0, proxyIndices = 0;
    Bounds overlayBounds;
    std::shared_ptr<const Geometry> rasterCurve;  // a big planar curve, drawn from its segments
    std::vector<std::uint8_t> coverage;
    // What the coverage texture holds: a frame with the same curve, view and size (the panel
    // redrawn, a still window) reuses it instead of rasterising millions of segments again.
    const Geometry* coverageOf = nullptr;
    glm::mat4 coverageView{0.0f};
    int coverageWidth = 0, coverageHeight = 0;
    Buffers baked, lines, curveQuad, groundQuad;
    Buffers bakedBack, linesBack;  // filled by a staged upload, then swapped in
    // A staged upload: the scene, and how many of its bytes (vertices, indices, lines, in that
    // order) are on the GPU so far.
    std::shared_ptr<const PreparedScene> staging;
    std::size_t stagedBytes = 0;
    // Staged uploads into persistently mapped storage (Renderer::persistentUploads): whether the
    // context has it and it is on, and the back buffers' mappings (vertices, indices, lines)
    // while one is filled.
    bool bufferStorage = false, persistentUploads = false;
    bool bigCurveRibbons = false;  // Renderer::bigCurveRibbons
    void* stagedMaps[3] = {};
    GLuint emptyVao = 0, curveInstances = 0, curveTexture = 0;
    GLuint shadowFbo = 0, shadowTexture = 0;
    // The shadow map depends on the scene and the sun, not on the camera: a picture from
    // another view with the same light uses it as it is (an orbit's still view skips a pass).
    // A moving frame of a scene that changes every frame (growth playback) may use the map of
    // an earlier scene, with the light's matrix it was made with, up to kStaleShadowFrames
    // frames running: fewer shadow updates while it moves.
    bool shadowMade = false;   // the map holds a scene's shadows
    bool shadowValid = false;  // of the scene uploaded now
    glm::mat4 shadowView{0.0f};
    float shadowTexel = 0;
    int shadowAge = 0;  // moving frames that used it since it was made
    std::uint64_t shadowGeneration = 0;  // shadow maps made
    // The plant's shadow on the ground as a texture (ground_shadow.frag) for the moving frames
    // of a software rasteriser: one lookup a pixel (ground_masked.frag) instead of the shadow
    // map's nine, which were half of a small plant's moving frame. Made again when the map,
    // or the ground's centre or radius, changes.
    GLuint groundShadowFbo = 0, groundShadowTexture = 0, groundShadowProgram = 0, groundMaskedProgram = 0;
    std::uint64_t groundShadowOf = UINT64_MAX;  // the shadow map generation it was made from
    glm::vec4 groundShadowAt{0.0f};             // the ground's centre and radius then
    int groundShadowMade = 0;                   // times made (for tests)
    void ensureGroundShadow(const RenderOptions& o, const glm::vec3& eye, const glm::vec3& centre, float radius);
    // The one the window's still view asks for when its shadow map is made, made after the
    // picture is shown (Renderer::prepareMoving) or by the first moving frame.
    struct GroundShadowWanted {
        RenderOptions o;
        glm::vec3 eye{0.0f}, centre{0.0f};
        float radius = 0;
        std::uint64_t generation = 0;  // of the shadow map
    };
    std::optional<GroundShadowWanted> groundShadowWanted;
    // Multisampled images: one for moving frames of big plants (2 samples) and for big curves
    // (1 sample, still and moving), one for other
    // moving frames (4 samples, half size in the window), one for still pictures, so that
    // starting or letting go of a drag does not allocate them again.
    // Their colour is a multisampled texture (read by resolveProgram), or with one sample or
    // none a renderbuffer (copied by glBlitFramebuffer).
    struct Msaa {
        GLuint fbo = 0, colour = 0, colourTexture = 0, depth = 0;
        int width = 0, height = 0, samples = 0;
    } msaa[3];
    const Msaa* msaaInUse = nullptr;  // the one ensureMsaa made or kept last
    std::size_t quickLinesFrom = detail::kQuickLines;  // RenderOptions::quickLines (0 while warming up)
    int samples = 1;
    int curveBatch = 1;

    // What was uploaded.
    std::size_t bakedIndices = 0, lineCount = 0, curveCount = 0;
    Bounds bounds;
    bool planarCurve = false;
    Quality detail = Quality::Still;

    // Baked triangles: position, normal, colour (polygon.vert's layout).
    static void bakedAttributes(GLuint vbo);
    static void makeBaked(Buffers& b);
    // Lines: position, colour.
    static void makeLines(Buffers& b);
    // `b` (of makeBaked, or makeLines when `lines`) with buffers whose size can be set again:
    // made anew when they have immutable storage (or `always`: fresh names for new storage).
    static void mutableAgain(Buffers& b, bool lines, bool always = false);
    // The programs, textures, buffers and the shadow map (Renderer::init); false with a message.
    bool build(std::string& error);
    // The multisampled image of `slot` (see Msaa) at w x h, made or kept; msaaInUse is it.
    void ensureMsaa(int w, int h, int wantSamples, int slot);
    // The image in use (ensureMsaa) resolved into `target` at (x, y); the framebuffer bound
    // after is `target`, depth testing on.
    void resolve(GLuint target, int x, int y, int w, int h);

    // Baked triangles and lines (numbered after the triangles) [from, to), in order.
    // The same of what a moving frame draws instead (proxyMesh, proxy) when `moving`; lines
    // without multisampling when `quickLines` and there are many (RenderOptions::quickLines);
    // triangles drawn by `program` (bakedDepth: a depth pass; bakedPlainProgram: no shadow
    // lookups; bakedVertexLitProgram: lit at the vertices); lines in `ink` when given (a
    // curve's sketch).
    void drawRange(const glm::mat4& viewProj, GLuint program, std::size_t from, std::size_t to, RenderStats& stats,
                   bool moving = false, bool quickLines = false, const glm::vec3* ink = nullptr);
    // The scene's translucent triangles (PreparedScene::translucent), the last of `baked`: a
    // copy of their indices and their centres, drawn from an index buffer of their own in the
    // order of their distance from `eye`, farthest first, sorted again as a picture begins
    // them; blended, without writing depth. In the shadow pass (bakedDepth) those at least half
    // opaque cast shadows (bakedDepthAlpha), in any order.
    std::vector<mesh::ShineRange> shines;  // PreparedScene::shines, drawn with their light's uniforms
    std::size_t translucentTris = 0;
    std::size_t closedStems = 0;  // PreparedScene::closedStems: the first triangles, drawn culled
    std::vector<std::uint32_t> translucentIndices;
    std::vector<glm::vec3> translucentCentres;
    // Each translucent triangle's image (its first vertex's TexCoord::texture; 0: none), and
    // the GL texture of each image id (imageTextures[id - 1]): a textured one is drawn with its
    // image, in runs of the sorted order that share one.
    std::vector<std::uint32_t> translucentImages;
    std::vector<GLuint> imageTextures;
    bool translucentTextured = false;
    GLuint translucentVao = 0, translucentEbo = 0, bakedDepthAlpha = 0;
    glm::vec3 eye{0.0f};  // the camera's, for the order of the translucent triangles
    void adoptTranslucent(const mesh::BakedMesh& baked, std::size_t count);
    // The lit programs' light uniforms: every surface's (uSpecular, uShininess, uEmission), or
    // a shining material's.
    void plainLight(GLuint program);
    void shineLight(GLuint program, const Shine& shine);
    void drawTranslucent(const glm::mat4& viewProj, GLuint program, std::size_t from, std::size_t to);
    std::vector<std::uint32_t> sortedImages;  // translucentImages in the order drawn
    void drawTranslucentRuns(const glm::mat4& viewProj, GLuint program, std::size_t from, std::size_t to);
    // The scene's textured triangles (PreparedScene::textured), before the translucent ones in
    // `baked`: each group with its image (a 1-pixel white one for an image that cannot be
    // read: the triangles in their colour), through a vertex array that adds their u, v from a
    // buffer of their own (none for a scene without textures). Images are made into GL
    // textures once a path (again when the file changes: mesh::textureImage).
    struct TexturedDraw {
        std::size_t first = 0, count = 0;
        GLuint texture = 0;
    };
    std::vector<TexturedDraw> textured;
    std::size_t texturedTris = 0;
    GLuint texturedVao = 0, texturedUvs = 0, texturedProgram = 0, texturedDepth = 0, whiteTexture = 0;
    struct TextureObject {
        std::shared_ptr<const mesh::TextureImage> image;
        GLuint texture = 0;
    };
    std::map<std::string, TextureObject> textureObjects;
    std::vector<std::string> textureProblems;  // Renderer::takeTextureProblems
    void adoptTextured(const PreparedScene& p);
    GLuint textureFor(const std::string& path);
    void drawTextured(const glm::mat4& viewProj, GLuint program, std::size_t from, std::size_t to);
    void texturedAttributes();
    // A big curve's raster made on a thread for a progressive draw, and its time.
    struct Raster {
        std::vector<std::uint8_t> coverage;
        double ms = 0;
    };
    std::future<Raster> raster;
    // Units (primitives, rows) a millisecond each part of each phase of a picture in pieces
    // draws here (Renderer::partOf), learnt from the pieces (continueDrawFor); first guesses
    // for software GL.
    double rate[6][3] = {{1, 5000, 8000}, {1, 1, 1}, {40, 40, 40}, {500, 500, 4000}, {50, 50, 50}, {1, 1, 1}};

    void setLighting(GLuint p, const RenderOptions& o, const glm::vec3& eye, const glm::mat4& lightViewProj, bool shadows,
                     float texel);
};

// One picture: everything worked out from the camera once, then drawn in passes that a
// progressive draw spreads over frames (beginDraw / continueDraw) and draw() runs at once.
// The primitives of a scene are numbered: curve ribbons, then baked triangles, then lines;
// a pass draws a range of them in that order, so a picture drawn in pieces has the pixels
// of one drawn whole.
struct Renderer::Pass {
    glm::mat4 viewProj{1.0f}, lightViewProj{1.0f};
    glm::vec3 eye{0.0f}, centre{0.0f};
    float texel = 0, groundRadius = 0;
    bool shadows = false, ground = false, curve = false, bigInteractive = false;
    bool plantShadows = false;  // the plant lit with the shadow map's lookups (the ground: shadows)
    bool vertexLit = false;     // the plant lit at its vertices (a moving frame on a software rasteriser)
    int width = 0, height = 0, x = 0, y = 0;
    unsigned target = 0;
    RenderOptions o;
    // Progress: the phase, and how many of its units (primitives, or rows of the backdrop)
    // are drawn; the phase and units of the last piece, for pieces sized by time.
    enum Phase { Shadow, Raster, Backdrop, Scene, Overlay, Finish };
    int phase = Shadow;
    std::size_t done = 0;
    bool started = false;  // the phase's set-up is done
    int lastPhase = Shadow, lastPart = 0;
    std::size_t lastUnits = 0;
    double spentMs = 0;  // the pieces' time (continueDrawFor), and a big curve's raster's
    double waitMs = 0;   // how long a piece may wait for the raster's thread (continueDrawFor)
    bool staleShadows = false;  // a moving frame with an earlier scene's shadow map
    bool sketch = false;        // a moving frame that draws the scene's proxy
    const std::atomic<bool>* cancel = nullptr;  // Renderer::prime: stop between passes once set
    RenderStats stats;
};

// The next piece of a phase: how many of its units it draws, and the move to the next phase.
// A piece is of one part of one phase only (their costs differ: a triangle covers pixels, a
// line few), unless all is drawn at once.
struct Renderer::Piece {
    const Renderer& r;
    Pass& p;
    std::size_t budget;
    bool wait;
    std::size_t take(std::size_t total) {
        p.lastPhase = p.phase;
        p.lastPart = r.partOf(p);
        const std::size_t end = wait ? total : std::min(total, r.partEnd(p));
        const std::size_t n = std::min(end - p.done, budget);
        p.lastUnits = n;
        return n;
    }
    bool next(int phase) {
        p.phase = phase, p.done = 0, p.started = false;
        // Go on to it now only when drawing at once (and not cancelled: Renderer::prime).
        return wait && !(p.cancel && p.cancel->load(std::memory_order_relaxed));
    }
};

}  // namespace sprout::render
