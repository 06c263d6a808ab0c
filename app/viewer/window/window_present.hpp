#pragma once
// Private to app/viewer: how the window's frame reaches the screen, apart from the main loop
// (window.cpp) because it is a mechanism of its own: the panel kept as an image and copied
// while ImGui draws the same, and the frame copied to the X server (software GL) or swapped.
#include <cstdint>
#include <memory>
#include <vector>

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
//
// A panel that changed is drawn again only where it changed: the strip is cut into tiles of
// kPanelTile units, each with a hash of the triangles ImGui draws over it (panelTiles), and
// the tiles whose hash differs from the image's are cleared and drawn again, in a few bands
// (panelBands), ImGui's clip rectangles cut to each. Dragging a curve's point changes the
// editor's canvas and a line of status: a third of the strip (the whole strip took 6-10 ms a
// frame on software GL while the worker derived on the other core).
struct PanelCache {
    std::unique_ptr<render::ColourTarget> image;
    int width = 0, height = 0;
    std::uint64_t hash = 0;
    std::vector<std::uint64_t> tiles;  // panelTiles of what the image holds
    int columns = 0;
};

constexpr float kPanelTile = 32;
// A part of the window in ImGui's display units (x0, y0 top left; x1, y1 excluded).
struct PanelRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
// The hash of each tile of the strip `width` x `height` (rows of `columns` tiles, the first
// at the display's top left): every triangle of `d` mixed into the tiles its bounds (within
// its clip rectangle) meet, in the order ImGui draws them.
std::vector<std::uint64_t> panelTiles(const ImDrawData* d, float width, float height, int& columns);
// The tiles that differ between `before` and `now` (the same grid) as at most `most` bands:
// each a run of rows holding a changed tile, as wide as their changed tiles reach; the nearest
// bands merged while there are more.
std::vector<PanelRect> panelBands(const std::vector<std::uint64_t>& before, const std::vector<std::uint64_t>& now, int columns,
                                  size_t most = 4);

// Whether everything ImGui draws this frame lies in the panel's strip (drawPanelCached then
// leaves the view's part of the window alone); made once a frame, after ImGui::Render.
bool drawnInStrip(const App& app, int fw);

// What drawPanelCached put in the window's back buffer: ImGui drawn over the whole window, the
// panel's strip copied from the cache, or nothing (the strip there is this frame's panel).
enum class PanelDrawn { Whole, Strip, Kept };

// The panel (ImGui's draw data of this frame) into the window's back buffer, whole or as its
// strip from the cache.
// `hash`: drawDataHash of this frame's draw data when the frame already made it, else 0.
// `kept`: the back buffer's strip holds the cached panel (the window was not swapped since).
// `inStrip`: drawnInStrip of this frame.
PanelDrawn drawPanelCached(App& app, PanelCache& cache, int fw, int fh, std::uint64_t hash, bool kept, bool inStrip);

// How a frame goes to the screen. Software GL under X (Mesa's drisw, GLX_MESA_copy_sub_buffer):
// the window's back buffer is copied to the X server by glXCopySubBufferMESA instead of
// swapped, so it keeps what it holds; a frame whose panel is as it was copies neither the
// panel's strip into it nor that strip to the server, only the view; a frame whose view is
// as it was (a curve's point dragged between two plants) neither stretches the view's
// picture into it nor copies the view to the server, only the panel's strip. Elsewhere (a
// GPU, whose swap is synchronised to the display, or no such extension) a swap.
struct Presenter {
    using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width, int height);
    using QueryExtensions = const char* (*)(void* display, int screen);
    CopySubBuffer copy = nullptr;
    void* display = nullptr;
    unsigned long drawable = 0;
    // The back buffer holds what the X server was last sent: its panel strip is the cached
    // panel and its view (the window right of the panel) the view's picture as last shown.
    // False after a frame whose ImGui drew over the whole window, or one swapped.
    bool kept = false;
    int width = 0, height = 0, panelWidth = 0;  // the window's and the panel's at the last frame shown

    void init(GLFWwindow* window, bool software);
    // Whether this frame may leave the back buffer's view as it is (when its picture has not
    // changed): `inStrip`, drawnInStrip of this frame.
    bool mayKeepView(bool inStrip, int panel, int fw, int fh) const {
        return copy && kept && inStrip && fw == width && fh == height && panel == panelWidth;
    }
    // `panel`: what drawPanelCached did; the view is the rest of the window right of the panel,
    // `viewShown` when the frame drew it into the back buffer.
    void present(GLFWwindow* window, PanelDrawn panel, int panelWidth, int fw, int fh, bool viewShown = true);
    // The window was exposed or drawn without the view: its next frame is drawn and sent whole.
    void forget() { kept = false; }
};

}  // namespace sprout::viewer::detail
