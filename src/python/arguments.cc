#include "python/arguments.h"

#include <algorithm>

#include "ga/genome_io.h"
#include "motor/assets.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "render/gl_context.h"
#include "run/inspect_request.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait::python {

// `damage`: as --damage (model/damage.h); the damaged model is what every call given this
// creature simulates, and SceneFor passes it on to the run layer's scene.
PyCreature MakeCreature(const std::optional<std::string>& path, const std::string& damage) {
  const std::string spec = path.value_or("");
  if (path && spec.empty()) throw InputError("creature: empty path");
  return {spec, std::make_shared<CreatureModel>(LoadDamagedCreature(spec, damage))};
}

// None, a name or path, or a Creature.
PyCreature CreatureArg(const py::handle& arg) {
  if (arg.is_none()) return MakeCreature(std::nullopt);
  if (py::isinstance<PyCreature>(arg)) return arg.cast<PyCreature>();
  if (py::isinstance<py::str>(arg)) return MakeCreature(arg.cast<std::string>());
  throw py::type_error("creature must be None, a name or path, or a hexgait.Creature");
}

PyMotorProgram MakeMotorProgram(const std::optional<std::string>& path,
                                const PyCreature& creature) {
  const std::string p = path.value_or("");
  if (path && p.empty()) throw InputError("motor: empty path");
  return {p, std::make_shared<MotorProgram>(
                 LoadMotorProgramOrDefault(p, *creature.model, creature.spec))};
}

PyMotorProgram MotorArg(const py::handle& arg, const PyCreature& creature) {
  if (arg.is_none()) return MakeMotorProgram(std::nullopt, creature);
  if (py::isinstance<PyMotorProgram>(arg)) return arg.cast<PyMotorProgram>();
  if (py::isinstance<py::str>(arg)) return MakeMotorProgram(arg.cast<std::string>(), creature);
  throw py::type_error("motor must be None, a path, or a hexgait.MotorProgram");
}

SceneOptions SceneFor(const PyCreature& creature, const PyMotorProgram& motor, double dt,
                      const std::string& integrator, bool allow_long) {
  SceneOptions scene;
  scene.creature_path = creature.spec;
  scene.motor_path = motor.path;
  scene.damage = creature.model->damage;
  scene.dt = dt;
  scene.integrator = integrator;
  scene.allow_long = allow_long;
  return scene;
}

// A genome from Python: None (unoptimized), a genome file, or an array of genes whose length
// picks the layout (full or symmetric).
Genome GenomeArg(const py::handle& arg, const PyCreature& creature, const PyMotorProgram& motor) {
  const auto layout = [&](bool symmetric) {
    return MakeGenomeLayout(*creature.model, *motor.program, symmetric);
  };
  if (arg.is_none()) return Genome(layout(false));
  if (py::isinstance<py::str>(arg)) {
    const std::string path = arg.cast<std::string>();
    if (path.empty()) throw InputError("genome: empty path");
    const std::string text = ReadTextFile(path);
    return ParseGenome(text, path, layout(GenomeFileIsSymmetric(text, path)));
  }
  const auto full = layout(false);
  const auto symmetric = layout(true);
  const py::array a = py::array::ensure(arg);
  const bool is_symmetric = a && a.ndim() == 1 && a.shape(0) == symmetric->num_genes();
  Genome genome(is_symmetric ? symmetric : full);
  int rows = 0;
  const std::vector<int8_t> genes = GenesFromArray(arg, genome.num_genes(), "genome", &rows);
  if (rows != 1) throw py::value_error("genome must be one genome, a 1-D array");
  for (int g = 0; g < genome.num_genes(); ++g) genome.set_gene(g, genes[g]);
  return genome;
}

py::array_t<int8_t> GenesToArray(const Genome& genome) {
  py::array_t<int8_t> out(genome.num_genes());
  std::copy(genome.genes().begin(), genome.genes().end(), out.mutable_data());
  return out;
}

// A text option from Python: None is the default (""); an empty string is refused, as the
// command line refuses an empty value.
std::string TextArg(const py::handle& arg, const char* name) {
  if (arg.is_none()) return "";
  if (!py::isinstance<py::str>(arg)) throw py::type_error(std::string(name) + " must be a string");
  std::string text = arg.cast<std::string>();
  if (text.empty()) throw InputError(std::string(name) + ": empty value");
  return text;
}

