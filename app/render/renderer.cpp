#include "app/render/renderer.hpp"

#include "app/render/curve_raster.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <future>
#include <unordered_map>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/render/bake.hpp"
#include "app/render/gl.hpp"
#include "app/render/meshes.hpp"
#include "app/render/shader.hpp"
#include "core/base/bounded.hpp"

namespace sprout::render {
namespace {

constexpr int kShadowSize = 2048;
constexpr int kStaleShadowFrames = 3;

// Levels of detail for stems, chosen by the stem's radius relative to the plant's size (the
// plant is framed whole, so that says how many pixels it covers at 720p): a round mesh with
// caps that close the joints, a coarser one, an open three-sided prism, and plain lines for
// stems under about a pixel. Measured on llvmpipe (2 cores): 98 k segments drawn as lines
// take 6 ms, as prisms baked on the CPU ~40 ms, as instanced cylinders read from a buffer
// texture 1 s; so everything is baked into one mesh and drawn with the simplest shader.
constexpr float kLevelThreshold[3] = {1.0f / 100, 1.0f / 300, 1.0f / 900};  // fine, medium, prism; below: line
// Interactive detail (the window while editing a big plant) trades roundness for speed:
// every triangle costs llvmpipe ~0.2 us of single-threaded setup.
constexpr float kInteractiveScale = 3.0f;
constexpr std::size_t kVertexBudget = 6'000'000;
// Planar curves with more segments than this are rasterised on the CPU (curve_raster.hpp):
// below it every preset keeps its ribbons, pixel for pixel; above it a ribbon per segment
// costs far more than the picture (the quadratic Gosper curve n=5: 9.8 M ribbons, 5.6 s).
constexpr std::size_t kRasterCurveSegments = 200'000;  // ~170 MB baked; past it, thresholds rise

void setUniform(GLuint p, const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(glGetUniformLocation(p, name), 1, GL_FALSE, glm::value_ptr(m));
}
void setUniform(GLuint p, const char* name, const glm::vec3& v) { glUniform3fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* name, const glm::vec2& v) { glUniform2fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* name, float v) { glUniform1f(glGetUniformLocation(p, name), v); }
void setUniform(GLuint p, const char* name, int v) { glUniform1i(glGetUniformLocation(p, name), v); }

struct Buffers {
    GLuint vao = 0, vbo = 0, ebo = 0;
};

}  // namespace

struct Renderer::Impl {
    GLuint bakedProgram = 0, bakedDepth = 0, lineProgram = 0, curveProgram = 0, backgroundProgram = 0,
           groundProgram = 0, curveRasterProgram = 0, curveImpostorProgram = 0, coverageTexture = 0, overlayProgram = 0;
    Buffers overlay;  // the environment drawn with the plant (setOverlay)
    std::size_t overlayIndices = 0;
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
    // Multisampled images: one for moving frames of big plants (2 samples), one for other
    // moving frames (4 samples, half size in the window), one for still pictures, so that
    // starting or letting go of a drag does not allocate them again.
    struct Msaa {
        GLuint fbo = 0, colour = 0, depth = 0;
        int width = 0, height = 0, samples = 0;
    } msaa[3];
    GLuint msaaFbo = 0;  // the one in use
    int samples = 1;
    int curveBatch = 1;

    // What was uploaded.
    std::size_t bakedIndices = 0, lineCount = 0, curveCount = 0;
    Bounds bounds;
    bool planarCurve = false;
    Quality detail = Quality::Still;

