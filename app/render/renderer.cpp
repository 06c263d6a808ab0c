#include "app/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/render/gl.hpp"
#include "app/render/meshes.hpp"
#include "app/render/shader.hpp"

namespace sprout::render {
namespace {

constexpr int kShadowSize = 2048;

// A unit mesh replicated uBatch times in one vertex buffer, each copy tagged with its index
// (attribute 7), so one draw instance renders a whole batch of segments or surfaces.
struct BatchedMesh {
    GLuint vao = 0, vbo = 0, ebo = 0;
    GLsizei indexCount = 0;  // for all copies
    int batch = 1;
    std::size_t trianglesPerCopy = 0;
};

struct Attribute {
    GLuint location;
    GLint size;  // floats
};

BatchedMesh makeBatched(const std::vector<float>& vertices, int floatsPerVertex, const std::vector<Attribute>& layout,
                        const std::vector<std::uint32_t>& indices) {
    BatchedMesh m;
    const std::size_t count = vertices.size() / std::size_t(floatsPerVertex);
    m.batch = int(std::clamp<std::size_t>(16384 / std::max<std::size_t>(count, 1), 1, 256));
    m.trianglesPerCopy = indices.size() / 3;
    std::vector<float> data;
    std::vector<std::uint32_t> idx;
    data.reserve(std::size_t(m.batch) * count * std::size_t(floatsPerVertex + 1));
    for (int copy = 0; copy < m.batch; ++copy) {
        for (std::size_t v = 0; v < count; ++v) {
            data.insert(data.end(), vertices.begin() + std::ptrdiff_t(v * std::size_t(floatsPerVertex)),
                        vertices.begin() + std::ptrdiff_t((v + 1) * std::size_t(floatsPerVertex)));
            data.push_back(float(copy));
        }
        for (auto i : indices) idx.push_back(i + std::uint32_t(std::size_t(copy) * count));
    }
    glGenVertexArrays(1, &m.vao);
    glBindVertexArray(m.vao);
    glGenBuffers(1, &m.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    const GLsizei stride = GLsizei((floatsPerVertex + 1) * sizeof(float));
    std::size_t offset = 0;
    for (const Attribute& a : layout) {
        glEnableVertexAttribArray(a.location);
        glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
        offset += std::size_t(a.size) * sizeof(float);
    }
    glEnableVertexAttribArray(7);
    glVertexAttribPointer(7, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(std::size_t(floatsPerVertex) * sizeof(float)));
    glGenBuffers(1, &m.ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * 4), idx.data(), GL_STATIC_DRAW);
    m.indexCount = GLsizei(idx.size());
    glBindVertexArray(0);
    return m;
}

// Instances [first, first + count) of a buffer texture, drawn in batches.
void drawBatched(GLuint program, const BatchedMesh& m, std::size_t first, std::size_t count) {
    if (!count) return;
    glUniform1i(glGetUniformLocation(program, "uFirst"), GLint(first));
    glUniform1i(glGetUniformLocation(program, "uCount"), GLint(count));
    glUniform1i(glGetUniformLocation(program, "uBatch"), m.batch);
    glBindVertexArray(m.vao);
    const GLsizei instances = GLsizei((count + std::size_t(m.batch) - 1) / std::size_t(m.batch));
    glDrawElementsInstanced(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr, instances);
}

// Levels of detail for the cylinders: sides around, rings per cap. Software rendering
// (llvmpipe) draws about 10 k instanced cylinders per 86 ms at 1280x720, so each segment
// gets the coarsest mesh that still looks round at its size: the plant is framed whole, so
// a segment's radius relative to the plant's size says how many pixels it covers.
struct Lod {
    int sides, capRings;
    float minRelativeRadius;  // radius / plant size from which this level is used
};
constexpr Lod kLods[3] = {{12, 2, 1.0f / 100}, {6, 0, 1.0f / 300}, {0, 0, 0.0f}};  // 0 sides: a strip

void setUniform(GLuint p, const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(glGetUniformLocation(p, name), 1, GL_FALSE, glm::value_ptr(m));
}
void setUniform(GLuint p, const char* name, const glm::vec3& v) { glUniform3fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* name, const glm::vec2& v) { glUniform2fv(glGetUniformLocation(p, name), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* name, float v) { glUniform1f(glGetUniformLocation(p, name), v); }
void setUniform(GLuint p, const char* name, int v) { glUniform1i(glGetUniformLocation(p, name), v); }

}  // namespace

struct Renderer::Impl {
    GLuint cylinderProgram = 0, cylinderDepth = 0, surfaceProgram = 0, surfaceDepth = 0;
    GLuint polygonProgram = 0, polygonDepth = 0, curveProgram = 0, backgroundProgram = 0, groundProgram = 0;
    BatchedMesh cylinders[3], leaf, petal, sphere, smallSphere, curveQuad;
    struct {
        GLuint vao = 0, vbo = 0, ebo = 0;
        GLsizei indexCount = 0;
    } polygon, groundQuad;
    // Instance arrays as buffer textures (words of CylinderInstance / SurfaceInstance).
    GLuint cylinderInstances = 0, surfaceInstances = 0, cylinderTexture = 0, surfaceTexture = 0, emptyVao = 0;
    GLuint shadowFbo = 0, shadowTexture = 0;
    GLuint msaaFbo = 0, msaaColour = 0, msaaDepth = 0;
    int msaaWidth = 0, msaaHeight = 0, samples = 1;
    // What was uploaded.
    std::size_t cylinderCount = 0, surfaceCount[3] = {0, 0, 0}, surfaceStart[3] = {0, 0, 0};
    std::size_t lodCount[3] = {0, 0, 0}, lodStart[3] = {0, 0, 0};  // cylinders sorted by level
    bool smallSpheres = false;
    std::size_t maxInstanceWords = 0;
    Bounds bounds;
    bool planarCurve = false;
    float maxRadius = 0;

