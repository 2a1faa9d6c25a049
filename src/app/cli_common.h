// Options every command shares (--creature, --motor, --dt, --integrator) and the loading of
// the scene they name.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/io_paths.h"
#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "sim/run.h"

namespace hexgait {

struct SceneOptions {
  std::string creature_path;  // a built-in name (app/assets.h), a file, or empty: the default
  std::string motor_path;     // empty: the creature's built-in program
  double dt = kPaperTimeStep;
  std::string integrator = "euler";
  bool allow_long = false;  // --allow-long: run even if the estimate is over an hour
};

struct Scene {
  CreatureModel model;
  MotorProgram program;
};

// `with_allow_long` adds --allow-long (for commands that simulate).
void AddSceneOptions(CLI::App* command, SceneOptions& options, bool with_allow_long = true);
Scene LoadScene(const SceneOptions& options);
// Range-checks the step and duration, and refuses `runs` runs of that length estimated at over
// an hour unless --allow-long (app/work_size.h); throws InputError.
RunOptions MakeRunOptions(const SceneOptions& options, double duration, int runs = 1);

// --genome FILE | --unoptimized (the default): the genome to run, and a name for it.
struct GenomeChoice {
  std::string path;
  bool unoptimized = false;
};
void AddGenomeOptions(CLI::App* command, GenomeChoice& choice);
Genome LoadGenomeChoice(const GenomeChoice& choice, const Scene& scene, std::string* label);

// The files a scene (and a genome, when given) reads, for IoPaths::Check; a built-in creature
// name is not a file.
IoPaths SceneInputs(const SceneOptions& scene, const GenomeChoice* genome = nullptr);

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
void PrintRunReport(const RunResult& result, const RunOptions& options, const std::string& label,
                    double cycle_period, std::FILE* out = stdout);

// For unsigned flags (--seed): CLI11 would wrap "-1" into 2^64 - 1 and clamp a larger number
// to it; this refuses any sign and anything above 2^64 - 1.
std::string CheckUnsigned64(const std::string& text);
inline const CLI::Validator kNoSign([](std::string& text) { return CheckUnsigned64(text); },
                                    "UINT");
// --seed, with kNoSign and its default shown. Every command's seed goes through this, so
// `--seed -1` is refused alike everywhere (CLI11's exit status 2) instead of wrapping to 2^64 - 1.
CLI::Option* AddSeedOption(CLI::App* command, uint64_t& seed, const std::string& help);

// The choices of --precision, the lanes' number type (simd/isa.h: ParsePrecision).
inline const std::vector<std::string> kPrecisionNames = {"double", "float"};
// --precision NAME, one of kPrecisionNames, default shown; parse it with ParsePrecision.
CLI::Option* AddPrecisionOption(CLI::App* command, std::string& precision, const std::string& help);

// Refuses an output whose extension does not match what is written ("render --out m.png"):
// `extension` is ".mp4", ".png", ...; throws InputError naming `flag`.
void CheckExtension(const std::string& path, const std::string& extension, const std::string& flag);

// Every option that takes a value refuses an empty one, in every command at once: "" is never a
// valid path, name or number, and `--resume ""` must not quietly mean "no --resume".
void RefuseEmptyValues(CLI::App& app);

// The one-line error for a diverged run: time, step, reason, and the largest stable step found
// by halving dt (LargestStableStep in sim/evaluate.h; 0 = none found).
std::string DivergenceMessage(const RunResult& result, const RunOptions& options, double stable_dt);

// Under mpirun every rank runs the same command line. A command that can spread its work over
// ranks declares it once, at registration; it then runs on every rank, and its evaluator (or
// task pool) keeps the worker ranks busy until rank 0 is done (eval/mpi_evaluator.h). Every
// other command runs on rank 0 only: LeaveMpiWorkersOut, called once after all commands are
// registered, ends it at once on the others.
void Distributed(CLI::App* command);
void LeaveMpiWorkersOut(CLI::App& app);

// "WxH", each side from 16 to 7680 (width) and 4320 (height); throws InputError.
void ParseSize(const std::string& text, int* width, int* height);

}  // namespace hexgait
