#include "app/headless.hpp"

#include <GL/osmesa.h>

namespace sprout {
namespace {
render::ProcAddress getProc(const char* name) { return reinterpret_cast<render::ProcAddress>(OSMesaGetProcAddress(name)); }
}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(int width, int height, std::string& error) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384) {
        error = "image size must be between 1x1 and 16384x16384";
        return nullptr;
    }
    const int attribs[] = {OSMESA_FORMAT,           OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE,          OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) {
        error = "could not create an OSMesa OpenGL 3.3 core context (is libosmesa6 installed?)";
        return nullptr;
    }
    std::unique_ptr<HeadlessContext> h(new HeadlessContext());
    h->m_context = ctx;
    h->m_buffer.resize(std::size_t(width) * std::size_t(height) * 4);
    if (!OSMesaMakeCurrent(ctx, h->m_buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
        error = "could not make the OSMesa context current";
        return nullptr;
    }
    return h;
}

HeadlessContext::~HeadlessContext() {
    if (m_context) OSMesaDestroyContext(static_cast<OSMesaContext>(m_context));
}

render::ProcLoader HeadlessContext::loader() const { return getProc; }

}  // namespace sprout
