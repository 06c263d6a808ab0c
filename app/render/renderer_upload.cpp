// The scene the renderer holds on the GPU: a prepared scene uploaded whole, or a piece per
// frame into back buffers that are swapped in when whole (persistently mapped where the
// context allows), and the environment (overlay) and picked stems (highlight) drawn with
// it. Its own file because uploads are a role apart from set-up (renderer.cpp) and drawing
// (renderer_draw.cpp): they only fill the buffers the other two make and read.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

#include "app/mesh/bake.hpp"
#include "app/render/gl.hpp"
#include "app/render/renderer.hpp"
#include "app/render/renderer_impl.hpp"

namespace sprout::render {

void Renderer::upload(const Geometry& g) {
    PreparedScene p;
    prepare(g, m->detail, p);
    upload(p);
}

void Renderer::upload(const PreparedScene& p) {
    Impl& s = *m;
    s.staging.reset();  // a whole upload replaces any staged one
    std::fill(std::begin(s.stagedMaps), std::end(s.stagedMaps), nullptr);
    s.mutableAgain(s.baked, false);
    s.mutableAgain(s.lines, true);
    glBindVertexArray(s.baked.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.baked.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.baked.vertices.size() * sizeof(mesh::BakedVertex)), p.baked.vertices.data(), GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(p.baked.indices.size() * 4), p.baked.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, s.lines.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.lines.size() * 4), p.lines.data(), GL_STATIC_DRAW);
    adopt(p);
}

// Everything of a scene but its baked and line buffers: bounds, curves, counts, statistics.
void Renderer::adopt(const PreparedScene& p) {
    Impl& s = *m;
    m_progress.reset();  // a picture in pieces is of the scene before
    s.shadowValid = false;
    m_lastPictureMs = 1e9;
    s.bounds = p.bounds;
    s.planarCurve = p.planarCurve;
    s.curveCount = p.curve.size();
    s.rasterCurve = p.curveGeometry;
    s.coverageOf = nullptr;  // a new scene: rasterise again (even at a recycled address)
    glBindBuffer(GL_TEXTURE_BUFFER, s.curveInstances);
    if (s.curveCount)
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(s.curveCount * sizeof(CylinderInstance)), p.curve.data(), GL_STATIC_DRAW);
    if (s.rasterCurve && s.bigCurveRibbons && s.rasterCurve->cylinders.size() <= kGpuCurveRibbons) {
        // A big curve as its ribbons, read from its geometry (no copy): when its segments fit
        // the buffer texture (2^27 texels on NVIDIA) and the GPU's memory.
        const auto& c = s.rasterCurve->cylinders;
        GLint maxTexels = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
        if (c.size() * (sizeof(CylinderInstance) / 4) <= std::size_t(maxTexels)) {
            for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k) {  // errors of before, cleared
            }
            glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(c.size() * sizeof(CylinderInstance)), c.data(), GL_STATIC_DRAW);
            if (glGetError() == GL_NO_ERROR) s.curveCount = c.size(), s.rasterCurve = nullptr;
            else glBufferData(GL_TEXTURE_BUFFER, 64, nullptr, GL_STATIC_DRAW);  // out of memory: rasterised
        }
    }
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    s.bakedIndices = p.baked.indices.size();
    s.adoptTranslucent(p.baked, p.translucent);
    s.closedStems = p.closedStems;
    s.adoptTextured(p);
    s.shines = p.shines;
    s.lineCount = p.lines.size() / 8;
    s.proxyCount = p.proxy.size() / 8;
    glBindBuffer(GL_ARRAY_BUFFER, s.proxy.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.proxy.size() * 4), p.proxy.data(), GL_STATIC_DRAW);
    s.proxyIndices = p.proxyBaked.indices.size();
    glBindVertexArray(s.proxyMesh.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.proxyMesh.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(p.proxyBaked.vertices.size() * sizeof(mesh::BakedVertex)), p.proxyBaked.vertices.data(),
                 GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(s.proxyIndices * 4), p.proxyBaked.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    m_stats = {};
    m_stats.cylinders = p.cylinders;
    m_stats.surfaces = p.surfaces;
    for (int l = 0; l < 4; ++l) m_stats.levels[l] = p.levels[l];
}

