#include "render/renderer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "embedded_shaders.h"
#include "render/gl_api.h"

namespace hexgait {
namespace {

// Owns one GL object name; `Delete` frees it through the context's table.
template <void (*Delete)(const GlApi&, GLuint)>
class GlName {
 public:
  GlName() = default;
  GlName(const GlApi& gl, GLuint name) : gl_(&gl), name_(name) {}
  ~GlName() {
    if (name_ != 0) Delete(*gl_, name_);
  }
  GlName(GlName&& other) noexcept : gl_(other.gl_), name_(other.name_) { other.name_ = 0; }
  GlName& operator=(GlName&& other) noexcept {
    std::swap(gl_, other.gl_);
    std::swap(name_, other.name_);
    return *this;
  }
  GLuint get() const { return name_; }

 private:
  const GlApi* gl_ = nullptr;
  GLuint name_ = 0;
};

void DeleteBuffer(const GlApi& gl, GLuint n) {
  gl.DeleteBuffers(1, &n);
}
void DeleteVertexArray(const GlApi& gl, GLuint n) {
  gl.DeleteVertexArrays(1, &n);
}
void DeleteFramebuffer(const GlApi& gl, GLuint n) {
  gl.DeleteFramebuffers(1, &n);
}
void DeleteRenderbuffer(const GlApi& gl, GLuint n) {
  gl.DeleteRenderbuffers(1, &n);
}
void DeleteProgram(const GlApi& gl, GLuint n) {
  gl.DeleteProgram(n);
}
void DeleteShader(const GlApi& gl, GLuint n) {
  gl.DeleteShader(n);
}

using Buffer = GlName<DeleteBuffer>;
using VertexArray = GlName<DeleteVertexArray>;
using Framebuffer = GlName<DeleteFramebuffer>;
using Renderbuffer = GlName<DeleteRenderbuffer>;
using Program = GlName<DeleteProgram>;
using Shader = GlName<DeleteShader>;

// Compiles one shader stage; on failure returns 0 and puts the GL log in `error`.
Shader Compile(const GlApi& gl, GLenum stage, const char* source, const char* name,
               std::string* error) {
  Shader shader(gl, gl.CreateShader(stage));
  gl.ShaderSource(shader.get(), 1, &source, nullptr);
  gl.CompileShader(shader.get());
  GLint ok = 0;
  gl.GetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetShaderInfoLog(shader.get(), sizeof log, nullptr, log);
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

bool MakeTarget(const GlApi& gl, int width, int height, int samples, bool with_depth,
                Target* target) {
  GLuint name = 0;
  gl.GenFramebuffers(1, &name);
  target->framebuffer = Framebuffer(gl, name);
  gl.BindFramebuffer(GL_FRAMEBUFFER, name);
  const auto storage = [&](GLenum format) {
    if (samples > 1) {
      gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
      gl.RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
  };
  gl.GenRenderbuffers(1, &name);
  target->colour = Renderbuffer(gl, name);
  gl.BindRenderbuffer(GL_RENDERBUFFER, name);
  storage(GL_RGBA8);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, name);
  if (with_depth) {
    gl.GenRenderbuffers(1, &name);
    target->depth = Renderbuffer(gl, name);
    gl.BindRenderbuffer(GL_RENDERBUFFER, name);
    storage(GL_DEPTH_COMPONENT24);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, name);
  }
  return gl.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace

struct Renderer::Impl {
  const GlApi* gl = nullptr;  // the table of the context current at Create
  Target draw;                // what the meshes are drawn into
  Target resolve;             // single-sample copy of `draw` for read-back; unused without MSAA
  Program program;
  VertexArray vertex_array;
  Buffer vertex_buffer;
  GLint view_projection = -1, light_direction = -1, ambient = -1, checker = -1, point_size = -1;
};

std::unique_ptr<Renderer> Renderer::Create(int width, int height, int samples, std::string* error) {
  const GlApi* api = CurrentGlApi();
  if (!api) {
    *error = "no OpenGL context is current (GlContext::Create)";
    return nullptr;
  }
  const GlApi& gl = *api;
  auto impl = std::make_unique<Impl>();
  impl->gl = api;
  GLint max_samples = 0;
  gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::max(samples, 1);
  if (samples > max_samples && samples > 1) {
    char text[80];
    std::snprintf(text, sizeof text, "this OpenGL supports at most %d MSAA samples", max_samples);
    *error = text;
    return nullptr;
  }
  if (!MakeTarget(gl, width, height, samples, true, &impl->draw) ||
      (samples > 1 && !MakeTarget(gl, width, height, 1, false, &impl->resolve))) {
    *error = "the off-screen framebuffer is incomplete";
    return nullptr;
  }
  const Shader vertex =
      Compile(gl, GL_VERTEX_SHADER, kShader_creature_vert, "creature.vert", error);
  if (vertex.get() == 0) return nullptr;
  const Shader fragment =
      Compile(gl, GL_FRAGMENT_SHADER, kShader_creature_frag, "creature.frag", error);
  if (fragment.get() == 0) return nullptr;
  impl->program = Program(gl, gl.CreateProgram());
  gl.AttachShader(impl->program.get(), vertex.get());
  gl.AttachShader(impl->program.get(), fragment.get());
  gl.LinkProgram(impl->program.get());
  GLint ok = 0;
  gl.GetProgramiv(impl->program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetProgramInfoLog(impl->program.get(), sizeof log, nullptr, log);
    *error = std::string("shaders do not link: ") + log;
    return nullptr;
  }
  const GLuint p = impl->program.get();
  impl->view_projection = gl.GetUniformLocation(p, "view_projection");
  impl->light_direction = gl.GetUniformLocation(p, "light_direction");
  impl->ambient = gl.GetUniformLocation(p, "ambient");
  impl->checker = gl.GetUniformLocation(p, "checker");
  impl->point_size = gl.GetUniformLocation(p, "point_size");

  GLuint name = 0;
  gl.GenVertexArrays(1, &name);
  impl->vertex_array = VertexArray(gl, name);
  gl.BindVertexArray(name);
  gl.GenBuffers(1, &name);
  impl->vertex_buffer = Buffer(gl, name);
  gl.BindBuffer(GL_ARRAY_BUFFER, name);
  const GLsizei stride = 9 * sizeof(float);
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    gl.EnableVertexAttribArray(attribute);
    gl.VertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, stride,
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
  Draw(meshes, view_projection, lighting);
  ReadBack(image);
}

void Renderer::Draw(const std::vector<Mesh>& meshes, const Eigen::Matrix4f& view_projection,
                    const Lighting& lighting) {
  const GlApi& gl = *impl_->gl;
  gl.BindFramebuffer(GL_FRAMEBUFFER, impl_->draw.framebuffer.get());
  gl.Viewport(0, 0, width_, height_);
  gl.ClearColor(lighting.background.x(), lighting.background.y(), lighting.background.z(), 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Enable(GL_DEPTH_TEST);
  gl.Enable(GL_PROGRAM_POINT_SIZE);
  gl.UseProgram(impl_->program.get());
  // Particles scale with the frame so the overlay reads the same at any size.
  gl.Uniform1f(impl_->point_size, std::fmax(3.0f, static_cast<float>(height_) / 90.0f));
  // Drawn upside down (clip-space y negated), so GL's bottom-up rows read back as the image's
  // top-first rows with no flip afterwards. Nothing is culled, so the reversed winding is moot.
  Eigen::Matrix4f upside_down = view_projection;
  upside_down.row(1) *= -1.0f;
  gl.UniformMatrix4fv(impl_->view_projection, 1, GL_FALSE, upside_down.data());
  gl.Uniform3fv(impl_->light_direction, 1, lighting.direction.data());
  gl.BindVertexArray(impl_->vertex_array.get());
  gl.BindBuffer(GL_ARRAY_BUFFER, impl_->vertex_buffer.get());
  for (const Mesh& mesh : meshes) {
    if (mesh.count() == 0) continue;
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)),
                  mesh.vertices.data(), GL_STREAM_DRAW);
    const bool lit = mesh.kind == Mesh::Kind::kLitTriangles || mesh.kind == Mesh::Kind::kGround;
    gl.Uniform1f(impl_->ambient, lit ? lighting.ambient : 1.0f);
    const bool on_ground = mesh.kind == Mesh::Kind::kGround || mesh.kind == Mesh::Kind::kShadow ||
                           mesh.kind == Mesh::Kind::kDecal;
    gl.Uniform1i(impl_->checker, on_ground ? 1 : 0);
    // Overlays are drawn over the polygons they belong to, as in the paper's Figure 1.
    if (mesh.kind == Mesh::Kind::kLines || mesh.kind == Mesh::Kind::kPoints ||
        mesh.kind == Mesh::Kind::kDecal) {
      gl.Disable(GL_DEPTH_TEST);
    }
    const GLenum mode = mesh.kind == Mesh::Kind::kLines    ? GL_LINES
                        : mesh.kind == Mesh::Kind::kPoints ? GL_POINTS
                                                           : GL_TRIANGLES;
    gl.DrawArrays(mode, 0, mesh.count());
    gl.Enable(GL_DEPTH_TEST);
  }
  if (samples_ > 1) {
    // Average the samples of every pixel into the single-sample target, then read that.
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, impl_->draw.framebuffer.get());
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, impl_->resolve.framebuffer.get());
    gl.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                       GL_NEAREST);
    gl.BindFramebuffer(GL_FRAMEBUFFER, impl_->resolve.framebuffer.get());
  }
  gl.Flush();  // starts the drawing now, not at the read-back
}

void Renderer::ReadBack(Image& image) {
  const GlApi& gl = *impl_->gl;
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, samples_ > 1 ? impl_->resolve.framebuffer.get()
                                                       : impl_->draw.framebuffer.get());
  image.width = width_;
  image.height = height_;
  image.rgba.resize(static_cast<size_t>(width_) * height_ * 4);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
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