    // Baked triangles: position, normal, colour (polygon.vert's layout).
    static void makeBaked(Buffers& b) {
        glGenVertexArrays(1, &b.vao);
        glBindVertexArray(b.vao);
        glGenBuffers(1, &b.vbo);
        glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
        const GLsizei bs = sizeof(BakedVertex);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, bs, reinterpret_cast<void*>(offsetof(BakedVertex, position)));
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, bs, reinterpret_cast<void*>(offsetof(BakedVertex, normal)));
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, bs, reinterpret_cast<void*>(offsetof(BakedVertex, colour)));
        glGenBuffers(1, &b.ebo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ebo);
        glBindVertexArray(0);
    }
    // Lines: position, colour.
    static void makeLines(Buffers& b) {
        glGenVertexArrays(1, &b.vao);
        glBindVertexArray(b.vao);
        glGenBuffers(1, &b.vbo);
        glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 16, nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 16, reinterpret_cast<void*>(12));
        glBindVertexArray(0);
    }

    bool build(std::string& error) {
        struct P {
            GLuint* out;
            const char *vs, *fs;
        } programs[] = {
            {&bakedProgram, "polygon.vert", "lit.frag"},       {&bakedDepth, "polygon.vert", "depth.frag"},
            {&lineProgram, "line.vert", "line.frag"},          {&curveProgram, "curve.vert", "curve.frag"},
            {&backgroundProgram, "background.vert", "background.frag"}, {&groundProgram, "ground.vert", "ground.frag"},
            {&curveRasterProgram, "background.vert", "curve_raster.frag"},
            {&curveImpostorProgram, "curve_impostor.vert", "curve_raster.frag"},
            {&overlayProgram, "polygon.vert", "overlay.frag"},
        };
        for (auto& p : programs)
            if (!(*p.out = buildProgram(p.vs, p.fs, error))) return false;

        glGenTextures(1, &coverageTexture);
        glBindTexture(GL_TEXTURE_2D, coverageTexture);
        // Linear: exact at the size it was made (samples at texel centres), smooth when moved.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);

        // Two sets of baked and line buffers: the one on screen, and the one a staged upload
        // fills a piece per frame (beginUpload) before they swap.
        for (Buffers* b : {&baked, &bakedBack, &overlay, &highlight, &proxyMesh}) makeBaked(*b);
        for (Buffers* b : {&lines, &linesBack, &proxy}) makeLines(*b);

        // Planar curves: screen-space ribbons, segments read from a buffer texture in batches
        // of quads (their width is in pixels, so they cannot be baked).
        glGenBuffers(1, &curveInstances);
        glBindBuffer(GL_TEXTURE_BUFFER, curveInstances);
        glBufferData(GL_TEXTURE_BUFFER, 64, nullptr, GL_STATIC_DRAW);
        glGenTextures(1, &curveTexture);
        glBindTexture(GL_TEXTURE_BUFFER, curveTexture);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_R32UI, curveInstances);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        {
            curveBatch = 1024;
            std::vector<float> v;
            std::vector<std::uint32_t> idx;
            const float corners[4][2] = {{0, -1}, {0, 1}, {1, -1}, {1, 1}};
            for (int copy = 0; copy < curveBatch; ++copy) {
                for (auto& c : corners) v.insert(v.end(), {c[0], c[1], float(copy)});
                std::uint32_t b = std::uint32_t(copy * 4);
                idx.insert(idx.end(), {b, b + 2, b + 1, b + 1, b + 2, b + 3});
            }
            glGenVertexArrays(1, &curveQuad.vao);
            glBindVertexArray(curveQuad.vao);
            glGenBuffers(1, &curveQuad.vbo);
            glBindBuffer(GL_ARRAY_BUFFER, curveQuad.vbo);
            glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * 4), v.data(), GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 12, nullptr);
            glEnableVertexAttribArray(7);
            glVertexAttribPointer(7, 1, GL_FLOAT, GL_FALSE, 12, reinterpret_cast<void*>(8));
            glGenBuffers(1, &curveQuad.ebo);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, curveQuad.ebo);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * 4), idx.data(), GL_STATIC_DRAW);
            glBindVertexArray(0);
        }
        {
            const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
            glGenVertexArrays(1, &groundQuad.vao);
            glBindVertexArray(groundQuad.vao);
            glGenBuffers(1, &groundQuad.vbo);
            glBindBuffer(GL_ARRAY_BUFFER, groundQuad.vbo);
            glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
            glBindVertexArray(0);
        }
        glGenVertexArrays(1, &emptyVao);

        GLint maxSamples = 1;
        glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
        samples = std::clamp(maxSamples, 1, 4);

        glGenTextures(1, &shadowTexture);
        glBindTexture(GL_TEXTURE_2D, shadowTexture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kShadowSize, kShadowSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glGenFramebuffers(1, &shadowFbo);
        glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadowTexture, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (!ok) error = "the shadow map framebuffer is incomplete";
        return ok;
    }

    void ensureMsaa(int w, int h, int wantSamples, int slot) {
        wantSamples = std::min(wantSamples, samples);
        Msaa& t = msaa[slot];
        msaaFbo = t.fbo;
        if (t.fbo && w == t.width && h == t.height && wantSamples == t.samples) return;
        // Moving frames change size with the window's resolution scale: a larger image is
        // drawn into in part (the picture's at the lower-left corner) rather than made again.
        if (slot < 2 && t.fbo && w <= t.width && h <= t.height && 4 * w * h >= t.width * t.height && wantSamples == t.samples)
            return;
        if (!t.fbo) {
            glGenFramebuffers(1, &t.fbo);
            glGenRenderbuffers(1, &t.colour);
            glGenRenderbuffers(1, &t.depth);
        }
        t.samples = wantSamples;
        glBindRenderbuffer(GL_RENDERBUFFER, t.colour);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, t.samples, GL_RGBA8, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, t.depth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, t.samples, GL_DEPTH_COMPONENT24, w, h);
        glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
        t.width = w;
        t.height = h;
        msaaFbo = t.fbo;
    }

    // Baked triangles and lines (numbered after the triangles) [from, to), in order.
    // The same of what a moving frame draws instead (proxyMesh, proxy) when `moving`.
    void drawRange(const glm::mat4& viewProj, bool depthOnly, std::size_t from, std::size_t to, RenderStats& stats,
                   bool moving = false);
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
                     float texel) {
        glUseProgram(p);
        setUniform(p, "uSunDir", glm::normalize(o.sunDirection));
        setUniform(p, "uSunColour", glm::vec3(1.0f, 0.96f, 0.88f) * o.sunIntensity);
        setUniform(p, "uSkyAmbient", glm::vec3(0.36f, 0.42f, 0.50f));
        setUniform(p, "uGroundAmbient", glm::vec3(0.20f, 0.18f, 0.14f));
        setUniform(p, "uEye", eye);
        setUniform(p, "uLightViewProj", lightViewProj);
        setUniform(p, "uShadowMap", 0);
        setUniform(p, "uShadows", shadows ? 1 : 0);
        setUniform(p, "uShadowTexel", texel);
    }
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
    bool staleShadows = false;  // a moving frame with an earlier scene's shadow map
    bool sketch = false;        // a moving frame that draws the scene's proxy
    RenderStats stats;
};

Renderer::Renderer() : m(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

void Renderer::setDetail(Quality detail) { m->detail = detail; }

bool Renderer::init(ProcLoader loader, std::string& error) {
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(loader))) {
        error = "could not load OpenGL functions";
        return false;
    }
    if (!GLAD_GL_VERSION_3_3) {
        error = "OpenGL 3.3 core is required";
        return false;
    }
    return m->build(error);
}

namespace {

// The unit meshes baking uses, made once (thread-safe: prepare() runs on worker threads).
struct UnitMeshes {
    CylinderMesh stems[3] = {makeCylinder(10, 2), makeCylinder(6, 0), makePrism(3)};
    SurfaceMesh leaf = makeLeaf(), petal = makePetal(), sphere = makeSphere(16, 10), smallSphere = makeSphere(6, 3);
};
const UnitMeshes& unitMeshes() {
    static const UnitMeshes m;
    return m;
}

}  // namespace

