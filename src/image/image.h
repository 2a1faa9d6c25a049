// An RGBA image in memory: what the renderer produces, the PNG writer and the video encoder
// consume. Below render and encode, so encode needs no render.
#pragma once

#include <cstdint>
#include <vector>

namespace hexgait {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // top row first
};

}  // namespace hexgait
