#include "ga/behaviour.h"

#include <algorithm>

#include "util/error.h"

namespace hexgait {
namespace {

// Each leg's duty factor, in the model's leg order (Cully et al.'s descriptor).
std::vector<std::string> LegAxes(const CreatureModel& model) {
  std::vector<std::string> axes;
  for (const Leg& leg : model.legs) axes.push_back(leg.name);
  return axes;
}

void DutyFactors(const CreatureModel& model, const RunResult& result, double* out) {
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    out[leg] = result.DutyFactor(static_cast<int>(leg));
  }
}

// The legs of each mirror pair (a leg without a mirror is a pair of its own), first leg first.
std::vector<std::vector<int>> MirrorPairs(const CreatureModel& model) {
  std::vector<std::vector<int>> pairs;
  std::vector<bool> taken(model.legs.size(), false);
  for (size_t leg = 0; leg < model.legs.size(); ++leg) {
    if (taken[leg]) continue;
    std::vector<int> pair = {static_cast<int>(leg)};
    taken[leg] = true;
    const int mirror = model.legs[leg].mirror;
    if (mirror >= 0 && !taken[static_cast<size_t>(mirror)]) {
      pair.push_back(mirror);
      taken[static_cast<size_t>(mirror)] = true;
    }
    pairs.push_back(pair);
  }
  return pairs;
}

// The mean duty factor of each mirror pair (rear, middle, front on the hexapod): a coarser
// map that tells front-to-back patterns apart and ignores the left-right ones.
std::vector<std::string> PairAxes(const CreatureModel& model) {
  std::vector<std::string> axes;
  for (const std::vector<int>& pair : MirrorPairs(model)) {
    std::string name = model.legs[static_cast<size_t>(pair[0])].name;
    if (pair.size() > 1) name += "+" + model.legs[static_cast<size_t>(pair[1])].name;
    axes.push_back(name);
  }
  return axes;
}

void PairDutyFactors(const CreatureModel& model, const RunResult& result, double* out) {
  const std::vector<std::vector<int>> pairs = MirrorPairs(model);
  for (size_t p = 0; p < pairs.size(); ++p) {
    double sum = 0;
    for (int leg : pairs[p]) sum += result.DutyFactor(leg);
    out[p] = sum / static_cast<double>(pairs[p].size());
  }
}

}  // namespace

const std::vector<BehaviourDescriptor>& BehaviourDescriptors() {
  static const std::vector<BehaviourDescriptor> descriptors = {
      {"duty", "each leg's fraction of the walk on the ground (Cully et al. 2015)", LegAxes,
       DutyFactors},
      {"pairs", "the mean duty factor of each pair of mirror-image legs", PairAxes,
       PairDutyFactors},
  };
  return descriptors;
}

const BehaviourDescriptor& FindBehaviourDescriptor(const std::string& name) {
  std::string known;
  for (const BehaviourDescriptor& d : BehaviourDescriptors()) {
    if (d.name == name) return d;
    known += (known.empty() ? "" : ", ") + d.name;
  }
  throw InputError("--descriptor '" + name + "': unknown (known: " + known + ")");
}

std::vector<double> BehaviourOf(const CreatureModel& model, const BehaviourDescriptor& descriptor,
                                const RunResult& result) {
  std::vector<double> b(static_cast<size_t>(kMaxLegs * 2));
  descriptor.measure(model, result, b.data());
  b.resize(descriptor.axes(model).size());
  return b;
}

}  // namespace hexgait
