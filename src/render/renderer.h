// Draws meshes into an off-screen framebuffer and reads the frame back. Needs a current GL
// context (GlContext). Knows nothing about creatures: scene.h turns a simulation state into
// meshes.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "render/png_io.h"

namespace hexgait {

struct Mesh {
  // kShadow: unlit, checker-patterned, pre-darkened polygons lying on the ground.
  // kDecal: unlit, checker-patterned marks on the ground (footprints, trails), drawn over what is
  // already there without a depth test, so they cannot flicker against the ground plane; drawn
  // before the creature, which then covers them where it stands in front.
  enum class Kind { kLitTriangles, kGround, kShadow, kDecal, kLines, kPoints };
  Kind kind = Kind::kLitTriangles;
  // Interleaved per vertex: position (3), normal (3), colour (3).
  std::vector<float> vertices;
  void Add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, const Eigen::Vector3f& c) {
    vertices.insert(vertices.end(),
                    {p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), c.x(), c.y(), c.z()});
  }
  int count() const { return static_cast<int>(vertices.size() / 9); }
};

struct Lighting {
  Eigen::Vector3f direction = Eigen::Vector3f(0.35f, -0.45f, 0.82f).normalized();  // to the light
  float ambient = 0.35f;
  Eigen::Vector3f background = Eigen::Vector3f(0.86f, 0.90f, 0.95f);
};

class Renderer {
 public:
  // `samples` > 1 renders with that many MSAA samples per pixel and resolves them before
  // read-back; 0 or 1 renders one sample. Returns nullptr and fills `error` if the
  // framebuffer or shaders cannot be made.
  static std::unique_ptr<Renderer> Create(int width, int height, int samples, std::string* error);
  ~Renderer();

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  // Draws the meshes in order (depth-tested) and returns the frame, top row first.
  Image Render(const std::vector<Mesh>& meshes, const Eigen::Matrix4f& view_projection,
               const Lighting& lighting);
  // The same, into `image` (resized if needed), so a movie reuses one buffer for every frame.
  void Render(const std::vector<Mesh>& meshes, const Eigen::Matrix4f& view_projection,
              const Lighting& lighting, Image& image);
  // Render in two halves, for a caller with other work to overlap with the drawing: Draw
  // hands the frame to GL and returns while it is drawn (llvmpipe's threads; a GPU); ReadBack
  // waits for it and reads it into `image`. Each Draw needs its ReadBack before the next Draw.
  void Draw(const std::vector<Mesh>& meshes, const Eigen::Matrix4f& view_projection,
            const Lighting& lighting);
  void ReadBack(Image& image);

 private:
  Renderer() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_ = 0, height_ = 0, samples_ = 1;
};

// Camera matrices (right-handed, z up in the world).
Eigen::Matrix4f LookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up);
Eigen::Matrix4f Perspective(float fov_y_degrees, float aspect, float near, float far);

}  // namespace hexgait
