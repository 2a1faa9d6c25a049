// PNG files through libpng's simplified API.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hexgait {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // top row first
};

// Writes atomically (temporary file, then rename); throws InputError on failure.
void WritePng(const std::string& path, const Image& image);
// Reads any PNG as 8-bit RGBA; throws InputError naming the file on failure.
Image ReadPng(const std::string& path);

}  // namespace hexgait
