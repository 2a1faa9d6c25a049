// One run of one genome, as `hexgait simulate` and Python's simulate() make it: the result, and
// on request a trace (body centre, lowest body particle, tilt, feet on the ground every
// `interval`) and every particle's position at chosen times. The run goes in chunks so a long
// one can show progress; the chunks give the same bits as one piece.
#pragma once

#include <vector>

#include "run/scene.h"
#include "sim/trace.h"

namespace hexgait {

struct SimulateRequest {
  double interval = 0;  // > 0: a trace sample every `interval` time units (the nearest step)
  std::vector<double> positions_at;  // times at which every particle's position is kept
};

struct SimulatedRun {
  RunResult result;
  std::vector<TraceSample> samples;  // the trace, from t = 0; empty without one
  // positions[i] holds x, y, z of every particle at position_steps[i], in the order asked.
  std::vector<long long> position_steps;
  std::vector<std::vector<double>> positions;
  double seconds = 0;  // wall time of the run
};

// Checks the request against `run` (the interval between dt and the run's time, every position
// time inside it; InputError naming `interval_name` or positions_at), runs, and refuses a
// diverged run with the largest stable step (InputError).
SimulatedRun SimulateGenome(const Scene& scene, const Genome& genome, const RunOptions& run,
                            const SimulateRequest& request, const std::string& interval_name,
                            const Progress& progress = {});

// The trace as `simulate --csv` writes it: time, the body centre, the lowest body particle, the
// tilt, and per leg whether its foot is on the ground.
std::string TraceCsv(const CreatureModel& model, const std::vector<TraceSample>& samples);

// `hexgait simulate`: one run of one genome, its trace written to `csv_path` when given ("-":
// kept for standard output, `csv_text`).
struct SimulateFile {
  SceneOptions scene;
  GenomeChoice genome;
  double time = kPaperDuration;
  std::string csv_path;  // "" none, "-" standard output
  double csv_interval = 0.1;
  bool early_stop = false;
  bool json = false;  // the report goes to standard output, which "-" cannot share
};
struct SimulatedFile {
  SimulatedRun simulated;
  RunOptions run;
  Scene scene;
  std::string label;     // the genome's name
  std::string csv_text;  // the trace, when csv_path is "-"
};
// Every check before any work, in this order: the run's length, --csv - against --json, the
// inputs and the --csv file, --csv-interval, the scene, the genome; then the run, and its trace
// written atomically (never a partial table of a failed or stopped run).
SimulatedFile SimulateToFile(const SimulateFile& request, const Progress& progress = {});

}  // namespace hexgait
