// Optimizers that run in generations and keep the best individual ever seen: what `hexgait
// evolve --algorithm` chooses among (the paper's GA, CMA-ES). The registry names them; adding
// one is a new file defining its OptimizerKind and one line in search/optimizers.cc.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ga/evolution.h"
#include "model/creature.h"
#include "motor/motor_program.h"
#include "search/optimizer.h"

namespace hexgait {

struct OptimizerKind;

class GenerationalOptimizer : public Optimizer {
 public:
  // Every generation's statistics, the best individual ever and the evaluations made.
  virtual const EvolutionResult& result() const = 0;
  // The individuals of the last told generation; those from first_new() on were evaluated in it
  // (the ones before are elites carried over).
  virtual const std::vector<Individual>& generation() const = 0;
  virtual size_t first_new() const = 0;
  virtual const EvolutionParams& params() const = 0;
  // The unoptimised program's result when this process evaluated it (the GA's individual 0 of
  // generation 0), else null.
  virtual const RunResult* unoptimized() const = 0;
  // One line naming the algorithm and its settings, for a run's header.
  virtual std::string Describe() const = 0;
  // Its entry in the registry.
  virtual const OptimizerKind& kind() const = 0;
};

struct OptimizerKind {
  const char* name;               // the --algorithm value
  const char* summary;            // for --help
  const char* checkpoint_format;  // the "format" of its checkpoint file
  int default_population;         // 0: the optimizer picks its own (CMA-ES's lambda)
  const ParamTable* params;       // its own parameters (EvolutionParams::settings)
  // Checks `params` (throws InputError naming the flag) and starts a search.
  std::unique_ptr<GenerationalOptimizer> (*start)(const SearchScene& scene,
                                                  const EvolutionParams& params);
  // Continues the search a checkpoint of this kind saved; throws InputError naming `source`.
  // Sets *unchecked for an old checkpoint without a checksum.
  std::unique_ptr<GenerationalOptimizer> (*resume)(const SearchScene& scene,
                                                   const std::string& text,
                                                   const std::string& source, bool* unchecked);
};

// The registered kinds, the paper's GA first.
const std::vector<const OptimizerKind*>& OptimizerKinds();
// The kind called `name`; throws InputError listing the names.
const OptimizerKind& FindOptimizerKind(const std::string& name);
// The kind whose checkpoint `text` is, by its "format"; the GA's for anything else, whose
// reader then says what is wrong with it.
const OptimizerKind& CheckpointKind(const std::string& text);

}  // namespace hexgait
