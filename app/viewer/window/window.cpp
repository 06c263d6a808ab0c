// The viewer's start-up and main loop: a GLFW window with the plant in 3D and the ImGui panel.
// The same renderer as `sprout render`, with a GLFW context instead of OSMesa. What a frame
// does is in the files beside it: window_input.cpp (mouse and keys), window_view.cpp (the
// plant to the GPU and its picture, moving or refined), window_present.cpp (the panel's cache,
// and the frame to the screen).
//
// Index of this file:
//   [SECTION] Fonts and warm-up
//   [SECTION] Window events
//   [SECTION] Start-up
//   [SECTION] A frame's parts
//   [SECTION] The main loop
#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#include "app/render/colour_target.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

#include "app/args.hpp"
#include "app/image.hpp"
#include "app/plant/presets.hpp"
#include "app/plant/scene.hpp"
#include "app/viewer/window/app.hpp"
#include "app/viewer/window/viewer.hpp"
#include "app/viewer/window/window_input.hpp"
#include "app/viewer/window/window_present.hpp"
#include "app/viewer/window/window_view.hpp"

// [SECTION] Fonts and warm-up
namespace sprout::viewer {
namespace {

// ImGui's own font has ASCII and Latin-1 only: text pasted from ABOP, a PDF or a web page
// (δ ω → − ≥ p₁ ’) would show as '?'. Those blocks are merged in from Debian's DejaVu Sans
// Mono (fonts-dejavu-core) when it is installed; ASCII keeps ImGui's font and layout.
void addNotationGlyphs() {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->AddFontDefault();
    for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf", "/usr/share/fonts/TTF/DejaVuSansMono.ttf"}) {
        if (FILE* f = std::fopen(path, "rb")) {
            std::fclose(f);
            static const ImWchar ranges[] = {0x0370, 0x03FF,   // Greek
                                             0x2000, 0x206F,   // punctuation: dashes, quotes, primes, spaces
                                             0x2070, 0x209F,   // super- and subscripts
                                             0x2190, 0x21FF,   // arrows
                                             0x2200, 0x22FF,   // mathematical operators
                                             0x27F0, 0x27FF,   // long arrows
                                             0};
            ImFontConfig config;
            config.MergeMode = true;
            config.GlyphMinAdvanceX = 7.0f;  // ImGui's font is 7 pixels a character
            config.GlyphMaxAdvanceX = 7.0f;
            io.Fonts->AddFontFromFileTTF(path, 13.0f, &config, ranges);
            return;
        }
    }
}


render::ProcAddress glfwProc(const char* name) { return reinterpret_cast<render::ProcAddress>(glfwGetProcAddress(name)); }

// Every way the window draws, done once before the first frame (renderer, the copy of the view
// into the window, the panel), at the view's size, while the worker derives the plant.
void warmUp(App& app, GLFWwindow* window) {
    // The renderer's ways compiled and its images made: the first moving picture took 37 ms,
    // then 11. About 0.1-0.2 s here, once (not for a screenshot).
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window, &fw, &fh);
    const int vw = std::max(1, fw - app.panelWidth), vh = std::max(1, fh);
    app.renderer.warmUp(vw, vh);
    // And the copies of the view into the window, stretched (moving frames) and not, at
    // the view's place: the first stretched one took 30 ms (with a copy of a few pixels
    // as a warm-up still 24).
    {
        render::ColourTarget view(vw, vh);
        glClear(GL_COLOR_BUFFER_BIT);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, view.fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, vw, vh, app.panelWidth, 0, app.panelWidth + vw, vh, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        GLuint picture = 0;
        glGenTextures(1, &picture);
        detail::makeViewPicture(picture, vw, vh);
        app.renderer.stretch(picture, vw / 2, vh / 2, vw, vh, 0, app.panelWidth, 0, vw, vh);
        glFinish();
        glDeleteTextures(1, &picture);
    }
    // And the panel's: its font atlas and its drawing (the first frame took 37 ms).
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::GetForegroundDrawList()->AddText(ImVec2(0, 0), IM_COL32_WHITE, "Sprout");
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
}

// Files dropped on the window (.lsys, Lparser .ls, Fractint .l), opened on the next frame.
std::vector<std::string> g_dropped;
// [SECTION] Window events
void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

// The window was uncovered (an X Expose, no compositor): its next frame is sent whole.
bool g_exposed = false;
void onRefresh(GLFWwindow*) { g_exposed = true; }

