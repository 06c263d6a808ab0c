#pragma once
// Private to app/viewer: how the window's frame reaches the screen, apart from the main loop
// (window.cpp) because it is a mechanism of its own: the panel kept as an image and copied
// while ImGui draws the same, and the frame copied to the X server (software GL) or swapped.
#include <cstdint>
#include <memory>

#include "app/render/colour_target.hpp"
#include "app/viewer/window/app.hpp"

struct GLFWwindow;
struct ImDrawData;

namespace sprout::viewer::detail {

// A hash of what ImGui draws in a frame (vertices, indices, commands): equal hashes, the
// same panel on screen.
std::uint64_t drawDataHash(const ImDrawData* d);

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

// What drawPanelCached put in the window's back buffer: ImGui drawn over the whole window, the
// panel's strip copied from the cache, or nothing (the strip there is this frame's panel).
enum class PanelDrawn { Whole, Strip, Kept };

// The panel (ImGui's draw data of this frame) into the window's back buffer, whole or as its
// strip from the cache.
// `hash`: drawDataHash of this frame's draw data when the frame already made it, else 0.
// `kept`: the back buffer's strip holds the cached panel (the window was not swapped since).
PanelDrawn drawPanelCached(App& app, PanelCache& cache, int fw, int fh, std::uint64_t hash, bool kept = false);

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

    void init(GLFWwindow* window, bool software);
    // `panel`: what drawPanelCached did; the view is the rest of the window right of the panel.
    void present(GLFWwindow* window, PanelDrawn panel, int panelWidth, int fw, int fh);
};

}  // namespace sprout::viewer::detail
