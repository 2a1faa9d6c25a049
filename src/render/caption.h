// Captions drawn onto rendered frames with a real font: glyphs are rasterised once with
// FreeType (DejaVu Sans, Debian's fonts-dejavu-core) and blended onto the image on the CPU,
// which costs a few microseconds per frame and needs nothing from GL.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "render/png_io.h"

namespace hexgait {

class CaptionFont {
 public:
  // Loads the font file (empty: the first DejaVu Sans found in the usual Debian places) at a
  // pixel height; returns nullptr and fills `error` when it cannot.
  static std::unique_ptr<CaptionFont> Create(int pixel_height, const std::string& font_path,
                                             std::string* error);

  int line_height() const { return line_height_; }
  int TextWidth(const std::string& text) const;
  // Draws lines of text in `colour` (RGB) at (x, y) = top-left of the first line, over a
  // translucent dark box so the caption reads on any background. Characters outside printable
  // ASCII are drawn as '?'. Clips at the image's edges.
  void DrawBox(Image& image, int x, int y, const std::vector<std::string>& lines) const;
  // One line of white text with its top at y, no box (for labels over a box already drawn).
  void DrawLine(Image& image, int x, int y, const std::string& text) const {
    DrawText(image, x, y + ascender_, text);
  }

 private:
  struct Glyph {
    int width = 0, rows = 0, left = 0, top = 0, advance = 0;
    std::vector<uint8_t> coverage;  // rows x width, 0..255
  };
  const Glyph& GlyphFor(char c) const;
  void DrawText(Image& image, int x, int baseline, const std::string& text) const;

  std::array<Glyph, 95> glyphs_;  // ' ' .. '~'
  int ascender_ = 0, line_height_ = 0;
};

// The DejaVu Sans file this machine has, or an empty string.
std::string FindCaptionFont();

}  // namespace hexgait