void Renderer::prepare(const Geometry& g, Quality detail, PreparedScene& out, std::shared_ptr<const Geometry> owner) {
    const UnitMeshes& meshes = unitMeshes();
    out = PreparedScene();
    out.detail = detail;
    out.bounds = g.bounds;
    out.planarCurve = g.planarCurve;
    out.cylinders = g.cylinders.size();
    out.surfaces = g.surfaces.size();
    BakedMesh& b = out.baked;
    const glm::vec3 size = g.bounds.empty ? glm::vec3(1) : g.bounds.size();
    const float extent = std::max({size.x, size.y, size.z, 1e-6f});
    if (g.planarCurve && g.cylinders.size() > kRasterCurveSegments) {
        // A big curve: rasterised from its segments at the size of the picture when drawn,
        // never copied (9.8 M segments are 390 MB).
        out.curveGeometry = owner ? std::move(owner) : std::shared_ptr<const Geometry>(&g, [](const Geometry*) {});
    } else if (g.planarCurve) {
        // A curve: every segment a screen-space ribbon.
        out.curve.assign(g.cylinders.begin(), g.cylinders.end());
    } else {
        // Pick the levels: the finest the vertex budget allows.
        float scale = detail == Quality::Interactive ? kInteractiveScale : 1.0f;
        auto levelOf = [&](const CylinderInstance& c) {
            float rel = std::max(c.startRadius, c.endRadius) / extent;
            for (int l = 0; l < 3; ++l)
                if (rel >= kLevelThreshold[l] * scale) return l;
            return 3;
        };
        for (;; scale *= 2) {
            std::size_t verts = 0;
            for (const auto& c : g.cylinders) {
                int l = levelOf(c);
                verts += l < 3 ? meshes.stems[l].vertices.size() : 0;
            }
            if (verts <= kVertexBudget || scale > 1e6f) break;
        }
        std::size_t reserve = 0;
        for (const auto& c : g.cylinders) {
            int l = levelOf(c);
            ++out.levels[l];
            reserve += l < 3 ? meshes.stems[l].vertices.size() : 0;
        }
        b.vertices.reserve(reserve);
        out.lines.reserve(out.levels[3] * 8);
        // Stems that continue straight on with the same radius and colour (F -> FF makes long
        // runs) are drawn as one tube or line: the same picture from a fraction of the primitives.
        auto continues = [](const CylinderInstance& a, const CylinderInstance& c) {
            if (a.colour != c.colour || a.endRadius != c.startRadius || glm::length(c.start - a.end) > 1e-5f * (1 + glm::length(a.end)))
                return false;
            glm::vec3 da = a.end - a.start, dc = c.end - c.start;
            float la = glm::length(da), lc = glm::length(dc);
            return la > 0 && lc > 0 && glm::dot(da, dc) > 0.99999f * la * lc;
        };
        CylinderInstance run{};
        int runLevel = -1;
        auto emit = [&] {
            if (runLevel < 0) return;
            if (runLevel < 3) {
                bakeCylinder(run, meshes.stems[runLevel], b);
            } else {
                std::uint32_t col = run.colour;
                float cf;
                std::memcpy(&cf, &col, 4);
                out.lines.insert(out.lines.end(), {run.start.x, run.start.y, run.start.z, cf, run.end.x, run.end.y, run.end.z, cf});
            }
            runLevel = -1;
        };
        for (const auto& c : g.cylinders) {
            int l = levelOf(c);
            if (runLevel == l && continues(run, c)) {
                run.end = c.end;
                run.endRadius = c.endRadius;
                continue;
            }
            emit();
            run = c;
            runLevel = l;
        }
        emit();
    }
    // Small spheres (seeds, buds) get a coarse mesh; they cover a few pixels.
    for (const auto& x : g.surfaces) {
        const SurfaceMesh& mesh = x.kind == SurfaceKind::Leaf    ? meshes.leaf
                                  : x.kind == SurfaceKind::Petal ? meshes.petal
                                  : x.size < extent / 60         ? meshes.smallSphere
                                                                 : meshes.sphere;
        bakeSurface(x, mesh, b);
    }
    bakePolygons(g.polygons, b);
}

namespace {

// Vertex clustering (Rossignac and Borrel): the vertices in one cell of a grid become one
// (their normals averaged), and triangles that collapse are dropped, so a mesh of any size
// becomes one bounded by the grid's cells on its surface.
BakedMesh clusterMesh(const BakedMesh& in, const Bounds& bounds, float cell) {
    BakedMesh out;
    std::unordered_map<std::uint64_t, std::uint32_t> cells;
    cells.reserve(in.vertices.size() / 4 + 16);
    std::vector<std::uint32_t> remap(in.vertices.size());
    std::vector<glm::vec3> normals;
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        const BakedVertex& v = in.vertices[i];
        const glm::vec3 q = glm::floor((v.position - bounds.min) / cell);
        auto axis = [](float x) { return std::uint64_t(std::clamp(saturate<int>(x), 0, (1 << 21) - 1)); };  // NaN: cell 0
        const std::uint64_t key = axis(q.x) | axis(q.y) << 21 | axis(q.z) << 42;
        const auto [at, fresh] = cells.try_emplace(key, std::uint32_t(out.vertices.size()));
        if (fresh) {
            out.vertices.push_back(v);
            normals.push_back(v.normal);
        } else {
            normals[at->second] += v.normal;
        }
        remap[i] = at->second;
    }
    for (std::size_t i = 0; i < out.vertices.size(); ++i) {
        const float l = glm::length(normals[i]);
        if (l > 1e-12f) out.vertices[i].normal = normals[i] / l;
    }
    for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3) {
        const std::uint32_t a = remap[in.indices[t]], b = remap[in.indices[t + 1]], c = remap[in.indices[t + 2]];
        if (a != b && b != c && a != c) out.indices.insert(out.indices.end(), {a, b, c});
    }
    return out;
}

}  // namespace

void Renderer::prepareForViewer(const Geometry& g, PreparedScene& out, std::shared_ptr<const Geometry> owner) {
    prepare(g, viewerDetail(g.cylinders.size()), out, std::move(owner));
    prepareMoving(g, out);
}

