#pragma once
// The images textured surfaces show (Geometry::textures, issue 53): PNG, JPEG and SGI files
// (VLab's objects carry `.rgb` images) read into RGBA, each file once (again when it changes),
// shared by the renderer and the exports. No GL.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sprout::mesh {

struct TextureImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // top row first
    std::string format;              // "png", "jpeg", "sgi"
    std::uint32_t average = 0xFFFFFFFFu;  // 0xRRGGBBFF: the mean of its pixels at least half opaque
    std::string error;               // why it could not be read; "": it was
    bool missing = false;            // no such file (the model's reader has said so)
};

// The image in `bytes`, by its first bytes' signature; `error` set for anything else or a
// broken file (never throws, never reads past the bytes).
TextureImage decodeImage(std::string_view bytes);

// The image of the file at `path`, read once and kept while the file's size and time stay the
// same; one with `error` set (naming the file) when it cannot be read.
std::shared_ptr<const TextureImage> textureImage(const std::string& path);

// The image as a file an exporter embeds or puts beside a model: a PNG or JPEG file's own bytes
// (`mime` image/png, image/jpeg), anything else (SGI) encoded as a PNG; "" when the file cannot
// be read.
std::string imageFileBytes(const std::string& path, std::string& mime);

// The textured vertices of `m` (its texcoords) in their colour times their image's average
// (`textures`: Geometry::textures), for pictures drawn without the images (a moving frame's
// coarse bake); an image that cannot be read leaves the colour.
struct BakedMesh;
void tintTextured(BakedMesh& m, const std::vector<std::string>& textures);

}  // namespace sprout::mesh
