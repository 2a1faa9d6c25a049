#include "render/gl_context.h"

#include <cstdlib>
#include <mutex>

#include "util/error.h"

namespace hexgait {

namespace {

struct GlBackend {
  const char* name;
  std::unique_ptr<GlContext> (*create)(std::string* error);
};

// The order tried when no backend is chosen: EGL first, since it is what a GPU is reached
// through and what Mesa keeps; OSMesa as the fallback on a Mesa without EGL.
const GlBackend kBackends[] = {
    {"egl", CreateEglContext},
    {"osmesa", CreateOsMesaContext},
};

std::mutex chosen_mutex;
std::string chosen;  // from SetGlBackend; "" = not chosen

const GlBackend* FindBackend(const std::string& name) {
  for (const GlBackend& b : kBackends) {
    if (name == b.name) return &b;
  }
  return nullptr;
}

std::string NameList() {
  std::string list;
  for (const GlBackend& b : kBackends) list += (list.empty() ? "" : ", ") + std::string(b.name);
  return list;
}

}  // namespace

const std::vector<std::string>& GlBackendNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const GlBackend& b : kBackends) n.emplace_back(b.name);
    return n;
  }();
  return names;
}

void SetGlBackend(const std::string& name) {
  if (!name.empty() && !FindBackend(name)) {
    throw InputError("--gl: unknown backend '" + name + "' (choose " + NameList() + ")");
  }
  std::lock_guard<std::mutex> lock(chosen_mutex);
  chosen = name;
}

namespace {

// Create's work; `unknown_name` tells the caller the failure is a misspelt choice (the user's
// setting) rather than the machine's.
std::unique_ptr<GlContext> CreateContext(std::string* error, bool* unknown_name) {
  std::string name;
  {
    std::lock_guard<std::mutex> lock(chosen_mutex);
    name = chosen;
  }
  std::string source = "--gl";
  if (name.empty()) {
    const char* env = std::getenv("HEXGAIT_GL");
    if (env && *env) {
      name = env;
      source = "HEXGAIT_GL";
    }
  }
  std::string why;
  if (!name.empty()) {
    const GlBackend* backend = FindBackend(name);
    if (!backend) {
      if (error) *error = source + ": unknown backend '" + name + "' (choose " + NameList() + ")";
      *unknown_name = true;
      return nullptr;
    }
    auto context = backend->create(&why);
    if (!context && error) *error = name + ": " + why;
    return context;
  }
  std::string tried;
  for (const GlBackend& backend : kBackends) {
    if (auto context = backend.create(&why)) return context;
    tried += (tried.empty() ? "" : "; ") + std::string(backend.name) + ": " + why;
  }
  if (error) *error = "no OpenGL 3.3 context from any backend (" + tried + ")";
  return nullptr;
}

}  // namespace

std::unique_ptr<GlContext> GlContext::Create(std::string* error) {
  bool unknown_name = false;
  return CreateContext(error, &unknown_name);
}

std::unique_ptr<GlContext> GlContext::CreateOrThrow(const std::string& what) {
  std::string error;
  bool unknown_name = false;
  auto context = CreateContext(&error, &unknown_name);
  if (context) return context;
  if (unknown_name) throw InputError(what + ": " + error);
  throw SystemError(what + ": " + error);
}

GlContext::~GlContext() {
  if (CurrentGlApi() == &api_) SetCurrentGlApi(nullptr);
}

bool GlContext::Activate(GlGetProc get_proc, std::string* error) {
  std::string missing;
  if (!LoadGlApi(get_proc, &api_, &missing)) {
    *error = "the context has no " + missing;
    return false;
  }
  SetCurrentGlApi(&api_);
  return true;
}

std::string GlContext::Describe() const {
  const auto* renderer = reinterpret_cast<const char*>(api_.GetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(api_.GetString(GL_VERSION));
  return backend_ + ": " + (renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

}  // namespace hexgait
