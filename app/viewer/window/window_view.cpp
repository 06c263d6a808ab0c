// The 3D view in the window (window_view.hpp): the plant the worker hands over, taken to the
// GPU; its picture, drawn moving or still (the still one a piece per frame) and shown beside
// the panel, stretched when it was drawn smaller; the moving view's resolution fitted to the
// frames' time; and what ImGui draws over the view.
#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#include "app/render/colour_target.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <memory>
#include <vector>

#include "app/labels.hpp"
#include "app/viewer/window/app.hpp"
#include "app/viewer/window/window_present.hpp"
#include "app/viewer/window/window_view.hpp"

namespace sprout::viewer::detail {
namespace {

// Bytes of a big plant's buffers copied to the GPU per frame: a few ms of memory copy on
// software GL, so a frame with a piece of upload still keeps its 16 ms.
constexpr std::size_t kUploadBytesPerFrame = 8u << 20;
// The time a piece of the still view may take (Renderer::continueDraw): with the panel's own
// few ms, a frame keeps its 16 ms while a big plant is refined.
constexpr double kRefineMs = 8.0;
// A scene whose still picture took at most this long is drawn at full quality while it moves.
constexpr double kFullWhileMovingMs = 10.0;
// The frame time the moving view's resolution is fitted to (App::movingScale).
constexpr double kMovingFrameMs = 10.0;

// The view's picture (drawn at app.drawWidth x app.drawHeight) over w x h at (x, 0) of
// framebuffer `target`: copied, or stretched when it was drawn smaller.
void showView(App& app, unsigned target, int x, int w, int h) {
    if (app.drawWidth == w && app.drawHeight == h) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, app.viewFbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
        glBlitFramebuffer(0, 0, w, h, x, 0, x + w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    } else {
        app.renderer.stretch(app.viewColour, app.drawWidth, app.drawHeight, app.viewWidth, app.viewHeight, target, x, 0, w, h);
    }
}

// The view's picture as the window shows it (showView), top row first.
std::vector<std::uint8_t> shownView(App& app, int w, int h) {
    render::ColourTarget shown(w, h);
    showView(app, shown.fbo, 0, w, h);
    return app.renderer.readPixels(w, h, shown.fbo);
}

// The share of pixels (in percent) whose colours differ by more than 30 of 765 (the summed
// differences of red, green and blue).
double differingPct(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    if (a.size() != b.size() || a.empty()) return -1;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); i += 4)
        n += std::abs(int(a[i]) - int(b[i])) + std::abs(int(a[i + 1]) - int(b[i + 1])) + std::abs(int(a[i + 2]) - int(b[i + 2])) > 30;
    return 100.0 * double(n) / double(a.size() / 4);
}

}  // namespace