bool Renderer::beginUpload(std::shared_ptr<const PreparedScene> p, std::size_t bytesPerFrame) {
    Impl& s = *m;
    const std::size_t vb = p->baked.vertices.size() * sizeof(mesh::BakedVertex), ib = p->baked.indices.size() * 4,
                      lb = p->lines.size() * 4;
    if (vb + ib + lb <= bytesPerFrame) {  // small: at once
        upload(*p);
        return true;
    }
    // The back buffers get their size now and their bytes a piece per frame; the scene on
    // screen is drawn meanwhile.
    std::fill(std::begin(s.stagedMaps), std::end(s.stagedMaps), nullptr);
    if (s.persistentUploads) {
        // Storage mapped for writing once: each piece a copy into it. Storage is immutable, so
        // the back buffers are made anew for each scene (the driver frees the old ones once no
        // drawing uses them: no wait here).
        s.mutableAgain(s.bakedBack, false, true);
        s.mutableAgain(s.linesBack, true, true);
        const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        auto storage = [flags](GLenum target, std::size_t size) {
            const auto n = GLsizeiptr(std::max<std::size_t>(size, 1));
            glBufferStorage(target, n, nullptr, flags);
            return glMapBufferRange(target, 0, n, flags);
        };
        glBindVertexArray(s.bakedBack.vao);
        glBindBuffer(GL_ARRAY_BUFFER, s.bakedBack.vbo);
        s.stagedMaps[0] = storage(GL_ARRAY_BUFFER, vb);
        s.stagedMaps[1] = storage(GL_ELEMENT_ARRAY_BUFFER, ib);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, s.linesBack.vbo);
        s.stagedMaps[2] = storage(GL_ARRAY_BUFFER, lb);
        s.bakedBack.immutable = s.linesBack.immutable = true;
        if (s.stagedMaps[0] && s.stagedMaps[1] && s.stagedMaps[2]) {
            s.staging = std::move(p);
            s.stagedBytes = 0;
            return false;
        }
        // Not mapped (out of address space): by glBufferSubData from now on.
        std::fill(std::begin(s.stagedMaps), std::end(s.stagedMaps), nullptr);
        s.persistentUploads = false;
    }
    s.mutableAgain(s.bakedBack, false);
    s.mutableAgain(s.linesBack, true);
    glBindVertexArray(s.bakedBack.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.bakedBack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vb), nullptr, GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(ib), nullptr, GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, s.linesBack.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lb), nullptr, GL_STATIC_DRAW);
    s.staging = std::move(p);
    s.stagedBytes = 0;
    return false;
}

bool Renderer::uploading() const { return m->staging != nullptr; }

bool Renderer::persistentUploads() const { return m->persistentUploads; }

void Renderer::setPersistentUploads(bool on) { m->persistentUploads = on && m->bufferStorage; }

bool Renderer::bigCurveRibbons() const { return m->bigCurveRibbons; }

void Renderer::setBigCurveRibbons(bool on) { m->bigCurveRibbons = on; }

