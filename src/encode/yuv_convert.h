// RGBA -> yuv420p (BT.709, limited range, chroma averaged over each 2x2 block): the colour
// conversion of every movie frame. swscale has no unscaled path for RGBA input (its generic
// scaler took 6.9 ms a 1280x720 frame here, half the renderer's time); this is integer
// arithmetic the compiler vectorises, exact and the same bits on every machine.
#pragma once

#include <cstdint>

namespace hexgait {

// `rgba`: width x height pixels, `rgba_stride` bytes apart row to row, top row first; width
// and height even. Writes the Y plane (width x height) and the U and V planes (half each way).
void RgbaToYuv420(const uint8_t* rgba, int rgba_stride, int width, int height, uint8_t* y,
                  int y_stride, uint8_t* u, int u_stride, uint8_t* v, int v_stride);

}  // namespace hexgait
