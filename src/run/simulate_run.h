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

}  // namespace hexgait
