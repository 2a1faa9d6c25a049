// The golden-image rule, written once: how far an image (or a movie frame) may be from the
// approved one. The project's own golden tests, `hexgait compare` and `--expect` all use it.
//
// Why these defaults: Mesa's llvmpipe draws the same frame bit for bit across runs and thread
// counts, but on other CPU features it moves at most 321 pixels of a 320x240 frame by one level
// (anti-aliased overlay lines) and at most one pixel by more (39 levels). So a pixel differs
// only when a channel moves by more than 24 levels, and an image fails only when more than 0.02%
// of its pixels differ (15 of 320x240, 15 times the worst case measured), while a changed digit
// in a caption, a creature moved by a pixel or a missing shadow changes tens to thousands.
#pragma once

#include "image/image.h"

namespace hexgait {

struct ImageTolerance {
  int pixel_threshold = 24;                // levels of 255 a channel may move, 0..255
  double max_different_fraction = 0.0002;  // of all pixels, 0..1
};

struct ImageDifference {
  long long different_pixels = 0;  // pixels with a channel off by more than the threshold
  long long pixels = 0;
  int max_difference = 0;  // the largest change of any channel, 0..255
  bool within = true;      // different_pixels is at most the tolerated fraction
  Image diff;              // differing pixels in red over a faded copy of the expected image

  double fraction() const { return pixels ? static_cast<double>(different_pixels) / pixels : 0; }
};

// Compares RGB (alpha ignored) of two images of the same size; throws InputError otherwise.
ImageDifference CompareImages(const Image& expected, const Image& actual,
                              const ImageTolerance& tolerance);

// Throws InputError naming the flag when a tolerance is out of its range.
void CheckImageTolerance(const ImageTolerance& tolerance);

}  // namespace hexgait