void Renderer::prepareMoving(const Geometry& g, PreparedScene& out) {
    out.proxy.clear();
    out.proxyBaked = BakedMesh();
    if (g.planarCurve) return;  // a big curve moves its raster
    const std::size_t budget = PreparedScene::kProxyLines;
    const std::size_t triangles = out.baked.indices.size() / 3, primitives = triangles + out.lines.size() / 8;
    // A sketch: every stem of the lowest branch orders (up to half the budget: the trunk and
    // main branches whole), then an even share of the others and of the leaves, as lines.
    auto sketch = [&] {
        const std::size_t count = g.cylinders.size() + g.surfaces.size();
        std::vector<std::size_t> perOrder(65536 + 1, 0);
        for (const auto& c : g.cylinders) ++perOrder[c.order];
        int whole = -1;  // orders 0..whole are drawn whole
        for (std::size_t sum = 0; whole + 1 < 65536 && sum + perOrder[size_t(whole + 1)] <= budget / 2;) sum += perOrder[size_t(++whole)];
        std::size_t main = 0;
        for (int k = 0; k <= whole; ++k) main += perOrder[size_t(k)];
        const std::size_t stride = count > budget ? (count - main) / (budget - main) + 1 : 1;
        out.proxy.reserve(std::min(count, budget) * 8 + 64);
        auto line = [&](const glm::vec3& a, const glm::vec3& e, std::uint32_t colour) {
            float cf;
            std::memcpy(&cf, &colour, 4);
            out.proxy.insert(out.proxy.end(), {a.x, a.y, a.z, cf, e.x, e.y, e.z, cf});
        };
        std::size_t k = 0;
        for (const auto& c : g.cylinders)
            if (int(c.order) <= whole || ++k % stride == 0) line(c.start, c.end, c.colour);
        for (const auto& x : g.surfaces)
            if (++k % stride == 0) line(x.position, x.position + x.heading * x.size, x.colour);
    };
    if (g.polygons.indices.size() / 3 > budget / 2 && triangles > budget) {
        // Mostly polygons (generalized cylinders, surfaces): no stems to sketch, so the mesh
        // is clustered on a grid of 1/200 of the scene (about two pixels of a framed view at
        // half size), with the stems' lines.
        const glm::vec3 size = g.bounds.empty ? glm::vec3(1) : g.bounds.size();
        out.proxyBaked = clusterMesh(out.baked, g.bounds, std::max({size.x, size.y, size.z, 1e-6f}) / 200);
        out.proxy = out.lines;
    } else if (out.detail == Quality::Interactive) {
        if (primitives > budget) sketch();
    } else if (triangles > PreparedScene::kProxyTriangles || primitives > budget) {
        // Full detail: the interactive bake, if it has far fewer triangles or fits the budget
        // (else its sketch).
        PreparedScene coarse;
        prepare(g, Quality::Interactive, coarse);
        const std::size_t coarseTriangles = coarse.baked.indices.size() / 3;
        if (coarseTriangles + coarse.lines.size() / 8 > budget) {
            sketch();
        } else if (2 * coarseTriangles < triangles || primitives > budget) {
            out.proxyBaked = std::move(coarse.baked);
            out.proxy = std::move(coarse.lines);
        }
    }
}

void Renderer::upload(const Geometry& g) {
    PreparedScene p;
    prepare(g, m->detail, p);
    upload(p);
}

void Renderer::upload(const PreparedScene& p) {
    Impl& s = *m;
    s.staging.reset();  // a whole upload replaces any staged one
    glBindVertexArray(s.baked.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.baked.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.baked.vertices.size() * sizeof(BakedVertex)), p.baked.vertices.data(), GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(p.baked.indices.size() * 4), p.baked.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, s.lines.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.lines.size() * 4), p.lines.data(), GL_STATIC_DRAW);
    adopt(p);
}

// Everything of a scene but its baked and line buffers: bounds, curves, counts, statistics.
void Renderer::adopt(const PreparedScene& p) {
    Impl& s = *m;
    m_progress.reset();  // a picture in pieces is of the scene before
    s.shadowValid = false;
    m_lastPictureMs = 1e9;
    s.bounds = p.bounds;
    s.planarCurve = p.planarCurve;
    s.curveCount = p.curve.size();
    s.rasterCurve = p.curveGeometry;
    s.coverageOf = nullptr;  // a new scene: rasterise again (even at a recycled address)
    if (s.curveCount) {
        glBindBuffer(GL_TEXTURE_BUFFER, s.curveInstances);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(s.curveCount * sizeof(CylinderInstance)), p.curve.data(), GL_STATIC_DRAW);
    }
    s.bakedIndices = p.baked.indices.size();
    s.lineCount = p.lines.size() / 8;
    s.proxyCount = p.proxy.size() / 8;
    glBindBuffer(GL_ARRAY_BUFFER, s.proxy.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.proxy.size() * 4), p.proxy.data(), GL_STATIC_DRAW);
    s.proxyIndices = p.proxyBaked.indices.size();
    glBindVertexArray(s.proxyMesh.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.proxyMesh.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.proxyBaked.vertices.size() * sizeof(BakedVertex)), p.proxyBaked.vertices.data(),
                 GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(s.proxyIndices * 4), p.proxyBaked.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    m_stats = {};
    m_stats.cylinders = p.cylinders;
    m_stats.surfaces = p.surfaces;
    for (int l = 0; l < 4; ++l) m_stats.levels[l] = p.levels[l];
}

bool Renderer::beginUpload(std::shared_ptr<const PreparedScene> p, std::size_t bytesPerFrame) {
    Impl& s = *m;
    const std::size_t vb = p->baked.vertices.size() * sizeof(BakedVertex), ib = p->baked.indices.size() * 4,
                      lb = p->lines.size() * 4;
    if (vb + ib + lb <= bytesPerFrame) {  // small: at once
        upload(*p);
        return true;
    }
    // The back buffers get their size now and their bytes a piece per frame; the scene on
    // screen is drawn meanwhile.
    glBindVertexArray(s.bakedBack.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.bakedBack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vb), nullptr, GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(ib), nullptr, GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, s.linesBack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lb), nullptr, GL_STATIC_DRAW);
    s.staging = std::move(p);
    s.stagedBytes = 0;
    return false;
}

bool Renderer::uploading() const { return m->staging != nullptr; }

