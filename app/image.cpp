#include "app/image.hpp"

#include <png.h>

#include "core/base/atomic_file.hpp"

#include <cstdio>
#include <cstring>
#include <memory>

namespace sprout {
namespace {

struct File {
    std::FILE* f = nullptr;
    ~File() {
        if (f) std::fclose(f);
    }
};

void onError(png_structp png, png_const_charp message) {
    auto* error = static_cast<std::string*>(png_get_error_ptr(png));
    if (error) *error = message;
    png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}

}  // namespace

bool writePng(const std::string& path, const Image& image, std::string& error) {
    // Through the atomic writer: a failed write never leaves half a file, a link is followed,
    // a FIFO or "-" is written directly (core/base/atomic_file.hpp).
    AtomicFile file;
    if (!file.open(path, error)) {
        error = "cannot write: " + error;
        return false;
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, onError, onWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        error = "out of memory";
        return false;
    }
    std::vector<png_bytep> rows(std::size_t(image.height));
    std::vector<png_text> texts;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;  // the AtomicFile removes its temporary
    }
    png_set_write_fn(
        png, &file,
        [](png_structp p, png_bytep data, png_size_t n) {
            auto* f = static_cast<AtomicFile*>(png_get_io_ptr(p));
            if (!f->write(data, n)) {
                // png_error does not return: no C++ object may live in this frame.
                static thread_local char message[256];
                std::snprintf(message, sizeof message, "cannot write: %s", f->error().c_str());
                png_error(p, message);
            }
        },
        [](png_structp) {});
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    for (const auto& [key, value] : image.text) {
        png_text t{};
        t.compression = PNG_ITXT_COMPRESSION_NONE;
        t.key = const_cast<char*>(key.c_str());
        t.text = const_cast<char*>(value.c_str());
        t.itxt_length = value.size();
        t.lang = nullptr;
        t.lang_key = nullptr;
        texts.push_back(t);
    }
    if (!texts.empty()) png_set_text(png, info, texts.data(), int(texts.size()));
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y)
        rows[std::size_t(y)] = const_cast<png_bytep>(image.rgba.data() + std::size_t(y) * std::size_t(image.width) * 4);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (!file.commit(error)) {
        error = "cannot write: " + error;
        return false;
    }
    return true;
}

bool readPng(const std::string& path, Image& image, std::string& error) {
    File file;
    file.f = std::fopen(path.c_str(), "rb");
    if (!file.f) {
        error = std::string("cannot open: ") + std::strerror(errno);
        return false;
    }
    unsigned char sig[8];
    if (std::fread(sig, 1, 8, file.f) != 8 || png_sig_cmp(sig, 0, 8)) {
        error = "not a PNG file";
        return false;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, onError, onWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        error = "out of memory";
        return false;
    }
    std::vector<png_bytep> rows;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        if (error.empty()) error = "damaged PNG file";
        else error = "damaged PNG file: " + error;
        return false;
    }
    png_init_io(png, file.f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    if (w > 32768 || h > 32768) png_error(png, "image too large");
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xFF, PNG_FILLER_AFTER);
    png_read_update_info(png, info);
    image.width = int(w);
    image.height = int(h);
    image.rgba.assign(std::size_t(w) * h * 4, 0);
    rows.resize(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = image.rgba.data() + std::size_t(y) * w * 4;
    png_read_image(png, rows.data());
    png_read_end(png, info);
    png_textp text = nullptr;
    int count = png_get_text(png, info, &text, nullptr);
    image.text.clear();
    for (int i = 0; i < count; ++i)
        image.text.emplace_back(text[i].key, std::string(text[i].text, text[i].itxt_length ? text[i].itxt_length : text[i].text_length));
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

}  // namespace sprout
