#include "render/render_libraries.h"

#include "library_names.h"
#include "util/error.h"
#include "util/shared_library.h"

namespace hexgait {
namespace {

template <class Api>
struct Loaded {
  Api api;
  std::string error;  // empty when the library and every function were found
};

// Opens `name` and binds every function `bind` names; `what` says what could not be done
// without it ("cannot write PNG files"), the start of the error message ("": the caller says).
template <class Api, class BindAll>
Loaded<Api> Load(const LibraryName& name, const char* what, BindAll bind) {
  Loaded<Api> loaded;
  const SharedLibrary* library = SharedLibrary::Open(name, &loaded.error);
  if (!library) {
    if (*what) loaded.error = std::string(what) + ": " + loaded.error;
    return loaded;
  }
  bind(*library, loaded.api, &loaded.error);
  return loaded;
}

#define HEXGAIT_BIND(function) \
  if (!library.Bind(#function, api.function, why)) return;

template <class Api>
const Api* Result(const Loaded<Api>& loaded, std::string* error) {
  if (loaded.error.empty()) return &loaded.api;
  *error = loaded.error;
  return nullptr;
}

}  // namespace

const OsMesaApi* OsMesa(std::string* error) {
  static const auto loaded =
      Load<OsMesaApi>(HEXGAIT_LIBRARY_OSMESA, "cannot use the osmesa backend",
                      [](const SharedLibrary& library, OsMesaApi& api, std::string* why) {
                        HEXGAIT_OSMESA_FUNCTIONS(HEXGAIT_BIND)
                      });
  return Result(loaded, error);
}

const EglApi* Egl(std::string* error) {
  static const auto loaded =
      Load<EglApi>(HEXGAIT_LIBRARY_EGL, "cannot use the egl backend",
                   [](const SharedLibrary& library, EglApi& api, std::string* why) {
                     HEXGAIT_EGL_FUNCTIONS(HEXGAIT_BIND)
                   });
  return Result(loaded, error);
}

const FreeTypeApi* FreeType(std::string* error) {
  static const auto loaded =
      // No prefix: CaptionFont's callers say "cannot draw captions".
      Load<FreeTypeApi>(HEXGAIT_LIBRARY_FREETYPE, "",
                        [](const SharedLibrary& library, FreeTypeApi& api, std::string* why) {
                          HEXGAIT_FREETYPE_FUNCTIONS(HEXGAIT_BIND)
                        });
  return Result(loaded, error);
}

const PngApi& Png() {
  static const auto loaded =
      Load<PngApi>(HEXGAIT_LIBRARY_PNG, "cannot read or write PNG files",
                   [](const SharedLibrary& library, PngApi& api, std::string* why) {
                     HEXGAIT_PNG_FUNCTIONS(HEXGAIT_BIND)
                   });
  std::string error;
  const PngApi* api = Result(loaded, &error);
  if (!api) throw SystemError(error);
  return *api;
}

}  // namespace hexgait