bool Renderer::continueUpload(std::size_t bytes) {
    Impl& s = *m;
    if (!s.staging) return true;
    const PreparedScene& p = *s.staging;
    struct Part {
        GLenum target;
        GLuint vao, buffer;
        const void* data;
        std::size_t size;
    } parts[] = {
        {GL_ARRAY_BUFFER, s.bakedBack.vao, s.bakedBack.vbo, p.baked.vertices.data(), p.baked.vertices.size() * sizeof(BakedVertex)},
        {GL_ELEMENT_ARRAY_BUFFER, s.bakedBack.vao, s.bakedBack.ebo, p.baked.indices.data(), p.baked.indices.size() * 4},
        {GL_ARRAY_BUFFER, 0, s.linesBack.vbo, p.lines.data(), p.lines.size() * 4},
    };
    std::size_t base = 0;
    for (const Part& part : parts) {
        const std::size_t from = s.stagedBytes > base ? s.stagedBytes - base : 0;
        if (bytes > 0 && from < part.size) {
            const std::size_t n = std::min(bytes, part.size - from);
            glBindVertexArray(part.vao);  // the element buffer is the vertex array's
            glBindBuffer(part.target, part.buffer);
            glBufferSubData(part.target, GLintptr(from), GLsizeiptr(n), static_cast<const char*>(part.data) + from);
            glBindVertexArray(0);
            s.stagedBytes += n;
            bytes -= n;
        }
        base += part.size;
    }
    if (s.stagedBytes < base) return false;
    std::swap(s.baked, s.bakedBack);
    std::swap(s.lines, s.linesBack);
    adopt(p);
    s.staging.reset();
    return true;
}