    bool build(std::string& error) {
        struct P {
            GLuint* out;
            const char *vs, *fs;
        } programs[] = {
            {&cylinderProgram, "cylinder.vert", "lit.frag"}, {&cylinderDepth, "cylinder.vert", "depth.frag"},
            {&surfaceProgram, "surface.vert", "lit.frag"},   {&surfaceDepth, "surface.vert", "depth.frag"},
            {&polygonProgram, "polygon.vert", "lit.frag"},   {&polygonDepth, "polygon.vert", "depth.frag"},
            {&curveProgram, "curve.vert", "curve.frag"},     {&backgroundProgram, "background.vert", "background.frag"},
            {&groundProgram, "ground.vert", "ground.frag"},
        };
        for (auto& p : programs)
            if (!(*p.out = buildProgram(p.vs, p.fs, error))) return false;

        for (auto [buffer, texture] : {std::pair{&cylinderInstances, &cylinderTexture}, std::pair{&surfaceInstances, &surfaceTexture}}) {
            glGenBuffers(1, buffer);
            glBindBuffer(GL_TEXTURE_BUFFER, *buffer);
            glBufferData(GL_TEXTURE_BUFFER, 64, nullptr, GL_STATIC_DRAW);
            glGenTextures(1, texture);
            glBindTexture(GL_TEXTURE_BUFFER, *texture);
            glTexBuffer(GL_TEXTURE_BUFFER, GL_R32UI, *buffer);
        }
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        for (int i = 0; i < 2; ++i) {
            CylinderMesh c = makeCylinder(kLods[i].sides, kLods[i].capRings);
            std::vector<float> v;
            for (const auto& p : c.vertices) v.insert(v.end(), {p.x, p.y, p.z, p.w});
            cylinders[i] = makeBatched(v, 4, {{0, 4}}, c.indices);
        }
        // The strip: x across (-1, 1), y past the ends by one radius, w start / end.
        cylinders[2] = makeBatched({-1, -1, 0, 0, 1, -1, 0, 0, -1, 1, 0, 1, 1, 1, 0, 1}, 4, {{0, 4}}, {0, 1, 3, 0, 3, 2});
        auto surface = [](const SurfaceMesh& m) {
            std::vector<float> v;
            for (std::size_t i = 0; i < m.positions.size(); ++i)
                v.insert(v.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z, m.normals[i].x, m.normals[i].y, m.normals[i].z});
            return makeBatched(v, 6, {{0, 3}, {1, 3}}, m.indices);
        };
        leaf = surface(makeLeaf());
        petal = surface(makePetal());
        sphere = surface(makeSphere(16, 10));
        smallSphere = surface(makeSphere(6, 3));
        curveQuad = makeBatched({0, -1, 0, 1, 1, -1, 1, 1}, 2, {{0, 2}}, {0, 2, 1, 1, 2, 3});
        makePolygonBuffers();
        makeGroundQuad();
        GLint maxTexels = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
        maxInstanceWords = std::size_t(maxTexels);
        glGenVertexArrays(1, &emptyVao);

