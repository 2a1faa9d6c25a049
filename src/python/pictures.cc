// hexgait.render_still, hexgait.render_movie and hexgait.compare: the run layer's still, gait
// movie and golden-image check, as `hexgait still`, `hexgait render` and `hexgait compare` do.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "python/arguments.h"
#include "python/bindings.h"
#include "python/interrupts.h"
#include "run/compare_request.h"
#include "run/movie_request.h"
#include "run/still_request.h"
#include "util/error.h"

namespace hexgait::python {
namespace {

py::array_t<uint8_t> RenderStillFrame(const py::handle& genome_arg, const py::handle& creature_arg,
                                      const py::handle& motor_arg, bool unoptimized, double time,
                                      const std::string& size, const py::handle& view,
                                      const py::handle& camera, const py::handle& track,
                                      const py::handle& cues, bool no_overlay, bool no_shadow,
                                      int msaa, double dt, const std::string& integrator,
                                      bool allow_long, const py::handle& gl) {
  StillRequest request;
  request.time = time;
  request.size = size;
  request.no_overlay = no_overlay;
  request.no_shadow = no_shadow;
  request.msaa = msaa;
  request.view = ViewArgs(view, camera, track, cues);
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  StillFile still;
  still.scene = SceneFor(creature, motor, dt, integrator, allow_long);
  still.genome = PictureGenomeChoice(genome_arg, unoptimized, creature, motor);
  still.still = request;
  still.out.clear();  // the frame comes back as an array
  ChooseGlBackend(gl);
  const Image image =
      Interruptible([&] { return WriteStill(still, CheckPythonSignalsBetween).image; });
  py::array_t<uint8_t> rgb({py::ssize_t{image.height}, py::ssize_t{image.width}, py::ssize_t{3}});
  uint8_t* dst = rgb.mutable_data();
  for (size_t p = 0; p < static_cast<size_t>(image.width) * image.height; ++p) {
    std::copy_n(image.rgba.data() + 4 * p, 3, dst + 3 * p);
  }
  return rgb;
}

py::object RenderMovieFile(const std::string& path, const py::handle& genome_arg,
                           const py::handle& creature_arg, const py::handle& motor_arg,
                           bool unoptimized, double time, const std::string& size, int fps,
                           double speed, int msaa, const std::string& preset, int crf, bool overlay,
                           bool no_shadow, bool no_caption, const py::handle& view,
                           const py::handle& camera, const py::handle& track,
                           const py::handle& cues, const py::handle& frames, double dt,
                           const std::string& integrator, bool allow_long, const py::handle& gl) {
  MovieRequest request;
  request.time = time;
  request.size = size;
  request.fps = fps;
  request.speed = speed;
  request.msaa = msaa;
  request.preset = preset;
  request.crf = crf;
  request.overlay = overlay;
  request.no_shadow = no_shadow;
  request.no_caption = no_caption;
  request.frames_dir = TextArg(frames, "frames");
  request.view = ViewArgs(view, camera, track, cues);
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  if (path.empty()) throw InputError("path: empty value");
  GaitMovieFile movie;
  movie.scene = SceneFor(creature, motor, dt, integrator, allow_long);
  movie.genome = PictureGenomeChoice(genome_arg, unoptimized, creature, motor);
  movie.movie = request;
  movie.out = path;
  movie.out_flag = "path";
  ChooseGlBackend(gl);
  // A Ctrl-C ends the call; the unfinished movie is removed (VideoEncoder).
  Interruptible([&] { return WriteGaitMovie(movie, CheckPythonSignalsBetween); });
  return AsMovie(path);
}

py::dict CompareFilesDict(const std::string& expected, const std::string& actual, double tolerance,
                          int pixel_threshold, const py::handle& diff) {
  CompareRequest request;
  request.expected = expected;
  request.actual = actual;
  request.tolerance.max_different_fraction = tolerance;
  request.tolerance.pixel_threshold = pixel_threshold;
  request.diff = TextArg(diff, "diff");
  const CompareResult r =
      Interruptible([&] { return CompareFiles(request, CheckPythonSignalsBetween); });
  py::dict out;
  out["match"] = r.match;
  out["summary"] = r.summary;
  out["frames"] = r.frames;
  out["expected_frames"] = r.expected_frames;
  out["actual_frames"] = r.actual_frames;
  out["differing_frames"] = r.differing_frames;
  out["sizes_differ"] = r.sizes_differ;
  out["worst_frame"] = r.worst_frame < 0 ? py::object(py::none()) : py::int_(r.worst_frame);
  out["different_pixels"] = r.worst.different_pixels;
  out["max_difference"] = r.worst.max_difference;
  out["diff"] = r.diff_path.empty() ? py::object(py::none()) : py::str(r.diff_path);
  return out;
}

}  // namespace

void BindPictures(py::module_& m) {
  m.def("render_still", &RenderStillFrame, py::kw_only(), py::arg("genome") = py::none(),
        py::arg("creature") = py::none(), py::arg("motor") = py::none(),
        py::arg("unoptimized") = false, py::arg("time") = 0.0, py::arg("size") = "1280x720",
        py::arg("view") = py::none(), py::arg("camera") = py::none(), py::arg("track") = py::none(),
        py::arg("cues") = py::none(), py::arg("no_overlay") = false, py::arg("no_shadow") = false,
        py::arg("msaa") = 0, py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler",
        py::arg("allow_long") = false, py::arg("gl") = py::none(),
        "An (H, W, 3) uint8 frame, as `hexgait still` draws it: genome= an array or a path "
        "(None: the unoptimised program), time= (0: the rest pose, the paper's Figure 1), size= "
        "'WxH', view=, camera=, track=, cues= (a string or a list), no_overlay=, no_shadow=, "
        "msaa=, dt=, integrator=, gl=");
  m.def("render_movie", &RenderMovieFile, py::arg("path"), py::kw_only(),
        py::arg("genome") = py::none(), py::arg("creature") = py::none(),
        py::arg("motor") = py::none(), py::arg("unoptimized") = false,
        py::arg("time") = kPaperDuration, py::arg("size") = "1280x720", py::arg("fps") = 30,
        py::arg("speed") = 0.0, py::arg("msaa") = 0, py::arg("preset") = "veryfast",
        py::arg("crf") = 20, py::arg("overlay") = false, py::arg("no_shadow") = false,
        py::arg("no_caption") = false, py::arg("view") = py::none(), py::arg("camera") = py::none(),
        py::arg("track") = py::none(), py::arg("cues") = py::none(), py::arg("frames") = py::none(),
        py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler",
        py::arg("allow_long") = false, py::arg("gl") = py::none(),
        "Writes an MP4 of one run, as `hexgait render --out path` does, and returns the path: "
        "genome=, time=, size=, fps=, speed= (0: a gait cycle per second), msaa=, preset=, crf=, "
        "overlay=, no_shadow=, no_caption=, view=, camera=, track=, cues=, frames= (a folder for "
        "PNGs), dt=, integrator=, gl=");
  m.def("compare", &CompareFilesDict, py::arg("expected"), py::arg("actual"), py::kw_only(),
        py::arg("tolerance") = ImageTolerance().max_different_fraction,
        py::arg("pixel_threshold") = ImageTolerance().pixel_threshold, py::arg("diff") = py::none(),
        "Compares an image or movie with the approved one, as `hexgait compare` does: a dict "
        "with match, summary (its one line), frames, differing_frames, worst_frame, "
        "different_pixels and max_difference of the worst frame, sizes_differ and diff (the "
        "PNG written where they differ, when diff= names one)");
}

}  // namespace hexgait::python