void Renderer::plan(Pass& p, const Camera& camera, int width, int height, const RenderOptions& o, unsigned target, int x,
                    int y) const {
    const Impl& s = *m;
    p = Pass();
    p.o = o;
    p.width = width, p.height = height, p.x = x, p.y = y, p.target = target;
    p.stats = m_stats;
    p.stats.curveMoved = false;
    p.stats.proxy = false;
    p.stats.triangles = 0;
    const float aspect = float(width) / float(std::max(height, 1));
    glm::vec3 size = s.bounds.empty ? glm::vec3(1) : s.bounds.size();
    const float radius = std::max(0.5f * glm::length(size), 1e-4f);
    p.centre = s.bounds.empty ? glm::vec3(0) : s.bounds.centre();
    const float dist = glm::length(camera.eye() - p.centre);
    // The ground reaches further than the plant: keep all of it between the clip planes
    // (llvmpipe left whole tiles unpainted where the ground crossed the near plane).
    float reach = std::max(radius, 1.3f * std::max({size.x, size.z, size.y}));
    if (s.overlayIndices && !s.overlayBounds.empty)  // the environment, which may reach further
        for (const glm::vec3& corner : {s.overlayBounds.min, s.overlayBounds.max})
            reach = std::max(reach, glm::length(corner - p.centre) * 1.8f);
    const float near = std::max(1e-3f * dist, (dist - reach * 1.5f) * 0.9f), far = dist + reach * 3;
    p.viewProj = camera.projection(aspect, camera.orthographic ? 1e-3f : near, far) * camera.view();
    p.eye = camera.eye();
    p.curve = s.planarCurve;
    // Interactive frames of big plants skip the shadow pass, which costs a second draw.
    p.sketch = o.quality == Quality::Interactive && (s.proxyCount || s.proxyIndices);
    p.bigInteractive = o.quality == Quality::Interactive && (s.bakedIndices / 3 + s.lineCount > 4000 || p.sketch);
    p.shadows = o.shadows && !p.curve && !p.bigInteractive;
    p.ground = o.ground && !p.curve && !s.bounds.empty;
    p.groundRadius = std::max({size.x, size.z, size.y}) * 1.2f;
    if (p.shadows) {  // from the sun: an orthographic box around the plant and its ground
        glm::vec3 sun = glm::normalize(o.sunDirection);
        float r = std::max(radius, p.groundRadius) * 1.05f;
        glm::vec3 up = std::fabs(sun.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        glm::mat4 lv = glm::lookAt(p.centre + sun * r * 2.0f, p.centre, up);
        p.lightViewProj = glm::ortho(-r, r, -r, r, 0.01f, r * 4.0f) * lv;
    }
    p.texel = p.shadows ? 2.1f * std::max(radius, p.groundRadius) / kShadowSize : 0.0f;
    p.phase = Pass::Raster;
    if (p.shadows && !(s.shadowValid && s.shadowView == p.lightViewProj)) {
        if (o.quality == Quality::Interactive && s.shadowMade && s.shadowAge < kStaleShadowFrames) {
            p.lightViewProj = s.shadowView;  // an earlier scene's shadows, where that map puts them
            p.texel = s.shadowTexel;
            p.staleShadows = true;
        } else {
            p.phase = Pass::Shadow;
        }
    }
}

// Baked triangles [from, to) and then lines, numbered after the triangles.
void Renderer::Impl::drawRange(const glm::mat4& viewProj, bool depthOnly, std::size_t from, std::size_t to,
                               RenderStats& stats, bool moving) {
    const Buffers& mesh = moving ? proxyMesh : baked;
    const Buffers& thin = moving ? proxy : lines;
    const std::size_t tris = (moving ? proxyIndices : bakedIndices) / 3, lineCount = moving ? proxyCount : this->lineCount;
    if (from < tris && from < to) {
        const std::size_t b = std::min(to, tris);
        GLuint p = depthOnly ? bakedDepth : bakedProgram;
        glUseProgram(p);
        setUniform(p, "uViewProj", viewProj);
        setUniform(p, "uSpecular", 0.1f);
        glBindVertexArray(mesh.vao);
        glDrawElements(GL_TRIANGLES, GLsizei(3 * (b - from)), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(3 * from * sizeof(std::uint32_t)));
        stats.triangles += b - from;
    }
    if (to > tris && lineCount) {  // depth pass and colour pass alike: a line has no surface to shade
        const std::size_t a = std::max(from, tris) - tris, b = std::min(to - tris, lineCount);
        if (a < b) {
            glUseProgram(lineProgram);
            setUniform(lineProgram, "uViewProj", viewProj);
            glBindVertexArray(thin.vao);
            glDrawArrays(GL_LINES, GLint(2 * a), GLsizei(2 * (b - a)));
        }
    }
    glBindVertexArray(0);
}

// The parts of a phase, by cost: the shadow map's triangles, then its lines; the scene's
// curve ribbons, triangles, lines.
int Renderer::partOf(const Pass& p) const {
    const std::size_t curves = p.curve ? m->curveCount : 0,
                      tris = (p.sketch && p.phase == Pass::Scene ? m->proxyIndices : m->bakedIndices) / 3;
    if (p.phase == Pass::Shadow) return p.done < tris ? 1 : 2;
    if (p.phase == Pass::Scene) return p.done < curves ? 0 : p.done < curves + tris ? 1 : 2;
    if (p.phase == Pass::Overlay) return int(std::min<std::size_t>(p.done / std::max<std::size_t>(m->overlayIndices / 3, 1), 2));
    return 0;
}

std::size_t Renderer::partEnd(const Pass& p) const {
    const std::size_t curves = p.curve ? m->curveCount : 0,
                      tris = (p.sketch && p.phase == Pass::Scene ? m->proxyIndices : m->bakedIndices) / 3;
    const int part = partOf(p);
    if (p.phase == Pass::Shadow && part == 1) return tris;
    if (p.phase == Pass::Scene && part == 0) return curves;
    if (p.phase == Pass::Scene && part == 1) return curves + tris;
    if (p.phase == Pass::Overlay) return std::size_t(part + 1) * (m->overlayIndices / 3);
    return SIZE_MAX;
}

bool Renderer::step(Pass& p, std::size_t budget, bool wait) {
    Impl& s = *m;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // leaves and petals are double-sided
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    budget = wait ? SIZE_MAX : std::max<std::size_t>(budget, 1);
    p.lastPhase = p.phase;
    p.lastPart = 0;
    p.lastUnits = 0;
    const std::size_t sceneCount = s.bakedIndices / 3 + s.lineCount;
    // The next piece of a phase of `total` units; a piece is of one part of one phase only
    // (their costs differ: a triangle covers pixels, a line few), unless all is drawn at once.
    auto take = [&](std::size_t total) {
        p.lastPhase = p.phase;
        p.lastPart = partOf(p);
        const std::size_t end = wait ? total : std::min(total, partEnd(p));
        const std::size_t n = std::min(end - p.done, budget);
        p.lastUnits = n;
        return n;
    };
    auto next = [&](int phase) {
        p.phase = phase, p.done = 0, p.started = false;
        return wait;  // go on to it now only when drawing at once
    };
    if (p.phase == Pass::Shadow) {
        glBindFramebuffer(GL_FRAMEBUFFER, s.shadowFbo);
        glViewport(0, 0, kShadowSize, kShadowSize);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);  // never sample the map while writing it
        if (!p.started) glClear(GL_DEPTH_BUFFER_BIT), p.started = true, s.shadowValid = s.shadowMade = false;
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 2.0f);
        const std::size_t n = take(sceneCount);
        RenderStats ignored;
        s.drawRange(p.lightViewProj, true, p.done, p.done + n, ignored);
        p.done += n;
        glDisable(GL_POLYGON_OFFSET_FILL);
        if (p.done < sceneCount) return false;
        s.shadowValid = s.shadowMade = true;
        s.shadowView = p.lightViewProj;
        s.shadowTexel = p.texel;
        s.shadowAge = 0;
        if (!next(Pass::Raster)) return false;
    }
    if (p.phase == Pass::Raster) {  // a big curve's raster, made on a thread when it may take its time
        bool made = false;
        if (p.curve && s.rasterCurve) {
            const bool sameCurve = s.coverageOf == s.rasterCurve.get() && s.coverageWidth == p.width && s.coverageHeight == p.height;
            const float lineWidth = std::max(1.5f, float(p.height) / 400.0f);
            // Dragging moves the last raster (in the backdrop), or else one is made for this view.
            if (!(sameCurve && s.coverageView == p.viewProj) && !(sameCurve && p.o.quality == Quality::Interactive)) {
                std::vector<std::uint8_t> coverage;
                if (wait) {
                    if (s.raster.valid()) s.raster.wait();  // a progressive one's thread is done with its buffers
                    coverage = std::move(s.coverage);
                    rasterizeCurve(s.rasterCurve->cylinders.data(), s.rasterCurve->cylinders.size(), p.viewProj, p.width,
                                   p.height, lineWidth, coverage);
                } else {
                    if (!p.started) {
                        if (s.raster.valid()) s.raster.wait();  // an abandoned one
                        s.raster = std::async(std::launch::async, [curve = s.rasterCurve, view = p.viewProj, w = p.width,
                                                                   h = p.height, lineWidth] {
                            const auto t0 = std::chrono::steady_clock::now();
                            Impl::Raster r;
                            rasterizeCurve(curve->cylinders.data(), curve->cylinders.size(), view, w, h, lineWidth, r.coverage);
                            r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
                            return r;
                        });
                        p.started = true;
                    }
                    if (s.raster.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
                    Impl::Raster r = s.raster.get();
                    coverage = std::move(r.coverage);
                    p.spentMs += r.ms;
                }
                s.coverage = std::move(coverage);
                glActiveTexture(GL_TEXTURE1);
                glBindTexture(GL_TEXTURE_2D, s.coverageTexture);
                glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
                glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, p.width, p.height, 0, GL_RED, GL_UNSIGNED_BYTE, s.coverage.data());
                glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
                glActiveTexture(GL_TEXTURE0);
                s.coverageOf = s.rasterCurve.get();
                s.coverageView = p.viewProj;
                s.coverageWidth = p.width;
                s.coverageHeight = p.height;
                made = true;
            }
        }
        p.phase = Pass::Backdrop, p.done = 0, p.started = false;
        if (made && !wait) return false;
    }
    // Interactive frames of big plants take 2 samples: a software rasteriser pays per sample.
    s.ensureMsaa(p.width, p.height, p.bigInteractive ? 2 : 4, p.bigInteractive ? 0 : p.o.quality == Quality::Interactive ? 1 : 2);
    glBindFramebuffer(GL_FRAMEBUFFER, s.msaaFbo);
    glViewport(0, 0, p.width, p.height);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, s.shadowTexture);
    if (p.phase == Pass::Backdrop) {
        // The sky, the ground and a big curve's ink: a band of rows a piece (every pixel pays
        // for the ground's shadow lookups).
        const std::size_t rows = take(std::size_t(p.height));
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, GLint(p.done), p.width, GLsizei(rows));
        p.done += rows;
        glClearColor(p.o.backgroundBottom.r, p.o.backgroundBottom.g, p.o.backgroundBottom.b, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(s.backgroundProgram);
        setUniform(s.backgroundProgram, "uTop", p.o.backgroundTop);
        setUniform(s.backgroundProgram, "uBottom", p.o.backgroundBottom);
        glBindVertexArray(s.emptyVao);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glEnable(GL_DEPTH_TEST);
        if (p.ground) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
            s.setLighting(s.groundProgram, p.o, p.eye, p.lightViewProj, p.shadows, p.texel);
            setUniform(s.groundProgram, "uViewProj", p.viewProj);
            setUniform(s.groundProgram, "uCentre", glm::vec3(p.centre.x, s.bounds.min.y, p.centre.z));
            setUniform(s.groundProgram, "uRadius", p.groundRadius);
            setUniform(s.groundProgram, "uGroundColour", p.o.groundColour);
            glBindVertexArray(s.groundQuad.vao);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
        }
        if (p.curve && s.rasterCurve) {
            // A big curve rasterised on the CPU, blended in as ink; while dragged, the last
            // raster moved to where its corners are in this view.
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, s.coverageTexture);
            GLuint program = s.curveRasterProgram;
            if (s.coverageView != p.viewProj) {
                program = s.curveImpostorProgram;
                p.stats.curveMoved = true;
                const glm::mat4 back = glm::inverse(s.coverageView);
                glm::vec2 corners[4];
                for (int k = 0; k < 4; ++k) {
                    const glm::vec2 ndc(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f);
                    // The image's corner in the plane z = 0 of the old view, then in this one.
                    const glm::vec4 a = back * glm::vec4(ndc, -1.0f, 1.0f), b = back * glm::vec4(ndc, 1.0f, 1.0f);
                    const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
                    const float t = std::fabs(p1.z - p0.z) > 1e-12f ? -p0.z / (p1.z - p0.z) : 0.0f;
                    const glm::vec4 c = p.viewProj * glm::vec4(p0 + (p1 - p0) * t, 1.0f);
                    corners[k] = glm::vec2(c) / c.w;
                }
                glUseProgram(program);
                glUniform2fv(glGetUniformLocation(program, "uCorners"), 4, glm::value_ptr(corners[0]));
            }
            glUseProgram(program);
            setUniform(program, "uCoverage", 1);
            setUniform(program, "uInk", p.o.curveInk);
            glDisable(GL_DEPTH_TEST);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glBindVertexArray(s.emptyVao);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            glDisable(GL_BLEND);
            glEnable(GL_DEPTH_TEST);
            glActiveTexture(GL_TEXTURE0);
            p.stats.curve = true;
        }
        glDisable(GL_SCISSOR_TEST);
        if (p.done < std::size_t(p.height)) return false;
        if (p.curve && s.rasterCurve) p.stats.triangles += 2;
        if (!next(Pass::Scene)) return false;
    }
    const std::size_t curveCount = p.curve ? s.curveCount : 0;
    if (p.phase == Pass::Scene) {
        // The primitives: curve ribbons, triangles, lines (or a big scene's sketch while the
        // view moves: the still view draws it whole again).
        const std::size_t total = curveCount + (p.sketch ? s.proxyIndices / 3 + s.proxyCount : sceneCount);
        const std::size_t from = p.done, to = p.done + take(total);
        if (from < curveCount && from < to) {
            const std::size_t b = std::min(to, curveCount);
            const GLuint prog = s.curveProgram;
            glUseProgram(prog);
            setUniform(prog, "uViewProj", p.viewProj);
            setUniform(prog, "uViewport", glm::vec2(p.width, p.height));
            setUniform(prog, "uWidth", std::max(1.5f, float(p.height) / 400.0f));
            setUniform(prog, "uInk", p.o.curveInk);
            setUniform(prog, "uInstances", 1);
            setUniform(prog, "uFirst", int(from));
            setUniform(prog, "uCount", int(b - from));
            setUniform(prog, "uBatch", s.curveBatch);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_BUFFER, s.curveTexture);
            glBindVertexArray(s.curveQuad.vao);
            const GLsizei instances = GLsizei((b - from + std::size_t(s.curveBatch) - 1) / std::size_t(s.curveBatch));
            glDrawElementsInstanced(GL_TRIANGLES, GLsizei(6 * s.curveBatch), GL_UNSIGNED_INT, nullptr, instances);
            glActiveTexture(GL_TEXTURE0);
            p.stats.triangles += 2 * (b - from);
            p.stats.curve = true;
        }
        if (to > curveCount) {
            const std::size_t a = std::max(from, curveCount) - curveCount, b = to - curveCount;
            for (GLuint prog : {s.bakedProgram, s.lineProgram}) s.setLighting(prog, p.o, p.eye, p.lightViewProj, p.shadows, p.texel);
            s.drawRange(p.viewProj, false, a, b, p.stats, p.sketch);
            p.stats.proxy = p.sketch;
        }
        p.done = to;
        if (p.done < total) return false;
        p.phase = Pass::Overlay, p.done = 0, p.started = false;
        if (s.overlayIndices && !wait) return false;
    }
    if (p.phase == Pass::Overlay && s.overlayIndices) {
        // The environment, after the plant: its solid parts, then the far and the near sides
        // of the translucent ones; each pass a range of triangles a piece (big glass covers
        // the picture three times over). Scissored bands of rows, as the backdrop is drawn,
        // gave other pixels on the bands' edges here (blended glass, on llvmpipe); ranges of
        // triangles in their order give the very pixels of one draw.
        const std::size_t tris = s.overlayIndices / 3;
        s.setLighting(s.overlayProgram, p.o, p.eye, p.lightViewProj, p.shadows, p.texel);
        setUniform(s.overlayProgram, "uViewProj", p.viewProj);
        glBindVertexArray(s.overlay.vao);
        for (std::size_t n = take(3 * tris); n > 0;) {
            const int pass = int(p.done / tris);
            const std::size_t first = p.done % tris, count = std::min(n, tris - first);
            if (pass >= 1) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                glDepthMask(GL_FALSE);
            }
            setUniform(s.overlayProgram, "uPass", pass);
            glDrawElements(GL_TRIANGLES, GLsizei(3 * count), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(3 * first * sizeof(std::uint32_t)));
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
            p.done += count, n -= count;
        }
        glBindVertexArray(0);
        if (p.done < 3 * tris) return false;
        p.stats.triangles += tris;
    }
    if (s.highlightIndices) {
        // What was picked, seen through whatever is in front of it.
        s.setLighting(s.overlayProgram, p.o, p.eye, p.lightViewProj, false, p.texel);
        setUniform(s.overlayProgram, "uViewProj", p.viewProj);
        setUniform(s.overlayProgram, "uPass", 0);
        glDisable(GL_DEPTH_TEST);
        glBindVertexArray(s.highlight.vao);
        glDrawElements(GL_TRIANGLES, GLsizei(s.highlightIndices), GL_UNSIGNED_INT, nullptr);
        glBindVertexArray(0);
        glEnable(GL_DEPTH_TEST);
    }
    // Resolve the multisampled image into the target.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, s.msaaFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, p.target);
    glBlitFramebuffer(0, 0, p.width, p.height, p.x, p.y, p.x + p.width, p.y + p.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, p.target);
    m_stats = p.stats;
    return true;
}

