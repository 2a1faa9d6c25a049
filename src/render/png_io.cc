#include "render/png_io.h"

#include <cerrno>
#include <cstring>

#include "render/render_libraries.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {
namespace {

// Owns a png_image's internal state (png_image_free is safe to call twice).
// Loads libpng first, so a missing library throws before anything needs freeing.
struct PngImageOwner {
  const PngApi& api = Png();
  png_image image;
  PngImageOwner() {
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
  }
  ~PngImageOwner() { api.png_image_free(&image); }
};

}  // namespace

void WritePng(const std::string& path, const Image& image) {
  AtomicFile file(path);
  PngImageOwner png;
  png.image.width = static_cast<png_uint_32>(image.width);
  png.image.height = static_cast<png_uint_32>(image.height);
  png.image.format = PNG_FORMAT_RGBA;
  errno = 0;
  if (!png.api.png_image_write_to_stdio(&png.image, file.handle(), 0, image.rgba.data(), 0,
                                        nullptr)) {
    // The image is valid, so the file is what failed (a full disk): libpng's "Write Error"
    // says less than the system's reason.
    const std::string reason = errno != 0 ? std::strerror(errno) : png.image.message;
    throw StorageError("writing PNG '" + path + "' failed: " + reason);
  }
  file.Commit();
}

Image ReadPng(const std::string& path) {
  PngImageOwner png;
  if (!png.api.png_image_begin_read_from_file(&png.image, path.c_str())) {
    throw InputError("'" + path + "': cannot read PNG: " + png.image.message);
  }
  png.image.format = PNG_FORMAT_RGBA;
  Image out;
  out.width = static_cast<int>(png.image.width);
  out.height = static_cast<int>(png.image.height);
  out.rgba.resize(PNG_IMAGE_SIZE(png.image));
  if (!png.api.png_image_finish_read(&png.image, nullptr, out.rgba.data(), 0, nullptr)) {
    throw InputError("'" + path + "': cannot decode PNG: " + png.image.message);
  }
  return out;
}

}  // namespace hexgait