// cues='footprints,strip' or ['footprints', 'strip'].
std::string CuesArg(const py::handle& arg) {
  if (py::isinstance<py::list>(arg) || py::isinstance<py::tuple>(arg)) {
    std::string text;
    for (const auto& item : arg) {
      if (!text.empty()) text += ',';
      text += TextArg(item, "cues");
    }
    return text;
  }
  return TextArg(arg, "cues");
}

// gl='egl' or 'osmesa' for this call; None: HEXGAIT_GL, else the first that works. A choice
// of an earlier call does not stick.
void ChooseGlBackend(const py::handle& arg) {
  const std::string name = TextArg(arg, "gl");
  const std::vector<std::string> names = GlBackendNames();
  if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InputError("gl '" + name + "': unknown OpenGL backend (use " + list + ")");
  }
  SetGlBackend(name);
}

ViewRequest ViewArgs(const py::handle& view, const py::handle& camera, const py::handle& track,
                     const py::handle& cues) {
  return {TextArg(view, "view"), TextArg(camera, "camera"), TextArg(track, "track"), CuesArg(cues)};
}

// The genome of a still or a movie and the caption's name for it.
GenomeChoice PictureGenomeChoice(const py::handle& genome_arg, bool unoptimized,
                                 const PyCreature& creature, const PyMotorProgram& motor) {
  if (unoptimized && !genome_arg.is_none()) {
    throw InputError("unoptimized=True and genome= exclude each other");
  }
  GenomeChoice choice;
  choice.unoptimized = unoptimized;
  if (genome_arg.is_none()) return choice;
  if (py::isinstance<py::str>(genome_arg)) {
    choice.path = genome_arg.cast<std::string>();
    if (choice.path.empty()) throw InputError("genome: empty path");
    return choice;
  }
  choice.genes = GenomeArg(genome_arg, creature, motor).genes();  // the array's checks
  return choice;
}

py::array_t<double> Float64Array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

void BindArguments(py::module_& m) {
  py::class_<PyCreature>(
      m, "Creature",
      "A creature: a built-in name ('hexapod', 'wedge') or a JSON file; None: the default. "
      "damage: as --damage, e.g. 'right_front:weak=0.2,left_rear:locked'")
      .def(py::init(&MakeCreature), py::arg("path") = py::none(), py::arg("damage") = "")
      .def_property_readonly("damage", [](const PyCreature& c) { return c.model->damage; })
      .def_property_readonly("name", [](const PyCreature& c) { return CreatureLabel(c.spec); })
      .def_property_readonly("particles",
                             [](const PyCreature& c) { return c.model->num_particles(); })
      .def_property_readonly("springs", [](const PyCreature& c) { return c.model->num_springs(); })
      .def_property_readonly("legs",
                             [](const PyCreature& c) {
                               std::vector<std::string> names;
                               for (const Leg& leg : c.model->legs) names.push_back(leg.name);
                               return names;
                             })
      .def("__repr__", [](const PyCreature& c) {
        const std::string damage =
            c.model->damage.empty() ? "" : ", damage='" + c.model->damage + "'";
        return "hexgait.Creature('" + CreatureLabel(c.spec) + "'" + damage + ")";
      });
  m.attr("builtin_creatures") = BuiltInCreatureNames();

  py::class_<PyMotorProgram>(m, "MotorProgram",
                             "A motor program file; None: the creature's built-in program")
      .def(py::init([](const std::optional<std::string>& path, const py::handle& creature) {
             return MakeMotorProgram(path, CreatureArg(creature));
           }),
           py::arg("path") = py::none(), py::arg("creature") = py::none())
      .def_property_readonly("cycle_period",
                             [](const PyMotorProgram& p) { return p.program->cycle_period; })
      .def_property_readonly("gene_length_step",
                             [](const PyMotorProgram& p) { return p.program->gene_length_step; })
      .def("__repr__", [](const PyMotorProgram& p) {
        return "hexgait.MotorProgram(" +
               (p.path.empty() ? std::string("built-in") : "'" + p.path + "'") + ")";
      });

  m.def(
      "inspect",
      [](const py::handle& creature_arg, const py::handle& motor_arg, double dt) {
        const PyCreature creature = CreatureArg(creature_arg);
        const PyMotorProgram motor = MotorArg(motor_arg, creature);
        return InspectReport(SceneFor(creature, motor, dt, "euler", false));
      },
      py::kw_only(), py::arg("creature") = py::none(), py::arg("motor") = py::none(),
      py::arg("dt") = kPaperTimeStep,
      "The report `hexgait inspect` prints, as a string: the creature's structure, natural "
      "frequencies and the explicit Euler step's margins at dt");
}

}  // namespace hexgait::python