        GLint maxSamples = 1;
        glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
        samples = std::clamp(maxSamples, 1, getenv("SPROUT_SAMPLES") ? atoi(getenv("SPROUT_SAMPLES")) : 4);

        glGenTextures(1, &shadowTexture);
        glBindTexture(GL_TEXTURE_2D, shadowTexture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kShadowSize, kShadowSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glGenFramebuffers(1, &shadowFbo);
        glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadowTexture, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (!ok) error = "the shadow map framebuffer is incomplete";
        return ok;
    }

    void makePolygonBuffers() {
        glGenVertexArrays(1, &polygon.vao);
        glBindVertexArray(polygon.vao);
        glGenBuffers(1, &polygon.vbo);
        glGenBuffers(1, &polygon.ebo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, polygon.ebo);
        glBindVertexArray(0);
    }

    void makeGroundQuad() {
        const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
        glGenVertexArrays(1, &groundQuad.vao);
        glBindVertexArray(groundQuad.vao);
        glGenBuffers(1, &groundQuad.vbo);
        glBindBuffer(GL_ARRAY_BUFFER, groundQuad.vbo);
        glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
        glBindVertexArray(0);
    }

    void ensureMsaa(int w, int h) {
        if (msaaFbo && w == msaaWidth && h == msaaHeight) return;
        if (!msaaFbo) {
            glGenFramebuffers(1, &msaaFbo);
            glGenRenderbuffers(1, &msaaColour);
            glGenRenderbuffers(1, &msaaDepth);
        }
        glBindRenderbuffer(GL_RENDERBUFFER, msaaColour);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, msaaDepth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
        glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaaColour);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaaDepth);
        msaaWidth = w;
        msaaHeight = h;
    }

    // Interactive frames of big plants drop one more level of detail.
    int lodShift(Quality q) const { return q == Quality::Interactive && cylinderCount > 20000 ? 1 : 0; }

    // Everything that casts or receives light, with one view-projection.
    void drawScene(const glm::mat4& viewProj, const glm::vec3& eye, bool depthOnly, const RenderOptions& o, float minRadius,
                   RenderStats& stats) {
        if (cylinderCount) {
            GLuint p = depthOnly ? cylinderDepth : cylinderProgram;
            glUseProgram(p);
            setUniform(p, "uViewProj", viewProj);
            setUniform(p, "uMinRadius", minRadius);
            setUniform(p, "uSpecular", 0.12f);
            setUniform(p, "uInstances", 1);
            setUniform(p, "uEye", eye);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_BUFFER, cylinderTexture);
            for (int level = 0; level < 3; ++level) {
                // Shadows need only the silhouette: the coarsest mesh casts them.
                int mesh = depthOnly ? 2 : std::min(2, level + lodShift(o.quality));
                setUniform(p, "uBillboard", mesh == 2 ? 1 : 0);
                drawBatched(p, cylinders[mesh], lodStart[level], lodCount[level]);
                stats.triangles += cylinders[mesh].trianglesPerCopy * lodCount[level];
                stats.levels[mesh] += lodCount[level];
            }
        }
        BatchedMesh* meshes[3] = {&leaf, &petal, smallSpheres || depthOnly ? &smallSphere : &sphere};
        GLuint sp = depthOnly ? surfaceDepth : surfaceProgram;
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_BUFFER, surfaceTexture);
        for (int k = 0; k < 3; ++k) {
            if (!surfaceCount[k]) continue;
            glUseProgram(sp);
            setUniform(sp, "uViewProj", viewProj);
            setUniform(sp, "uSpecular", k == 2 ? 0.3f : 0.08f);
            setUniform(sp, "uInstances", 1);
            drawBatched(sp, *meshes[k], surfaceStart[k], surfaceCount[k]);
            stats.triangles += meshes[k]->trianglesPerCopy * surfaceCount[k];
        }
        glActiveTexture(GL_TEXTURE0);
        if (polygon.indexCount) {
            GLuint p = depthOnly ? polygonDepth : polygonProgram;
            glUseProgram(p);
            setUniform(p, "uViewProj", viewProj);
            setUniform(p, "uSpecular", 0.05f);
            glBindVertexArray(polygon.vao);
            glDrawElements(GL_TRIANGLES, polygon.indexCount, GL_UNSIGNED_INT, nullptr);
            stats.triangles += std::size_t(polygon.indexCount / 3);
        }
        glBindVertexArray(0);
    }

    void setLighting(GLuint p, const RenderOptions& o, const glm::vec3& eye, const glm::mat4& lightViewProj, bool shadows, float texel) {
        glUseProgram(p);
        glm::vec3 sun = glm::normalize(o.sunDirection);
        setUniform(p, "uSunDir", sun);
        setUniform(p, "uSunColour", glm::vec3(1.0f, 0.96f, 0.88f) * o.sunIntensity);
        setUniform(p, "uSkyAmbient", glm::vec3(0.36f, 0.42f, 0.50f));
        setUniform(p, "uGroundAmbient", glm::vec3(0.20f, 0.18f, 0.14f));
        setUniform(p, "uEye", eye);
        setUniform(p, "uLightViewProj", lightViewProj);
        setUniform(p, "uShadowMap", 0);
        setUniform(p, "uShadows", shadows ? 1 : 0);
        setUniform(p, "uShadowTexel", texel);
    }
};

