#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>

#include "model/damage.h"
#include "render/camera.h"
#include "render/gl_context.h"
#include "render/leg_colours.h"
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

// A damaged leg is drawn so that a viewer sees it: at t = 0 (the same pose, whatever the damage)
// a damaged creature's still differs from the intact one's only on the damaged leg, which is red.
TEST_F(RenderTest, ADamagedLegAndOnlyItLooksDifferent) {
  std::string error;
  constexpr int kW = 320, kH = 240;
  auto renderer = Renderer::Create(kW, kH, 1, &error);
  ASSERT_TRUE(renderer) << error;
  const CreatureModel intact = test::DefaultCreature();
  for (const char* damage :
       {"right_front:locked", "left_middle:weak=0.3", "right_rear:short=0.8", "right_front:lost"}) {
    const bool lost = std::string(damage).ends_with(":lost");
    CreatureModel damaged = intact;
    ApplyDamage(ParseDamage(damage, damaged), &damaged);
    const SimState state = MakeRestState(intact);
    MeshStyle look;
    look.overlay = false;
    look.shadow = !lost;  // a lost leg's shadow goes with it, outside the leg's box
    const Eigen::Matrix4f vp =
        ViewProjection(CameraSpec(), BodyCentre(intact, state).cast<float>(), float(kW) / kH);
    const Image a = renderer->Render(BuildMeshes(intact, state, look), vp, look.lighting);
    const Image b = renderer->Render(BuildMeshes(damaged, state, look), vp, look.lighting);
    // Where the damaged leg's polygons can be: the box around its vertices on screen.
    const int leg =
        static_cast<int>(std::find(damaged.leg_damaged.begin(), damaged.leg_damaged.end(), 1) -
                         damaged.leg_damaged.begin());
    const Leg& hurt = damaged.legs[leg];
    float x0 = kW, y0 = kH, x1 = 0, y1 = 0;
    for (const Polygon& polygon : damaged.polygons) {
      bool on_leg = false;
      for (int v : polygon.vertices) {
        if (v == hurt.foot) on_leg = true;
        if (v >= damaged.num_particles()) {
          for (const auto& [particle, weight] :
               damaged.skin_vertices[v - damaged.num_particles()].blend) {
            on_leg = on_leg || (particle == hurt.foot && weight != 0);
          }
        }
      }
      if (!polygon.is_leg || !on_leg) continue;
      for (int v : polygon.vertices) {
        const Eigen::Vector3d at =
            VertexPosition(damaged, state.x.data(), state.y.data(), state.z.data(), v);
        const Eigen::Vector4f clip = vp * Eigen::Vector4f(at.x(), at.y(), at.z(), 1);
        const float px = (clip.x() / clip.w() + 1) / 2 * kW,
                    py = (1 - clip.y() / clip.w()) / 2 * kH;
        x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
      }
    }
    int changed = 0, outside = 0, red = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const size_t i = (static_cast<size_t>(y) * kW + x) * 4;
        red += b.rgba[i] > b.rgba[i + 1] + 80 && b.rgba[i] > b.rgba[i + 2] + 80;
        if (std::equal(&a.rgba[i], &a.rgba[i] + 3, &b.rgba[i])) continue;
        ++changed;
        outside += x < x0 - 2 || x > x1 + 2 || y < y0 - 2 || y > y1 + 2;
      }
    }
    // (The left middle leg is mostly hidden behind the body in this view: 47 pixels.)
    EXPECT_GT(changed, 20) << damage << ": the damaged leg must look different";
    EXPECT_EQ(outside, 0) << damage << ": pixels changed away from the damaged leg";
    if (lost) {  // not drawn: what changed is now the ground or body behind it, never red
      EXPECT_EQ(red, 0) << damage << ": a lost leg is not drawn";
      continue;
    }
    EXPECT_GT(red, changed / 2) << damage << ": the damaged leg is drawn red";
  }
}

// Captions and titles say how the damage is drawn: red, or not at all for a lost leg.
TEST(DamageNote, SaysHowEachDamageIsDrawn) {
  EXPECT_EQ(DamageNote(std::string()), "");
  EXPECT_EQ(DamageNote("right_front:weak=0.2"), "damaged (red): right_front:weak=0.2");
  EXPECT_EQ(DamageNote("left_rear:lost"), "damaged (lost legs not drawn): left_rear:lost");
  EXPECT_EQ(DamageNote("left_rear:lost,right_front:locked"),
            "damaged (red; lost legs not drawn): left_rear:lost,right_front:locked");
}

}  // namespace
}  // namespace hexgait
