// Damage as data: a list of per-leg injuries, parsed from text ("right_front:weak=0.2,
// left_rear:locked"), written back the same way, and applied as a transform of the creature, so
// every path that simulates it (scalar, batched float and double, MPI ranks, Python) sees the
// same damaged creature. For Intelligent Trial and Error (Cully et al., Nature 521, 2015): the
// damaged creature is the "real robot" on which a repertoire's gaits are tried.
#pragma once

#include <string>
#include <vector>

#include "model/creature.h"

namespace hexgait {

enum class DamageKind {
  kWeak,    // weak=F: the leg's motor springs' stiffness and damping times F, F in [0.01, 1]
  kLocked,  // locked: the leg's motor springs keep their rest lengths whatever the program says
  kShort,   // short=F: rest lengths of the springs that reach the leg's foot times F, [0.5, 1]
  // lost: every spring that reaches the leg's foot has no stiffness and no damping, so the foot
  // is a loose particle that neither holds the body up nor pushes it; the closest this model
  // of point masses comes to a leg cut off (docs/model.md, "Adapting to damage").
  kLost,
};

// What --damage takes, for every command's help.
inline constexpr const char* kDamageHelp =
    "LEG:KIND[=F], comma-separated; kinds weak=F (motor springs' stiffness and damping times F "
    "in [0.01,1]), locked (motor springs keep their rest lengths), short=F (foot springs' rest "
    "lengths times F in [0.5,1]), lost (the foot's springs cut: a loose foot); e.g. "
    "right_front:weak=0.2,left_rear:locked";

struct LegDamage {
  int leg = -1;  // index into CreatureModel::legs
  DamageKind kind = DamageKind::kWeak;
  double factor = 1.0;  // weak and short; 1 for locked and lost
};

struct CreatureDamage {
  std::vector<LegDamage> legs;  // in the order written
  bool empty() const { return legs.empty(); }
};

// Parses `text` (empty: no damage) against `model`'s leg names. Throws InputError with one line
// naming the entry at fault: an unknown leg (listing the valid names), an unknown kind, a
// missing, non-numeric or out-of-range factor, or a leg damaged twice with the same kind.
CreatureDamage ParseDamage(const std::string& text, const CreatureModel& model);

// The damage as ParseDamage reads it (shortest round-trip factors); "" for none.
std::string DamageText(const CreatureDamage& damage, const CreatureModel& model);

// The injuries a library of simulated damages holds by default, each on every leg (hexgait
// adapt --library): each kind, and the two with a strength at several
// (scripts/adapt_library_study.py measured what such a library gives).
const std::vector<std::string>& DefaultDamageLibraryKinds();

// Every leg of `model` with each of `kinds` (an injury without its leg: "weak=0.2", "lost"), leg
// by leg, as DamageText writes them. Throws InputError naming a kind that names a leg or does
// not parse.
std::vector<std::string> DamageLibrary(const CreatureModel& model,
                                       const std::vector<std::string>& kinds);

// Damages `model` in place. A model once damaged stays so: apply to a freshly loaded creature.
void ApplyDamage(const CreatureDamage& damage, CreatureModel* model);

}  // namespace hexgait
