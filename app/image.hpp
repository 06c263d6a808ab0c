#pragma once
// PNG files through libpng: RGBA, with optional text chunks (the grammar travels inside
// the PNG so it can be reopened).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sprout {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // top row first
    std::vector<std::pair<std::string, std::string>> text;  // keyword, UTF-8 text
};

bool writePng(const std::string& path, const Image& image, std::string& error);
bool readPng(const std::string& path, Image& image, std::string& error);

}  // namespace sprout
