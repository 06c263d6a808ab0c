// The viewer's start-up and main loop: a GLFW window with the plant in 3D and the ImGui panel.
// The same renderer as `sprout render`, with a GLFW context instead of OSMesa.
#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#include "app/render/colour_target.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

#include "app/cli/args.hpp"
#include "app/cli/commands.hpp"
#include "app/image.hpp"
#include "app/labels.hpp"
#include "app/presets.hpp"
#include "app/viewer/app.hpp"
#include "app/viewer/window_input.hpp"

// GLFW's X11 display and GLX window (glfw3native.h would bring X11's and GL's headers in over
// glad's): Display* and GLXWindow, an XID.
extern "C" void* glfwGetX11Display(void);
extern "C" unsigned long glfwGetGLXWindow(GLFWwindow* window);

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

// Storage for the view's picture, w x h: a texture, as a moving frame's smaller picture is
// drawn stretched over the view (showView).
void makeViewPicture(GLuint texture, int w, int h) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
}

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
        makeViewPicture(picture, vw, vh);
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

// Labels (L-Py's @L) over the 3D view, where the camera shows their points, in the panel's font
// with a dark outline (as `paintLabels` paints them into pictures).
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

// A hash of what ImGui draws in a frame (vertices, indices, commands): equal hashes, the
// same panel on screen.
std::uint64_t drawDataHash(const ImDrawData* d) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    auto mix = [&h](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        std::size_t i = 0;
        for (std::uint64_t w; i + 8 <= n; i += 8) {
            std::memcpy(&w, b + i, 8);
            h = (h ^ w) * 0x100000001B3ull;
            h ^= h >> 29;
        }
        for (; i < n; ++i) h = (h ^ b[i]) * 0x100000001B3ull;
    };
    if (!d || !d->Valid) return 0;
    mix(&d->CmdListsCount, sizeof d->CmdListsCount);
    for (int k = 0; k < d->CmdListsCount; ++k) {
        const ImDrawList* l = d->CmdLists[k];
        mix(l->VtxBuffer.Data, std::size_t(l->VtxBuffer.Size) * sizeof(ImDrawVert));
        mix(l->IdxBuffer.Data, std::size_t(l->IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& c : l->CmdBuffer) {
            mix(&c.ClipRect, sizeof c.ClipRect);
            mix(&c.TextureId, sizeof c.TextureId);
            mix(&c.VtxOffset, sizeof c.VtxOffset);
            mix(&c.IdxOffset, sizeof c.IdxOffset);
            mix(&c.ElemCount, sizeof c.ElemCount);
        }
    }
    return h;
}

// The panel as ImGui last drew it, kept in an image of the window's size: a frame whose
// panel is what it was (the same draw data) copies the panel's strip of the window from it
// instead of drawing ImGui's triangles again (3.6 ms a frame on software GL; the copy ~1).
// Only when everything ImGui draws lies in the strip: a popup or an image over the view is
// drawn as it comes. The image is cleared to the panel's own colour, which is what the
// window's strip shows under ImGui's barely transparent panel after its first frames.
struct PanelCache {
    std::unique_ptr<render::ColourTarget> image;
    int width = 0, height = 0;
    std::uint64_t hash = 0;
};

// What drawPanel put in the window's back buffer: ImGui drawn over the whole window, the
// panel's strip copied from the cache, or nothing (the strip there is this frame's panel).
enum class PanelDrawn { Whole, Strip, Kept };

