// How the window's frame reaches the screen (window_present.hpp): the panel drawn whole or
// copied from its cache, and the back buffer copied to the X server or swapped.
#include "app/render/gl.hpp"  // glad first: GLFW must not include GL/gl.h
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

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

PanelDrawn drawPanelCached(App& app, PanelCache& cache, int fw, int fh, std::uint64_t hash, bool kept) {
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

void Presenter::init(GLFWwindow* window, bool software) {
    if (!software || std::getenv("SPROUT_SWAP")) return;
    display = glfwGetX11Display();
    drawable = glfwGetGLXWindow(window);
    auto query = reinterpret_cast<QueryExtensions>(glfwGetProcAddress("glXQueryExtensionsString"));
    const char* extensions = display && drawable && query ? query(display, 0) : nullptr;
    if (extensions && std::strstr(extensions, "GLX_MESA_copy_sub_buffer"))
        copy = reinterpret_cast<CopySubBuffer>(glfwGetProcAddress("glXCopySubBufferMESA"));
}

void Presenter::present(GLFWwindow* window, PanelDrawn panel, int panelWidth, int fw, int fh) {
    if (!copy) {
        glfwSwapBuffers(window);
        return;
    }
    if (panel == PanelDrawn::Kept) copy(display, drawable, panelWidth, 0, fw - panelWidth, fh);
    else copy(display, drawable, 0, 0, fw, fh);
    kept = panel != PanelDrawn::Whole;
}

}  // namespace sprout::viewer::detail