void takePlant(App& app, Frame& frame) {
    auto previous = app.state.plant();
    if (app.state.update() && app.state.plant()->image) {
        // An iterated function system: its density image goes to a texture.
        auto p = app.state.plant();
        if (!app.imageTexture) glGenTextures(1, &app.imageTexture);
        glBindTexture(GL_TEXTURE_2D, app.imageTexture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, p->imageWidth, p->imageHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE, p->image->data());
        app.needsRedraw = true;
    } else if (app.state.plant() && app.state.plant() != previous && app.state.plant()->geometry) {
        auto t0 = std::chrono::steady_clock::now();
        const Geometry& g = *app.state.plant()->geometry;
        // Small edits keep the view; a plant of another kind or size is framed anew.
        if (previous && previous->geometry && !app.state.playing()) {  // growth keeps the view
            const Geometry& p = *previous->geometry;
            float a = glm::length(p.bounds.size()), b = glm::length(g.bounds.size());
            float moved = glm::length(p.bounds.centre() - g.bounds.centre());
            if (p.planarCurve != g.planarCurve || b > 2 * a || a > 2 * b || moved > 0.5f * std::max(a, b))
                app.frameOnNextPlant = true;
        }
        // Big plants are edited at interactive detail (more thin stems as lines), baked on
        // the worker; screenshots re-upload at full detail.
        app.bigPlant = render::viewerDetail(g.cylinders.size()) == render::Quality::Interactive;
        // A big plant goes to the GPU a piece per frame (the plant on screen stays until
        // the new one is whole), so that its arrival does not cost one long frame.
        if (auto prepared = app.state.plant()->prepared)
            app.sceneArrived = app.renderer.beginUpload(std::static_pointer_cast<const render::PreparedScene>(prepared),
                                                        kUploadBytesPerFrame),
            app.stagedUploads += !app.sceneArrived;
        else app.renderer.upload(g), app.sceneArrived = true;
        app.uploadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        frame.uploadedNow = true;
        if (app.frameOnNextPlant) {
            app.frame();
            app.frameOnNextPlant = false;
        }
        app.needsRedraw = true;
    }
    for (const std::string& problem : app.renderer.takeTextureProblems()) app.say(problem);  // a broken image, once
    // A click that waited for the derivation's origins; the highlight follows the plant.
    if (app.pendingPick && app.state.plant() && app.state.plant()->pick) app.pickAt(app.pendingPick->first, app.pendingPick->second);
    if ((app.highlightDirty || app.highlightOf != app.state.plant()) && !app.renderer.uploading()) app.updateHighlight();
    // The environment changes with the plant on screen: after a staged upload is whole.
    if (app.environmentDirty || app.environmentOf != app.state.plant()) app.updateEnvironment();
    app.showEnvironment();
    // The plant on screen is drawn until the new one is whole (its picture is kept meanwhile).
    if (app.renderer.uploading()) {
        frame.uploadedNow = true;
        if (app.renderer.continueUpload(kUploadBytesPerFrame)) app.needsRedraw = app.sceneArrived = true;
    }
}


void makeViewPicture(GLuint texture, int w, int h) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void drawLabels(App& app, int fw, int fh) {
    auto plant = app.state.plant();
    const int vw = fw - app.panelWidth, vh = fh;
    if (!plant || !plant->geometry || plant->geometry->labels.empty() || vw <= 0 || vh <= 0) return;
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    ImDrawList* list = ImGui::GetForegroundDrawList();
    for (const Geometry::Label& label : plant->geometry->labels) {
        float x = 0, y = 0;
        if (!labelPosition(app.camera, vw, vh, label.position, x, y) || x < 0 || x >= float(vw) || y < 0 || y >= float(vh)) continue;
        const ImVec2 at((float(app.panelWidth) + x + 3) / std::max(scale.x, 1e-3f), (y - label.size - 1) / std::max(scale.y, 1e-3f));
        const std::uint32_t c = label.colour;
        const char* text = label.text.c_str();
        for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1)})
            list->AddText(nullptr, label.size, ImVec2(at.x + d.x, at.y + d.y), IM_COL32(20, 20, 20, 160), text);
        list->AddText(nullptr, label.size, at, IM_COL32(c >> 24, (c >> 16) & 0xFF, (c >> 8) & 0xFF, 255), text);
    }
}

void showDensityImage(App& app, int vw, int vh) {
    auto p = app.state.plant();
    float scale = std::min(float(vw) / float(p->imageWidth), float(vh) / float(p->imageHeight));
    ImVec2 size(float(p->imageWidth) * scale, float(p->imageHeight) * scale);
    ImGui::SetNextWindowPos(ImVec2(float(app.panelWidth) + (float(vw) - size.x) / 2, (float(vh) - size.y) / 2));
    ImGui::SetNextWindowSize(size);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
    ImGui::Begin("##ifs", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoBringToFrontOnFocus |
                     ImGuiWindowFlags_NoBackground);
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(app.imageTexture)), size);
    ImGui::End();
    ImGui::PopStyleVar(2);
}

