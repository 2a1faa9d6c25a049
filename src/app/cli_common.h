// Options every command shares (--creature, --motor, --dt, --integrator) and the loading of
// the scene they name.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "ga/genome.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/run.h"

namespace hexgait {

struct SceneOptions {
  std::string creature_path;  // empty: the built-in assets/hexapod.json
  std::string motor_path;     // empty: the built-in assets/metachronal.json
  double dt = kPaperTimeStep;
  std::string integrator = "euler";
};

struct Scene {
  CreatureModel model;
  MotorProgram program;
};

void AddSceneOptions(CLI::App* command, SceneOptions& options);
Scene LoadScene(const SceneOptions& options);
// Range-checks the step and duration; throws InputError.
RunOptions MakeRunOptions(const SceneOptions& options, double duration);

// --genome FILE | --unoptimized (the default): the genome to run, and a name for it.
struct GenomeChoice {
  std::string path;
  bool unoptimized = false;
};
void AddGenomeOptions(CLI::App* command, GenomeChoice& choice);
Genome LoadGenomeChoice(const GenomeChoice& choice, const Scene& scene, std::string* label);

}  // namespace hexgait
