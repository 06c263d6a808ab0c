// The materials' own drawing (issue 53): the lit programs' light for plain and shining
// surfaces, the translucent triangles drawn farthest first from their own index buffer, and
// the textured ones with their images.
// Apart from renderer_draw.cpp's passes, which call them for their ranges of triangles.
#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdint>
#include <string>
#include <utility>
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
    translucentImages.assign(translucentTris, 0);
    translucentTextured = false;
    for (std::size_t t = 0; t < translucentTris; ++t) {
        glm::vec3 c(0.0f);
        for (int k = 0; k < 3; ++k) c += b.vertices[translucentIndices[3 * t + std::size_t(k)]].position;
        translucentCentres[t] = c / 3.0f;
        const std::uint32_t first = translucentIndices[3 * t];
        if (first < b.texcoords.size() && b.texcoords[first].texture) translucentImages[t] = b.texcoords[first].texture, translucentTextured = true;
    }
    sortedImages = translucentImages;  // the index buffer's order until a picture sorts them
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
        if (translucentTextured)  // else all 0 as they are
            for (std::size_t t = 0; t < order.size(); ++t) sortedImages[t] = translucentImages[order[t]];
    }
    if (!depth) return drawTranslucentRuns(viewProj, p, from, to);
    bakedAttributes(baked.vbo);  // the scene's vertices (its buffers swap with a staged upload)
    glUseProgram(bakedDepthAlpha);
    setUniform(bakedDepthAlpha, "uViewProj", viewProj);
    glDrawElements(GL_TRIANGLES, GLsizei(3 * (to - from)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * from * sizeof(std::uint32_t)));
    glBindVertexArray(0);
}

// The sorted translucent triangles [from, to) in runs of one image (one run when none has
// an image): the plain ones by `program`, the textured ones by the textured program with
// their image; blended by their alpha (times the image's), without writing depth.
void Renderer::Impl::drawTranslucentRuns(const glm::mat4& viewProj, GLuint program, std::size_t from, std::size_t to) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glActiveTexture(GL_TEXTURE0 + detail::kImageUnit);
    for (std::size_t a = from; a < to && a < sortedImages.size();) {
        std::size_t b = a + 1;
        while (b < to && sortedImages[b] == sortedImages[a]) ++b;
        const std::uint32_t image = sortedImages[a];
        const GLuint prog = image ? texturedProgram : program;
        glUseProgram(prog);
        setUniform(prog, "uViewProj", viewProj);
        plainLight(prog);
        setUniform(prog, "uTranslucent", 1.0f);
        if (image) {
            texturedAttributes();
            glBindTexture(GL_TEXTURE_2D, image <= imageTextures.size() && imageTextures[image - 1] ? imageTextures[image - 1] : whiteTexture);
        } else {
            glBindVertexArray(translucentVao);
            bakedAttributes(baked.vbo);
        }
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, translucentEbo);
        glDrawElements(GL_TRIANGLES, GLsizei(3 * (b - a)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * a * sizeof(std::uint32_t)));
        setUniform(prog, "uTranslucent", 0.0f);
        a = b;
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
}

void Renderer::Impl::adoptTextured(const PreparedScene& p) {
    textured.clear();
    imageTextures.clear();
    texturedTris = 0;
    if (p.textured.empty() && !translucentTextured) return;
    for (const std::string& path : p.textures) imageTextures.push_back(textureFor(path));
    std::vector<float> uv(2 * p.baked.vertices.size(), 0.0f);
    for (std::size_t k = 0; k < p.baked.texcoords.size() && k < p.baked.vertices.size(); ++k)
        uv[2 * k] = p.baked.texcoords[k].u, uv[2 * k + 1] = p.baked.texcoords[k].v;
    glBindBuffer(GL_ARRAY_BUFFER, texturedUvs);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(uv.size() * 4), uv.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    for (const mesh::TextureRange& r : p.textured) {
        const GLuint t = r.texture >= 1 && r.texture <= imageTextures.size() ? imageTextures[r.texture - 1] : 0;
        textured.push_back({r.first, r.count, t ? t : whiteTexture});
        texturedTris += r.count;
    }
}

GLuint Renderer::Impl::textureFor(const std::string& path) {
    std::shared_ptr<const mesh::TextureImage> image = mesh::textureImage(path);
    TextureObject& o = textureObjects[path];
    if (o.image == image) return o.texture;
    // (A missing file the model's reader has warned of; a broken one is said here, once.)
    if (!image->error.empty() && !image->missing && (!o.image || o.image->error != image->error)) {
        std::fprintf(stderr, "warning: %s: drawn in its colour\n", image->error.c_str());
        textureProblems.push_back(image->error + ": drawn in its colour");
    }
    o.image = image;
    if (image->error.empty() && !o.texture) glGenTextures(1, &o.texture);
    if (!image->error.empty()) return o.texture = 0;
    glBindTexture(GL_TEXTURE_2D, o.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image->rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);  // PlantGL's repeatS, repeatT
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    return o.texture;
}

// The textured vertex array bound: the scene's vertices (its buffers swap with a staged
// upload) and their u, v.
void Renderer::Impl::texturedAttributes() {
    glBindVertexArray(texturedVao);
    bakedAttributes(baked.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, texturedUvs);
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 8, nullptr);
}

std::vector<std::string> Renderer::takeTextureProblems() { return std::exchange(m->textureProblems, {}); }

void Renderer::Impl::drawTextured(const glm::mat4& viewProj, GLuint p, std::size_t from, std::size_t to) {
    const bool depth = p == bakedDepth;
    const GLuint program = depth ? texturedDepth : texturedProgram;
    glUseProgram(program);
    setUniform(program, "uViewProj", viewProj);
    texturedAttributes();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, baked.ebo);
    glActiveTexture(GL_TEXTURE0 + detail::kImageUnit);
    for (const TexturedDraw& r : textured) {
        const std::size_t a = std::max(from, r.first), b = std::min(to, r.first + r.count);
        if (a >= b) continue;
        glBindTexture(GL_TEXTURE_2D, r.texture);
        glDrawElements(GL_TRIANGLES, GLsizei(3 * (b - a)), GL_UNSIGNED_INT, reinterpret_cast<const void*>(3 * a * sizeof(std::uint32_t)));
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
}

}  // namespace sprout::render