void drawView(App& app, Frame& frame, int vw, int vh, int fw, int fh) {
    render::RenderOptions o = app.view.render;  // still quality; drawMoving picks the moving frames'
    o.quality = render::Quality::Still;
    o.quickLines = app.renderer.software();
    const bool interactive = app.interacting || app.shaping || app.state.playing() || app.view.turntable;
    const bool onlyShaping = app.shaping && !app.interacting && !app.state.playing() && !app.view.turntable;
    if (!app.viewFbo) {
        glGenFramebuffers(1, &app.viewFbo);
        glGenTextures(1, &app.viewColour);
    }
    const bool resized = vw != app.viewWidth || vh != app.viewHeight;  // a picture waiting to be shown is lost
    if (resized) {
        makeViewPicture(app.viewColour, vw, vh);
        glBindFramebuffer(GL_FRAMEBUFFER, app.viewFbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, app.viewColour, 0);
        app.viewWidth = vw, app.viewHeight = vh;
        app.needsRedraw = true;
    }
    // Letting go of a drag refines the picture to full size and quality.
    // Taking hold of a panel's control changes nothing on screen until its first plant comes;
    // letting go of anything refines the picture if it was drawn moving.
    if (interactive != app.viewInteractive) {
        app.viewInteractive = interactive;
        if (interactive ? !onlyShaping : app.viewMoving) app.needsRedraw = true;
    }
    // A picture in pieces abandoned (a screenshot drew in between): begin it again.
    if (app.refining && !app.renderer.drawing()) app.refining = false, app.needsRedraw = true;
    auto drawMoving = [&] {
        auto t0 = std::chrono::steady_clock::now();
        // A scene whose still picture takes a few ms (a GPU, or a small plant) moves at
        // full quality. Others at a fraction of the pixels each way, half at most and
        // less while frames take too long (a big 2D curve keeps its full-size raster,
        // which moves as a picture while dragged), and big ones as their sketch or a
        // coarser bake with no shadow pass.
        const bool full = app.view.fullWhileMoving || app.renderer.lastPictureMs() <= kFullWhileMovingMs;
        render::RenderOptions m = o;
        m.quality = full ? render::Quality::Still : render::Quality::Interactive;
        const bool scaled = !full && !app.renderer.rasterCurve();
        app.fullMovingDraws += full;
        app.drawWidth = scaled ? std::max(1, int(float(vw) * app.movingScale)) : vw;
        app.drawHeight = scaled ? std::max(1, int(float(vh) * app.movingScale)) : vh;
        app.renderer.draw(app.camera, app.drawWidth, app.drawHeight, m, app.viewFbo, 0, 0);  // abandons a refinement
        app.refining = false;
        app.drawMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        ++app.viewDraws;
        app.sketchDraws += app.renderer.stats().proxy;
        app.movingWarm = true;
        frame.viewUpdated = true;
    };
    // The moving-quality picture comes first, the still one following in pieces, when
    // the still one takes several frames: for a new scene (a big plant, or a slider
    // dragged over a plant whose picture is slow: each new plant is seen at once) and
    // for a camera moved by the wheel or the keys. And for the first scene, so that the
    // moving path has run before the first drag (a software rasteriser compiles its
    // shader variants on first use: a long frame).
    const glm::mat4 cameraKey = app.camera.projection(float(vw) / float(vh), 1, 100) * app.camera.view();
    const bool slow = app.lastStillMs > kRefineMs;
    const bool cameraMoved = cameraKey != app.drawnCamera;
    const bool arrived = app.sceneArrived;
    // Not for a big curve: its moving picture is its raster, which the still one makes on
    // a thread (made here, it held the window 130 ms when the Gosper curve n=5 arrived).
    const bool preview = app.needsRedraw && !interactive && !app.renderer.rasterCurve() &&
                         ((arrived && (app.bigPlant || slow || !app.movingWarm)) || (cameraMoved && slow));
    // A plant that comes while a panel's control is held is drawn in one frame and shown in
    // the next, on software GL where the window keeps the view shown meanwhile: its drawing
    // (5-7 ms for lsystem9's sketch on llvmpipe) and the stretch of it over the view with its
    // copy to the X server (4-5 ms) made one frame of 10-16 ms. The frame that shows it draws
    // nothing new: a plant that came meanwhile is drawn in the frame after.
    const bool showLate = app.viewPending && !resized;
    app.viewPending = false;
    if (!showLate) app.sceneArrived = false;
    if (app.needsRedraw && !showLate) app.drawnCamera = cameraKey;
    if (showLate) {
        // Nothing drawn: the picture drawn in the last frame is shown below.
    } else if (app.needsRedraw && interactive) {
        drawMoving();
        frame.moved = true;
        app.viewMoving = true;
        app.viewPending = onlyShaping && frame.mayKeepView;
    } else if (app.needsRedraw) {  // still: the full picture, a piece per frame
        if (app.measureMoving && app.viewMoving) {
            const auto t0 = std::chrono::steady_clock::now();
            app.movingPicture = shownView(app, vw, vh);
            frame.measuringMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        }
        if (preview) drawMoving(), frame.moved = cameraMoved && !arrived, frame.previewed = true;  // moving: the wheel or keys
        app.renderer.beginDraw(app.camera, vw, vh, o, app.viewFbo, 0, 0);
        app.refining = true;
        app.refineStart = glfwGetTime();
        app.refineWorstMs = 0;
        app.refineFrames = 0;
    }
    if (!showLate) app.needsRedraw = false;
    if (app.refining) {
        frame.refinedPiece = true;
        // A frame that drew the moving picture first has that much less for its piece.
        const bool whole = app.renderer.continueDrawFor(frame.previewed ? std::max(1.0, kRefineMs - app.drawMs) : kRefineMs);
        if (whole) {
            app.refining = false;

            app.lastStillMs = app.renderer.lastPictureMs();
            app.drawWidth = vw, app.drawHeight = vh;
            app.drawMs = (glfwGetTime() - app.refineStart) * 1000;
            if (!app.movingPicture.empty()) {
                const auto t0 = std::chrono::steady_clock::now();
                app.movingDifferPct = differingPct(app.movingPicture, app.renderer.readPixels(vw, vh, app.viewFbo));
                app.movingPicture.clear();
                frame.measuringMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            }
            ++app.viewDraws;
            frame.viewUpdated = true;
            app.viewMoving = false;
        }
    }
    // A frame in which nothing on screen changes is not shown: while the still view is
    // drawn in pieces the window shows its last picture, so unless the panel changed
    // (hover, typing, the caret), its pieces follow each other without the copy of
    // the view and the panel's drawing (~7 ms a frame on software GL).
    const bool refiningOn = app.refining && !frame.viewUpdated && !showLate;  // only then can a frame be left out
    const std::uint64_t ui = frame.uiHash = refiningOn ? drawDataHash(ImGui::GetDrawData()) : 0;
    frame.present = !refiningOn || ui != app.presentedUi || fw != app.presentedWidth || fh != app.presentedHeight;
    if (frame.present) {
        app.presentedUi = ui;  // 0 after a frame that was not hashed: the next one is shown
        app.presentedWidth = fw, app.presentedHeight = fh;
        // The panel covers the left part; the view goes beside it (stretched when drawn small),
        // unless the window's back buffer shows its picture already.
        if (showLate || (frame.viewUpdated && !app.viewPending) || !frame.mayKeepView)
            showView(app, 0, app.panelWidth, vw, vh), frame.viewShown = true;
    }
}

