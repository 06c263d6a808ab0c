#pragma once
// The headless context provider: an OSMesa OpenGL 3.3 core context (llvmpipe) with no
// display. The renderer draws into it exactly as into a window.
#include <memory>
#include <string>
#include <vector>

#include "app/render/renderer.hpp"

namespace sprout {

class HeadlessContext {
public:
    // A context for images up to width x height; null with a message on failure.
    static std::unique_ptr<HeadlessContext> create(int width, int height, std::string& error);
    ~HeadlessContext();
    render::ProcLoader loader() const;
    // The context on this thread (create() makes it current on its own); release() leaves
    // this thread without one, so that another thread may take it.
    bool makeCurrent();
    static void release();

private:
    HeadlessContext() = default;
    void* m_context = nullptr;
    int m_width = 0, m_height = 0;
    std::vector<unsigned char> m_buffer;
};

}  // namespace sprout
