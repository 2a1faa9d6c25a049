// Cameras and gait cues without a GL context: parsing, tracking modes, the bounded history and
// touch-down detection.
#include <gtest/gtest.h>

#include "movie/cue_recorder.h"
#include "render/camera.h"
#include "render/cue_layers.h"
#include "render/gait_cues.h"
#include "render/ring_buffer.h"
#include "test_util.h"

namespace hexgait {
namespace {

TEST(Camera, PresetsHaveUniqueNamesAndTheDefaultIsFirst) {
  EXPECT_STREQ(CameraPresets().front().name, "three-quarter");
  for (const CameraPreset& p : CameraPresets()) EXPECT_EQ(FindCameraPreset(p.name), &p);
  EXPECT_EQ(FindCameraPreset("sideways"), nullptr);
  EXPECT_EQ(CameraPresetNames(), "three-quarter|side|front|top");
}

TEST(Camera, ParsesFieldsOverAPreset) {
  CameraSpec spec;
  EXPECT_EQ(ParseCameraSpec("fov=50;eye=1,-2,3", &spec), "");
  EXPECT_EQ(spec.eye_offset, Eigen::Vector3f(1, -2, 3));
  EXPECT_EQ(spec.fov_y, 50.0f);
  EXPECT_EQ(spec.target_offset, CameraSpec().target_offset);  // untouched
  for (const char* bad : {"", "eye=1,2", "eye=1,2,3,4", "eye=1,,3", "eye=1,2,3,", "fov=4",
                          "fov=nan", "eye=1,2,inf", "zoom=1", "eye", "eye=0,0,0"}) {
    CameraSpec unchanged;
    EXPECT_NE(ParseCameraSpec(bad, &unchanged), "") << bad;
    EXPECT_EQ(unchanged.eye_offset, CameraSpec().eye_offset) << bad;
  }
}

TEST(Camera, TrackingModes) {
  const Eigen::Vector3f start(0, 0, 1), moved(2, 0.5f, 0.4f);
  CameraTracker follow(CameraSpec::Tracking::kFollow, start);
  CameraTracker track_x(CameraSpec::Tracking::kTrackX, start);
  CameraTracker fixed(CameraSpec::Tracking::kFixed, start);
  EXPECT_EQ(track_x.Update(moved), Eigen::Vector3f(2, 0, 1));  // x only, height kept
  EXPECT_EQ(fixed.Update(moved), start);
  const Eigen::Vector3f eased = follow.Update(moved);
  EXPECT_GT(eased.x(), 0.0f);
  EXPECT_LT(eased.x(), 2.0f);  // eases, does not jump
  CameraSpec::Tracking t;
  EXPECT_TRUE(ParseTracking("x", &t));
  EXPECT_EQ(t, CameraSpec::Tracking::kTrackX);
  EXPECT_FALSE(ParseTracking("y", &t));
}

TEST(Camera, StraightDownIsWellDefined) {
  const Eigen::Matrix4f m =
      ViewProjection(FindCameraPreset("top")->spec, Eigen::Vector3f(0, 0, 1), 4.0f / 3.0f);
  EXPECT_TRUE(m.allFinite());
}

// A camera that cannot show the creature is named (issue: a frame of sky, silently), and a far
// one is not: the depth range follows the eye instead of ending at 100 units.
TEST(Camera, SeesTheCreatureFromAfarAndNamesACameraThatCannot) {
  for (const CameraPreset& preset : CameraPresets()) {
    EXPECT_EQ(CameraBlindness(preset.spec, 16.0f / 9.0f), "") << preset.name;
  }
  CameraSpec far;
  far.eye_offset = Eigen::Vector3f(0, -300, 40);
  EXPECT_EQ(CameraBlindness(far, 16.0f / 9.0f), "");
  CameraSpec up;
  up.target_offset = Eigen::Vector3f(0, 0, 80);
  EXPECT_NE(CameraBlindness(up, 16.0f / 9.0f).find("outside the field of view"), std::string::npos);
  CameraSpec behind;
  behind.eye_offset = Eigen::Vector3f(-1, 0, -0.05f);
  behind.target_offset = Eigen::Vector3f(0, 0, -50);
  EXPECT_NE(CameraBlindness(behind, 1.0f), "");
}

TEST(Cues, Parse) {
  CueOptions cues;
  EXPECT_EQ(ParseCues("all", &cues), "");
  EXPECT_TRUE(cues.footprints && cues.trail && cues.swing && cues.strip);
  EXPECT_EQ(ParseCues("strip,swing", &cues), "");
  EXPECT_TRUE(cues.strip && cues.swing && !cues.footprints && !cues.trail);
  EXPECT_EQ(ParseCues("none", &cues), "");
  EXPECT_FALSE(cues.any());
  EXPECT_NE(ParseCues("footprints,", &cues), "");
  EXPECT_NE(ParseCues("shadow", &cues), "");
}

TEST(Cues, RingBufferDropsTheOldest) {
  RingBuffer<int> ring(3);
  for (int i = 0; i < 5; ++i) ring.Push(i);
  ASSERT_EQ(ring.size(), 3u);
  EXPECT_EQ(ring[0], 2);
  EXPECT_EQ(ring.back(), 4);
}

TEST(Cues, AFootTouchingDownLeavesOnePrint) {
  const CreatureModel model = test::DefaultCreature();
  CueRecorder recorder(model, 10.0);
  SimState state = MakeRestState(model);
  recorder.Sample(state);  // at rest: every foot down, one print each
  EXPECT_EQ(recorder.history().footprints.size(), model.legs.size());
  const int foot = model.legs[0].foot;
  const double ground = state.z[foot];
  state.time = 1;
  state.z[foot] = 0.3;  // lifted
  recorder.Sample(state);
  EXPECT_EQ(recorder.history().feet_down & 1u, 0u);
  state.time = 2;
  state.z[foot] = ground;  // down again on the same spot: a bounce, no new print
  recorder.Sample(state);
  EXPECT_EQ(recorder.history().footprints.size(), model.legs.size());
  state.time = 3;
  state.z[foot] = 0.3;
  recorder.Sample(state);
  state.time = 4;
  state.z[foot] = ground;
  state.x[foot] += 0.5;  // a step forward
  recorder.Sample(state);
  ASSERT_EQ(recorder.history().footprints.size(), model.legs.size() + 1);
  EXPECT_EQ(recorder.history().footprints.back().leg, 0);
  EXPECT_EQ(recorder.history().strip.size(), 5u);
}

TEST(Cues, EveryLegPolygonBelongsToALeg) {
  const CreatureModel model = test::DefaultCreature();
  const std::vector<int> legs = PolygonLegs(model);
  ASSERT_EQ(legs.size(), model.polygons.size());
  std::vector<int> per_leg(model.legs.size(), 0);
  for (size_t p = 0; p < legs.size(); ++p) {
    EXPECT_EQ(legs[p] >= 0, model.polygons[p].is_leg) << p;
    if (legs[p] >= 0) ++per_leg[static_cast<size_t>(legs[p])];
  }
  // The hexapod's legs are alike: each has as many polygons as the first.
  for (int count : per_leg) EXPECT_EQ(count, per_leg[0]);
}

}  // namespace
}  // namespace hexgait
