// The EGL backend: a context with no surface and no config (EGL_KHR_surfaceless_context,
// EGL_KHR_no_config_context). It first looks for a hardware device (EGL_EXT_platform_device,
// skipping Mesa's software device), which is how a headless program reaches a GPU, then falls
// back to Mesa's surfaceless platform (llvmpipe without a GPU).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

#include "render/gl_context.h"
#include "render/render_libraries.h"

namespace hexgait {

namespace {

void* EglProc(const char* name) {
  std::string unused;
  return reinterpret_cast<void*>(Egl(&unused)->eglGetProcAddress(name));
}

bool HasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

class EglContext : public GlContext {
 public:
  EglContext() : GlContext("egl") {}
  // The display stays initialised for the rest of the process, as EGL allows: it is shared by
  // every later context, and terminating it would unload Mesa's driver before LeakSanitizer
  // could name the allocations Mesa keeps (tests/support/lsan.supp).
  ~EglContext() override {
    if (display_ != EGL_NO_DISPLAY) {
      api_->eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (context_ != EGL_NO_CONTEXT) api_->eglDestroyContext(display_, context_);
    }
  }

  bool Init(std::string* error) {
    api_ = Egl(error);
    if (!api_) return false;
    const auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        api_->eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) {
      *error = "EGL has no eglGetPlatformDisplayEXT";
      return false;
    }
    std::string why;
    for (EGLDeviceEXT device : HardwareDevices()) {
      if (Open(get_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr), &why)) {
        return Activate(EglProc, error);
      }
      Close();
    }
    if (!Open(get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), &why)) {
      *error = why;
      return false;
    }
    return Activate(EglProc, error);
  }

 private:
  // GPUs EGL can open without a display: every device but Mesa's software one.
  std::vector<EGLDeviceEXT> HardwareDevices() const {
    const auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(api_->eglGetProcAddress("eglQueryDevicesEXT"));
    const auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        api_->eglGetProcAddress("eglQueryDeviceStringEXT"));
    std::vector<EGLDeviceEXT> found;
    if (!query_devices || !query_string) return found;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!query_devices(16, devices, &count)) return found;
    for (EGLint i = 0; i < count; ++i) {
      if (!HasExtension(query_string(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software")) {
        found.push_back(devices[i]);
      }
    }
    return found;
  }

  bool Open(EGLDisplay display, std::string* error) {
    display_ = display;
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !api_->eglInitialize(display_, &major, &minor)) {
      display_ = EGL_NO_DISPLAY;
      *error = "no EGL display (eglInitialize failed)";
      return false;
    }
    const char* extensions = api_->eglQueryString(display_, EGL_EXTENSIONS);
    if (!HasExtension(extensions, "EGL_KHR_no_config_context") ||
        !HasExtension(extensions, "EGL_KHR_surfaceless_context")) {
      *error = "the EGL display lacks EGL_KHR_no_config_context or EGL_KHR_surfaceless_context";
      return false;
    }
    if (!api_->eglBindAPI(EGL_OPENGL_API)) {
      *error = "EGL cannot bind the OpenGL API";
      return false;
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = api_->eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
      *error = "eglCreateContext failed: no OpenGL 3.3 core context";
      return false;
    }
    if (!api_->eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      *error = "eglMakeCurrent failed";
      return false;
    }
    return true;
  }

  void Close() {
    if (display_ == EGL_NO_DISPLAY) return;
    if (context_ != EGL_NO_CONTEXT) api_->eglDestroyContext(display_, context_);
    display_ = EGL_NO_DISPLAY;
    context_ = EGL_NO_CONTEXT;
  }

  const EglApi* api_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> CreateEglContext(std::string* error) {
  auto context = std::make_unique<EglContext>();
  if (!context->Init(error)) return nullptr;
  return context;
}

}  // namespace hexgait