bool Renderer::continueUpload(std::size_t bytes) {
    Impl& s = *m;
    if (!s.staging) return true;
    const PreparedScene& p = *s.staging;
    struct Part {
        GLenum target;
        GLuint vao, buffer;
        const void* data;
        std::size_t size;
    } parts[] = {
        {GL_ARRAY_BUFFER, s.bakedBack.vao, s.bakedBack.vbo, p.baked.vertices.data(), p.baked.vertices.size() * sizeof(mesh::BakedVertex)},
        {GL_ELEMENT_ARRAY_BUFFER, s.bakedBack.vao, s.bakedBack.ebo, p.baked.indices.data(), p.baked.indices.size() * 4},
        {GL_ARRAY_BUFFER, 0, s.linesBack.vbo, p.lines.data(), p.lines.size() * 4},
    };
    std::size_t base = 0;
    for (std::size_t i = 0; i < std::size(parts); ++i) {
        const Part& part = parts[i];
        const std::size_t from = s.stagedBytes > base ? s.stagedBytes - base : 0;
        if (bytes > 0 && from < part.size) {
            const std::size_t n = std::min(bytes, part.size - from);
            if (s.stagedMaps[i]) {
                std::memcpy(static_cast<char*>(s.stagedMaps[i]) + from, static_cast<const char*>(part.data) + from, n);
            } else {
                glBindVertexArray(part.vao);  // the element buffer is the vertex array's
                glBindBuffer(part.target, part.buffer);
                glBufferSubData(part.target, GLintptr(from), GLsizeiptr(n), static_cast<const char*>(part.data) + from);
                glBindVertexArray(0);
            }
            s.stagedBytes += n;
            bytes -= n;
        }
        base += part.size;
    }
    if (s.stagedBytes < base) return false;
    if (s.stagedMaps[0]) {  // whole: unmapped before it is drawn
        for (std::size_t i = 0; i < std::size(parts); ++i) {
            glBindVertexArray(parts[i].vao);
            glBindBuffer(parts[i].target, parts[i].buffer);
            glUnmapBuffer(parts[i].target);
            glBindVertexArray(0);
        }
        std::fill(std::begin(s.stagedMaps), std::end(s.stagedMaps), nullptr);
    }
    std::swap(s.baked, s.bakedBack);
    std::swap(s.lines, s.linesBack);
    adopt(p);
    s.staging.reset();
    return true;
}

bool Renderer::rasterCurve() const { return m->rasterCurve != nullptr; }

namespace {
std::size_t uploadBaked(const mesh::BakedMesh& baked, GLuint vao, GLuint vbo, GLuint ebo) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(baked.vertices.size() * sizeof(mesh::BakedVertex)), baked.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(baked.indices.size() * 4), baked.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    return baked.indices.size();
}
std::size_t uploadMesh(const Mesh& mesh, GLuint vao, GLuint vbo, GLuint ebo) {
    mesh::BakedMesh baked;
    mesh::bakePolygons(mesh, baked);
    return uploadBaked(baked, vao, vbo, ebo);
}
}  // namespace

void Renderer::setHighlight(const Mesh& mesh) {
    m->highlightIndices = uploadMesh(mesh, m->highlight.vao, m->highlight.vbo, m->highlight.ebo);
}

void Renderer::setOverlay(const Mesh& mesh) {
    Impl& s = *m;
    // The opaque triangles, then the translucent ones (overlay_body.glsl's test, alpha >= 0.99:
    // 253 of 255), each in the order given: every pass draws only its own, as the passes'
    // discards left them (env_space_colonisation's free points were drawn three times, its
    // glass crown three times). A triangle of both kinds is in both.
    mesh::BakedMesh baked;
    mesh::bakePolygons(mesh, baked);
    const std::vector<std::uint32_t> given = std::move(baked.indices);
    baked.indices.clear();
    baked.indices.reserve(given.size());
    auto opaque = [&](std::uint32_t v) { return v < baked.vertices.size() && (baked.vertices[v].colour & 0xffu) >= 253; };
    auto take = [&](bool translucent) {
        const std::size_t before = baked.indices.size() / 3;
        for (std::size_t t = 0; t + 2 < given.size(); t += 3) {
            const std::uint32_t* v = &given[t];
            const int opaqueCorners = int(opaque(v[0])) + int(opaque(v[1])) + int(opaque(v[2]));
            if (translucent ? opaqueCorners < 3 : opaqueCorners > 0) baked.indices.insert(baked.indices.end(), v, v + 3);
        }
        return baked.indices.size() / 3 - before;
    };
    s.overlayOpaque = take(false);
    s.overlayTranslucent = take(true);
    s.overlayTriangles = given.size() / 3;
    s.overlayIndices = uploadBaked(baked, s.overlay.vao, s.overlay.vbo, s.overlay.ebo);
    s.overlayBounds = Bounds();
    for (const glm::vec3& p : mesh.positions) s.overlayBounds.add(p);
}

}  // namespace sprout::render
