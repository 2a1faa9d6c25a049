#include "image/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "util/error.h"

namespace hexgait {

void CheckImageTolerance(const ImageTolerance& tolerance) {
  if (tolerance.pixel_threshold < 0 || tolerance.pixel_threshold > 255) {
    throw InputError("--pixel-threshold must be between 0 and 255 (levels a channel may move)");
  }
  if (!(tolerance.max_different_fraction >= 0 && tolerance.max_different_fraction <= 1)) {
    throw InputError(
        "--tolerance must be between 0 and 1 (the fraction of pixels that may differ)");
  }
}

ImageDifference CompareImages(const Image& expected, const Image& actual,
                              const ImageTolerance& tolerance) {
  if (expected.width != actual.width || expected.height != actual.height) {
    throw InputError("sizes differ: expected " + std::to_string(expected.width) + "x" +
                     std::to_string(expected.height) + ", actual " + std::to_string(actual.width) +
                     "x" + std::to_string(actual.height));
  }
  ImageDifference d;
  d.pixels = static_cast<long long>(expected.width) * expected.height;
  d.diff = expected;
  for (size_t p = 0; p < expected.rgba.size(); p += 4) {
    int worst = 0;
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, std::abs(actual.rgba[p + k] - expected.rgba[p + k]));
    }
    d.max_difference = std::max(d.max_difference, worst);
    const bool differs = worst > tolerance.pixel_threshold;
    d.different_pixels += differs;
    for (int k = 0; k < 3; ++k) {
      d.diff.rgba[p + k] =
          differs ? (k == 0 ? 255 : 0) : static_cast<uint8_t>(128 + expected.rgba[p + k] / 2);
    }
    d.diff.rgba[p + 3] = 255;
  }
  d.within = d.different_pixels <= tolerance.max_different_fraction * d.pixels;
  return d;
}

}  // namespace hexgait