void Renderer::draw(const Camera& camera, int width, int height, const RenderOptions& o, unsigned target, int x,
                    int y) {
    m_progress.reset();  // the multisampled image is this picture's now
    Pass p;
    plan(p, camera, width, height, o, target, x, y);
    m->shadowAge += p.staleShadows;
    step(p, SIZE_MAX, true);
}

void Renderer::beginDraw(const Camera& camera, int width, int height, const RenderOptions& o, unsigned target, int x, int y) {
    m_progress = std::make_unique<Pass>();
    plan(*m_progress, camera, width, height, o, target, x, y);
    m->shadowAge += m_progress->staleShadows;
}

bool Renderer::continueDraw(std::size_t primitives) {
    if (!m_progress) return true;
    if (!step(*m_progress, std::max<std::size_t>(primitives, 1), false)) return false;
    m_progress.reset();
    return true;
}

bool Renderer::continueDrawFor(double milliseconds) {
    if (!m_progress) return true;
    Pass& p = *m_progress;
    double& rate = m->rate[p.phase][partOf(p)];
    const std::size_t units = std::size_t(std::clamp(rate * milliseconds, 1.0, 1e9));
    const auto t0 = std::chrono::steady_clock::now();
    const bool whole = step(p, units, false);
    glFinish();  // a software rasteriser draws at the flush: the piece's time is until it is done
    const double took = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    // A full piece says how fast this part draws here. One cut short by the end of its part
    // carries fixed costs that would say too slow, unless it overran: then the rate was too
    // high (a few hundred big leaves in one piece took 75 ms).
    double& learnt = m->rate[p.lastPhase][p.lastPart];
    const double measured = double(p.lastUnits) / std::max(took, 0.05);
    // It grows slowly (the triangles of a part differ: leaves near the eye cover more).
    if (p.lastPhase != Pass::Raster && p.lastUnits == units) learnt = std::clamp(measured, learnt / 4, learnt * 1.5);
    else if (p.lastPhase != Pass::Raster && p.lastUnits > 0 && took > milliseconds) learnt = std::clamp(measured, learnt / 16, learnt);
    p.spentMs += took;
    if (whole) m_lastPictureMs = p.spentMs;
    if (whole) m_progress.reset();
    return whole;
}

