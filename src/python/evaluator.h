// hexgait.Evaluator: the simulator as a batched, deterministic fitness function, one whole
// population per call on every thread; the GIL is released while it runs, and one call at a
// time per evaluator (its threads are its own). Also hexgait.simulate, load_genome and
// save_genome.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "eval/evaluator.h"
#include "motor/leg_targets.h"
#include "python/arguments.h"
#include "sim/step_loop.h"

namespace hexgait::python {

namespace py = pybind11;

// What evaluate() computed, whole: the dict's arrays are for reading, this is what Search.tell
// takes, so a Python loop continues with the command's bits.
struct PyRunResults {
  std::vector<RunResult> results;
  uint64_t fingerprint = 0;  // what they answer (search/search_driver.h: EvaluationFingerprint)
};

class PyEvaluator {
 public:
  PyEvaluator(const py::handle& creature, const py::handle& motor, double time, double dt,
              const std::string& integrator, const std::string& precision, int threads,
              bool symmetric, int batch_lanes, bool allow_long, bool stop_at_fall);

  // genomes: (n, genes) integers in [-8, 7]; offsets: (n, genes) rest-length offsets.
  py::dict Evaluate(const py::handle& genomes);
  py::dict EvaluateOffsets(const py::handle& offsets);

  int genes() const { return layout_->num_genes(); }
  double gene_length_step() const { return motor_.program->gene_length_step; }
  std::vector<std::pair<std::string, std::string>> gene_names() const;
  std::string Describe() const { return evaluator_->Describe(); }
  const PyCreature& creature() const { return creature_; }
  const PyMotorProgram& motor() const { return motor_; }
  const EvaluatorConfig& config() const { return config_; }
  const std::shared_ptr<const GenomeLayout>& layout() const { return layout_; }

 private:
  py::dict Run(const std::vector<RestLengthTable>& tables);
  void RefuseLongBatch(size_t creatures) const;

  PyCreature creature_;
  PyMotorProgram motor_;
  bool allow_long_ = false;
  EvaluatorConfig config_;
  std::shared_ptr<const GenomeLayout> layout_;
  RestLengthTable geometric_;
  std::unique_ptr<Evaluator> evaluator_;
  std::mutex mutex_;
};

}  // namespace hexgait::python
