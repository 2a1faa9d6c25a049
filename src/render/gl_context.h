// An off-screen OpenGL 3.3 core context, from one of the backends: EGL (surfaceless or a GPU
// device; Mesa's replacement for OSMesa, and how a headless program reaches a GPU) or OSMesa
// (software rendering, removed from Mesa in 25.1). Which one: `--gl` (SetGlBackend), else the
// environment variable HEXGAIT_GL, else the first that works in the order of GlBackendNames().
// Each backend is one file (gl_context_<name>.cc) and one line in gl_context.cc's table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/gl_api.h"

namespace hexgait {

class GlContext {
 public:
  // Creates a context and makes it current on this thread (rendering goes to framebuffer
  // objects). Returns nullptr and fills `error` if the chosen backend, or every backend when
  // none was chosen, fails.
  static std::unique_ptr<GlContext> Create(std::string* error);
  // Create for a command: throws InputError when HEXGAIT_GL names no backend (the user's
  // setting), SystemError when no context can be made (the machine's), each message starting
  // with `what` ("cannot render").
  static std::unique_ptr<GlContext> CreateOrThrow(const std::string& what);
  virtual ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  const std::string& backend() const { return backend_; }
  const GlApi& api() const { return api_; }
  std::string Describe() const;  // "egl: llvmpipe (...), OpenGL 4.5 (Core Profile) Mesa 22.3.6"

 protected:
  explicit GlContext(std::string backend) : backend_(std::move(backend)) {}
  // For a backend's constructor: loads the table through `get_proc` and makes it this
  // thread's current one. False, with `error` set, if a function is missing.
  bool Activate(GlGetProc get_proc, std::string* error);

 private:
  std::string backend_;
  GlApi api_;
};

// "egl", "osmesa": the backends built in, in the order tried when none is chosen.
const std::vector<std::string>& GlBackendNames();
// Chooses the backend for every later Create in this process ("" = HEXGAIT_GL or the first
// that works). Throws InputError for an unknown name.
void SetGlBackend(const std::string& name);

// The backends, for gl_context.cc's table; each returns nullptr and fills `error` on failure.
std::unique_ptr<GlContext> CreateEglContext(std::string* error);
std::unique_ptr<GlContext> CreateOsMesaContext(std::string* error);

}  // namespace hexgait
