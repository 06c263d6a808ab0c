#pragma once
// An offscreen RGBA8 image to draw or copy into, bound as the framebuffer when made and
// deleted (the default framebuffer bound again) when it goes. Needs a current GL context.
#include "app/render/gl.hpp"

namespace sprout::render {

struct ColourTarget {
    GLuint fbo = 0, colour = 0;
    ColourTarget(int width, int height) {
        glGenFramebuffers(1, &fbo);
        glGenRenderbuffers(1, &colour);
        glBindRenderbuffer(GL_RENDERBUFFER, colour);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    }
    ~ColourTarget() {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteRenderbuffers(1, &colour);
        glDeleteFramebuffers(1, &fbo);
    }
    ColourTarget(const ColourTarget&) = delete;
    ColourTarget& operator=(const ColourTarget&) = delete;
};

}  // namespace sprout::render
