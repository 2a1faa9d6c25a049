#include "render/gl_context.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>

namespace hexgait {

struct GlContext::Impl {
  struct Destroy {
    void operator()(osmesa_context* c) const { OSMesaDestroyContext(c); }
  };
  std::unique_ptr<osmesa_context, Destroy> context;
  // OSMesa needs a colour buffer to make the context current; frames are drawn into FBOs.
  std::vector<unsigned char> buffer = std::vector<unsigned char>(16 * 16 * 4);
};

std::unique_ptr<GlContext> GlContext::Create(std::string* error) {
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
  auto impl = std::make_unique<Impl>();
  impl->context.reset(OSMesaCreateContextAttribs(attributes, nullptr));
  if (!impl->context) {
    if (error) *error = "OSMesaCreateContextAttribs failed: no OpenGL 3.3 core context";
    return nullptr;
  }
  if (!OSMesaMakeCurrent(impl->context.get(), impl->buffer.data(), GL_UNSIGNED_BYTE, 16, 16)) {
    if (error) *error = "OSMesaMakeCurrent failed";
    return nullptr;
  }
  std::unique_ptr<GlContext> context(new GlContext());
  context->impl_ = std::move(impl);
  return context;
}

GlContext::~GlContext() = default;

std::string GlContext::Describe() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

}  // namespace hexgait