Renderer::Renderer() : m(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

int Renderer::samples() const { return m->samples; }

bool Renderer::init(ProcLoader loader, std::string& error) {
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(loader))) {
        error = "could not load OpenGL functions";
        return false;
    }
    if (!GLAD_GL_VERSION_3_3) {
        error = "OpenGL 3.3 core is required";
        return false;
    }
    return m->build(error);
}

void Renderer::upload(const Geometry& g) {
    Impl& s = *m;
    s.cylinderCount = g.cylinders.size();
    // Cylinders grouped by level of detail (one counting pass, one scatter pass).
    const glm::vec3 size = g.bounds.empty ? glm::vec3(1) : g.bounds.size();
    const float extent = std::max({size.x, size.y, size.z, 1e-6f});
    auto levelOf = [&](const CylinderInstance& c) {
        float rel = std::max(c.startRadius, c.endRadius) / extent;
        return rel >= kLods[0].minRelativeRadius ? 0 : rel >= kLods[1].minRelativeRadius ? 1 : 2;
    };
    for (auto& n : s.lodCount) n = 0;
    for (const auto& c : g.cylinders) ++s.lodCount[levelOf(c)];
    s.lodStart[0] = 0;
    s.lodStart[1] = s.lodCount[0];
    s.lodStart[2] = s.lodCount[0] + s.lodCount[1];
    glBindBuffer(GL_TEXTURE_BUFFER, s.cylinderInstances);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(std::max<std::size_t>(g.cylinders.size(), 1) * sizeof(CylinderInstance)), nullptr,
                 GL_STATIC_DRAW);
    if (s.lodCount[0] == s.cylinderCount || s.lodCount[1] == s.cylinderCount || s.lodCount[2] == s.cylinderCount) {
        glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(g.cylinders.size() * sizeof(CylinderInstance)), g.cylinders.data());
    } else if (auto* dst = static_cast<CylinderInstance*>(glMapBuffer(GL_TEXTURE_BUFFER, GL_WRITE_ONLY))) {
        std::size_t next[3] = {s.lodStart[0], s.lodStart[1], s.lodStart[2]};
        for (const auto& c : g.cylinders) dst[next[levelOf(c)]++] = c;
        glUnmapBuffer(GL_TEXTURE_BUFFER);
    }
    // A buffer texture holds at most GL_MAX_TEXTURE_BUFFER_SIZE words (128 M on llvmpipe):
    // beyond that the plant is drawn in part rather than not at all.
    const std::size_t maxCylinders = s.maxInstanceWords / 10;
    if (s.cylinderCount > maxCylinders) {
        s.cylinderCount = maxCylinders;
        for (int l = 0; l < 3; ++l)
            s.lodCount[l] = std::min(s.lodCount[l], maxCylinders > s.lodStart[l] ? maxCylinders - s.lodStart[l] : 0);
    }
    float maxSphere = 0;
    for (const auto& x : g.surfaces)
        if (x.kind == SurfaceKind::Sphere) maxSphere = std::max(maxSphere, x.size);
    s.smallSpheres = maxSphere < extent / 60;

    // Surfaces grouped by kind so each kind is one instanced draw.
    std::vector<SurfaceInstance> sorted(g.surfaces.begin(), g.surfaces.end());
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const SurfaceInstance& a, const SurfaceInstance& b) { return a.kind < b.kind; });
    for (int k = 0; k < 3; ++k) s.surfaceCount[k] = 0;
    for (const auto& x : sorted) ++s.surfaceCount[std::min<std::uint32_t>(std::uint32_t(x.kind), 2)];
    s.surfaceStart[0] = 0;
    s.surfaceStart[1] = s.surfaceCount[0];
    s.surfaceStart[2] = s.surfaceCount[0] + s.surfaceCount[1];
    glBindBuffer(GL_TEXTURE_BUFFER, s.surfaceInstances);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(std::max<std::size_t>(sorted.size(), 1) * sizeof(SurfaceInstance)), nullptr,
                 GL_STATIC_DRAW);
    glBufferSubData(GL_TEXTURE_BUFFER, 0, GLsizeiptr(sorted.size() * sizeof(SurfaceInstance)), sorted.data());

    const Mesh& p = g.polygons;
    glBindVertexArray(s.polygon.vao);
    glBindBuffer(GL_ARRAY_BUFFER, s.polygon.vbo);
    // Interleaving is not worth a copy here: positions, normals and colours in one buffer.
    const std::size_t n = p.positions.size();
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(n * (24 + 4)), nullptr, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(n * 12), p.positions.data());
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(n * 12), GLsizeiptr(n * 12), p.normals.data());
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(n * 24), GLsizeiptr(n * 4), p.colours.data());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, reinterpret_cast<void*>(n * 12));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, reinterpret_cast<void*>(n * 24));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.polygon.ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(p.indices.size() * 4), p.indices.data(), GL_STATIC_DRAW);
    s.polygon.indexCount = GLsizei(p.indices.size());
    glBindVertexArray(0);

    s.bounds = g.bounds;
    s.planarCurve = g.planarCurve;
    s.maxRadius = g.maxRadius;
    m_stats = {};
    m_stats.cylinders = s.cylinderCount;
    m_stats.surfaces = g.surfaces.size();
}

