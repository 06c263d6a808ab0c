#include "app/headless.hpp"

#include <dlfcn.h>

#include <mutex>

#include <GL/osmesa.h>

namespace sprout {
namespace {

// OSMesa is loaded when the first picture is rendered, not at start: it pulls in LLVM, whose
// start-up costs about 30 ms (measured: a program that only links libOSMesa takes 30 ms to
// do nothing), which every `sprout expand` and the viewer's start would otherwise pay.
struct OSMesa {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
    std::string error;
};

const OSMesa& osmesa() {
    // Never destroyed: a context prepared for a picture (app/snapshot.cpp) is let go at exit,
    // after the function-local statics made before it.
    static OSMesa& api = *new OSMesa;
    static std::once_flag once;
    std::call_once(once, [] {
        void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        if (!lib) {
            api.error = std::string("cannot load OSMesa (is libosmesa6 installed?): ") + dlerror();
            return;
        }
        api.createContextAttribs = reinterpret_cast<decltype(api.createContextAttribs)>(dlsym(lib, "OSMesaCreateContextAttribs"));
        api.makeCurrent = reinterpret_cast<decltype(api.makeCurrent)>(dlsym(lib, "OSMesaMakeCurrent"));
        api.destroyContext = reinterpret_cast<decltype(api.destroyContext)>(dlsym(lib, "OSMesaDestroyContext"));
        api.getProcAddress = reinterpret_cast<decltype(api.getProcAddress)>(dlsym(lib, "OSMesaGetProcAddress"));
        if (!api.createContextAttribs || !api.makeCurrent || !api.destroyContext || !api.getProcAddress)
            api.error = "the OSMesa library lacks OSMesaCreateContextAttribs (OpenGL 3.3 core needs Mesa 11 or later)";
    });
    return api;
}

render::ProcAddress getProc(const char* name) { return reinterpret_cast<render::ProcAddress>(osmesa().getProcAddress(name)); }

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(int width, int height, std::string& error) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384) {
        error = "image size must be between 1x1 and 16384x16384";
        return nullptr;
    }
    const OSMesa& api = osmesa();
    if (!api.error.empty()) {
        error = api.error;
        return nullptr;
    }
    const int attribs[] = {OSMESA_FORMAT,           OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE,          OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = api.createContextAttribs(attribs, nullptr);
    if (!ctx) {
        error = "could not create an OSMesa OpenGL 3.3 core context (is libosmesa6 installed?)";
        return nullptr;
    }
    std::unique_ptr<HeadlessContext> h(new HeadlessContext());
    h->m_context = ctx;
    h->m_width = width;
    h->m_height = height;
    h->m_buffer.resize(std::size_t(width) * std::size_t(height) * 4);
    if (!h->makeCurrent()) {
        error = "could not make the OSMesa context current";
        return nullptr;
    }
    return h;
}

bool HeadlessContext::makeCurrent() {
    return osmesa().makeCurrent(static_cast<OSMesaContext>(m_context), m_buffer.data(), GL_UNSIGNED_BYTE, m_width, m_height);
}

void HeadlessContext::release() { osmesa().makeCurrent(nullptr, nullptr, 0, 0, 0); }

HeadlessContext::~HeadlessContext() {
    if (m_context) osmesa().destroyContext(static_cast<OSMesaContext>(m_context));
}

render::ProcLoader HeadlessContext::loader() const { return getProc; }

}  // namespace sprout
