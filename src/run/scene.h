// What a run is made of, as every command and the Python module name it: the creature, its motor
// program, the step and integrator, and the genome to play; their loading and range checks, and
// what is reported of one run. Messages name the command-line flags (--dt, --time), which the
// Python module's keyword arguments share.
#pragma once

#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "run/io_paths.h"
#include "sim/step_loop.h"
#include "util/progress.h"

namespace hexgait {

struct SceneOptions {
  std::string creature_path;  // a built-in name (motor/assets.h), a file, or empty: the default
  std::string motor_path;     // empty: the creature's built-in program
  std::string damage;         // --damage: LEG:KIND[=F],... (model/damage.h); empty: intact
  double dt = kPaperTimeStep;
  std::string integrator = "euler";
  bool allow_long = false;  // --allow-long: run even if the estimate is over an hour
  // The scene flags the user gave ("--creature", "--dt", ...; AddSceneOptions records them), so
  // a folder's consumer can tell a flag from a default (run/folder_scene.h). Empty from code.
  std::set<std::string> given;
  // Set by SceneOfFolders: LoadScene refuses a scene whose SceneFingerprint (hex) differs, and
  // names `expected_by`, the folder that recorded it.
  std::string expected_fingerprint, expected_by;
};

struct Scene {
  CreatureModel model;
  MotorProgram program;
};

// The creature (a built-in name, a file, or "" for the default) damaged as `damage` says
// (--damage, model/damage.h; "" intact): the one loader of every scene's creature.
CreatureModel LoadDamagedCreature(const std::string& creature_path, const std::string& damage);

// Loads the creature, damages it as options.damage says, then loads the motor program; refuses
// one whose fingerprint is not options.expected_fingerprint (when set).
Scene LoadScene(const SceneOptions& options);
// options.damage as ParseDamage reads it back (model/damage.h), for the records; "" intact.
std::string SceneDamageText(const SceneOptions& options, const CreatureModel& model);
// Refuses a --dt that is not a positive number of at most 1 time unit; throws InputError.
void CheckStep(double dt);
// Range-checks the step (CheckStep) and duration, and refuses `runs` runs of that length estimated
// at over an hour unless --allow-long (run/work_size.h); throws InputError. `time_flag` names the
// duration's option in messages ("--movie-time" for repertoire's grid).
RunOptions MakeRunOptions(const SceneOptions& options, double duration, int runs = 1,
                          const std::string& time_flag = "--time");

// --genome FILE | --unoptimized (the default): the genome to run, and a name for it. From
// Python, the genes themselves (an array): their count picks the full or symmetric layout.
struct GenomeChoice {
  std::string path;
  bool unoptimized = false;
  std::vector<int8_t> genes;  // given in memory; empty: none
};
Genome LoadGenomeChoice(const GenomeChoice& choice, const Scene& scene, std::string* label);

// The files a scene (and a genome, when given) reads, for IoPaths::Check; a built-in creature
// name is not a file.
IoPaths SceneInputs(const SceneOptions& scene, const GenomeChoice* genome = nullptr);

// One genome in its scene, loaded for a request that writes one file of it (a still, a
// filmstrip, a movie, a replay page).
struct SceneAndGenome {
  Scene scene;
  Genome genome;
  std::string label;  // the genome's name ("unoptimized", "genome FILE", "genome")
};
// The start every such request makes, in this order: the inputs against the output `out`
// (skipped when empty: a Python caller that takes the result back), the output's extension and
// folder (messages name `out_flag`), the scene, the genome.
SceneAndGenome LoadForOutput(const SceneOptions& scene, const GenomeChoice& genome,
                             const std::string& out, const std::string& extension,
                             const std::string& out_flag = "--out");

// A run's outcome as JSON: distance, fell, fall_time and fall_cycle (null when it did not
// fall), diverged. Shared by `simulate --json` and `evolve`'s run.json.
nlohmann::json RunResultJson(const RunResult& result);

// What `simulate` reports of a run, and `render` of the run its movie shows: as one JSON object
// (RunResultJson plus program, steps, time, dt, integrator, cycles, lowest body, largest tilt,
// feet on the ground, each leg's duty factor and the legs' names in the same order), or as lines
// of text.
nlohmann::json RunReportJson(const RunResult& result, const RunOptions& options,
                             const std::string& label, const CreatureModel& model,
                             double cycle_period);
// A damaged creature's damage is named on its own line.
void PrintRunReport(const RunResult& result, const RunOptions& options, const std::string& label,
                    const CreatureModel& model, double cycle_period, std::FILE* out = stdout);

// The one-line error for a diverged run: time, step, reason, and the largest stable step found
// by halving dt (LargestStableStep in sim/evaluate.h; 0 = none found).
std::string DivergenceMessage(const RunResult& result, const RunOptions& options, double stable_dt);

}  // namespace hexgait
