// RGBA -> yuv420p (BT.709, limited range, chroma averaged over each 2x2 block): the colour
// conversion of every movie frame. swscale has no unscaled path for RGBA input (its generic
// scaler took 6.9 ms a 1280x720 frame here, half the renderer's time); this is integer
// arithmetic the compiler vectorises, exact and the same bits on every machine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "image/image.h"

namespace hexgait {

// `rgba`: width x height pixels, `rgba_stride` bytes apart row to row, top row first; width
// and height even. Writes the Y plane (width x height) and the U and V planes (half each way).
void RgbaToYuv420(const uint8_t* rgba, int rgba_stride, int width, int height, uint8_t* y,
                  int y_stride, uint8_t* u, int u_stride, uint8_t* v, int v_stride);

// One yuv420p frame in one buffer: the Y plane, then U, then V, rows packed.
struct Yuv420Frame {
  int width = 0, height = 0;
  std::vector<uint8_t> data;

  void Resize(int w, int h) {
    width = w;
    height = h;
    data.resize(static_cast<size_t>(w) * h * 3 / 2);
  }
  uint8_t* plane(int p) {
    const size_t luma = static_cast<size_t>(width) * height;
    return data.data() + (p == 0 ? 0 : p == 1 ? luma : luma + luma / 4);
  }
  const uint8_t* plane(int p) const { return const_cast<Yuv420Frame*>(this)->plane(p); }
  int stride(int p) const { return p == 0 ? width : width / 2; }
};

// `image` into `frame` (resized to match).
void RgbaToYuv420(const Image& image, Yuv420Frame* frame);

// The inverse, for reading movies back: yuv420p planes (Y, U, V with their strides) to an opaque
// RGBA image of width x height (resized to match), each chroma sample shared by its 2x2 block.
void Yuv420ToRgba(const uint8_t* const planes[3], const int strides[3], int width, int height,
                  Image* image);

}  // namespace hexgait
