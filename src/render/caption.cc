#include "render/caption.h"

#include <algorithm>
#include <filesystem>

#include "render/render_libraries.h"

namespace hexgait {
namespace {

struct LibraryDeleter {
  void operator()(FT_Library library) const { ft->FT_Done_FreeType(library); }
  const FreeTypeApi* ft;
};
struct FaceDeleter {
  void operator()(FT_Face face) const { ft->FT_Done_Face(face); }
  const FreeTypeApi* ft;
};
using LibraryPtr = std::unique_ptr<FT_LibraryRec_, LibraryDeleter>;
using FacePtr = std::unique_ptr<FT_FaceRec_, FaceDeleter>;

constexpr char kFirstChar = ' ', kLastChar = '~';

}  // namespace

std::string FindCaptionFont() {
  for (const char* path :
       {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
        "/usr/share/fonts/dejavu/DejaVuSans.ttf"}) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
  }
  return "";
}

std::unique_ptr<CaptionFont> CaptionFont::Create(int pixel_height, const std::string& font_path,
                                                 std::string* error) {
  const std::string path = font_path.empty() ? FindCaptionFont() : font_path;
  if (path.empty()) {
    *error = "no DejaVu Sans font found (install Debian's fonts-dejavu-core, or turn captions off)";
    return nullptr;
  }
  const FreeTypeApi* ft = FreeType(error);
  if (!ft) return nullptr;
  FT_Library raw_library = nullptr;
  if (ft->FT_Init_FreeType(&raw_library) != 0) {
    *error = "FreeType cannot start";
    return nullptr;
  }
  const LibraryPtr library(raw_library, LibraryDeleter{ft});
  FT_Face raw_face = nullptr;
  if (ft->FT_New_Face(library.get(), path.c_str(), 0, &raw_face) != 0) {
    *error = "font '" + path + "' cannot be read by FreeType";
    return nullptr;
  }
  const FacePtr face(raw_face, FaceDeleter{ft});
  if (ft->FT_Set_Pixel_Sizes(face.get(), 0, static_cast<FT_UInt>(pixel_height)) != 0) {
    *error = "font '" + path + "' has no usable size";
    return nullptr;
  }
  std::unique_ptr<CaptionFont> font(new CaptionFont());
  font->ascender_ = static_cast<int>(face->size->metrics.ascender >> 6);
  font->line_height_ = static_cast<int>(face->size->metrics.height >> 6);
  for (char c = kFirstChar; c <= kLastChar; ++c) {
    if (ft->FT_Load_Char(face.get(), static_cast<FT_ULong>(c), FT_LOAD_RENDER) != 0) {
      *error = std::string("font '") + path + "' cannot render '" + c + "'";
      return nullptr;
    }
    const FT_GlyphSlot slot = face->glyph;
    Glyph& g = font->glyphs_[static_cast<size_t>(c - kFirstChar)];
    g.width = static_cast<int>(slot->bitmap.width);
    g.rows = static_cast<int>(slot->bitmap.rows);
    g.left = slot->bitmap_left;
    g.top = slot->bitmap_top;
    g.advance = static_cast<int>(slot->advance.x >> 6);
    g.coverage.resize(static_cast<size_t>(g.width) * g.rows);
    for (int r = 0; r < g.rows; ++r) {
      std::copy_n(slot->bitmap.buffer + r * slot->bitmap.pitch, g.width,
                  g.coverage.begin() + static_cast<ptrdiff_t>(r) * g.width);
    }
  }
  return font;
}

const CaptionFont::Glyph& CaptionFont::GlyphFor(char c) const {
  if (c < kFirstChar || c > kLastChar) c = '?';
  return glyphs_[static_cast<size_t>(c - kFirstChar)];
}

int CaptionFont::TextWidth(const std::string& text) const {
  int width = 0;
  for (char c : text) width += GlyphFor(c).advance;
  return width;
}

void CaptionFont::DrawText(Image& image, int x, int baseline, const std::string& text) const {
  for (char c : text) {
    const Glyph& g = GlyphFor(c);
    for (int r = 0; r < g.rows; ++r) {
      const int py = baseline - g.top + r;
      if (py < 0 || py >= image.height) continue;
      for (int col = 0; col < g.width; ++col) {
        const int px = x + g.left + col;
        if (px < 0 || px >= image.width) continue;
        const unsigned a = g.coverage[static_cast<size_t>(r) * g.width + col];
        if (a == 0) continue;
        uint8_t* p = &image.rgba[(static_cast<size_t>(py) * image.width + px) * 4];
        // White text: blend towards 255 by the glyph's coverage.
        for (int k = 0; k < 3; ++k)
          p[k] = static_cast<uint8_t>(p[k] + ((255u - p[k]) * a + 127) / 255);
      }
    }
    x += g.advance;
  }
}

void CaptionFont::DrawBox(Image& image, int x, int y, const std::vector<std::string>& lines) const {
  int width = 0;
  for (const std::string& line : lines) width = std::max(width, TextWidth(line));
  const int pad = std::max(2, line_height_ / 3);
  const int x0 = std::max(0, x - pad), y0 = std::max(0, y - pad);
  const int x1 = std::min(image.width, x + width + pad);
  const int y1 = std::min(image.height, y + line_height_ * static_cast<int>(lines.size()) + pad);
  // Darken the box to 40 % so white text stands out on the light ground.
  for (int py = y0; py < y1; ++py) {
    uint8_t* p = &image.rgba[(static_cast<size_t>(py) * image.width + x0) * 4];
    for (int px = x0; px < x1; ++px, p += 4) {
      for (int k = 0; k < 3; ++k) p[k] = static_cast<uint8_t>((p[k] * 2u) / 5u);
    }
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    DrawText(image, x, y + ascender_ + static_cast<int>(i) * line_height_, lines[i]);
  }
}

}  // namespace hexgait
