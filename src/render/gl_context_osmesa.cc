// The OSMesa backend: Mesa's off-screen software renderer (llvmpipe), no display, no GPU.
// Removed from Mesa in 25.1; Debian 12 has it.
#include <vector>

#include "render/gl_context.h"
#include "render/render_libraries.h"

namespace hexgait {

namespace {

void* OsMesaProc(const char* name) {
  std::string unused;
  return reinterpret_cast<void*>(OsMesa(&unused)->OSMesaGetProcAddress(name));
}

class OsMesaContext : public GlContext {
 public:
  OsMesaContext() : GlContext("osmesa") {}
  ~OsMesaContext() override {
    if (context_) api_->OSMesaDestroyContext(context_);
  }

  bool Init(std::string* error) {
    api_ = OsMesa(error);
    if (!api_) return false;
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = api_->OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) {
      *error = "OSMesaCreateContextAttribs failed: no OpenGL 3.3 core context";
      return false;
    }
    // OSMesa needs a colour buffer to make the context current; frames go to FBOs.
    if (!api_->OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16)) {
      *error = "OSMesaMakeCurrent failed";
      return false;
    }
    return Activate(OsMesaProc, error);
  }

 private:
  const OsMesaApi* api_ = nullptr;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(16 * 16 * 4);
};

}  // namespace

std::unique_ptr<GlContext> CreateOsMesaContext(std::string* error) {
  auto context = std::make_unique<OsMesaContext>();
  if (!context->Init(error)) return nullptr;
  return context;
}

}  // namespace hexgait
