// Golden-image tests: small frames of the real pipeline (simulation -> scene -> renderer ->
// caption) compared with reviewed PNGs in tests/golden/.
//
// The tolerance is the golden-image rule users get from `hexgait compare` (image/image_compare.h,
// where the measurements behind it are).
//
// UPDATE_GOLDENS=1 rewrites the goldens instead of comparing; on a failure the actual,
// expected and difference images go to out/golden/.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "ga/genome_eval.h"
#include "ga/genome_io.h"
#include "image/image_compare.h"
#include "motor/leg_targets.h"
#include "movie/filmstrip.h"
#include "movie/movie_maker.h"
#include "render/camera.h"
#include "render/gait_cues.h"
#include "render/gl_context.h"
#include "render/png_io.h"
#include "test_util.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

constexpr int kWidth = 320, kHeight = 240;

const std::string kSourceDir = HEXGAIT_SOURCE_DIR;

void CheckGolden(const std::string& name, const Image& actual) {
  const std::string golden = kSourceDir + "/tests/golden/" + name + ".png";
  if (const char* update = std::getenv("UPDATE_GOLDENS"); update && std::string(update) == "1") {
    WritePng(golden, actual);
    std::printf("rewrote %s\n", golden.c_str());
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden))
      << golden << " is missing; make it with UPDATE_GOLDENS=1 ctest -R Golden and review it";
  const Image expected = ReadPng(golden);
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  const ImageTolerance tolerance;
  const ImageDifference c = CompareImages(expected, actual, tolerance);
  long long any_change = 0;
  for (size_t p = 0; p < actual.rgba.size(); p += 4) {
    any_change += actual.rgba[p] != expected.rgba[p] ||
                  actual.rgba[p + 1] != expected.rgba[p + 1] ||
                  actual.rgba[p + 2] != expected.rgba[p + 2];
  }
  std::printf("%s: %lld pixels changed at all, %lld by more than %d levels, largest %d\n",
              name.c_str(), any_change, c.different_pixels, tolerance.pixel_threshold,
              c.max_difference);
  if (!c.within) {
    const std::string dir = kSourceDir + "/out/golden/";
    std::filesystem::create_directories(dir);
    WritePng(dir + name + "_actual.png", actual);
    WritePng(dir + name + "_expected.png", expected);
    WritePng(dir + name + "_diff.png", c.diff);
    ADD_FAILURE() << name << ": " << c.different_pixels << " pixels (" << 100 * c.fraction()
                  << " %) differ by more than " << tolerance.pixel_threshold << " levels (limit "
                  << 100 * tolerance.max_different_fraction << " %), largest difference "
                  << c.max_difference << "; actual, expected and diff images are in " << dir;
  }
}

// Every golden on every GL backend (EGL and OSMesa): both must give the same images within the
// goldens' tolerance, and both must work, so a backend that cannot make a context fails.
class GoldenTest : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    std::string error;
    SetGlBackend(GetParam());
    context_ = GlContext::Create(&error);
    ASSERT_TRUE(context_) << "no GL context from " << GetParam() << ": " << error;
    model_ = test::DefaultCreature();
    program_ = LoadMotorProgramOrDefault("", model_);
  }

  RestLengthTable Unoptimized() const {
    return PerturbedRestLengths(model_, program_,
                                Genome(MakeGenomeLayout(model_, program_, false)));
  }
  RestLengthTable Evolved() const {
    const std::string path = kSourceDir + "/tests/data/evolved_seed1.genome";
    const Genome genome =
        ParseGenome(ReadTextFile(path), path, MakeGenomeLayout(model_, program_, false));
    return PerturbedRestLengths(model_, program_, genome);
  }

  // The last frame of a small movie of `time` units: the whole pipeline a user's movie takes.
  Image LastFrame(const std::vector<MoviePanel>& panels, double time, bool overlay, bool caption,
                  const CameraSpec& camera = CameraSpec(), const CueOptions& cues = {}) {
    MovieSettings settings;
    settings.camera = camera;
    settings.cues = cues;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.run.duration = time;
    settings.look.overlay = overlay;
    settings.caption = caption;
    Image last;
    MakeMovie(model_, program_, panels, settings, [&](const Image& frame) { last = frame; });
    return last;
  }

  void TearDown() override { SetGlBackend(""); }

  std::unique_ptr<GlContext> context_;
  CreatureModel model_;
  MotorProgram program_;
};

TEST_P(GoldenTest, Figure1AtRest) {
  // One frame at t = 0: the rest pose with particles and springs over the polygons.
  CheckGolden("figure1", LastFrame({{"at rest", Unoptimized()}}, 0.0025, true, false));
}

