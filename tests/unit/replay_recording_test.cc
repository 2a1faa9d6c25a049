// The browser replay's data: its frames are the run's states at the movie's frame times, bit for
// bit (as floats, what the renderer draws), decimation drops whole frames and nothing else, and
// the page's text cannot be broken out of.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "ga/genome.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "movie/cue_recorder.h"
#include "movie/panel_view.h"
#include "replay/replay_page.h"
#include "replay/replay_recording.h"
#include "run/replay_request.h"
#include "run/scene.h"
#include "sim/step_loop.h"
#include "test_util.h"
#include "util/error.h"
#include "util/html_text.h"

namespace hexgait {
namespace {

struct ReplayRun {
  CreatureModel model = test::DefaultCreature();
  MotorProgram program = LoadMotorProgramOrDefault("", model);
  Genome genome = test::RandomGenome(model, program, 3);
  RunOptions run;
  long long every = 0;
  ReplayRun() {
    run.duration = 40;
    every = DefaultSampleSteps(program.cycle_period, run.dt);
  }
  ReplayRecording Record(int stride) {
    SimState state = MakeRestState(model);
    ReplayRecorder recorder(model, program.cycle_period, state, every, stride, 64);
    recorder.Sample(state, true);
    MotorController controller(model, program, PerturbedRestLengths(model, program, genome),
                               run.dt);
    const RunResult result = Simulate(model, controller, state, run, recorder);
    recorder.Sample(state, true);
    return recorder.Finish(result);
  }
  // The state a separate run reaches after `steps` steps.
  SimState StateAfter(long long steps) {
    SimState state = MakeRestState(model);
    RunOptions options = run;
    options.duration = steps * run.dt;
    MotorController controller(model, program, PerturbedRestLengths(model, program, genome),
                               run.dt);
    NullObserver none;
    Simulate(model, controller, state, options, none);
    return state;
  }
};

TEST(Replay, FramesAreTheRunsStatesAtTheMovieFrameTimes) {
  ReplayRun f;
  const ReplayRecording r = f.Record(1);
  const long long steps = std::llround(f.run.duration / f.run.dt);
  // The start, one frame per `every` steps, and the end when it falls between frames.
  const int expected = 1 + static_cast<int>(steps / f.every) + (steps % f.every != 0 ? 1 : 0);
  ASSERT_EQ(r.frames(), expected);
  const int n = f.model.num_particles();
  for (int frame : {0, 3, expected - 2, expected - 1}) {
    const long long at = frame == expected - 1 ? steps : frame * f.every;
    const SimState state = f.StateAfter(at);
    EXPECT_EQ(r.time[frame], static_cast<float>(state.time)) << "frame " << frame;
    for (int i = 0; i < n; ++i) {
      const size_t o = (static_cast<size_t>(frame) * n + i) * 3;
      ASSERT_EQ(r.position[o], static_cast<float>(state.x[i])) << "frame " << frame;
      ASSERT_EQ(r.position[o + 1], static_cast<float>(state.y[i]));
      ASSERT_EQ(r.position[o + 2], static_cast<float>(state.z[i]));
    }
  }
}

TEST(Replay, DecimationKeepsEveryKthFrameAndTheLastButAllCues) {
  ReplayRun f;
  const ReplayRecording all = f.Record(1), third = f.Record(3);
  const int n = f.model.num_particles();
  ASSERT_EQ(third.frames(), (all.frames() - 2) / 3 + 2);  // every third, and the last
  for (int k = 0; k + 1 < third.frames(); ++k) {
    EXPECT_EQ(third.time[k], all.time[3 * k]);
    EXPECT_EQ(third.follow[3 * k], all.follow[9 * k]);  // the camera eased at every frame
    for (int c = 0; c < 3 * n; ++c) {
      ASSERT_EQ(third.position[k * 3 * n + c], all.position[9 * k * n + c]);
    }
  }
  EXPECT_EQ(third.time.back(), all.time.back());
  ASSERT_EQ(third.footprints.size(), all.footprints.size());
  ASSERT_FALSE(all.footprints.empty());
  for (size_t i = 0; i < all.footprints.size(); ++i) {
    EXPECT_EQ(third.footprints[i].time, all.footprints[i].time);
    EXPECT_EQ(third.footprints[i].leg, all.footprints[i].leg);
  }
}

// Samples a CueRecorder every `every` steps, as a still or filmstrip samples its PanelView.
struct ReplayCueSampler {
  CueRecorder& cues;
  long long every, until;
  void OnStep(const SimState& state) {
    if (--until > 0) return;
    until = every;
    cues.Sample(state);
  }
};

TEST(Replay, FootprintsAreTheMovieCueRecordersTouchDowns) {
  ReplayRun f;
  const ReplayRecording r = f.Record(1);
  // The movies' recorder on the same run: its ring (not yet full) holds the same prints.
  CueRecorder cues(f.model, f.program.cycle_period);
  SimState state = MakeRestState(f.model);
  cues.Sample(state);
  MotorController controller(f.model, f.program, PerturbedRestLengths(f.model, f.program, f.genome),
                             f.run.dt);
  ReplayCueSampler sampler{cues, f.every, f.every};
  Simulate(f.model, controller, state, f.run, sampler);
  cues.Sample(state);
  const GaitHistory& h = cues.history();
  ASSERT_FALSE(r.footprints.empty());
  ASSERT_EQ(h.footprints.size(), r.footprints.size());
  for (size_t i = 0; i < r.footprints.size(); ++i) {
    EXPECT_EQ(h.footprints[i].leg, r.footprints[i].leg);
    EXPECT_EQ(h.footprints[i].time, r.footprints[i].time);
    EXPECT_EQ(h.footprints[i].at, r.footprints[i].at);
  }
  ASSERT_EQ(h.trail.size(), r.trail.size());
  EXPECT_EQ(h.trail.back().at, r.trail.back().at);
  EXPECT_EQ(h.feet_down, r.feet_down.back());
}

TEST(Replay, Base64IsRfc4648) {
  EXPECT_EQ(Base64("", 0), "");
  EXPECT_EQ(Base64("f", 1), "Zg==");
  EXPECT_EQ(Base64("fo", 2), "Zm8=");
  EXPECT_EQ(Base64("foo", 3), "Zm9v");
  EXPECT_EQ(Base64("foobar", 6), "Zm9vYmFy");
  const unsigned char bytes[] = {0xff, 0xfe, 0x00, 0x80};
  EXPECT_EQ(Base64(bytes, 4), "//4AgA==");
}

TEST(Replay, ATitleCannotEndThePagesScripts) {
  ReplayRun f;
  f.run.duration = 5;
  const ReplayRecording r = f.Record(1);
  ReplayPageOptions options;
  options.title = "a</script><script>alert(1)</script>";
  options.summary = "<b>";
  const std::string page = ReplayPage(f.model, r, options);
  size_t scripts = 0;
  for (size_t at = page.find("</script"); at != std::string::npos;
       at = page.find("</script", at + 1)) {
    ++scripts;
  }
  EXPECT_EQ(scripts, 2u);  // the data's and the code's, nothing from the title
  EXPECT_NE(page.find("<title>hexgait replay: a&lt;/script&gt;"), std::string::npos);
}

// "<!--<script>" in a script element switches the HTML parser into its escaped state, which
// swallows the element's end and blanks the page: the data script holds no '<' at all, and its
// JSON reads back with the name as it was.
TEST(Replay, ANameCannotSwitchTheParserIntoItsEscapedState) {
  ReplayRun f;
  f.run.duration = 5;
  f.model.name = "x<!--<script>&\u2028";
  const ReplayRecording r = f.Record(1);
  ReplayPageOptions options;
  options.title = "<!--<script>";
  const std::string page = ReplayPage(f.model, r, options);
  const size_t open = page.find("<script type=\"application/json\" id=\"replay-data\"");
  ASSERT_NE(open, std::string::npos);
  const size_t body = page.find('>', open) + 1;
  const size_t close = page.find("</script>", body);
  ASSERT_NE(close, std::string::npos);
  const std::string data = page.substr(body, close - body);
  EXPECT_EQ(data.find('<'), std::string::npos);
  EXPECT_EQ(data.find("\u2028"), std::string::npos);
  EXPECT_EQ(ScriptJson("\"<!--&\u2028\""), "\"\\u003c!--\\u0026\\u2028\"");
  EXPECT_EQ(nlohmann::json::parse(ScriptJson(R"({"a":"</script><!--&>"})"))["a"],
            "</script><!--&>");
}

// The stated limit is the limit: a replay of exactly LongestReplay time units fits a page (at
// the sparsest stride, the start and the end frames counted), and one a cycle longer does not.
TEST(Replay, TheLongestReplayFitsAPage) {
  const SceneOptions options;  // the default creature and step
  const Scene scene = LoadScene(options);
  ReplayRequest request;
  request.time = LongestReplay(scene, MakeRunOptions(options, 1).dt);
  const ReplaySettings settings = MakeReplaySettings(request, options, scene);
  EXPECT_EQ(settings.stride, kReplayMaxStride);
  EXPECT_LE(settings.frames, kReplayMaxFrames);
  request.time += scene.program.cycle_period;
  EXPECT_THROW(MakeReplaySettings(request, options, scene), InputError);
}

}  // namespace
}  // namespace hexgait