bool Renderer::drawing() const { return m_progress != nullptr; }

bool Renderer::rasterCurve() const { return m->rasterCurve != nullptr; }

namespace {
std::size_t uploadMesh(const Mesh& mesh, GLuint vao, GLuint vbo, GLuint ebo) {
    BakedMesh baked;
    bakePolygons(mesh, baked);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(baked.vertices.size() * sizeof(BakedVertex)), baked.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(baked.indices.size() * 4), baked.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    return baked.indices.size();
}
}  // namespace

void Renderer::setHighlight(const Mesh& mesh) {
    m->highlightIndices = uploadMesh(mesh, m->highlight.vao, m->highlight.vbo, m->highlight.ebo);
}

void Renderer::setOverlay(const Mesh& mesh) {
    Impl& s = *m;
    s.overlayIndices = uploadMesh(mesh, s.overlay.vao, s.overlay.vbo, s.overlay.ebo);
    s.overlayBounds = Bounds();
    for (const glm::vec3& p : mesh.positions) s.overlayBounds.add(p);
}

std::vector<std::uint8_t> Renderer::renderImage(const Camera& camera, int width, int height, const RenderOptions& o) {
    GLuint fbo = 0, colour = 0;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    draw(camera, width, height, o, fbo);
    std::vector<std::uint8_t> pixels = readPixels(width, height, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteRenderbuffers(1, &colour);
    glDeleteFramebuffers(1, &fbo);
    return pixels;
}

std::vector<std::uint8_t> Renderer::readPixels(int width, int height, unsigned source) const {
    std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    // GL's rows go bottom-up; images go top-down.
    const std::size_t row = std::size_t(width) * 4;
    std::vector<std::uint8_t> line(row);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* a = pixels.data() + std::size_t(y) * row;
        std::uint8_t* b = pixels.data() + std::size_t(height - 1 - y) * row;
        std::memcpy(line.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, line.data(), row);
    }
    return pixels;
}

}  // namespace sprout::render
