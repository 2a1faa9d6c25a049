// hexgait.replay_html: the page `hexgait replay` writes, as a string.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "python/arguments.h"
#include "python/bindings.h"
#include "python/interrupts.h"
#include "run/replay_request.h"
#include "util/error.h"

namespace hexgait::python {
namespace {

py::object ReplayPageText(const py::handle& genome_arg, const py::handle& creature_arg,
                          const py::handle& motor_arg, bool unoptimized, double time,
                          const py::handle& view, const py::handle& camera, const py::handle& track,
                          const py::handle& cues, bool no_overlay, bool no_shadow, double dt,
                          const std::string& integrator, bool allow_long) {
  ReplayRequest request;
  request.time = time;
  request.no_overlay = no_overlay;
  request.no_shadow = no_shadow;
  request.view = ViewArgs(view, camera, track, cues);
  const PyCreature creature = CreatureArg(creature_arg);
  const PyMotorProgram motor = MotorArg(motor_arg, creature);
  const Scene scene{*creature.model, *motor.program};
  const ReplaySettings settings =
      MakeReplaySettings(request, SceneFor(creature, motor, dt, integrator, allow_long), scene);
  if (!settings.decimation.empty()) {
    if (PyErr_WarnEx(PyExc_UserWarning, settings.decimation.c_str(), 1) < 0) {
      throw py::error_already_set();  // warnings turned into errors
    }
  }
  std::string label;
  const Genome genome = LoadGenomeChoice(
      PictureGenomeChoice(genome_arg, unoptimized, creature, motor), scene, &label);
  return AsReplayPage(Interruptible(
      [&] { return ReplayHtml(scene, genome, settings, label, CheckPythonSignalsBetween); }));
}

}  // namespace

void BindReplay(py::module_& m) {
  m.def("replay_html", &ReplayPageText, py::kw_only(), py::arg("genome") = py::none(),
        py::arg("creature") = py::none(), py::arg("motor") = py::none(),
        py::arg("unoptimized") = false, py::arg("time") = kPaperDuration,
        py::arg("view") = py::none(), py::arg("camera") = py::none(), py::arg("track") = py::none(),
        py::arg("cues") = py::none(), py::arg("no_overlay") = false, py::arg("no_shadow") = false,
        py::arg("dt") = kPaperTimeStep, py::arg("integrator") = "euler",
        py::arg("allow_long") = false,
        "The self-contained HTML page `hexgait replay` writes, as a string (in Jupyter: "
        "IPython.display.HTML(page)): genome= an array or a path (None: the unoptimised "
        "program), time=, view=, camera=, track=, cues= (what the page opens with), "
        "no_overlay=, no_shadow=, dt=, integrator=. A run too long for a page is decimated with "
        "a UserWarning, or refused");
}

}  // namespace hexgait::python
