// How the window's frame reaches the screen (window_present.hpp): the panel drawn whole or
// copied from its cache, and the back buffer copied to the X server or swapped.
#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "app/viewer/window/app.hpp"
#include "app/viewer/window/window_present.hpp"

// GLFW's X11 display and GLX window (glfw3native.h would bring X11's and GL's headers in over
// glad's): Display* and GLXWindow, an XID.
extern "C" void* glfwGetX11Display(void);
extern "C" unsigned long glfwGetGLXWindow(GLFWwindow* window);

namespace sprout::viewer::detail {

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

std::vector<std::uint64_t> panelTiles(const ImDrawData* d, float width, float height, int& columns) {
    columns = std::max(1, int(std::ceil(width / kPanelTile)));
    const int rows = std::max(1, int(std::ceil(height / kPanelTile)));
    std::vector<std::uint64_t> tiles(size_t(columns) * size_t(rows), 0x9E3779B97F4A7C15ull);
    auto mix = [](std::uint64_t& h, std::uint64_t w) {
        h = (h ^ w) * 0x100000001B3ull;
        h ^= h >> 29;
    };
    const ImVec2 o = d->DisplayPos;
    for (int k = 0; k < d->CmdListsCount; ++k) {
        const ImDrawList* l = d->CmdLists[k];
        for (const ImDrawCmd& c : l->CmdBuffer) {
            if (c.UserCallback) continue;
            std::uint64_t texture = 0;
            std::memcpy(&texture, &c.TextureId, std::min(sizeof texture, sizeof c.TextureId));
            for (unsigned e = 0; e + 2 < c.ElemCount; e += 3) {
                float lo[2] = {c.ClipRect.z, c.ClipRect.w}, hi[2] = {c.ClipRect.x, c.ClipRect.y};
                std::uint64_t h = texture;
                bool valid = true;
                for (unsigned v = 0; v < 3; ++v) {
                    const unsigned idx = c.IdxOffset + e + v;
                    const unsigned vtx = idx < unsigned(l->IdxBuffer.Size) ? c.VtxOffset + l->IdxBuffer[int(idx)] : ~0u;
                    if (vtx >= unsigned(l->VtxBuffer.Size)) {
                        valid = false;
                        break;
                    }
                    const ImDrawVert& p = l->VtxBuffer[int(vtx)];
                    lo[0] = std::min(lo[0], p.pos.x), lo[1] = std::min(lo[1], p.pos.y);
                    hi[0] = std::max(hi[0], p.pos.x), hi[1] = std::max(hi[1], p.pos.y);
                    std::uint64_t w[3] = {0, 0, 0};
                    std::memcpy(w, &p, std::min(sizeof w, sizeof p));
                    mix(h, w[0]), mix(h, w[1]), mix(h, w[2]);
                }
                if (!valid) break;
                // Within the clip rectangle and the strip, in tiles.
                const float x0 = std::max(lo[0], c.ClipRect.x) - o.x, y0 = std::max(lo[1], c.ClipRect.y) - o.y;
                const float x1 = std::min(std::min(hi[0], c.ClipRect.z) - o.x, width), y1 = std::min(std::min(hi[1], c.ClipRect.w) - o.y, height);
                if (!(x1 >= x0 && y1 >= y0) || x1 < 0 || y1 < 0 || x0 >= width || y0 >= height) continue;
                const int c0 = std::max(0, int(x0 / kPanelTile)), c1 = std::min(columns - 1, int(x1 / kPanelTile));
                const int r0 = std::max(0, int(y0 / kPanelTile)), r1 = std::min(rows - 1, int(y1 / kPanelTile));
                std::uint64_t clip[2];
                std::memcpy(clip, &c.ClipRect, sizeof clip);
                mix(h, clip[0]), mix(h, clip[1]);
                for (int r = r0; r <= r1; ++r)
                    for (int col = c0; col <= c1; ++col) mix(tiles[size_t(r) * size_t(columns) + size_t(col)], h);
            }
        }
    }
    return tiles;
}

std::vector<PanelRect> panelBands(const std::vector<std::uint64_t>& before, const std::vector<std::uint64_t>& now, int columns,
                                  size_t most) {
    std::vector<PanelRect> bands;
    const size_t rows = columns > 0 ? now.size() / size_t(columns) : 0;
    for (size_t r = 0; r < rows; ++r) {
        int c0 = columns, c1 = -1;
        for (int c = 0; c < columns; ++c)
            if (before[r * size_t(columns) + size_t(c)] != now[r * size_t(columns) + size_t(c)]) c0 = std::min(c0, c), c1 = c;
        if (c1 < 0) continue;
        const PanelRect row{float(c0) * kPanelTile, float(r) * kPanelTile, float(c1 + 1) * kPanelTile, float(r + 1) * kPanelTile};
        if (!bands.empty() && bands.back().y1 == row.y0)
            bands.back() = {std::min(bands.back().x0, row.x0), bands.back().y0, std::max(bands.back().x1, row.x1), row.y1};
        else bands.push_back(row);
    }
    while (bands.size() > most) {  // the two nearest bands as one
        size_t best = 0;
        for (size_t i = 1; i + 1 < bands.size(); ++i)
            if (bands[i + 1].y0 - bands[i].y1 < bands[best + 1].y0 - bands[best].y1) best = i;
        PanelRect& a = bands[best];
        const PanelRect& b = bands[best + 1];
        a = {std::min(a.x0, b.x0), a.y0, std::max(a.x1, b.x1), b.y1};
        bands.erase(bands.begin() + std::ptrdiff_t(best) + 1);
    }
    return bands;
}

namespace {
// ImGui's draw data drawn into the bound framebuffer in `bands` only: each band cleared to the
// panel's colour, then ImGui's commands drawn with their clip rectangles cut to it.
void drawPanelIn(ImDrawData* d, const std::vector<PanelRect>& bands) {
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    const ImVec2 o = d->DisplayPos, scale = d->FramebufferScale;
    const int fbHeight = int(d->DisplaySize.y * scale.y);
    std::vector<ImVec4> clips;
    for (int k = 0; k < d->CmdListsCount; ++k)
        for (const ImDrawCmd& c : d->CmdLists[k]->CmdBuffer) clips.push_back(c.ClipRect);
    glClearColor(bg.x, bg.y, bg.z, 1);
    for (const PanelRect& b : bands) {
        glEnable(GL_SCISSOR_TEST);
        const int x0 = int(b.x0 * scale.x), y0 = int(b.y0 * scale.y);
        const int x1 = int(std::ceil(b.x1 * scale.x)), y1 = int(std::ceil(b.y1 * scale.y));
        glScissor(x0, fbHeight - y1, x1 - x0, y1 - y0);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        size_t i = 0;
        for (int k = 0; k < d->CmdListsCount; ++k)
            for (ImDrawCmd& c : d->CmdLists[k]->CmdBuffer) {
                const ImVec4 was = clips[i++];
                c.ClipRect = ImVec4(std::max(was.x, b.x0 + o.x), std::max(was.y, b.y0 + o.y), std::min(was.z, b.x1 + o.x),
                                    std::min(was.w, b.y1 + o.y));
            }
        ImGui_ImplOpenGL3_RenderDrawData(d);
    }
    size_t i = 0;
    for (int k = 0; k < d->CmdListsCount; ++k)
        for (ImDrawCmd& c : d->CmdLists[k]->CmdBuffer) c.ClipRect = clips[i++];
}
}  // namespace

// Each command's clip rectangle, or where its triangles are when it is clipped to more (a
// window's background is clipped to the whole display; its text may run past its edge,
// clipped to the window).
bool drawnInStrip(const App& app, int fw) {
    const ImDrawData* d = ImGui::GetDrawData();
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
    return inStrip;
}

PanelDrawn drawPanelCached(App& app, PanelCache& cache, int fw, int fh, std::uint64_t hash, bool kept, bool inStrip) {
    ImDrawData* d = ImGui::GetDrawData();
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
    const ImVec2 scale = d->FramebufferScale;
    const float stripW = float(app.panelWidth) / scale.x, stripH = float(fh) / scale.y;
    std::vector<PanelRect> bands{{0, 0, stripW, stripH}};  // what is drawn again: all, or where it changed
    if (h != cache.hash || h == 0) {
        int columns = 0;
        std::vector<std::uint64_t> tiles = panelTiles(d, stripW, stripH, columns);
        if (columns == cache.columns && tiles.size() == cache.tiles.size() && cache.hash != 0) bands = panelBands(cache.tiles, tiles, columns);
        glBindFramebuffer(GL_FRAMEBUFFER, cache.image->fbo);
        drawPanelIn(d, bands);
        cache.hash = h;
        cache.tiles = std::move(tiles);
        cache.columns = columns;
        ++app.panelDraws;
    } else {
        ++app.panelCopies;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, cache.image->fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    if (!kept) bands = {{0, 0, stripW, stripH}};  // the back buffer's strip is not the image's: all of it
    for (const PanelRect& b : bands) {
        const int x0 = int(b.x0 * scale.x), x1 = int(std::ceil(b.x1 * scale.x));
        const int y0 = fh - int(std::ceil(b.y1 * scale.y)), y1 = fh - int(b.y0 * scale.y);
        glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return PanelDrawn::Strip;
}

void Presenter::init(GLFWwindow* window, bool software) {
    if (!software || std::getenv("SPROUT_SWAP")) return;
    display = glfwGetX11Display();
    drawable = glfwGetGLXWindow(window);
    auto query = reinterpret_cast<QueryExtensions>(glfwGetProcAddress("glXQueryExtensionsString"));
    const char* extensions = display && drawable && query ? query(display, 0) : nullptr;
    if (extensions && std::strstr(extensions, "GLX_MESA_copy_sub_buffer"))
        copy = reinterpret_cast<CopySubBuffer>(glfwGetProcAddress("glXCopySubBufferMESA"));
}

void Presenter::present(GLFWwindow* window, PanelDrawn panel, int panelWidth, int fw, int fh, bool viewShown) {
    if (!copy) {
        glfwSwapBuffers(window);
        return;
    }
    if (panel == PanelDrawn::Kept) {
        if (viewShown) copy(display, drawable, panelWidth, 0, fw - panelWidth, fh);
    } else {
        copy(display, drawable, 0, 0, viewShown ? fw : panelWidth, fh);
    }
    kept = panel != PanelDrawn::Whole;  // ImGui drawn over the whole window: over the view too
    width = fw, height = fh, this->panelWidth = panelWidth;
}

}  // namespace sprout::viewer::detail