// `hash`: drawDataHash of this frame's draw data when the frame already made it, else 0.
// `kept`: the back buffer's strip holds the cached panel (the window was not swapped since).
PanelDrawn drawPanel(App& app, PanelCache& cache, int fw, int fh, std::uint64_t hash, bool kept = false) {
    ImDrawData* d = ImGui::GetDrawData();
    // Whether everything ImGui draws lies in the strip: each command's clip rectangle, or
    // where its triangles are when it is clipped to more (a window's background is clipped
    // to the whole display; its text may run past its edge, clipped to the window).
    bool inStrip = d && d->Valid && app.panelWidth > 0 && app.panelWidth <= fw;
    const float right = float(app.panelWidth) + 0.5f;
    for (int k = 0; inStrip && k < d->CmdListsCount; ++k) {
        const ImDrawList* l = d->CmdLists[k];
        for (const ImDrawCmd& c : l->CmdBuffer) {
            if (c.UserCallback) inStrip = false;
            if (!inStrip || c.ClipRect.z <= right) continue;
            for (unsigned e = 0; e < c.ElemCount; ++e) {
                const unsigned idx = c.IdxOffset + e;
                if (idx >= unsigned(l->IdxBuffer.Size)) break;
                const unsigned vtx = c.VtxOffset + l->IdxBuffer[int(idx)];
                if (vtx >= unsigned(l->VtxBuffer.Size) || !(l->VtxBuffer[int(vtx)].pos.x <= right)) {
                    inStrip = false;
                    break;
                }
            }
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    if (!inStrip) {
        cache.hash = 0;
        ImGui_ImplOpenGL3_RenderDrawData(d);
        return PanelDrawn::Whole;
    }
    if (!cache.image || cache.width != fw || cache.height != fh) {
        cache.image = std::make_unique<render::ColourTarget>(fw, fh);
        cache.width = fw, cache.height = fh, cache.hash = 0;
    }
    const std::uint64_t h = hash ? hash : drawDataHash(d);
    if (kept && h == cache.hash && h != 0) {
        ++app.panelCopies;
        return PanelDrawn::Kept;
    }
    if (h != cache.hash || h == 0) {
        glBindFramebuffer(GL_FRAMEBUFFER, cache.image->fbo);
        const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
        glClearColor(bg.x, bg.y, bg.z, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(d);
        cache.hash = h;
        ++app.panelDraws;
    } else {
        ++app.panelCopies;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, cache.image->fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, app.panelWidth, fh, 0, 0, app.panelWidth, fh, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return PanelDrawn::Strip;
}

// How a frame goes to the screen. Software GL under X (Mesa's drisw, GLX_MESA_copy_sub_buffer):
// the window's back buffer is copied to the X server by glXCopySubBufferMESA instead of
// swapped, so it keeps what it holds; a frame whose panel is as it was copies neither the
// panel's strip into it nor that strip to the server, only the view. Elsewhere (a GPU, whose
// swap is synchronised to the display, or no such extension) a swap.
struct Presenter {
    using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width, int height);
    using QueryExtensions = const char* (*)(void* display, int screen);
    CopySubBuffer copy = nullptr;
    void* display = nullptr;
    unsigned long drawable = 0;
    bool kept = false;  // the back buffer's panel strip is the cached panel

    void init(GLFWwindow* window, bool software) {
        if (!software || std::getenv("SPROUT_SWAP")) return;
        display = glfwGetX11Display();
        drawable = glfwGetGLXWindow(window);
        auto query = reinterpret_cast<QueryExtensions>(glfwGetProcAddress("glXQueryExtensionsString"));
        const char* extensions = display && drawable && query ? query(display, 0) : nullptr;
        if (extensions && std::strstr(extensions, "GLX_MESA_copy_sub_buffer"))
            copy = reinterpret_cast<CopySubBuffer>(glfwGetProcAddress("glXCopySubBufferMESA"));
    }
    // `panel`: what drawPanel did; the view is the rest of the window right of the panel.
    void present(GLFWwindow* window, PanelDrawn panel, int panelWidth, int fw, int fh) {
        if (!copy) {
            glfwSwapBuffers(window);
            return;
        }
        if (panel == PanelDrawn::Kept) copy(display, drawable, panelWidth, 0, fw - panelWidth, fh);
        else copy(display, drawable, 0, 0, fw, fh);
        kept = panel != PanelDrawn::Whole;
    }
};

// Files dropped on the window (.lsys, Lparser .ls, Fractint .l), opened on the next frame.
std::vector<std::string> g_dropped;
void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

// The window was uncovered (an X Expose, no compositor): its next frame is sent whole.
bool g_exposed = false;
void onRefresh(GLFWwindow*) { g_exposed = true; }

}  // namespace

}  // namespace sprout::viewer

namespace sprout::cli {

using namespace sprout::viewer;

int runViewer(int argc, char** argv) {
    Args args(argc, argv, 1, {}, {"--screenshot", "--window-screenshot", "--script", "--size"});
    if (!args.error().empty() || args.positionals().size() > 1) {
        std::cerr << "sprout: " << (args.error().empty() ? "expects at most one FILE or PRESET" : args.error())
                  << "\nusage: sprout [FILE|PRESET] [--size WxH] [--screenshot OUT.png] [--script FILE]\n";
        return 2;
    }
    const std::string source = args.positionals().empty() ? std::string(kDefaultPreset) : args.positionals()[0];
    int width = 1440, height = 860;
    if (auto s = args.value("--size"); s && !cli::parseSize(*s, width, height)) {
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

    if (!glfwInit()) {
        std::cerr << "sprout: cannot open a window (no display?); try: sprout render " << source << " -o plant.png\n";
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(width, height, "Sprout", nullptr, nullptr);
    if (!window) {
        std::cerr << "sprout: cannot create an OpenGL 3.3 window; try: sprout render " << source << " -o plant.png\n";
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);

    App app(std::filesystem::read_symlink("/proc/self/exe").string());
    app.window = window;
    app.measureMoving = !script.empty();
    std::string error;
    if (!app.renderer.init(glfwProc, error)) {
        std::cerr << "sprout: " << error << "\n";
        return 1;
    }
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

    app.state.worker().prepare = [](const std::shared_ptr<const Geometry>& owner) -> std::shared_ptr<const void> {
        const Geometry& g = *owner;
        auto p = std::make_shared<render::PreparedScene>();
        render::Renderer::prepareForViewer(g, *p, owner);
        return p;
    };
    // Forest scenes find their species among the presets and beside the scene's file.
    app.state.worker().speciesSource = [&app](const std::string& name) -> std::optional<std::string> {
        for (const auto& base : {app.state.path(), app.state.importedFrom()}) {
            if (base.empty()) continue;
            std::ifstream in(base.parent_path() / name, std::ios::binary);
            if (in) return std::string(std::istreambuf_iterator<char>(in), {});
        }
        if (auto t = presetText(name)) return std::string(*t);
        return std::nullopt;
    };
    // Open the file or preset.
    if (std::filesystem::exists(source)) {
        if (!app.state.open(source, error)) {
            std::cerr << "sprout: " << error << "\n";
            return 1;
        }
    } else if (auto text = presetText(source)) {
        app.state.openText(std::string(*text), {}, source);
    } else {
        std::cerr << source << ": no such file or preset\n";
        return 1;
    }
    if (!screenshot) warmUp(app, window);
    // A previous session ended without saving: offer its text back.
    bool offerRecovery = app.state.recoverable().has_value() && !screenshot && script.empty();

    viewer::detail::Mouse mouse;
    double last = glfwGetTime(), lastDiskCheck = last;
    bool screenshotDone = false;
    PanelCache panelCache;
    Presenter presenter;
    presenter.init(window, app.renderer.software());
    int framesWithPlant = 0;
    std::string windowTitle;
    while (!glfwWindowShouldClose(window) || (app.state.dirty() && !app.quitConfirmed && script.empty() && !screenshot)) {
        if (glfwWindowShouldClose(window)) {  // unsaved edits: ask first
            glfwSetWindowShouldClose(window, GLFW_FALSE);
            app.quitPopup = true;
        }
        // The window's title names what is being edited, as the panel does.
        if (std::string title = "Sprout - " + app.state.title() + (app.state.dirty() ? " *" : ""); title != windowTitle) {
            glfwSetWindowTitle(window, title.c_str());
            windowTitle = std::move(title);
        }
        const bool animating = app.state.playing() || app.view.turntable || app.state.worker().busy() || !script.empty() || screenshot ||
                               app.refining || app.environmentJob.valid();
        if (animating || app.needsRedraw) glfwPollEvents();
        else glfwWaitEventsTimeout(0.25);  // idle: no frames, no CPU
        const double now = glfwGetTime(), dt = now - last;
        last = now;
        auto frameStart = std::chrono::steady_clock::now();
        bool refinedPiece = false;  // a piece of the still view drawn in this frame
        bool moved = false;         // the moving view drawn in this frame
        bool viewUpdated = false;   // the view's picture changed in this frame
        bool previewed = false;     // a new scene's moving-quality picture drawn in this frame
        std::uint64_t uiHash = 0;   // drawDataHash of this frame's panel, when made
        bool present = true;        // the frame is shown (see below)
        double measuringMs = 0;     // spent measuring for a script (not the frame's own time)

        auto previous = app.state.plant();
        bool uploadedNow = false;  // a new plant went to the GPU (or began to) in this frame
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
            uploadedNow = true;
            if (app.frameOnNextPlant) {
                app.frame();
                app.frameOnNextPlant = false;
            }
            app.needsRedraw = true;
        }
        // A click that waited for the derivation's origins; the highlight follows the plant.
        if (app.pendingPick && app.state.plant() && app.state.plant()->pick) app.pickAt(app.pendingPick->first, app.pendingPick->second);
        if ((app.highlightDirty || app.highlightOf != app.state.plant()) && !app.renderer.uploading()) app.updateHighlight();
        // The environment changes with the plant on screen: after a staged upload is whole.
        if (app.environmentDirty || app.environmentOf != app.state.plant()) app.updateEnvironment();
        app.showEnvironment();
        // The plant on screen is drawn until the new one is whole (its picture is kept meanwhile).
        if (app.renderer.uploading()) {
            uploadedNow = true;
            if (app.renderer.continueUpload(kUploadBytesPerFrame)) app.needsRedraw = app.sceneArrived = true;
        }
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
            app.thumbnails.poll(all, !app.interacting && !app.refining && !app.state.playing() && !app.view.turntable);
        }
        if (!g_dropped.empty()) {
            std::string path = g_dropped.front();
            g_dropped.clear();
            app.openFile(path);
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
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
        if (showImage) {  // the density image, fitted to the view
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
        // The recovery question last in the frame: a modal opened before the panel's windows
        // first appear fails ImGui's check for the modal that blocks them (it aborted the
        // viewer on the first start after a crash).
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
        drawLabels(app, fw, fh);
        ImGui::Render();
        if (app.state.plant() && app.state.plant()->geometry && fw > 0 && fh > 0) {
            render::RenderOptions o = app.view.render;  // still quality; drawMoving picks the moving frames'
            o.quality = render::Quality::Still;
            o.quickLines = app.renderer.software();
            const bool interactive = app.interacting || app.state.playing() || app.view.turntable;
            if (!app.viewFbo) {
                glGenFramebuffers(1, &app.viewFbo);
                glGenTextures(1, &app.viewColour);
            }
            if (vw != app.viewWidth || vh != app.viewHeight) {
                makeViewPicture(app.viewColour, vw, vh);
                glBindFramebuffer(GL_FRAMEBUFFER, app.viewFbo);
                glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, app.viewColour, 0);
                app.viewWidth = vw, app.viewHeight = vh;
                app.needsRedraw = true;
            }
            // Letting go of a drag refines the picture to full size and quality.
            if (interactive != app.viewInteractive) app.viewInteractive = interactive, app.needsRedraw = true;
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
                viewUpdated = true;
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
            app.sceneArrived = false;
            if (app.needsRedraw) app.drawnCamera = cameraKey;
            if (app.needsRedraw && interactive) {
                drawMoving();
                moved = true;
                app.viewMoving = true;
            } else if (app.needsRedraw) {  // still: the full picture, a piece per frame
                if (app.measureMoving && app.viewMoving) {
                    const auto t0 = std::chrono::steady_clock::now();
                    app.movingPicture = shownView(app, vw, vh);
                    measuringMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
                }
                if (preview) drawMoving(), moved = cameraMoved && !arrived, previewed = true;  // moving: the wheel or keys
                app.renderer.beginDraw(app.camera, vw, vh, o, app.viewFbo, 0, 0);
                app.refining = true;
                app.refineStart = glfwGetTime();
                app.refineWorstMs = 0;
                app.refineFrames = 0;
            }
            app.needsRedraw = false;
            if (app.refining) {
                refinedPiece = true;
                // A frame that drew the moving picture first has that much less for its piece.
                const bool whole = app.renderer.continueDrawFor(previewed ? std::max(1.0, kRefineMs - app.drawMs) : kRefineMs);
                if (whole) {
                    app.refining = false;

                    app.lastStillMs = app.renderer.lastPictureMs();
                    app.drawWidth = vw, app.drawHeight = vh;
                    app.drawMs = (glfwGetTime() - app.refineStart) * 1000;
                    if (!app.movingPicture.empty()) {
                        const auto t0 = std::chrono::steady_clock::now();
                        app.movingDifferPct = differingPct(app.movingPicture, app.renderer.readPixels(vw, vh, app.viewFbo));
                        app.movingPicture.clear();
                        measuringMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
                    }
                    ++app.viewDraws;
                    viewUpdated = true;
                    app.viewMoving = false;
                }
            }
            // A frame in which nothing on screen changes is not shown: while the still view is
            // drawn in pieces the window shows its last picture, so unless the panel changed
            // (hover, typing, the caret), its pieces follow each other without the copy of
            // the view and the panel's drawing (~7 ms a frame on software GL).
            const bool refiningOn = app.refining && !viewUpdated;  // only then can a frame be left out
            const std::uint64_t ui = uiHash = refiningOn ? drawDataHash(ImGui::GetDrawData()) : 0;
            present = !refiningOn || ui != app.presentedUi || fw != app.presentedWidth || fh != app.presentedHeight;
            if (present) {
                app.presentedUi = ui;  // 0 after a frame that was not hashed: the next one is shown
                app.presentedWidth = fw, app.presentedHeight = fh;
                // The panel covers the left part; the view goes beside it (stretched when drawn small).
                showView(app, 0, app.panelWidth, vw, vh);
            }
            ++framesWithPlant;
        } else {
            // No 3D view now (an IFS image, drawn by the panel's pass; a minimised window): a
            // picture in pieces is left, and the view is drawn anew when it is back (its size
            // is forgotten). Nothing to redraw meanwhile: an IFS on screen costs no frames.
            app.refining = false;
            app.viewWidth = app.viewHeight = 0;
            app.needsRedraw = false;
            app.presentedWidth = 0;
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fw, fh);
            glClearColor(0.957f, 0.949f, 0.918f, 1);  // the density image's background
            glClear(GL_COLOR_BUFFER_BIT);
            presenter.kept = false;  // the panel's strip too
            if (app.state.plant()) ++framesWithPlant;
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        if (std::exchange(g_exposed, false)) presenter.kept = false;  // its next shown frame sends it whole
        PanelDrawn panelDrawn = PanelDrawn::Whole;
        if (present) panelDrawn = drawPanel(app, panelCache, fw, fh, uiHash, presenter.kept);

        // A text that makes no plant (errors, an L-Py model not trusted) is on screen as it
        // is: screenshots and scripts go on once its result is in.
        if (!app.state.plant() && app.state.latest() && !app.state.worker().busy()) ++framesWithPlant;
        if (screenshot && !screenshotDone && framesWithPlant >= 2 && !app.state.worker().busy() && script.empty() && app.viewSettled()) {
            // The whole window as the user sees it: panel and plant.
            glFinish();
            Image img;
            img.width = fw;
            img.height = fh;
            img.rgba = app.renderer.readPixels(fw, fh, 0);
            std::string e;
            if (!writePng(*screenshot, img, e)) std::cerr << *screenshot << ": " << e << "\n";
            screenshotDone = true;
            app.quitConfirmed = true;
            glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
        if (present) presenter.present(window, panelDrawn, app.panelWidth, fw, fh);
        else glFlush();  // the piece goes on drawing meanwhile
        if (!script.empty() && framesWithPlant > 0 && !script.step(app)) {
            app.quitConfirmed = true;
            glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
        app.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count() - measuringMs;
        app.worstFrameMs = std::max(app.worstFrameMs * 0.995, app.frameMs);
        if (refinedPiece) app.refineWorstMs = std::max(app.refineWorstMs, app.frameMs), ++app.refineFrames;
        if (moved || previewed) {
            // The moving view's share of the pixels follows its frames' time (which goes with
            // the pixels drawn): fewer while a frame takes longer than kMovingFrameMs, back
            // towards half each way when quick.
            const float k = float(std::sqrt(kMovingFrameMs / std::max(app.frameMs, 1.0)));
            app.movingScale = std::clamp(app.movingScale * std::clamp(k, 0.6f, 1.1f), 0.25f, 0.5f);
        }
        if (moved) {
            if (app.frameMs > app.movingWorstMs) {
                char what[160];
                const render::RenderStats& drawn = app.renderer.stats();
                std::snprintf(what, sizeof what, "frame_%llu_step_%d_tris_%zu_view_%dx%d_in_%.1fms%s%s%s",
                              static_cast<unsigned long long>(app.movingFrames + 1),
                              app.state.plant() ? app.state.plant()->displayStep : -1, drawn.triangles, app.drawWidth,
                              app.drawHeight, app.drawMs, drawn.shadowPass ? "_shadow_pass" : "", drawn.proxy ? "_sketch" : "",
                              uploadedNow ? "_new_plant" : "");
                app.movingWorstWhat = what;
            }
            app.movingWorstMs = std::max(app.movingWorstMs, app.frameMs);
            app.movingTotalMs += app.frameMs;
            ++app.movingFrames;
        }
    }
    app.state.autosave(true);
    app.state.markCleanExit();
    panelCache.image.reset();  // while the context is current
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

}  // namespace sprout::cli
