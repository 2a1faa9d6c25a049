#include "render/gl_api.h"

namespace hexgait {

namespace {
thread_local const GlApi* current_api = nullptr;
}  // namespace

bool LoadGlApi(GlGetProc get_proc, GlApi* api, std::string* missing) {
#define HEXGAIT_GL_LOAD(name, type)                         \
  api->name = reinterpret_cast<type>(get_proc("gl" #name)); \
  if (!api->name) {                                         \
    *missing = "gl" #name;                                  \
    return false;                                           \
  }
  HEXGAIT_GL_FUNCTIONS(HEXGAIT_GL_LOAD)
#undef HEXGAIT_GL_LOAD
  return true;
}

const GlApi* CurrentGlApi() {
  return current_api;
}

void SetCurrentGlApi(const GlApi* api) {
  current_api = api;
}

}  // namespace hexgait
