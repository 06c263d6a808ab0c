// A picture: worked out from the camera (plan), then drawn in passes (step): the shadow map,
// sky and ground, the plant, the environment, the highlight; at once (draw) or in pieces.
#include "app/render/renderer.hpp"

#include "app/render/curve_raster.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <future>
#include <memory>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/render/gl.hpp"
#include "app/render/renderer_impl.hpp"

namespace sprout::render {
namespace {

constexpr int kStaleShadowFrames = 3;

void setUniform(GLuint p, const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(glGetUniformLocation(p, name), 1, GL_FALSE, glm::value_ptr(m));
}
void setUniform(GLuint p, const char* name, const glm::vec3& v) { glUniform3fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* name, const glm::vec2& v) { glUniform2fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* name, float v) { glUniform1f(glGetUniformLocation(p, name), v); }
void setUniform(GLuint p, const char* name, int v) { glUniform1i(glGetUniformLocation(p, name), v); }

}  // namespace

using detail::kShadowSize;
using detail::kGroundShadowSize;

void Renderer::Impl::setLighting(GLuint p, const RenderOptions& o, const glm::vec3& eye, const glm::mat4& lightViewProj,
                                 bool shadows, float texel) {
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

void Renderer::Impl::ensureGroundShadow(const RenderOptions& o, const glm::vec3& eye, const glm::vec3& centre, float radius) {
    const glm::vec4 at(centre, radius);
    if (groundShadowOf == shadowGeneration && groundShadowAt == at) return;
    groundShadowOf = shadowGeneration;
    groundShadowAt = at;
    ++groundShadowMade;
    // ground.vert's square, mapped onto the whole texture: x to x, z to y.
    glm::mat4 toTexture(0.0f);
    toTexture[0][0] = 1.0f / radius;
    toTexture[2][1] = 1.0f / radius;
    toTexture[3] = glm::vec4(-centre.x / radius, -centre.z / radius, 0.0f, 1.0f);
    glBindFramebuffer(GL_FRAMEBUFFER, groundShadowFbo);
    glViewport(0, 0, kGroundShadowSize, kGroundShadowSize);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, shadowTexture);
    setLighting(groundShadowProgram, o, eye, shadowView, true, shadowTexel);
    setUniform(groundShadowProgram, "uViewProj", toTexture);
    setUniform(groundShadowProgram, "uCentre", centre);
    setUniform(groundShadowProgram, "uRadius", radius);
    glBindVertexArray(groundQuad.vao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
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
    p.stats.shadowPass = false;
    p.stats.triangles = 0;
    p.stats.overlayDrawn = 0;
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
    // On a software rasteriser a moving frame lights the plant without the shadow map (the
    // ground keeps its shadow): thin stems are shaded in whole blocks of pixels, nine lookups
    // each. The binary tree's 3 k triangles took 11.6 of a 17 ms moving frame at 505x430 with
    // them, 4.5 without.
    p.plantShadows = p.shadows && !(o.quality == Quality::Interactive && m_software);
    // And lights it at the vertices: its fragments pass a colour on (about 1 ms of a 10 ms
    // moving frame of lparser_topiary_bush's 4 k overlapping leaves, or of a generalized
    // cylinder plant's 21 k clustered triangles).
    p.vertexLit = o.quality == Quality::Interactive && m_software;
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

void Renderer::Impl::resolve(GLuint target, int x, int y, int w, int h) {
    if (msaaInUse->samples <= 1) {  // a copy (no shader: the blit copies memory)
        glBindFramebuffer(GL_READ_FRAMEBUFFER, msaaInUse->fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
        glBlitFramebuffer(0, 0, w, h, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(x, y, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, msaaInUse->colourTexture);
    glUseProgram(resolveProgram);
    setUniform(resolveProgram, "uImage", 3);
    setUniform(resolveProgram, "uSamples", msaaInUse->samples);
    setUniform(resolveProgram, "uScale", 1.0f / float(msaaInUse->samples));
    glUniform2i(glGetUniformLocation(resolveProgram, "uOffset"), x, y);
    glBindVertexArray(emptyVao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_DEPTH_TEST);
}

// Baked triangles [from, to) and then lines, numbered after the triangles.
void Renderer::Impl::drawRange(const glm::mat4& viewProj, GLuint p, std::size_t from, std::size_t to, RenderStats& stats,
                               bool moving, bool quickLines, const glm::vec3* ink) {
    const Buffers& mesh = moving ? proxyMesh : baked;
    const Buffers& thin = moving ? proxy : lines;
    const std::size_t tris = (moving ? proxyIndices : bakedIndices) / 3, lineCount = moving ? proxyCount : this->lineCount;
    if (from < tris && from < to) {
        const std::size_t b = std::min(to, tris);
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
            const GLuint program = ink ? inkLineProgram : lineProgram;
            glUseProgram(program);
            setUniform(program, "uViewProj", viewProj);
            if (ink) setUniform(program, "uInk", *ink);
            glBindVertexArray(thin.vao);
            const bool single = quickLines && (moving || lineCount > quickLinesFrom);
            if (single) glDisable(GL_MULTISAMPLE);
            glDrawArrays(GL_LINES, GLint(2 * a), GLsizei(2 * (b - a)));
            if (single) glEnable(GL_MULTISAMPLE);
        }
    }
    glBindVertexArray(0);
}

// The parts of a phase, by cost: the shadow map's triangles, then its lines; the scene's
// curve ribbons, triangles, lines.
int Renderer::partOf(const Pass& p) const {
    const std::size_t curves = p.curve && !p.sketch ? m->curveCount : 0,
                      tris = (p.sketch && p.phase == Pass::Scene ? m->proxyIndices : m->bakedIndices) / 3;
    if (p.phase == Pass::Shadow) return p.done < tris ? 1 : 2;
    if (p.phase == Pass::Scene) return p.done < curves ? 0 : p.done < curves + tris ? 1 : 2;
    if (p.phase == Pass::Overlay) return m->overlayPass(p.done);
    return 0;
}

std::size_t Renderer::partEnd(const Pass& p) const {
    const std::size_t curves = p.curve && !p.sketch ? m->curveCount : 0,
                      tris = (p.sketch && p.phase == Pass::Scene ? m->proxyIndices : m->bakedIndices) / 3;
    const int part = partOf(p);
    if (p.phase == Pass::Shadow && part == 1) return tris;
    if (p.phase == Pass::Scene && part == 0) return curves;
    if (p.phase == Pass::Scene && part == 1) return curves + tris;
    if (p.phase == Pass::Overlay) return m->overlayPassEnd(part);
    return SIZE_MAX;
}

int Renderer::groundShadowTextures() const { return m->groundShadowMade; }

glm::vec3 Renderer::groundCentre(const Pass& p) const { return glm::vec3(p.centre.x, m->bounds.min.y, p.centre.z); }

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
        // Go on to it now only when drawing at once (and not cancelled: Renderer::prime).
        return wait && !(p.cancel && p.cancel->load(std::memory_order_relaxed));
    };
    if (p.phase == Pass::Shadow) {
        glBindFramebuffer(GL_FRAMEBUFFER, s.shadowFbo);
        glViewport(0, 0, kShadowSize, kShadowSize);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);  // never sample the map while writing it
        if (!p.started) glClear(GL_DEPTH_BUFFER_BIT), p.started = true, s.shadowValid = s.shadowMade = false;
        p.stats.shadowPass = true;
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 2.0f);
        const std::size_t n = take(sceneCount);
        RenderStats ignored;
        s.drawRange(p.lightViewProj, s.bakedDepth, p.done, p.done + n, ignored);
        p.done += n;
        glDisable(GL_POLYGON_OFFSET_FILL);
        if (p.done < sceneCount) return false;
        s.shadowValid = s.shadowMade = true;
        ++s.shadowGeneration;
        s.shadowView = p.lightViewProj;
        s.shadowTexel = p.texel;
        s.shadowAge = 0;
        // The ground's shadow texture for the moving frames to come, with the map of the
        // window's still view (drawn in pieces: a piece pays for it, not the first frame of a
        // drag); a picture drawn at once (`sprout render`, a video's frame) has none to come.
        if (m_software && p.ground && !wait) s.ensureGroundShadow(p.o, p.eye, groundCentre(p), p.groundRadius);
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
                    // Waiting on it, not polling: a frame that only polled came back at once, and
                    // the window's frames, shown or not, spun a core the raster's thread needed
                    // (666 frames while the Gosper curve n=5 was rasterised on two cores).
                    const auto wait = std::chrono::duration<double, std::milli>(p.waitMs);
                    if (s.raster.wait_for(wait) != std::future_status::ready) return false;
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
    // The ground of a moving frame on a software rasteriser reads the plant's shadow from a
    // texture of its own, made (before the frame's image is bound) when the map or the ground
    // changed.
    const bool groundShadowTexture = p.phase == Pass::Backdrop && p.ground && p.shadows && !p.plantShadows;
    if (groundShadowTexture) s.ensureGroundShadow(p.o, p.eye, groundCentre(p), p.groundRadius);
    // Interactive frames of big plants take 2 samples: a software rasteriser pays per sample.
    // A big curve's picture takes one: its raster is its own antialiasing, and sky and ink
    // have no edges to smooth (its moving frames took 19 ms at 2 samples, 1440x860).
    if (p.curve && s.rasterCurve) s.ensureMsaa(p.width, p.height, 0, 0);
    else s.ensureMsaa(p.width, p.height, p.bigInteractive ? 2 : 4, p.bigInteractive ? 0 : p.o.quality == Quality::Interactive ? 1 : 2);
    glBindFramebuffer(GL_FRAMEBUFFER, s.msaaInUse->fbo);
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
            const GLuint ground = groundShadowTexture ? s.groundMaskedProgram : p.shadows ? s.groundProgram : s.groundPlainProgram;
            s.setLighting(ground, p.o, p.eye, p.lightViewProj, p.shadows, p.texel);
            if (groundShadowTexture) {
                glActiveTexture(GL_TEXTURE2);
                glBindTexture(GL_TEXTURE_2D, s.groundShadowTexture);
                glActiveTexture(GL_TEXTURE0);
                setUniform(ground, "uGroundShadow", 2);
            }
            setUniform(ground, "uViewProj", p.viewProj);
            setUniform(ground, "uCentre", groundCentre(p));
            setUniform(ground, "uRadius", p.groundRadius);
            setUniform(ground, "uGroundColour", p.o.groundColour);
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
    const std::size_t curveCount = p.curve && !p.sketch ? s.curveCount : 0;  // a curve's sketch: its lines instead
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
            const GLuint lit = p.plantShadows ? s.bakedProgram : p.vertexLit ? s.bakedVertexLitProgram : s.bakedPlainProgram;
            for (GLuint prog : {lit, s.lineProgram}) s.setLighting(prog, p.o, p.eye, p.lightViewProj, p.plantShadows, p.texel);
            s.drawRange(p.viewProj, lit, a, b, p.stats, p.sketch, p.o.quickLines,
                        p.curve ? &p.o.curveInk : nullptr);
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
        // Lit as the plant is: without the shadow map's lookups in a moving frame on a
        // software rasteriser (nine a fragment, each of three passes: `env_space_colonisation`'s
        // glass crown held its moving frames at 12-13 ms at the smallest resolution).
        const std::size_t units = s.overlayPassEnd(2);
        const GLuint program = p.plantShadows ? s.overlayProgram : s.overlayPlainProgram;
        s.setLighting(program, p.o, p.eye, p.lightViewProj, p.plantShadows, p.texel);
        setUniform(program, "uViewProj", p.viewProj);
        glBindVertexArray(s.overlay.vao);
        for (std::size_t n = take(units); n > 0;) {
            const int pass = s.overlayPass(p.done);
            const std::size_t first = s.overlayTriangle(p.done), count = std::min(n, s.overlayPassEnd(pass) - p.done);
            if (pass >= 1) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                glDepthMask(GL_FALSE);
            }
            setUniform(program, "uPass", pass);
            glDrawElements(GL_TRIANGLES, GLsizei(3 * count), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(3 * first * sizeof(std::uint32_t)));
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
            p.done += count, n -= count;
            p.stats.overlayDrawn += count;
        }
        glBindVertexArray(0);
        if (p.done < units) return false;
        p.stats.triangles += s.overlayTriangles;
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
    s.resolve(p.target, p.x, p.y, p.width, p.height);
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
    p.waitMs = milliseconds;
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
    if (p.lastPhase != Pass::Raster) p.spentMs += took;  // a raster's own time is counted when it is in, not the wait
    if (whole) m_lastPictureMs = p.spentMs;
    if (whole) m_progress.reset();
    return whole;
}

bool Renderer::drawing() const { return m_progress != nullptr; }

}  // namespace sprout::render
