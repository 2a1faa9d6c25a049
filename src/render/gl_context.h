// The one file that knows how a GL context is made: an off-screen OSMesa core-profile context
// (software rendering, no X server, no GPU). Mesa dropped OSMesa after 25.0; an EGL surfaceless
// backend would replace only gl_context.cc.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace hexgait {

class GlContext {
 public:
  // Creates a GL 3.3 core context with a small default framebuffer (rendering goes to
  // framebuffer objects). Returns nullptr and fills `error` if none can be made.
  static std::unique_ptr<GlContext> Create(std::string* error);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  std::string Describe() const;  // renderer and version strings

 private:
  GlContext() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hexgait
