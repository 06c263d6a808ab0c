// The phases of a picture (Renderer::step, renderer_draw.cpp), in order: the shadow map, a big
// curve's raster, the backdrop (sky, ground, the curve's ink), the scene, the environment's
// overlay, the highlight. Each draws its next piece and says whether the picture goes on.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <future>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/render/curve_raster.hpp"
#include "app/render/gl.hpp"
#include "app/render/renderer.hpp"
#include "app/render/renderer_impl.hpp"

namespace sprout::render {

using detail::kShadowSize;

// The shadow map, from the light: the scene's depth, a range of it a piece.
bool Renderer::shadowPhase(Piece& piece) {
    Impl& s = *m;
    Pass& p = piece.p;
    glBindFramebuffer(GL_FRAMEBUFFER, s.shadowFbo);
    glViewport(0, 0, kShadowSize, kShadowSize);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);  // never sample the map while writing it
    if (!p.started) glClear(GL_DEPTH_BUFFER_BIT), p.started = true, s.shadowValid = s.shadowMade = false;
    p.stats.shadowPass = true;
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    const std::size_t sceneCount = s.bakedIndices / 3 + s.lineCount;
    const std::size_t n = piece.take(sceneCount);
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
    // window's still view (drawn in pieces): made once the picture is shown (prepareMoving),
    // not in one of its pieces (3 ms of lsystem9's 70 on llvmpipe), nor in the first frame
    // of a drag. A picture drawn at once (`sprout render`, a video's frame) has none to come.
    if (m_software && p.ground && !piece.wait)
        s.groundShadowWanted = Impl::GroundShadowWanted{p.o, p.eye, groundCentre(p), p.groundRadius, s.shadowGeneration};
    return piece.next(Pass::Raster);
}

// A big curve's raster, made on a thread when it may take its time.
bool Renderer::rasterPhase(Pass& p, bool wait) {
    Impl& s = *m;
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
    return !(made && !wait);
}

// The sky, the ground and a big curve's ink: a band of rows a piece (every pixel pays for the
// ground's shadow lookups).
bool Renderer::backdropPhase(Piece& piece, bool groundShadowTexture) {
    Impl& s = *m;
    Pass& p = piece.p;
    const std::size_t rows = piece.take(std::size_t(p.height));
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
        // The colour blended, the alpha made "over" (1 over the sky): the pictures' alpha was
        // below 1 where the ground fades into the sky (0.75 at its rim in a PNG of `render`).
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
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
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // as the ground's
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
    return piece.next(Pass::Scene);
}

// The primitives: curve ribbons, triangles, lines (or a big scene's sketch while the view
// moves: the still view draws it whole again).
bool Renderer::scenePhase(Piece& piece) {
    Impl& s = *m;
    Pass& p = piece.p;
const std::size_t curveCount = p.curve && !p.sketch ? s.curveCount : 0;  // a curve's sketch: its lines instead
    const std::size_t sceneCount = s.bakedIndices / 3 + s.lineCount;
    const std::size_t total = curveCount + (p.sketch ? s.proxyIndices / 3 + s.proxyCount : sceneCount);
    const std::size_t from = p.done, to = p.done + piece.take(total);
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
        if (s.texturedTris || s.translucentTextured) s.setLighting(s.texturedProgram, p.o, p.eye, p.lightViewProj, p.plantShadows, p.texel);
        s.eye = p.eye;
        s.drawRange(p.viewProj, lit, a, b, p.stats, p.sketch, p.o.quickLines,
                    p.curve ? &p.o.curveInk : nullptr);
        p.stats.proxy = p.sketch;
    }
    p.done = to;
    if (p.done < total) return false;
    p.phase = Pass::Overlay, p.done = 0, p.started = false;
    return !(s.overlayIndices && !piece.wait);
}

bool Renderer::overlayPhase(Piece& piece) {
    Impl& s = *m;
    Pass& p = piece.p;
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
    for (std::size_t n = piece.take(units); n > 0;) {
        const int pass = s.overlayPass(p.done);
        const std::size_t first = s.overlayTriangle(p.done), count = std::min(n, s.overlayPassEnd(pass) - p.done);
        if (pass >= 1) {
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // as the ground's
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
    return true;
}

// What was picked, seen through whatever is in front of it.
void Renderer::drawHighlight(const Pass& p) {
    Impl& s = *m;
    s.setLighting(s.overlayProgram, p.o, p.eye, p.lightViewProj, false, p.texel);
    setUniform(s.overlayProgram, "uViewProj", p.viewProj);
    setUniform(s.overlayProgram, "uPass", 0);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(s.highlight.vao);
    glDrawElements(GL_TRIANGLES, GLsizei(s.highlightIndices), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace sprout::render