// [SECTION] Start-up
// The window with an OpenGL 3.3 core context, current on this thread; null, said on standard
// error, when there is none (no display).
GLFWwindow* openWindow(int width, int height, const std::string& source) {
    if (!glfwInit()) {
        std::cerr << "sprout: cannot open a window (no display?); try: sprout render " << source << " -o plant.png\n";
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, "Sprout", nullptr, nullptr);
    if (!window) {
        std::cerr << "sprout: cannot create an OpenGL 3.3 window; try: sprout render " << source << " -o plant.png\n";
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    return window;
}

// Dear ImGui on the window: its style, the notation's glyphs, dropped files and exposures.
void startPanel(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed: no imgui.ini files left around
    addNotationGlyphs();
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0;
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    glfwSetDropCallback(window, onDrop);
    glfwSetWindowRefreshCallback(window, onRefresh);
    ImGui_ImplOpenGL3_Init("#version 330");
}

// What the worker does for the window: a plant prepared for the renderer on its thread, and
// a forest scene's species found among the presets and beside the scene's file.
void connectWorker(App& app) {
    app.state.worker().finished = [] { glfwPostEmptyEvent(); };  // the loop waits for it (runViewer)
    app.state.worker().prepare = [](const std::shared_ptr<const Geometry>& owner) -> std::shared_ptr<const void> {
        const Geometry& g = *owner;
        auto p = std::make_shared<render::PreparedScene>();
        render::Renderer::prepareForViewer(g, *p, owner);
        return p;
    };
    app.state.worker().speciesSource = [&app](const std::string& name) {
        std::vector<std::filesystem::path> folders;
        for (const auto& base : {app.state.path(), app.state.importedFrom()})
            if (!base.empty()) folders.push_back(base.parent_path());
        return speciesText(name, folders);
    };
}

// The file or preset the viewer opens on; false, said on standard error, when there is none.
bool openFirst(App& app, const std::string& source) {
    std::string error;
    if (std::filesystem::exists(source)) {
        if (!app.state.open(source, error)) {
            std::cerr << "sprout: " << error << "\n";
            return false;
        }
    } else if (auto text = presetText(source)) {
        app.state.openText(std::string(*text), {}, source);
    } else {
        std::cerr << source << ": no such file or preset\n";
        return false;
    }
    return true;
}

// [SECTION] A frame's parts
// What moves between frames: the document's clock and autosave, the file changed on disk, the
// turntable, the presets' thumbnails, a file dropped on the window.
void updateBeforeFrame(App& app, double now, double dt, double& lastDiskCheck) {
    app.state.tick(dt);
    app.state.autosave();
    if (now - lastDiskCheck > 1.0) {
        lastDiskCheck = now;
        if (app.state.reloadIfChangedOnDisk()) app.say("reloaded: the file changed on disk");
    }
    if (app.view.turntable) {
        app.camera.yaw += app.view.turntableSpeed * float(dt);
        app.needsRedraw = true;
    }
    {
        static const std::vector<std::string> all = [] {
            auto n = presetNames();
            for (const auto& x : ifsPresetNames()) n.push_back(x);
            for (const auto& x : scenePresetNames()) n.push_back(x);
            return n;
        }();
        // Thumbnails wait while the model is being edited (a curve or a slider dragged: a new
        // derivation every frame) and for half a second after, so that they take no frame of it.
        static std::uint64_t lastGeneration = 0;
        static double lastEdit = 0;
        if (app.state.generation() != lastGeneration) lastGeneration = app.state.generation(), lastEdit = now;
        const bool editing = app.state.worker().busy() || now - lastEdit < 0.5;
        app.thumbnails.poll(all, !app.interacting && !app.refining && !app.state.playing() && !app.view.turntable && !editing);
    }
    if (!g_dropped.empty()) {
        std::string path = g_dropped.front();
        g_dropped.clear();
        app.openFile(path);
    }
}

// The recovery question (the text autosaved by a session that did not close normally).
void recoveryPopup(App& app, bool& offerRecovery) {
    if (offerRecovery) {
        ImGui::OpenPopup("Recover unsaved grammar?");
        offerRecovery = false;
    }
    if (ImGui::BeginPopupModal("Recover unsaved grammar?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted("Sprout did not close normally last time.\nThe grammar you were editing was autosaved.");
        if (ImGui::Button("Restore it")) {
            app.state.restoreRecovered();
            app.state.discardRecovery();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard")) {
            app.state.discardRecovery();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

// No 3D view now (an IFS image, drawn by the panel's pass; a minimised window): a picture in
// pieces is left, and the view is drawn anew when it is back (its size is forgotten). Nothing
// to redraw meanwhile: an IFS on screen costs no frames.
void clearWithoutView(App& app, detail::Presenter& presenter, int fw, int fh) {
    app.refining = false;
    app.viewWidth = app.viewHeight = 0;
    app.needsRedraw = false;
    app.presentedWidth = 0;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glClearColor(0.957f, 0.949f, 0.918f, 1);  // the density image's background
    glClear(GL_COLOR_BUFFER_BIT);
    presenter.forget();  // the panel's strip too
}

// --screenshot: the whole window as the user sees it, panel and plant.
void writeWindowPicture(App& app, int fw, int fh, const std::string& path) {
    glFinish();
    Image img;
    img.width = fw;
    img.height = fh;
    img.rgba = app.renderer.readPixels(fw, fh, 0);
    std::string e;
    if (!writePng(path, img, e)) std::cerr << path << ": " << e << "\n";
}

// Frames are drawn as fast as they come only while something moves. While the worker alone
// works, the loop waits for its result (Worker::finished wakes it) or an event, and for a
// progress bar's next frame: frames spun meanwhile took the cores from the worker (below the
// window's priority), which took 12-57 ms for lsystem9's curve drag's last plant instead of
// 5-9 ms. Idle: no frames, no CPU.
void awaitFrame(App& app, const Script& script, bool screenshot) {
    const bool scriptMoves = !script.empty() && !script.waitsForWorker(app);
    const bool animating = app.state.playing() || app.view.turntable || scriptMoves || screenshot || app.refining ||
                           app.viewPending || app.environmentJob.valid();
    if (animating || app.needsRedraw) glfwPollEvents();
    else glfwWaitEventsTimeout(app.state.worker().busy() ? 1.0 / 30 : 0.25);
}

// The window's title names what is being edited, as the panel does.
void nameWindow(App& app, std::string& shown) {
    if (std::string title = "Sprout - " + app.state.title() + (app.state.dirty() ? " *" : ""); title != shown) {
        glfwSetWindowTitle(app.window, title.c_str());
        shown = std::move(title);
    }
}

}  // namespace

// [SECTION] The main loop
int runViewer(int argc, char** argv) {
    Args args(argc, argv, 1, {}, {"--screenshot", "--window-screenshot", "--script", "--size"});
    if (!args.error().empty() || args.positionals().size() > 1) {
        std::cerr << "sprout: " << (args.error().empty() ? "expects at most one FILE or PRESET" : args.error())
                  << "\nusage: sprout [FILE|PRESET] [--size WxH] [--screenshot OUT.png] [--script FILE]\n";
        return 2;
    }
    const std::string source = args.positionals().empty() ? std::string(kDefaultPreset) : args.positionals()[0];
    int width = 1440, height = 860;
    if (auto s = args.value("--size"); s && !parseSize(*s, width, height)) {
        std::cerr << "sprout: --size expects WIDTHxHEIGHT between 16x16 and 8192x8192, e.g. 1440x860\n";
        return 2;
    }
    Script script;
    if (auto s = args.value("--script")) {
        std::string error;
        if (!script.load(*s, error)) {
            std::cerr << *s << ": " << error << "\n";
            return 1;
        }
    }
    // --screenshot: the whole window (panel and plant) once the plant is on screen, then exit.
    const std::optional<std::string> screenshot = args.value("--screenshot");

    GLFWwindow* window = openWindow(width, height, source);
    if (!window) return 1;

    App app(std::filesystem::read_symlink("/proc/self/exe").string());
    app.window = window;
    app.measureMoving = !script.empty();
    std::string error;
    if (!app.renderer.init(glfwProc, error)) {
        std::cerr << "sprout: " << error << "\n";
        return 1;
    }
    startPanel(window);

    connectWorker(app);
    if (!openFirst(app, source)) return 1;
    if (!screenshot) warmUp(app, window);
    // A previous session ended without saving: offer its text back.
    bool offerRecovery = app.state.recoverable().has_value() && !screenshot && script.empty();

    viewer::detail::Mouse mouse;
    double last = glfwGetTime(), lastDiskCheck = last;
    bool screenshotDone = false;
    viewer::detail::PanelCache panelCache;
    viewer::detail::Presenter presenter;
    presenter.init(window, app.renderer.software());
    int framesWithPlant = 0;
    std::string windowTitle;
    while (!glfwWindowShouldClose(window) || (app.state.dirty() && !app.quitConfirmed && script.empty() && !screenshot)) {
        if (glfwWindowShouldClose(window)) {  // unsaved edits: ask first
            glfwSetWindowShouldClose(window, GLFW_FALSE);
            app.quitPopup = true;
        }
        nameWindow(app, windowTitle);
        awaitFrame(app, script, screenshot.has_value());
        const double now = glfwGetTime(), dt = now - last;
        last = now;
        auto frameStart = std::chrono::steady_clock::now();
        viewer::detail::Frame frame;

        // The plant the worker finished, to the GPU (window_view.cpp).
        viewer::detail::takePlant(app, frame);
        updateBeforeFrame(app, now, dt, lastDiskCheck);

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        if (app.scriptMouse.on) {  // the script's mouse, in place of the window system's
            ImGui::GetIO().MousePos = ImVec2(app.scriptMouse.x, app.scriptMouse.y);
            ImGui::GetIO().MouseDown[0] = app.scriptMouse.down;
        }
        ImGui::NewFrame();
        drawPanel(app);

        // The camera and the keyboard shortcuts (window_input.cpp).
        viewer::detail::handleInput(app, window, mouse, dt);
        if (app.quitRequested) {
            app.quitRequested = false;
            if (app.state.dirty()) app.quitPopup = true;
            else app.quitConfirmed = true;
        }
        if (app.quitConfirmed) glfwSetWindowShouldClose(window, GLFW_TRUE);

        // The 3D view, redrawn only when something changed (a software rasteriser may take
        // longer than a frame on a big plant; the panel stays responsive either way).
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        const int vw = std::max(1, fw - app.panelWidth), vh = std::max(1, fh);
        const bool showImage = app.state.plant() && app.state.plant()->image && app.imageTexture;
        if (showImage) viewer::detail::showDensityImage(app, vw, vh);  // the density image, fitted to the view
        // The recovery question last in the frame: a modal opened before the panel's windows
        // first appear fails ImGui's check for the modal that blocks them (it aborted the
        // viewer on the first start after a crash).
        recoveryPopup(app, offerRecovery);
        viewer::detail::drawLabels(app, fw, fh);
        ImGui::Render();
        if (std::exchange(g_exposed, false)) presenter.forget();  // its next shown frame sends it whole
        const bool inStrip = viewer::detail::drawnInStrip(app, fw);
        if (app.state.plant() && app.state.plant()->geometry && fw > 0 && fh > 0) {
            frame.mayKeepView = presenter.mayKeepView(inStrip, app.panelWidth, fw, fh);
            viewer::detail::drawView(app, frame, vw, vh, fw, fh);  // window_view.cpp
            ++framesWithPlant;
        } else {
            clearWithoutView(app, presenter, fw, fh);
            frame.viewShown = true;  // cleared: sent whole
            if (app.state.plant()) ++framesWithPlant;
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        viewer::detail::PanelDrawn panelDrawn = viewer::detail::PanelDrawn::Whole;
        if (frame.present) panelDrawn = viewer::detail::drawPanelCached(app, panelCache, fw, fh, frame.uiHash, presenter.kept, inStrip);

        // A text that makes no plant (errors, an L-Py model not trusted) is on screen as it
        // is: screenshots and scripts go on once its result is in.
        if (!app.state.plant() && app.state.latest() && !app.state.worker().busy()) ++framesWithPlant;
        if (screenshot && !screenshotDone && framesWithPlant >= 2 && !app.state.worker().busy() && script.empty() && app.viewSettled()) {
            writeWindowPicture(app, fw, fh, *screenshot);
            screenshotDone = true;
            app.quitConfirmed = true;
            glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
        if (frame.present) presenter.present(window, panelDrawn, app.panelWidth, fw, fh, frame.viewShown);
        else glFlush();  // the piece goes on drawing meanwhile
        if (!script.empty() && framesWithPlant > 0 && !script.step(app)) {
            app.quitConfirmed = true;
            glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
        // The still picture is on screen: what moving frames take from it is made now.
        if (!app.refining) app.renderer.prepareMoving();
        app.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count() - frame.measuringMs;
        app.worstFrameMs = std::max(app.worstFrameMs * 0.995, app.frameMs);
        if (frame.refinedPiece) app.refineWorstMs = std::max(app.refineWorstMs, app.frameMs), ++app.refineFrames;
        viewer::detail::noteFrame(app, frame);
    }
    app.state.autosave(true);
    app.state.markCleanExit();
    app.state.worker().stop();  // its last result wakes the loop through GLFW, which ends below
    panelCache.image.reset();  // while the context is current
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

}  // namespace sprout::viewer