void noteFrame(App& app, const Frame& frame) {
    if (frame.moved || frame.previewed) {
        // The moving view's share of the pixels follows its frames' time (which goes with
        // the pixels drawn): fewer while a frame takes longer than kMovingFrameMs, back
        // towards half each way when quick.
        const float k = float(std::sqrt(kMovingFrameMs / std::max(app.frameMs, 1.0)));
        app.movingScale = std::clamp(app.movingScale * std::clamp(k, 0.6f, 1.1f), kSmallestMovingScale, 0.5f);
    }
    if (frame.moved) {
        if (app.frameMs > app.movingWorstMs) {
            char what[160];
            const render::RenderStats& drawn = app.renderer.stats();
            std::snprintf(what, sizeof what, "frame_%llu_step_%d_tris_%zu_view_%dx%d_in_%.1fms%s%s%s",
                          static_cast<unsigned long long>(app.movingFrames + 1),
                          app.state.plant() ? app.state.plant()->displayStep : -1, drawn.triangles, app.drawWidth,
                          app.drawHeight, app.drawMs, drawn.shadowPass ? "_shadow_pass" : "", drawn.proxy ? "_sketch" : "",
                          frame.uploadedNow ? "_new_plant" : "");
            app.movingWorstWhat = what;
        }
        app.movingWorstMs = std::max(app.movingWorstMs, app.frameMs);
        app.movingTotalMs += app.frameMs;
        ++app.movingFrames;
    }
}

}  // namespace sprout::viewer::detail
