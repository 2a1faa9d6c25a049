#include "render/renderer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "embedded_shaders.h"

namespace hexgait {
namespace {

// Owns one GL object name; `Delete` frees it.
template <void (*Delete)(GLuint)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint name) : name_(name) {}
  ~GlName() {
    if (name_ != 0) Delete(name_);
  }
  GlName(GlName&& other) noexcept : name_(other.name_) { other.name_ = 0; }
  GlName& operator=(GlName&& other) noexcept {
    std::swap(name_, other.name_);
    return *this;
  }
  GLuint get() const { return name_; }

 private:
  GLuint name_ = 0;
};

void DeleteBuffer(GLuint n) {
  glDeleteBuffers(1, &n);
}
void DeleteVertexArray(GLuint n) {
  glDeleteVertexArrays(1, &n);
}
void DeleteFramebuffer(GLuint n) {
  glDeleteFramebuffers(1, &n);
}
void DeleteRenderbuffer(GLuint n) {
  glDeleteRenderbuffers(1, &n);
}
void DeleteProgram(GLuint n) {
  glDeleteProgram(n);
}
void DeleteShader(GLuint n) {
  glDeleteShader(n);
}

using Buffer = GlName<DeleteBuffer>;
using VertexArray = GlName<DeleteVertexArray>;
using Framebuffer = GlName<DeleteFramebuffer>;
using Renderbuffer = GlName<DeleteRenderbuffer>;
using Program = GlName<DeleteProgram>;
using Shader = GlName<DeleteShader>;

// Compiles one shader stage; on failure returns 0 and puts the GL log in `error`.
Shader Compile(GLenum stage, const char* source, const char* name, std::string* error) {
  Shader shader(glCreateShader(stage));
  glShaderSource(shader.get(), 1, &source, nullptr);
  glCompileShader(shader.get());
  GLint ok = 0;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader.get(), sizeof log, nullptr, log);
    *error = std::string("shader ") + name + " does not compile: " + log;
    return Shader();
  }
  return shader;
}

// A framebuffer with colour and depth renderbuffers, multisampled when samples > 1.
struct Target {
  Framebuffer framebuffer;
  Renderbuffer colour, depth;
};

bool MakeTarget(int width, int height, int samples, bool with_depth, Target* target) {
  GLuint name = 0;
  glGenFramebuffers(1, &name);
  target->framebuffer = Framebuffer(name);
  glBindFramebuffer(GL_FRAMEBUFFER, name);
  const auto storage = [&](GLenum format) {
    if (samples > 1) {
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
      glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
  };
  glGenRenderbuffers(1, &name);
  target->colour = Renderbuffer(name);
  glBindRenderbuffer(GL_RENDERBUFFER, name);
  storage(GL_RGBA8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, name);
  if (with_depth) {
    glGenRenderbuffers(1, &name);
    target->depth = Renderbuffer(name);
    glBindRenderbuffer(GL_RENDERBUFFER, name);
    storage(GL_DEPTH_COMPONENT24);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, name);
  }
  return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace

struct Renderer::Impl {
  Target draw;     // what the meshes are drawn into
  Target resolve;  // single-sample copy of `draw` for read-back; unused without MSAA
  Program program;
  VertexArray vertex_array;
  Buffer vertex_buffer;
  GLint view_projection = -1, light_direction = -1, ambient = -1, checker = -1, point_size = -1;
};

std::unique_ptr<Renderer> Renderer::Create(int width, int height, int samples, std::string* error) {
  auto impl = std::make_unique<Impl>();
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::max(samples, 1);
  if (samples > max_samples && samples > 1) {
    char text[80];
    std::snprintf(text, sizeof text, "this OpenGL supports at most %d MSAA samples", max_samples);
    *error = text;
    return nullptr;
  }
  if (!MakeTarget(width, height, samples, true, &impl->draw) ||
      (samples > 1 && !MakeTarget(width, height, 1, false, &impl->resolve))) {
    *error = "the off-screen framebuffer is incomplete";
    return nullptr;
  }
  const Shader vertex = Compile(GL_VERTEX_SHADER, kShader_creature_vert, "creature.vert", error);
  if (vertex.get() == 0) return nullptr;
  const Shader fragment =
      Compile(GL_FRAGMENT_SHADER, kShader_creature_frag, "creature.frag", error);
  if (fragment.get() == 0) return nullptr;
  impl->program = Program(glCreateProgram());
  glAttachShader(impl->program.get(), vertex.get());
  glAttachShader(impl->program.get(), fragment.get());
  glLinkProgram(impl->program.get());
  GLint ok = 0;
  glGetProgramiv(impl->program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(impl->program.get(), sizeof log, nullptr, log);
    *error = std::string("shaders do not link: ") + log;
    return nullptr;
  }
  const GLuint p = impl->program.get();
  impl->view_projection = glGetUniformLocation(p, "view_projection");
  impl->light_direction = glGetUniformLocation(p, "light_direction");
  impl->ambient = glGetUniformLocation(p, "ambient");
  impl->checker = glGetUniformLocation(p, "checker");
  impl->point_size = glGetUniformLocation(p, "point_size");

  GLuint name = 0;
  glGenVertexArrays(1, &name);
  impl->vertex_array = VertexArray(name);
  glBindVertexArray(name);
  glGenBuffers(1, &name);
  impl->vertex_buffer = Buffer(name);
  glBindBuffer(GL_ARRAY_BUFFER, name);
  const GLsizei stride = 9 * sizeof(float);
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexAttribArray(attribute);
    glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(attribute * 3 * sizeof(float)));
  }
  std::unique_ptr<Renderer> renderer(new Renderer());
  renderer->impl_ = std::move(impl);
  renderer->width_ = width;
  renderer->height_ = height;
  renderer->samples_ = samples;
  return renderer;
}

