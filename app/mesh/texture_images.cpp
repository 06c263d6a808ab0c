// Texture images (texture_images.hpp): PNG through libpng's simplified API, JPEG through
// libjpeg, SGI's format (`.rgb`, `.sgi`, `.bw`: verbatim or run-length, 8 bits a channel, one to
// four channels) read here, as VLab's cpfg reads it (rle.c).
#include "app/mesh/texture_images.hpp"

#include "app/mesh/bake.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include <jpeglib.h>
#include <png.h>

namespace sprout::mesh {

namespace {

constexpr std::size_t kMaxPixels = std::size_t(1) << 26;  // 8192 x 8192: a texture, not a poster

TextureImage failed(std::string why) {
    TextureImage t;
    t.error = std::move(why);
    return t;
}

TextureImage decodePng(std::string_view bytes) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) return failed(std::string("a broken PNG: ") + image.message);
    if (std::size_t(image.width) * image.height > kMaxPixels || image.width == 0 || image.height == 0) {
        png_image_free(&image);
        return failed("a PNG too large for a texture");
    }
    image.format = PNG_FORMAT_RGBA;
    TextureImage t;
    t.width = int(image.width), t.height = int(image.height), t.format = "png";
    t.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, t.rgba.data(), 0, nullptr)) return failed(std::string("a broken PNG: ") + image.message);
    return t;
}

struct JpegError {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

void jpegFailed(j_common_ptr info) {
    auto* e = reinterpret_cast<JpegError*>(info->err);
    e->mgr.format_message(info, e->message);
    std::longjmp(e->jump, 1);
}

TextureImage decodeJpeg(std::string_view bytes) {
    // Before the jump point: nothing owning memory is made after it, which a jump would skip.
    TextureImage t;
    std::vector<unsigned char> row;
    jpeg_decompress_struct info;
    JpegError err;
    err.message[0] = 0;
    info.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = jpegFailed;
    err.mgr.output_message = [](j_common_ptr) {};  // warnings: not printed
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&info);
        t.rgba.clear();
        t.error = std::string("a broken JPEG: ") + err.message;
        return t;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&info, TRUE);
    if (std::size_t(info.image_width) * info.image_height > kMaxPixels) {  // before libjpeg allocates for it
        jpeg_destroy_decompress(&info);
        t.error = "a JPEG too large for a texture";
        return t;
    }
    info.out_color_space = JCS_RGB;
    jpeg_start_decompress(&info);
    if (std::size_t(info.output_width) * info.output_height > kMaxPixels || info.output_components != 3) {
        jpeg_destroy_decompress(&info);
        t.error = "a JPEG too large for a texture";
        return t;
    }
    t.width = int(info.output_width), t.height = int(info.output_height), t.format = "jpeg";
    t.rgba.assign(std::size_t(t.width) * std::size_t(t.height) * 4, 255);
    row.resize(std::size_t(t.width) * 3);
    while (info.output_scanline < info.output_height) {
        const std::size_t y = info.output_scanline;
        unsigned char* rows[] = {row.data()};
        jpeg_read_scanlines(&info, rows, 1);
        for (std::size_t x = 0; x < std::size_t(t.width); ++x)
            std::memcpy(&t.rgba[(y * std::size_t(t.width) + x) * 4], &row[x * 3], 3);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return t;
}

// SGI's image file: a 512-byte header (magic 474, storage, bytes a channel, dimension, x, y and
// z sizes, big-endian), then each channel's rows bottom first, verbatim or run-length (a
// table of each row's start and length, then runs: a count byte, its top bit set for that
// many bytes to copy, clear for the next byte repeated that many times, 0 ending the row).
TextureImage decodeSgi(std::string_view bytes) {
    auto u8 = [&](std::size_t at) { return at < bytes.size() ? std::uint8_t(bytes[at]) : std::uint8_t(0); };
    auto u16 = [&](std::size_t at) { return std::size_t(u8(at)) << 8 | u8(at + 1); };
    auto u32 = [&](std::size_t at) { return std::size_t(u16(at)) << 16 | u16(at + 2); };
    if (bytes.size() < 512) return failed("a broken SGI image: shorter than its header");
    const bool rle = u8(2) == 1;
    if (u8(3) != 1) return failed("an SGI image of 16 bits a channel (Sprout reads 8)");
    const std::size_t w = u16(6), h = u16(4 + 4), zs = u16(10) ? u16(10) : 1;
    const std::size_t dimension = u16(4);
    const std::size_t height = dimension == 1 ? 1 : h, channels = dimension < 3 ? 1 : zs;
    if (w == 0 || height == 0 || channels == 0 || channels > 4 || w * height > kMaxPixels) return failed("a broken SGI image: its size");
    TextureImage t;
    t.width = int(w), t.height = int(height), t.format = "sgi";
    t.rgba.assign(w * height * 4, 255);
    if (rle && 512 + 8 * channels * height > bytes.size()) return failed("a broken SGI image: its row table");
    std::vector<std::uint8_t> line(w);
    for (std::size_t z = 0; z < channels; ++z)
        for (std::size_t y = 0; y < height; ++y) {
            if (!rle) {
                const std::size_t at = 512 + (z * height + y) * w;
                if (at + w > bytes.size()) return failed("a broken SGI image: it ends early");
                std::memcpy(line.data(), bytes.data() + at, w);
            } else {
                std::size_t at = u32(512 + 4 * (z * height + y)), x = 0;
                for (;;) {
                    if (at >= bytes.size()) return failed("a broken SGI image: a row runs past the end");
                    const std::uint8_t c = u8(at++);
                    std::size_t n = c & 0x7F;
                    if (n == 0) break;
                    if (x + n > w) return failed("a broken SGI image: a row longer than the image");
                    if (c & 0x80) {
                        if (at + n > bytes.size()) return failed("a broken SGI image: a row runs past the end");
                        std::memcpy(line.data() + x, bytes.data() + at, n);
                        at += n;
                    } else {
                        std::memset(line.data() + x, u8(at++), n);
                    }
                    x += n;
                }
            }
            const std::size_t row = height - 1 - y;  // the file's first row is the bottom one
            for (std::size_t x = 0; x < w; ++x) {
                std::uint8_t* px = &t.rgba[(row * w + x) * 4];
                if (channels < 3 && z == 0) px[0] = px[1] = px[2] = line[x];  // grey
                else if (channels == 2 && z == 1) px[3] = line[x];
                else px[z] = line[x];
            }
        }
    return t;
}

}  // namespace

