// PNG files through libpng's simplified API.
#pragma once

#include <string>

#include "image/image.h"

namespace hexgait {

// Writes atomically (temporary file, then rename); throws InputError on failure.
void WritePng(const std::string& path, const Image& image);
// Reads any PNG as 8-bit RGBA; throws InputError naming the file on failure.
Image ReadPng(const std::string& path);

}  // namespace hexgait
