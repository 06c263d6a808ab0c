#pragma once
// cpfg's surface files (`.s`): bicubic Bezier patches with a contact point, a heading, an up
// vector and a size, placed by a `~name` module in the turtle's frame (cpfg manual, "Surface
// specification"). Parsed once with the grammar; drawn into the plant's polygon mesh.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace sprout {

// Triangles in the surface's own frame, normalised: x along its heading, y along its left,
// z along its up, the contact point at the origin, and divided by its SIZE, so that `~name(s)`
// scales it by s.
struct SurfaceFile {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
    int patches = 0;
    // Stems in the same frame, as pairs of points (L-Py's @g of a curve: a polyline; of a
    // point set: a short stem at each point), drawn as thick as the turtle's width.
    std::vector<glm::vec3> lines;
    // Each position's own colour (0xRRGGBBAA; 0: the turtle's), where the surface has colours
    // of its own (L-Py's @g of Shapes in their Materials); empty: all the turtle's.
    std::vector<std::uint32_t> colours;
    // Each position's place in a texture image (u, v; PlantGL's and cpfg's coordinates of the
    // surface), where the surface has them; empty: none, never textured.
    std::vector<std::array<float, 2>> uvs;
    // The same across the whole surface (cpfg's texture per surface, `S:`): x and y in the
    // file's own coordinates over their ranges; empty where `uvs` is.
    std::vector<std::array<float, 2>> surfaceUvs;
    // Its own image (an L-Py @g Shape in a texture appearance), on `uvs`; "": the image of the
    // turtle's material, if any.
    std::string texture;
};

// `error` says what is wrong and on which line when the text is not a surface file.
std::optional<SurfaceFile> parseSurfaceFile(std::string_view text, std::string& error);

}  // namespace sprout
