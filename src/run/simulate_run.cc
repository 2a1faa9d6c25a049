#include "run/simulate_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "run/io_paths.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {
namespace {

// The trace and the positions at the wanted steps (sorted), in one observer.
class RunRecorder {
 public:
  RunRecorder(const CreatureModel& model, long long every, std::vector<long long> steps)
      : trace_(model, every), steps_(std::move(steps)) {}
  void OnStep(const SimState& s) {
    trace_.OnStep(s);
    Capture(s);
  }
  // The state before the first step (time 0).
  void Start(const SimState& s) {
    trace_.Record(s);
    Capture(s);
  }
  const TraceRecorder& trace() const { return trace_; }
  std::vector<std::vector<double>>& positions() { return positions_; }

 private:
  void Capture(const SimState& s) {
    while (next_ < steps_.size() && steps_[next_] == s.step) {
      std::vector<double> xyz;
      xyz.reserve(static_cast<size_t>(s.num_particles()) * 3);
      for (int p = 0; p < s.num_particles(); ++p) xyz.insert(xyz.end(), {s.x[p], s.y[p], s.z[p]});
      positions_.push_back(std::move(xyz));
      ++next_;
    }
  }
  TraceRecorder trace_;
  std::vector<long long> steps_;  // sorted
  size_t next_ = 0;
  std::vector<std::vector<double>> positions_;
};

}  // namespace

SimulatedRun SimulateGenome(const Scene& scene, const Genome& genome, const RunOptions& run,
                            const SimulateRequest& request, const std::string& interval_name,
                            const Progress& progress) {
  const bool traced = request.interval > 0;
  if (traced && !(request.interval >= run.dt && request.interval <= run.duration)) {
    throw InputError(interval_name + " must be between " +
                     (interval_name == "interval" ? "dt and time" : "--dt and --time"));
  }
  SimulatedRun out;
  for (double t : request.positions_at) {
    if (!(t >= 0 && t <= run.duration)) {
      throw InputError("positions_at: time " + std::to_string(t) + " is outside [0, time]");
    }
    out.position_steps.push_back(std::llround(t / run.dt));
  }
  const RestLengthTable table = PerturbedRestLengths(scene.model, scene.program, genome);
  MotorController controller(scene.model, scene.program, table, run.dt);
  SimState state = MakeRestState(scene.model);
  const auto on_chunk = [&](long long done, long long total) {
    if (progress) progress("steps", done, total);
  };
  constexpr long long kChunkSteps = 1 << 16;
  const auto start = Clock::now();
  if (!traced && request.positions_at.empty()) {
    NullObserver none;
    out.result = SimulateInChunks(scene.model, controller, state, run, none, kChunkSteps, on_chunk);
  } else {
    std::vector<long long> sorted = out.position_steps;
    std::sort(sorted.begin(), sorted.end());
    const long long every =
        traced ? std::max(1LL, std::llround(request.interval / run.dt)) : (1LL << 62);
    RunRecorder recorder(scene.model, every, sorted);
    recorder.Start(state);
    out.result =
        SimulateInChunks(scene.model, controller, state, run, recorder, kChunkSteps, on_chunk);
    if (traced) out.samples = recorder.trace().samples();
    // Captured in step order, handed back in the order asked.
    std::vector<size_t> order(out.position_steps.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return out.position_steps[a] < out.position_steps[b];
    });
    out.positions.resize(order.size());
    for (size_t rank = 0; rank < order.size() && rank < recorder.positions().size(); ++rank) {
      out.positions[order[rank]] = std::move(recorder.positions()[rank]);
    }
  }
  out.seconds = SecondsSince(start);
  // A diverged run has no distance worth reporting and no trace worth keeping.
  if (out.result.diverged) {
    throw InputError(DivergenceMessage(out.result, run,
                                       LargestStableStep(scene.model, scene.program, table, run)));
  }
  return out;
}

std::string TraceCsv(const CreatureModel& model, const std::vector<TraceSample>& samples) {
  std::ostringstream out;
  out << "time,centre_x,centre_y,centre_z,lowest_body_z,tilt_degrees";
  for (const Leg& leg : model.legs) out << ",foot_" << leg.name;
  out << '\n';
  char line[256];
  for (const TraceSample& s : samples) {
    std::snprintf(line, sizeof line, "%.4f,%.6f,%.6f,%.6f,%.6f,%.3f", s.time, s.centre.x(),
                  s.centre.y(), s.centre.z(), s.lowest_body, s.tilt_degrees);
    out << line;
    for (size_t leg = 0; leg < model.legs.size(); ++leg) {
      out << ',' << ((s.feet_on_ground >> leg) & 1u);
    }
    out << '\n';
  }
  return out.str();
}

SimulatedFile SimulateToFile(const SimulateFile& request, const Progress& progress) {
  SimulatedFile out;
  out.run = MakeRunOptions(request.scene, request.time);
  out.run.early_stop = request.early_stop;
  const bool trace = !request.csv_path.empty();
  const bool csv_to_stdout = request.csv_path == "-";
  if (csv_to_stdout && request.json) {
    throw InputError("--csv - and --json both write to standard output; choose one");
  }
  IoPaths paths = SceneInputs(request.scene, &request.genome);
  if (trace && !csv_to_stdout) {
    paths.Output("--csv", request.csv_path).Check();
    CheckOutputPath(request.csv_path, "--csv");
  } else {
    paths.Check();
  }
  if (trace &&
      !(request.csv_interval >= request.scene.dt && request.csv_interval <= request.time)) {
    throw InputError("--csv-interval must be between --dt and --time");
  }
  out.scene = LoadScene(request.scene);
  const Genome genome = LoadGenomeChoice(request.genome, out.scene, &out.label);
  SimulateRequest simulate;
  if (trace) simulate.interval = request.csv_interval;
  out.simulated = SimulateGenome(out.scene, genome, out.run, simulate, "--csv-interval", progress);
  if (csv_to_stdout) {
    out.csv_text = TraceCsv(out.scene.model, out.simulated.samples);
  } else if (trace) {
    WriteFileAtomically(request.csv_path, TraceCsv(out.scene.model, out.simulated.samples));
  }
  return out;
}

}  // namespace hexgait
