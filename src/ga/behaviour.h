// Behaviour descriptors for MAP-Elites (ga/map_elites.h): what a gait does, as a point in
// [0, 1]^dims, measured from its run's result. The default is Cully et al.'s (Nature 2015):
// each leg's duty factor, the fraction of the walk its foot is on the ground. A new descriptor
// is one function in behaviour.cc and one line in its table.
#pragma once

#include <string>
#include <vector>

#include "model/creature.h"
#include "sim/step_loop.h"

namespace hexgait {

struct BehaviourDescriptor {
  std::string name;         // as --descriptor takes it
  std::string description;  // one line for --help and the report
  // The axes' names for this creature (their count is the archive's dimension).
  std::vector<std::string> (*axes)(const CreatureModel& model);
  // Writes axes(model).size() coordinates in [0, 1] for `result`.
  void (*measure)(const CreatureModel& model, const RunResult& result, double* out);
};

// Every descriptor, the default first.
const std::vector<BehaviourDescriptor>& BehaviourDescriptors();
// The descriptor called `name`; throws InputError listing the known names.
const BehaviourDescriptor& FindBehaviourDescriptor(const std::string& name);

// `result`'s coordinates under `descriptor`, one per axis.
std::vector<double> BehaviourOf(const CreatureModel& model, const BehaviourDescriptor& descriptor,
                                const RunResult& result);

}  // namespace hexgait
