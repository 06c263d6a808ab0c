// The materials' own drawing (issue 53): the lit programs' light for plain and shining
// surfaces, and the translucent triangles drawn farthest first from their own index buffer.
// Apart from renderer_draw.cpp's passes, which call them for their ranges of triangles.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>
#include <glm/geometric.hpp>

#include "app/render/gl.hpp"
#include "app/render/renderer.hpp"
#include "app/render/renderer_impl.hpp"

namespace sprout::render {

namespace {
glm::vec3 rgbOf(std::uint32_t c) { return glm::vec3(float(c >> 24 & 0xFF), float(c >> 16 & 0xFF), float(c >> 8 & 0xFF)) / 255.0f; }
}  // namespace

// Every surface's light: a little grey highlight, (n.h)^32.
void Renderer::Impl::plainLight(GLuint p) {
    setUniform(p, "uSpecular", glm::vec3(0.1f));
    setUniform(p, "uShininess", 32.0f);
    setUniform(p, "uEmission", glm::vec3(0.0f));
}

// A material's: its specular colour at 128 x its shininess (at least 1), as PlantGL gives
// OpenGL, and its emission.
void Renderer::Impl::shineLight(GLuint p, const Shine& s) {
    setUniform(p, "uSpecular", rgbOf(s.specular));
    setUniform(p, "uShininess", std::max(1.0f, 128.0f * s.shininess));
    setUniform(p, "uEmission", rgbOf(s.emission));
}

void Renderer::Impl::adoptTranslucent(const mesh::BakedMesh& b, std::size_t count) {
    translucentTris = std::min(count, b.indices.size() / 3);
    translucentIndices.assign(b.indices.end() - std::ptrdiff_t(3 * translucentTris), b.indices.end());
    translucentCentres.resize(translucentTris);
    for (std::size_t t = 0; t < translucentTris; ++t) {
        glm::vec3 c(0.0f);
        for (int k = 0; k < 3; ++k) c += b.vertices[translucentIndices[3 * t + std::size_t(k)]].position;
        translucentCentres[t] = c / 3.0f;
    }
    glBindVertexArray(translucentVao);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, translucentEbo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(translucentIndices.size() * 4), translucentIndices.data(), GL_DYNAMIC_DRAW);
    glBindVertexArray(0);
}

void Renderer::Impl::drawTranslucent(const glm::mat4& viewProj, GLuint p, std::size_t from, std::size_t to) {
    const bool depth = p == bakedDepth;
    glBindVertexArray(translucentVao);
    if (from == 0 && !depth) {  // a picture begins them: farthest first from this eye
        std::vector<std::uint32_t> order(translucentTris);
        for (std::uint32_t t = 0; t < order.size(); ++t) order[t] = t;
        std::vector<float> distance(translucentTris);
        for (std::size_t t = 0; t < translucentTris; ++t) distance[t] = glm::length(translucentCentres[t] - eye);
        std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return distance[a] > distance[b]; });
        std::vector<std::uint32_t> sorted(3 * translucentTris);
        for (std::size_t t = 0; t < order.size(); ++t)
            for (std::size_t k = 0; k < 3; ++k) sorted[3 * t + k] = translucentIndices[3 * std::size_t(order[t]) + k];
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, translucentEbo);
        glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, GLsizeiptr(sorted.size() * 4), sorted.data());
    }
    bakedAttributes(baked.vbo);  // the scene's vertices (its buffers swap with a staged upload)
    const GLuint program = depth ? bakedDepthAlpha : p;
    glUseProgram(program);
    setUniform(program, "uViewProj", viewProj);
    if (!depth) {
        plainLight(program);
        setUniform(program, "uTranslucent", 1.0f);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    glDrawElements(GL_TRIANGLES, GLsizei(3 * (to - from)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * from * sizeof(std::uint32_t)));
    if (!depth) {
        setUniform(program, "uTranslucent", 0.0f);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    glBindVertexArray(0);
}

}  // namespace sprout::render