void Renderer::draw(const Camera& camera, int width, int height, const RenderOptions& o, unsigned target, int x,
                    int y) {
    Impl& s = *m;
    RenderStats stats;
    stats.cylinders = s.cylinderCount;
    stats.surfaces = s.surfaceCount[0] + s.surfaceCount[1] + s.surfaceCount[2];
    const float aspect = float(width) / float(std::max(height, 1));
    glm::vec3 size = s.bounds.empty ? glm::vec3(1) : s.bounds.size();
    const float radius = std::max(0.5f * glm::length(size), 1e-4f);
    const glm::vec3 centre = s.bounds.empty ? glm::vec3(0) : s.bounds.centre();
    const float dist = glm::length(camera.eye() - centre);
    const float near = std::max(1e-4f, (dist - radius * 3) * 0.9f), far = dist + radius * 4;
    const glm::mat4 viewProj = camera.projection(aspect, camera.orthographic ? 1e-3f : near, far) * camera.view();
    // World size of a pixel at the plant, so thin twigs stay visible.
    const float pixel = camera.orthographic ? camera.orthoHeight / float(height)
                                            : 2 * dist * std::tan(glm::radians(camera.fovY) / 2) / float(height);
    const bool curve = s.planarCurve;
    const bool shadows = o.shadows && !curve;
    const bool ground = o.ground && !curve && !s.bounds.empty;

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // leaves and petals are double-sided

    // Shadow map from the sun, an orthographic box around the plant and its ground.
    glm::mat4 lightViewProj(1.0f);
    const float groundRadius = std::max({size.x, size.z, size.y}) * 1.2f;
    if (shadows) {
        glm::vec3 sun = glm::normalize(o.sunDirection);
        float r = std::max(radius, groundRadius) * 1.05f;
        glm::vec3 up = std::fabs(sun.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        glm::mat4 lv = glm::lookAt(centre + sun * r * 2.0f, centre, up);
        lightViewProj = glm::ortho(-r, r, -r, r, 0.01f, r * 4.0f) * lv;
        glBindFramebuffer(GL_FRAMEBUFFER, s.shadowFbo);
        glViewport(0, 0, kShadowSize, kShadowSize);
        glClear(GL_DEPTH_BUFFER_BIT);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);  // never sample the map while writing it
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 2.0f);
        RenderStats ignored;
        s.drawScene(lightViewProj, centre + glm::normalize(o.sunDirection) * radius * 1000.0f, true, o, pixel * 0.5f, ignored);
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    const float texel = shadows ? 2.1f * std::max(radius, groundRadius) / kShadowSize : 0.0f;

    s.ensureMsaa(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, s.msaaFbo);
    glViewport(0, 0, width, height);
    glClearColor(o.backgroundBottom.r, o.backgroundBottom.g, o.backgroundBottom.b, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, s.shadowTexture);

    // Background gradient.
    glDisable(GL_DEPTH_TEST);
    glUseProgram(s.backgroundProgram);
    setUniform(s.backgroundProgram, "uTop", o.backgroundTop);
    setUniform(s.backgroundProgram, "uBottom", o.backgroundBottom);
    glBindVertexArray(s.emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);

    const glm::vec3 eye = camera.eye();
    if (ground) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        s.setLighting(s.groundProgram, o, eye, lightViewProj, shadows, texel);
        setUniform(s.groundProgram, "uViewProj", viewProj);
        setUniform(s.groundProgram, "uCentre", glm::vec3(centre.x, s.bounds.min.y, centre.z));
        setUniform(s.groundProgram, "uRadius", groundRadius);
        setUniform(s.groundProgram, "uGroundColour", o.groundColour);
        glBindVertexArray(s.groundQuad.vao);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }

    if (curve) {
        glUseProgram(s.curveProgram);
        setUniform(s.curveProgram, "uViewProj", viewProj);
        setUniform(s.curveProgram, "uViewport", glm::vec2(width, height));
        setUniform(s.curveProgram, "uWidth", std::max(1.5f, float(height) / 400.0f));
        setUniform(s.curveProgram, "uInk", o.curveInk);
        setUniform(s.curveProgram, "uInstances", 1);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_BUFFER, s.cylinderTexture);
        drawBatched(s.curveProgram, s.curveQuad, 0, s.cylinderCount);
        glActiveTexture(GL_TEXTURE0);
        stats.triangles += 2 * s.cylinderCount;
        stats.curve = true;
        // Polygons of a planar system still fill.
        std::size_t saved = s.cylinderCount;
        s.cylinderCount = 0;  // drawn as the curve above
        for (GLuint p : {s.surfaceProgram, s.polygonProgram}) s.setLighting(p, o, eye, lightViewProj, false, 0);
        s.drawScene(viewProj, eye, false, o, 0, stats);
        s.cylinderCount = saved;
    } else {
        for (GLuint p : {s.cylinderProgram, s.surfaceProgram, s.polygonProgram})
            s.setLighting(p, o, eye, lightViewProj, shadows, texel);
        s.drawScene(viewProj, eye, false, o, pixel * 0.5f, stats);
    }

    // Resolve the multisampled image into the target.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, s.msaaFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(0, 0, width, height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    m_stats = stats;
}

std::vector<std::uint8_t> Renderer::renderImage(const Camera& camera, int width, int height, const RenderOptions& o) {
    GLuint fbo = 0, colour = 0;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    draw(camera, width, height, o, fbo);
    std::vector<std::uint8_t> pixels = readPixels(width, height, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteRenderbuffers(1, &colour);
    glDeleteFramebuffers(1, &fbo);
    return pixels;
}

std::vector<std::uint8_t> Renderer::readPixels(int width, int height, unsigned source) const {
    std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    // GL's rows go bottom-up; images go top-down.
    const std::size_t row = std::size_t(width) * 4;
    std::vector<std::uint8_t> line(row);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* a = pixels.data() + std::size_t(y) * row;
        std::uint8_t* b = pixels.data() + std::size_t(height - 1 - y) * row;
        std::memcpy(line.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, line.data(), row);
    }
    return pixels;
}

}  // namespace sprout::render
