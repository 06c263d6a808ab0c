#pragma once
// What the turtle draws: plain arrays the renderer uploads as they are (instanced cylinders,
// instanced surfaces, one polygon mesh) plus bounds. No GL here.
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/base/pod_buffer.hpp"
#include "core/base/shine.hpp"

namespace sprout {

// A tapered stem segment. Its ends carry round caps in the renderer, so consecutive
// segments join without gaps at any angle.
struct CylinderInstance {
    glm::vec3 start;
    float startRadius;
    glm::vec3 end;
    float endRadius;
    std::uint32_t colour;   // 0xRRGGBBAA
    std::uint16_t order;    // branch order: 0 for the trunk, +1 inside each [ ]
    std::uint16_t step;     // derivation step that created the module (0 without ages)
};
static_assert(sizeof(CylinderInstance) == 40);

enum class SurfaceKind : std::uint32_t { Leaf = 0, Petal = 1, Sphere = 2 };

// A predefined surface placed in the turtle frame: `heading` is H, `up` is U, `size` scales.
struct SurfaceInstance {
    glm::vec3 position;
    float size;
    glm::vec3 heading;
    std::uint32_t colour;
    glm::vec3 up;
    SurfaceKind kind;
};
static_assert(sizeof(SurfaceInstance) == 48);

// A textured vertex's place in its image (u, v after the model's texture transforms; the
// image repeats outside [0, 1]) and the image: Geometry::textures[texture - 1]; 0: none.
struct TexCoord {
    float u = 0, v = 0;
    std::uint32_t texture = 0;
};

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> colours;
    std::vector<std::uint32_t> indices;  // triangles
    // Empty when nothing is textured; else one a position (untextured ones: texture 0). A
    // triangle is textured when its first vertex is.
    std::vector<TexCoord> texcoords;
    void clear() {
        positions.clear();
        normals.clear();
        colours.clear();
        indices.clear();
        texcoords.clear();
    }
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    bool empty = true;
    void add(const glm::vec3& p);
    void add(const Bounds& b);
    glm::vec3 centre() const { return (min + max) * 0.5f; }
    glm::vec3 size() const { return max - min; }
};

struct Geometry {
    PodBuffer<CylinderInstance> cylinders;  // written in place, never zeroed first
    PodBuffer<SurfaceInstance> surfaces;
    Mesh polygons;
    Bounds bounds;
    // A curve in one plane without branches (Koch, Sierpinski, dragon): the renderer draws
    // it as a crisp 2D line, seen face-on with an orthographic camera.
    bool planarCurve = false;
    // Texts at points (Label(k[, size]): Settings::labels), drawn facing the viewer.
    struct Label {
        glm::vec3 position;
        std::string text;
        float size;            // pixels
        std::uint32_t colour;  // 0xRRGGBBAA
    };
    std::vector<Label> labels;
    // The colours (0xRRGGBBAA) whose surfaces shine (a material's specular, shininess and
    // emission); the first listed for a colour counts. The others are lit plainly.
    std::vector<std::pair<std::uint32_t, Shine>> shines;
    // The images textured vertices name (TexCoord::texture - 1): paths as the model's folder
    // resolves them. The renderer reads each once; one it cannot read is drawn in its colour.
    std::vector<std::string> textures;
    // The id (TexCoord::texture, from 1) of image `path` in `textures`, added when it is new.
    std::uint32_t textureId(const std::string& path);
    // A VLab object's background scene (cpfg's `background scene:`, background_scene.hpp): its
    // triangles are in `polygons`, the vertices from `backdropFirst` (`backdropCount` of them).
    // `bounds` leaves them out, as cpfg frames the plant alone; `backdrop` holds theirs.
    Bounds backdrop;
    std::uint32_t backdropFirst = 0, backdropCount = 0;
    // All that is drawn: the plant's bounds and the background scene's (clip planes, exports).
    Bounds extent() const {
        Bounds b = bounds;
        b.add(backdrop);
        return b;
    }

    void clear();  // keeps capacity: re-interpretation reuses the buffers
    std::uint64_t bytes() const;  // what its instances, triangles and labels take
};

}  // namespace sprout
