#include <gtest/gtest.h>

#include <cstdio>

#include "render/camera.h"
#include "render/gl_context.h"
#include "render/meshes.h"
#include "render/png_io.h"
#include "render/renderer.h"
#include "test_util.h"

namespace hexgait {
namespace {

class RenderTest : public testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    context_ = GlContext::Create(&error);
    if (!context_) GTEST_SKIP() << "no GL context: " << error;
  }
  std::unique_ptr<GlContext> context_;
};

TEST_F(RenderTest, FlatQuadCoversExactlyTheExpectedPixels) {
  std::string error;
  auto renderer = Renderer::Create(64, 64, 1, &error);
  ASSERT_TRUE(renderer) << error;
  // An unlit quad from -0.5 to 0.5 in normalised device coordinates (identity matrix): pixel
  // centres (i + 0.5) / 32 - 1 inside it are i = 16 .. 47 in both directions.
  Mesh solid;
  solid.kind = Mesh::Kind::kLitTriangles;
  const Eigen::Vector3f n(0, 0, 1), c(1.0f, 0.0f, 0.0f);
  const Eigen::Vector3f p[4] = {
      {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
  for (int i : {0, 1, 2, 0, 2, 3}) solid.Add(p[i], n, c);
  Lighting light;
  light.ambient = 1.0f;  // no shading: the colour must come through exactly
  light.background = Eigen::Vector3f(0, 0, 1);
  const Image image = renderer->Render({solid}, Eigen::Matrix4f::Identity(), light);
  ASSERT_EQ(image.width, 64);
  int wrong = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const uint8_t* px = &image.rgba[(y * 64 + x) * 4];
      const bool inside = x >= 16 && x <= 47 && y >= 16 && y <= 47;
      const bool red = px[0] == 255 && px[1] == 0 && px[2] == 0;
      const bool blue = px[0] == 0 && px[1] == 0 && px[2] == 255;
      wrong += inside ? !red : !blue;
    }
  }
  EXPECT_EQ(wrong, 0);
}

TEST_F(RenderTest, ImageRowsRunTopDown) {
  std::string error;
  auto renderer = Renderer::Create(32, 32, 1, &error);
  ASSERT_TRUE(renderer) << error;
  // A triangle in the upper half of NDC must land in the first rows of the image.
  Mesh solid;
  const Eigen::Vector3f n(0, 0, 1), c(0, 1, 0);
  solid.Add({-1, 0.5f, 0}, n, c);
  solid.Add({1, 0.5f, 0}, n, c);
  solid.Add({0, 1, 0}, n, c);
  Lighting light;
  light.ambient = 1.0f;
  light.background = Eigen::Vector3f::Zero();
  const Image image = renderer->Render({solid}, Eigen::Matrix4f::Identity(), light);
  EXPECT_EQ(image.rgba[(2 * 32 + 16) * 4 + 1], 255);  // row 2: green
  EXPECT_EQ(image.rgba[(29 * 32 + 16) * 4 + 1], 0);   // row 29: background
}

TEST_F(RenderTest, Figure1ShowsTheCreatureOnTheGround) {
  std::string error;
  auto renderer = Renderer::Create(320, 240, 1, &error);
  ASSERT_TRUE(renderer) << error;
  const CreatureModel model = test::DefaultCreature();
  const SimState state = MakeRestState(model);
  MeshStyle look;
  const Image image = renderer->Render(
      BuildMeshes(model, state, look),
      ViewProjection(CameraSpec(), BodyCentre(model, state).cast<float>(), 320.0f / 240.0f),
      MeshStyle().lighting);
  // Count pixels whose colour is dominated by the body (orange) and the legs (blue).
  int body = 0, legs = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    body += r > g + 40 && g > b + 20;
    legs += b > r + 40 && b > g + 20;
  }
  // The hexapod's flat body covers 1579 pixels here (2% of the frame; the wedge's tall one
  // covered more than 1/30): a missing or hidden body gives none.
  EXPECT_GT(body, 320 * 240 / 60) << "the body must be clearly visible";
  EXPECT_GT(legs, 320 * 240 / 200) << "the legs must be visible";
  // And it round-trips through a PNG file.
  const std::string path = testing::TempDir() + "/figure1_test.png";
  WritePng(path, image);
  const Image back = ReadPng(path);
  EXPECT_EQ(back.width, 320);
  EXPECT_EQ(back.rgba, image.rgba);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace hexgait