TEST_P(GoldenTest, UnoptimizedAfterItsFall) {
  CheckGolden("unoptimized_t300", LastFrame({{"unoptimized", Unoptimized()}}, 300, false, true));
}

TEST_P(GoldenTest, EvolvedWalking) {
  CheckGolden("evolved_t400", LastFrame({{"evolved", Evolved()}}, 400, false, true));
}

TEST_P(GoldenTest, EvolvedWithOverlay) {
  CheckGolden("evolved_overlay_t100", LastFrame({{"evolved", Evolved()}}, 100, true, false));
}

TEST_P(GoldenTest, ComparisonStacksBothOnOneClock) {
  CheckGolden("comparison_t250", LastFrame({{"unoptimized", Unoptimized()}, {"evolved", Evolved()}},
                                           250, false, true));
}

// One golden per camera preset: the evolved walker at t = 200, no caption.
TEST_P(GoldenTest, EveryViewPreset) {
  for (const CameraPreset& preset : CameraPresets()) {
    SCOPED_TRACE(preset.name);
    CheckGolden(std::string("view_") + preset.name + "_t200",
                LastFrame({{"evolved", Evolved()}}, 200, false, false, preset.spec));
  }
}

// Every gait cue on: footprints, trail, swinging legs and the footfall strip.
TEST_P(GoldenTest, EvolvedWithEveryCue) {
  CheckGolden("cues_all_t300", LastFrame({{"evolved", Evolved()}}, 300, false, true, CameraSpec(),
                                         CueOptions{true, true, true, true}));
}

// A filmstrip is one run from rest to its last frame, its frames side by side with rules between.
TEST_P(GoldenTest, FilmstripIsOneRunAcrossACycle) {
  FilmstripSettings settings;
  settings.frames = 4;
  settings.cycle = 2;
  settings.frame_width = 80;
  settings.frame_height = 60;
  settings.msaa_samples = 1;
  const FilmstripResult strip = MakeFilmstrip(model_, program_, Evolved(), settings);
  EXPECT_EQ(strip.image.width, 4 * 80 + 3 * 2);
  EXPECT_EQ(strip.image.height, 60);
  const double last = program_.cycle_period * (1.0 + 3.0 / 4.0);
  EXPECT_NEAR(strip.run.end_time, last, settings.run.dt);
}

// The comparison itself must be able to fail: a change the size of one caption digit is caught.
TEST(GoldenCompare, CatchesASmallChange) {
  Image a;
  a.width = kWidth;
  a.height = kHeight;
  a.rgba.assign(static_cast<size_t>(kWidth) * kHeight * 4, 200);
  Image b = a;
  // A 4x5 patch (20 pixels, 0.026 %) changed: over the limit.
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 4; ++x) b.rgba[(static_cast<size_t>(y) * kWidth + x) * 4] = 100;
  }
  const ImageDifference changed = CompareImages(a, b, ImageTolerance());
  EXPECT_EQ(changed.different_pixels, 20);
  EXPECT_EQ(changed.max_difference, 100);
  EXPECT_FALSE(changed.within);
  // The diff marks exactly the changed pixels in red.
  EXPECT_EQ(changed.diff.rgba[0], 255);
  EXPECT_EQ(changed.diff.rgba[1], 0);
  EXPECT_EQ(changed.diff.rgba[4 * 4], 228);
  // 15 changed pixels (0.0195 %) are within the rule; a change of 24 levels is not a difference.
  for (int y = 0; y < 5; ++y) b.rgba[(static_cast<size_t>(y) * kWidth + 3) * 4] = 200;
  EXPECT_TRUE(CompareImages(a, b, ImageTolerance()).within);
  Image c = a;
  for (size_t p = 0; p < c.rgba.size(); p += 4) c.rgba[p + 2] = 224;
  EXPECT_EQ(CompareImages(a, c, ImageTolerance()).different_pixels, 0);
  EXPECT_EQ(CompareImages(a, c, ImageTolerance{23, 0.0002}).different_pixels, kWidth * kHeight);
  const ImageDifference same = CompareImages(a, a, ImageTolerance());
  EXPECT_EQ(same.different_pixels, 0);
  EXPECT_TRUE(same.within);
  Image small = a;
  small.width = kWidth / 2;
  EXPECT_THROW(CompareImages(a, small, ImageTolerance()), InputError);
}

INSTANTIATE_TEST_SUITE_P(EveryGlBackend, GoldenTest, testing::ValuesIn(GlBackendNames()),
                         [](const testing::TestParamInfo<std::string>& param) {
                           return param.param;
                         });

}  // namespace
}  // namespace hexgait
