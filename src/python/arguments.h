// What Python passes, turned into what the run layer takes: creatures, motor programs, genomes
// and text options, with the command line's checks and messages (an empty value is refused as
// the command line refuses one). Also the Creature and MotorProgram classes.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "run/scene.h"
#include "run/view_request.h"

namespace hexgait::python {

namespace py = pybind11;

// A creature: a built-in name or a file, kept with the name it was made from (the commands
// take the name; a run records it).
struct PyCreature {
  std::string spec;  // "" = the default creature
  std::shared_ptr<const CreatureModel> model;
};

struct PyMotorProgram {
  std::string path;  // "" = the creature's built-in program
  std::shared_ptr<const MotorProgram> program;
};

// `damage`: as --damage (model/damage.h); the damaged model is what every call given this
// creature simulates, and SceneFor passes it on to the run layer's scene.
PyCreature MakeCreature(const std::optional<std::string>& path, const std::string& damage = "");
// None, a name or path, or a Creature.
PyCreature CreatureArg(const py::handle& arg);
PyMotorProgram MakeMotorProgram(const std::optional<std::string>& path, const PyCreature& creature);
PyMotorProgram MotorArg(const py::handle& arg, const PyCreature& creature);
SceneOptions SceneFor(const PyCreature& creature, const PyMotorProgram& motor, double dt,
                      const std::string& integrator, bool allow_long);

// A genome from Python: None (unoptimized), a genome file, or an array of genes whose length
// picks the layout (full or symmetric).
Genome GenomeArg(const py::handle& arg, const PyCreature& creature, const PyMotorProgram& motor);
py::array_t<int8_t> GenesToArray(const Genome& genome);
// The genome of a still, a movie or a replay as the run layer takes it (run/scene.h): None
// (unoptimized), a genome file, or an array (checked here, passed on as genes).
GenomeChoice PictureGenomeChoice(const py::handle& genome_arg, bool unoptimized,
                                 const PyCreature& creature, const PyMotorProgram& motor);

// A text option from Python: None is the default (""); an empty string is refused, as the
// command line refuses an empty value.
std::string TextArg(const py::handle& arg, const char* name);
ViewRequest ViewArgs(const py::handle& view, const py::handle& camera, const py::handle& track,
                     const py::handle& cues);
// gl='egl' or 'osmesa' for this call; None: HEXGAIT_GL, else the first that works. A choice
// of an earlier call does not stick.
void ChooseGlBackend(const py::handle& arg);

py::array_t<double> Float64Array(const std::vector<double>& values);

}  // namespace hexgait::python