Renderer::~Renderer() = default;

Image Renderer::Render(const std::vector<Mesh>& meshes, const Eigen::Matrix4f& view_projection,
                       const Lighting& lighting) {
  Image image;
  Render(meshes, view_projection, lighting, image);
  return image;
}

void Renderer::Render(const std::vector<Mesh>& meshes, const Eigen::Matrix4f& view_projection,
                      const Lighting& lighting, Image& image) {
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->draw.framebuffer.get());
  glViewport(0, 0, width_, height_);
  glClearColor(lighting.background.x(), lighting.background.y(), lighting.background.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(impl_->program.get());
  // Particles scale with the frame so the overlay reads the same at any size.
  glUniform1f(impl_->point_size, std::fmax(3.0f, static_cast<float>(height_) / 90.0f));
  glUniformMatrix4fv(impl_->view_projection, 1, GL_FALSE, view_projection.data());
  glUniform3fv(impl_->light_direction, 1, lighting.direction.data());
  glBindVertexArray(impl_->vertex_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, impl_->vertex_buffer.get());
  for (const Mesh& mesh : meshes) {
    if (mesh.count() == 0) continue;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)),
                 mesh.vertices.data(), GL_STREAM_DRAW);
    const bool lit = mesh.kind == Mesh::Kind::kLitTriangles || mesh.kind == Mesh::Kind::kGround;
    glUniform1f(impl_->ambient, lit ? lighting.ambient : 1.0f);
    const bool on_ground = mesh.kind == Mesh::Kind::kGround || mesh.kind == Mesh::Kind::kShadow ||
                           mesh.kind == Mesh::Kind::kDecal;
    glUniform1i(impl_->checker, on_ground ? 1 : 0);
    // Overlays are drawn over the polygons they belong to, as in the paper's Figure 1.
    if (mesh.kind == Mesh::Kind::kLines || mesh.kind == Mesh::Kind::kPoints ||
        mesh.kind == Mesh::Kind::kDecal) {
      glDisable(GL_DEPTH_TEST);
    }
    const GLenum mode = mesh.kind == Mesh::Kind::kLines    ? GL_LINES
                        : mesh.kind == Mesh::Kind::kPoints ? GL_POINTS
                                                           : GL_TRIANGLES;
    glDrawArrays(mode, 0, mesh.count());
    glEnable(GL_DEPTH_TEST);
  }
  if (samples_ > 1) {
    // Average the samples of every pixel into the single-sample target, then read that.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->draw.framebuffer.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, impl_->resolve.framebuffer.get());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, impl_->resolve.framebuffer.get());
  }
  image.width = width_;
  image.height = height_;
  image.rgba.resize(static_cast<size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's rows run bottom-up; images are stored top row first.
  const size_t row = static_cast<size_t>(width_) * 4;
  for (int y = 0; y < height_ / 2; ++y) {
    std::swap_ranges(image.rgba.begin() + y * row, image.rgba.begin() + (y + 1) * row,
                     image.rgba.begin() + (height_ - 1 - y) * row);
  }
}

Eigen::Matrix4f LookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up) {
  const Eigen::Vector3f f = (target - eye).normalized();
  const Eigen::Vector3f s = f.cross(up).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4f Perspective(float fov_y_degrees, float aspect, float near, float far) {
  const float t = 1.0f / std::tan(fov_y_degrees * static_cast<float>(M_PI) / 360.0f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2.0f * far * near / (near - far);
  m(3, 2) = -1.0f;
  return m;
}

}  // namespace hexgait
