// A picture: worked out from the camera (plan), then drawn in passes (step): the shadow map,
// sky and ground, the plant, the environment, the highlight (each pass is renderer_phases.cpp);
// at once (draw) or in pieces.
#include "app/render/renderer.hpp"

#include "app/render/curve_raster.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <utility>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/render/gl.hpp"
#include "app/render/renderer_impl.hpp"

namespace sprout::render {
namespace {

constexpr int kStaleShadowFrames = 3;

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
    groundShadowWanted.reset();  // a moving frame's comes first
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
        const std::size_t b = std::min(to, tris), opaque = moving ? tris : tris - translucentTris;
        const std::size_t plainEnd = moving ? opaque : opaque - std::min(opaque, texturedTris);  // then the textured ones
        if (from < plainEnd) {
            glUseProgram(p);
            setUniform(p, "uViewProj", viewProj);
            plainLight(p);
            glBindVertexArray(mesh.vao);
            // The plain triangles, then each shining material's with its light (not in the
            // depth pass, nor a moving frame's, which are one draw).
            std::size_t at = from;
            const std::size_t end = std::min(b, plainEnd);
            for (const mesh::ShineRange& r : moving || p == bakedDepth ? std::vector<mesh::ShineRange>{} : shines) {
                const std::size_t r0 = std::max(r.first, at), r1 = std::min(r.first + r.count, end);
                if (r0 >= r1) continue;
                if (r0 > at) glDrawElements(GL_TRIANGLES, GLsizei(3 * (r0 - at)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * at * sizeof(std::uint32_t)));
                shineLight(p, r.shine);
                glDrawElements(GL_TRIANGLES, GLsizei(3 * (r1 - r0)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * r0 * sizeof(std::uint32_t)));
                plainLight(p);
                at = r1;
            }
            if (!moving && at < std::min(end, closedStems)) {  // closed stems: their back faces are never seen
                const std::size_t cut = std::min(end, closedStems);
                glEnable(GL_CULL_FACE);
                glDrawElements(GL_TRIANGLES, GLsizei(3 * (cut - at)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * at * sizeof(std::uint32_t)));
                glDisable(GL_CULL_FACE);
                at = cut;
            }
            if (end > at)
                glDrawElements(GL_TRIANGLES, GLsizei(3 * (end - at)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * at * sizeof(std::uint32_t)));
        }
        if (b > plainEnd && from < opaque) drawTextured(viewProj, p, std::max(from, plainEnd), std::min(b, opaque));
        if (b > opaque) drawTranslucent(viewProj, p, std::max(from, opaque) - opaque, b - opaque);
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
bool Renderer::groundShadowCurrent() const { return m->groundShadowOf == m->shadowGeneration; }

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
    Piece piece{*this, p, budget, wait};
    if (p.phase == Pass::Shadow && !shadowPhase(piece)) return false;
    if (p.phase == Pass::Raster && !rasterPhase(p, wait)) return false;
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
    if (p.phase == Pass::Backdrop && !backdropPhase(piece, groundShadowTexture)) return false;
    if (p.phase == Pass::Scene && !scenePhase(piece)) return false;
    if (p.phase == Pass::Overlay && s.overlayIndices && !overlayPhase(piece)) return false;
    if (s.highlightIndices) drawHighlight(p);
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

bool Renderer::prepareMoving() {
    Impl& s = *m;
    const std::optional<Impl::GroundShadowWanted> w = std::exchange(s.groundShadowWanted, std::nullopt);
    if (!w || w->generation != s.shadowGeneration || m_progress) return false;
    const int made = s.groundShadowMade;
    GLint framebuffer = 0, viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    s.ensureGroundShadow(w->o, w->eye, w->centre, w->radius);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    return s.groundShadowMade != made;
}

}  // namespace sprout::render
