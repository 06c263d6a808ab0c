// The renderer's set-up: its GL objects (programs, buffers, the shadow map) and multisampled
// images, the warm-up that compiles every way it draws before the first frame, the stretch
// of a smaller picture over a bigger one, and readback. What it draws is uploaded by
// renderer_upload.cpp and drawn by renderer_draw.cpp.
//
// Index of this file:
//   [SECTION] Helpers
//   [SECTION] GL objects: buffers and programs
//   [SECTION] Multisampled images
//   [SECTION] Set-up and warm-up
//   [SECTION] Readback
#include "app/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>

#include "app/mesh/bake.hpp"
#include "app/render/colour_target.hpp"
#include "app/render/gl.hpp"
#include "app/render/renderer_impl.hpp"
#include "app/render/shader.hpp"

namespace sprout::render {

using detail::kShadowSize;
using detail::kGroundShadowSize;

// [SECTION] Helpers
namespace {
// The texture bound now is filtered linearly and clamped at its edges.
void linearClamped() {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

// A planar curve of one segment, 10 long (warmUp and prime draw it).
Geometry oneSegmentCurve() {
    Geometry segment;
    segment.planarCurve = true;
    segment.cylinders.push_back({{0, 0, 0}, 0.5f, {0, 10, 0}, 0.5f, 0x6B4F2AFFu, 0, 0});
    segment.bounds.add({0, 0, 0}), segment.bounds.add({0, 10, 0});
    return segment;
}
}  // namespace

// [SECTION] GL objects: buffers and programs
// The bound vertex array reads baked triangles' vertices from `vbo`: position, normal, colour
// (polygon.vert's layout).
void Renderer::Impl::bakedAttributes(GLuint vbo) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    const GLsizei bs = sizeof(mesh::BakedVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, bs, reinterpret_cast<void*>(offsetof(mesh::BakedVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, bs, reinterpret_cast<void*>(offsetof(mesh::BakedVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, bs, reinterpret_cast<void*>(offsetof(mesh::BakedVertex, colour)));
}

// Baked triangles, in a vertex array of their own.
void Renderer::Impl::makeBaked(Buffers& b) {
    glGenVertexArrays(1, &b.vao);
    glBindVertexArray(b.vao);
    glGenBuffers(1, &b.vbo);
    bakedAttributes(b.vbo);
    glGenBuffers(1, &b.ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ebo);
    glBindVertexArray(0);
}

// Lines: position, colour.
void Renderer::Impl::makeLines(Buffers& b) {
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

void Renderer::Impl::mutableAgain(Buffers& b, bool lines, bool always) {
    if (!b.immutable && !always) return;
    const GLuint buffers[] = {b.vbo, b.ebo};
    glDeleteVertexArrays(1, &b.vao);
    glDeleteBuffers(2, buffers);  // a mapping goes with its buffer; 0 is ignored
    b = {};
    lines ? makeLines(b) : makeBaked(b);
}

bool Renderer::Impl::build(std::string& error) {
    struct P {
        GLuint* out;
        const char *vs, *fs;
    } programs[] = {
        {&bakedProgram, "polygon.vert", "lit.frag"},       {&bakedDepth, "polygon.vert", "depth.frag"},
        {&bakedDepthAlpha, "polygon.vert", "depth_alpha.frag"},
        {&texturedProgram, "polygon_tex.vert", "lit_tex.frag"}, {&texturedDepth, "polygon_tex.vert", "depth_tex.frag"},
        {&bakedPlainProgram, "polygon.vert", "lit_plain.frag"}, {&bakedVertexLitProgram, "polygon_lit.vert", "colour.frag"},
        {&lineProgram, "line.vert", "line.frag"},          {&curveProgram, "curve.vert", "curve.frag"},
        {&inkLineProgram, "line.vert", "curve.frag"},
        {&backgroundProgram, "background.vert", "background.frag"}, {&groundProgram, "ground.vert", "ground.frag"},
        {&groundPlainProgram, "ground.vert", "ground_plain.frag"},
        {&groundShadowProgram, "ground.vert", "ground_shadow.frag"}, {&groundMaskedProgram, "ground.vert", "ground_masked.frag"},
        {&curveRasterProgram, "background.vert", "curve_raster.frag"},
        {&curveImpostorProgram, "curve_impostor.vert", "curve_raster.frag"},
        {&overlayProgram, "polygon.vert", "overlay.frag"}, {&overlayPlainProgram, "polygon.vert", "overlay_plain.frag"},
        {&stretchProgram, "stretch.vert", "stretch.frag"}, {&resolveProgram, "resolve.vert", "resolve.frag"},
    };
    for (auto& p : programs)
        if (!(*p.out = buildProgram(p.vs, p.fs, error))) return false;
    for (GLuint p : {bakedProgram, bakedPlainProgram, bakedVertexLitProgram, texturedProgram}) glUseProgram(p), plainLight(p);  // never unset
    for (GLuint p : {texturedProgram, texturedDepth}) glUseProgram(p), setUniform(p, "uImage", detail::kImageUnit);
    glUseProgram(0);

    glGenTextures(1, &coverageTexture);
    glBindTexture(GL_TEXTURE_2D, coverageTexture);
    // Linear: exact at the size it was made (samples at texel centres), smooth when moved.
    linearClamped();
    glBindTexture(GL_TEXTURE_2D, 0);

    // Two sets of baked and line buffers: the one on screen, and the one a staged upload
    // fills a piece per frame (beginUpload) before they swap.
    for (Buffers* b : {&baked, &bakedBack, &overlay, &highlight, &proxyMesh}) makeBaked(*b);
    for (Buffers* b : {&lines, &linesBack, &proxy}) makeLines(*b);
    glGenVertexArrays(1, &translucentVao);
    glGenBuffers(1, &translucentEbo);
    glGenVertexArrays(1, &texturedVao);
    glGenBuffers(1, &texturedUvs);
    {
        const std::uint8_t white[4] = {255, 255, 255, 255};
        glGenTextures(1, &whiteTexture);
        glBindTexture(GL_TEXTURE_2D, whiteTexture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

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

    GLint maxSamples = 1, maxTextureSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &maxTextureSamples);
    samples = std::clamp(std::min(maxSamples, maxTextureSamples), 1, 4);

    glGenTextures(1, &shadowTexture);
    glBindTexture(GL_TEXTURE_2D, shadowTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kShadowSize, kShadowSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    linearClamped();
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

    glGenTextures(1, &groundShadowTexture);
    glBindTexture(GL_TEXTURE_2D, groundShadowTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kGroundShadowSize, kGroundShadowSize, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
    linearClamped();
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &groundShadowFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, groundShadowFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, groundShadowTexture, 0);
    if (ok && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        ok = false, error = "the ground shadow framebuffer is incomplete";
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ok;
}

// [SECTION] Multisampled images
void Renderer::Impl::ensureMsaa(int w, int h, int wantSamples, int slot) {
    wantSamples = std::min(wantSamples, samples);
    Msaa& t = msaa[slot];
    msaaInUse = &t;
    if (t.fbo && w == t.width && h == t.height && wantSamples == t.samples) return;
    // Moving frames change size with the window's resolution scale: a larger image is
    // drawn into in part (the picture's at the lower-left corner) rather than made again
    // (a new image's memory is first touched by its first frame: one slow frame a drag).
    if (slot < 2 && t.fbo && w <= t.width && h <= t.height && wantSamples == t.samples) return;
    if (!t.fbo) {
        glGenFramebuffers(1, &t.fbo);
        glGenRenderbuffers(1, &t.colour);
        glGenTextures(1, &t.colourTexture);
        glGenRenderbuffers(1, &t.depth);
    }
    t.samples = wantSamples;
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
    if (t.samples > 1) {
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.colourTexture);
        glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, t.samples, GL_RGBA8, w, h, GL_TRUE);
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, t.colourTexture, 0);
    } else {
        glBindRenderbuffer(GL_RENDERBUFFER, t.colour);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, t.samples, GL_RGBA8, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, t.depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, t.samples, GL_DEPTH_COMPONENT24, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
    t.width = w;
    t.height = h;
}

Renderer::Renderer() : m(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

void Renderer::setDetail(Quality detail) { m->detail = detail; }

// [SECTION] Set-up and warm-up
bool Renderer::init(ProcLoader loader, std::string& error) {
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(loader))) {
        error = "could not load OpenGL functions";
        return false;
    }
    if (!GLAD_GL_VERSION_3_3) {
        error = "OpenGL 3.3 core is required";
        return false;
    }
    const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    m_glRenderer = name ? name : "";
    m_glVersion = version ? version : "";
    m->bufferStorage = m->persistentUploads = GLAD_GL_ARB_buffer_storage;
    m_software = m_glRenderer.find("llvmpipe") != std::string::npos || m_glRenderer.find("softpipe") != std::string::npos;
    m->bigCurveRibbons = !m_software;
    return m->build(error);
}

std::vector<std::uint8_t> Renderer::renderImage(const Camera& camera, int width, int height, const RenderOptions& o) {
    ColourTarget target(width, height);
    draw(camera, width, height, o, target.fbo);
    return readPixels(width, height, target.fbo);
}

void Renderer::warmUp(int width, int height) {
    // A stem for each level of detail, leaves, and past 4000 primitives in all (so that moving
    // frames take the big scene's path) twigs of lines.
    Geometry plant;
    auto stem = [&](glm::vec3 a, glm::vec3 b, float r) {
        plant.cylinders.push_back({a, r, b, r, 0x6B4F2AFFu, 0, 0});
        plant.bounds.add(a), plant.bounds.add(b);
    };
    stem({0, 0, 0}, {0, 4, 0}, 0.2f);
    stem({0, 4, 0}, {1, 6, 0}, 0.02f);
    stem({0, 4, 0}, {-1, 6, 0}, 0.006f);
    for (int i = 0; i < 4500; ++i) {
        const float a = float(i) * 0.0137f, h = 2.0f + float(i % 100) * 0.04f;
        stem({0, h, 0}, {0.5f * std::cos(a), h + 0.3f, 0.5f * std::sin(a)}, 1e-4f);
    }
    plant.surfaces.push_back({{1, 6, 0}, 0.8f, {1, 0.5f, 0}, 0x4C8C3AFFu, {0, 0, 1}, SurfaceKind::Leaf});
    // And a small one (its moving frames keep 4 samples and the shadows).
    Geometry small;
    small.cylinders.push_back(plant.cylinders[0]);
    small.cylinders.push_back(plant.cylinders[2]);
    small.surfaces.push_back(plant.surfaces[0]);
    small.bounds = plant.bounds;
    // Curves: one of ribbons (whose moving frames draw its sketch of lines), and one past 200 k
    // segments, rasterised on the CPU, whose moving frames move its last raster (drawn again
    // from another view).
    Geometry curve, bigCurve;
    curve.planarCurve = bigCurve.planarCurve = true;
    for (int i = 0; i < 200'001; ++i) {
        const glm::vec3 a(float(i % 1000), float(i / 1000 + i % 2), 0), b(float(i % 1000 + 1), float(i / 1000 + (i + 1) % 2), 0);
        for (Geometry* c : {&curve, &bigCurve}) {
            if (c == &curve && i > int(PreparedScene::kCurveSketch)) continue;  // moves as its sketch
            c->cylinders.push_back({a, 0.1f, b, 0.1f, 0x000000FFu, 0, 0});
            c->bounds.add(a), c->bounds.add(b);
        }
    }
    // And a curve of one segment, fewer than a batch of ribbons (a plant's first step can be
    // one: it took 30 ms to draw the first time).
    Geometry segment = oneSegmentCurve();
    // An environment with the small plant: a stone triangle and a glass one (the overlay's
    // three passes, lit with and without the shadow map).
    Mesh environment;
    for (int k = 0; k < 2; ++k) {
        const float x = float(k) * 0.5f;
        environment.positions.insert(environment.positions.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0.5f}});
        environment.normals.insert(environment.normals.end(), 3, glm::vec3(0, 0, 1));
        environment.colours.insert(environment.colours.end(), 3, k ? 0x8FB4D260u : 0x808080FFu);
        environment.indices.insert(environment.indices.end(), {3u * std::uint32_t(k), 3u * std::uint32_t(k) + 1, 3u * std::uint32_t(k) + 2});
    }
    for (const Geometry* g : {&plant, &small, &curve, &segment, &bigCurve}) {
        PreparedScene scene;  // as the window's worker prepares a scene, with what moving frames draw
        prepare(*g, m->detail, scene);
        prepareMoving(*g, scene);
        upload(scene);
        setOverlay(g == &small ? environment : Mesh());
        const Camera camera = frameGeometry(*g, 1.0f, ViewPreset::Auto);
        Camera moved = camera;
        moved.yaw += 10, moved.target.x += 0.05f * moved.orthoHeight;
        RenderOptions o;
        for (bool quick : {false, true}) {  // lines with multisampling and without (any number of them here)
            if (quick && !m_software) continue;
            o.quickLines = quick;
            m->quickLinesFrom = quick ? 0 : detail::kQuickLines;
            for (Quality q : {Quality::Still, Quality::Interactive}) {
                o.quality = q;
                // At the sizes the window draws (its moving frames at half size each way, a big
                // curve's at full size): the images are made, and their memory first touched, here.
                const int k = q == Quality::Still || g == &bigCurve ? 1 : 2, w = std::max(width / k, 16), h = std::max(height / k, 16);
                renderImage(q == Quality::Still ? camera : moved, w, h, o);
            }
        }
        m->quickLinesFrom = detail::kQuickLines;
    }
    upload(Geometry());
    setOverlay(Mesh());
    m_lastPictureMs = 1e9;
}

void Renderer::prime(int width, int height, const RenderOptions& options, const std::atomic<bool>& cancel) {
    Geometry plant;
    plant.cylinders.push_back({{0, 0, 0}, 0.1f, {0, 2, 0}, 0.08f, 0x6B4F2AFFu, 0, 0});
    plant.surfaces.push_back({{0, 2, 0}, 0.8f, {1, 0.5f, 0}, 0x4C8C3AFFu, {0, 0, 1}, SurfaceKind::Leaf});
    plant.bounds.add({-1, 0, -1}), plant.bounds.add({1, 3, 1});
    Geometry curve = oneSegmentCurve();
    const float aspect = float(width) / float(std::max(height, 1));
    for (const Geometry* g : {&plant, &curve}) {  // a 3D plant first: most pictures are of one
        if (cancel.load()) break;
        upload(*g);
        Pass p;
        plan(p, frameGeometry(*g, aspect, ViewPreset::Auto), width, height, options, 0, 0, 0);
        p.cancel = &cancel;
        step(p, SIZE_MAX, true);
    }
    glFinish();  // the rasteriser's threads done with it here, not in the picture's time
    upload(Geometry());
}

void Renderer::stretch(unsigned texture, int width, int height, int textureWidth, int textureHeight, unsigned target, int x,
                       int y, int targetWidth, int targetHeight) {
    // Texture coordinates, in texels, of a target pixel's centre c: 0.5 + (c - 0.5) * k, k the
    // ratio of the spans between the outermost centres; at the quad's corners (c = 0, c = size).
    auto map = [](int from, int to, int size) {
        const float k = to > 1 ? float(from - 1) / float(to - 1) : 0.0f;
        const float first = 0.5f - 0.5f * k, last = 0.5f + (float(to) - 0.5f) * k;
        return glm::vec2(first / float(size), (last - first) / float(size));
    };
    const glm::vec2 u = map(width, targetWidth, textureWidth), v = map(height, targetHeight, textureHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(x, y, targetWidth, targetHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(m->stretchProgram);
    glUniform4f(glGetUniformLocation(m->stretchProgram, "uMap"), u.x, v.x, u.y, v.y);
    glUniform1i(glGetUniformLocation(m->stretchProgram, "uPicture"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindVertexArray(m->emptyVao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnable(GL_DEPTH_TEST);
}

// [SECTION] Readback
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