TextureImage decodeImage(std::string_view bytes) {
    TextureImage t = bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0  ? decodePng(bytes)
                     : bytes.size() >= 3 && std::memcmp(bytes.data(), "\xff\xd8\xff", 3) == 0      ? decodeJpeg(bytes)
                     : bytes.size() >= 2 && std::uint8_t(bytes[0]) == 0x01 && std::uint8_t(bytes[1]) == 0xDA ? decodeSgi(bytes)
                                                                                                     : failed("not a PNG, JPEG or SGI image");
    std::uint64_t sum[3] = {0, 0, 0}, n = 0;
    for (std::size_t k = 0; k + 3 < t.rgba.size(); k += 4)
        if (t.rgba[k + 3] >= 128) sum[0] += t.rgba[k], sum[1] += t.rgba[k + 1], sum[2] += t.rgba[k + 2], ++n;
    if (n) t.average = std::uint32_t(sum[0] / n) << 24 | std::uint32_t(sum[1] / n) << 16 | std::uint32_t(sum[2] / n) << 8 | 0xFFu;
    return t;
}

std::string imageFileBytes(const std::string& path, std::string& mime) {
    const std::shared_ptr<const TextureImage> image = textureImage(path);
    if (!image->error.empty()) return "";
    if (image->format == "png" || image->format == "jpeg") {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        mime = image->format == "png" ? "image/png" : "image/jpeg";
        return bytes.str();
    }
    png_image out;
    std::memset(&out, 0, sizeof out);
    out.version = PNG_IMAGE_VERSION;
    out.width = png_uint_32(image->width), out.height = png_uint_32(image->height), out.format = PNG_FORMAT_RGBA;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&out, nullptr, &size, 0, image->rgba.data(), 0, nullptr)) return "";
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&out, bytes.data(), &size, 0, image->rgba.data(), 0, nullptr)) return "";
    bytes.resize(size);
    mime = "image/png";
    return bytes;
}

void tintTextured(BakedMesh& m, const std::vector<std::string>& textures) {
    std::vector<std::uint32_t> average(textures.size() + 1, 0xFFFFFFFFu);
    for (std::size_t k = 0; k < textures.size(); ++k)
        if (const auto image = textureImage(textures[k]); image->error.empty()) average[k + 1] = image->average;
    for (std::size_t k = 0; k < m.texcoords.size() && k < m.vertices.size(); ++k) {
        const std::uint32_t id = m.texcoords[k].texture;
        if (id == 0 || id >= average.size()) continue;
        std::uint32_t& c = m.vertices[k].colour;
        std::uint32_t out = c & 0xFFu;
        for (int shift = 8; shift <= 24; shift += 8)
            out |= ((c >> shift & 0xFFu) * (average[id] >> shift & 0xFFu) / 255u) << shift;
        c = out;
    }
}

std::shared_ptr<const TextureImage> textureImage(const std::string& path) {
    namespace fs = std::filesystem;
    struct Kept {
        std::uintmax_t size = 0;
        fs::file_time_type time{};
        std::shared_ptr<const TextureImage> image;
    };
    static std::mutex lock;
    static std::map<std::string, Kept> kept;
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    const fs::file_time_type time = ec ? fs::file_time_type{} : fs::last_write_time(path, ec);
    std::lock_guard<std::mutex> hold(lock);
    Kept& k = kept[path];
    if (k.image && k.size == size && k.time == time) return k.image;
    auto image = std::make_shared<TextureImage>();
    if (ec) {
        image->error = "texture image '" + path + "' cannot be read";
        image->missing = true;
    } else if (size > (std::uintmax_t(1) << 28)) {
        image->error = "texture image '" + path + "' is too large";
    } else {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        *image = decodeImage(bytes.str());
        if (!image->error.empty()) image->error = "texture image '" + path + "': " + image->error;
    }
    k = {size, time, image};
    return image;
}

}  // namespace sprout::mesh
