// The C functions the renderer calls from Mesa (OSMesa, EGL), FreeType and libpng, each library
// opened the first time something draws, writes a PNG or sets a caption (util/shared_library.h).
// A function keeps its own name and declared type: `OsMesa(&error)->OSMesaMakeCurrent(...)`.
#pragma once

#include <EGL/egl.h>
#include <GL/osmesa.h>
#include <ft2build.h>
#include <png.h>
#include FT_FREETYPE_H

#include <string>

namespace hexgait {

#define HEXGAIT_OSMESA_FUNCTIONS(X) \
  X(OSMesaCreateContextAttribs)     \
  X(OSMesaDestroyContext)           \
  X(OSMesaGetProcAddress)           \
  X(OSMesaMakeCurrent)

#define HEXGAIT_EGL_FUNCTIONS(X) \
  X(eglGetProcAddress)           \
  X(eglInitialize)               \
  X(eglQueryString)              \
  X(eglBindAPI)                  \
  X(eglCreateContext)            \
  X(eglMakeCurrent)              \
  X(eglDestroyContext)

#define HEXGAIT_FREETYPE_FUNCTIONS(X) \
  X(FT_Init_FreeType)                 \
  X(FT_Done_FreeType)                 \
  X(FT_New_Face)                      \
  X(FT_Done_Face)                     \
  X(FT_Set_Pixel_Sizes)               \
  X(FT_Load_Char)

#define HEXGAIT_PNG_FUNCTIONS(X)    \
  X(png_image_begin_read_from_file) \
  X(png_image_finish_read)          \
  X(png_image_free)                 \
  X(png_image_write_to_stdio)

#define HEXGAIT_LIBRARY_POINTER(function) decltype(&::function) function = nullptr;
struct OsMesaApi {
  HEXGAIT_OSMESA_FUNCTIONS(HEXGAIT_LIBRARY_POINTER)
};
struct EglApi {
  HEXGAIT_EGL_FUNCTIONS(HEXGAIT_LIBRARY_POINTER)
};
struct FreeTypeApi {
  HEXGAIT_FREETYPE_FUNCTIONS(HEXGAIT_LIBRARY_POINTER)
};
struct PngApi {
  HEXGAIT_PNG_FUNCTIONS(HEXGAIT_LIBRARY_POINTER)
};
#undef HEXGAIT_LIBRARY_POINTER

// Each loads its library once per process; nullptr with `error` naming the library and its
// Debian package when it is missing.
const OsMesaApi* OsMesa(std::string* error);
const EglApi* Egl(std::string* error);
const FreeTypeApi* FreeType(std::string* error);
// Throws InputError instead.
const PngApi& Png();

}  // namespace hexgait
