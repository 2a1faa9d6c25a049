#include "model/damage.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "util/error.h"

namespace hexgait {
namespace {

const char* KindName(DamageKind kind) {
  switch (kind) {
    case DamageKind::kWeak:
      return "weak";
    case DamageKind::kLocked:
      return "locked";
    case DamageKind::kShort:
      return "short";
    case DamageKind::kLost:
      return "lost";
  }
  return "?";
}

constexpr const char* kKinds = "weak=F, locked, short=F, lost";

std::string LegNames(const CreatureModel& model) {
  std::string names;
  for (const Leg& leg : model.legs) names += (names.empty() ? "" : ", ") + leg.name;
  return names;
}

std::string FactorText(double factor) {
  char text[32];
  const auto r = std::to_chars(text, text + sizeof text, factor);
  return std::string(text, r.ptr);
}

// One entry, LEG:KIND[=FACTOR]; `entry` is quoted in every message.
LegDamage ParseEntry(const std::string& entry, const CreatureModel& model) {
  const std::string where = "--damage entry '" + entry + "'";
  const size_t colon = entry.find(':');
  if (colon == std::string::npos) {
    throw InputError(where + " must be LEG:KIND (kinds: " + std::string(kKinds) + ")");
  }
  LegDamage d;
  const std::string leg = entry.substr(0, colon);
  d.leg = model.LegIndex(leg);
  if (d.leg < 0) {
    throw InputError(where + ": unknown leg '" + leg + "' (legs: " + LegNames(model) + ")");
  }
  const std::string rest = entry.substr(colon + 1);
  const size_t eq = rest.find('=');
  const std::string kind = rest.substr(0, eq);
  if (kind == "weak") {
    d.kind = DamageKind::kWeak;
  } else if (kind == "locked") {
    d.kind = DamageKind::kLocked;
  } else if (kind == "short") {
    d.kind = DamageKind::kShort;
  } else if (kind == "lost") {
    d.kind = DamageKind::kLost;
  } else {
    throw InputError(where + ": unknown kind '" + kind + "' (kinds: " + std::string(kKinds) + ")");
  }
  if (d.kind == DamageKind::kLocked || d.kind == DamageKind::kLost) {
    if (eq != std::string::npos) throw InputError(where + ": " + kind + " takes no factor");
    return d;
  }
  // weak: [0.01, 1]: 1 is intact, above 1 a stronger leg is no damage, and 0 would be a severed
  // leg, which is not a weakened one (its foot would hang on the passive springs alone); below
  // a hundredth the leg is severed in all but name (and 5e-324 is a stiffness lost in rounding).
  // short: [0.5, 1]: above 1 a longer leg is no damage; below a half the foot's springs would
  // pull the foot up to the body (its springs are the only thing holding it off).
  const bool weak = d.kind == DamageKind::kWeak;
  const std::string range = weak ? "[0.01, 1]" : "[0.5, 1]";
  if (eq == std::string::npos || eq + 1 == rest.size()) {
    throw InputError(where + ": " + kind + " needs a factor (" + kind + "=F, F in " + range + ")");
  }
  const std::string number = rest.substr(eq + 1);
  char* end = nullptr;
  d.factor = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !std::isfinite(d.factor)) {
    throw InputError(where + ": factor '" + number + "' is not a number");
  }
  const bool in_range = weak ? d.factor >= 0.01 && d.factor <= 1 : d.factor >= 0.5 && d.factor <= 1;
  if (!in_range) {
    throw InputError(where + ": factor " + number + " is outside " + range + " for " + kind);
  }
  return d;
}

}  // namespace

CreatureDamage ParseDamage(const std::string& text, const CreatureModel& model) {
  CreatureDamage damage;
  if (text.empty()) return damage;
  size_t begin = 0;
  while (true) {
    const size_t comma = text.find(',', begin);
    const std::string entry = text.substr(begin, comma - begin);
    if (entry.empty()) throw InputError("--damage '" + text + "' has an empty entry");
    const LegDamage d = ParseEntry(entry, model);
    for (const LegDamage& other : damage.legs) {
      if (other.leg == d.leg && other.kind == d.kind) {
        throw InputError("--damage damages leg " + model.legs[d.leg].name + " twice with " +
                         KindName(d.kind));
      }
    }
    damage.legs.push_back(d);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return damage;
}

std::string DamageText(const CreatureDamage& damage, const CreatureModel& model) {
  std::string text;
  for (const LegDamage& d : damage.legs) {
    if (!text.empty()) text += ',';
    text += model.legs[d.leg].name + ':' + KindName(d.kind);
    if (d.kind == DamageKind::kWeak || d.kind == DamageKind::kShort) {
      text += '=' + FactorText(d.factor);
    }
  }
  return text;
}

const std::vector<std::string>& DefaultDamageLibraryKinds() {
  static const std::vector<std::string> kinds = {"weak=0.1",  "weak=0.2",  "weak=0.3",
                                                 "weak=0.5",  "short=0.7", "short=0.8",
                                                 "short=0.9", "locked",    "lost"};
  return kinds;
}

std::vector<std::string> DamageLibrary(const CreatureModel& model,
                                       const std::vector<std::string>& kinds) {
  std::vector<std::string> library;
  for (const Leg& leg : model.legs) {
    for (const std::string& kind : kinds) {
      if (kind.find(':') != std::string::npos || kind.find(',') != std::string::npos) {
        throw InputError("library kind '" + kind +
                         "': one injury without its leg, e.g. weak=0.2 (every leg gets it)");
      }
      try {
        library.push_back(DamageText(ParseDamage(leg.name + ':' + kind, model), model));
      } catch (const InputError& error) {
        throw InputError("library kind '" + kind + "': " + error.what());
      }
    }
  }
  return library;
}

void ApplyDamage(const CreatureDamage& damage, CreatureModel* model) {
  if (damage.empty()) return;
  // Sized on the first damage only: an intact creature keeps them empty (creature.h).
  model->spring_locked.resize(model->num_springs(), 0);
  model->motor_length_scale.resize(model->num_springs(), 1.0);
  model->leg_damaged.resize(model->legs.size(), 0);
  for (const LegDamage& d : damage.legs) model->leg_damaged[d.leg] = 1;
  const std::string text = DamageText(damage, *model);
  model->damage += (model->damage.empty() ? "" : ",") + text;
  for (const LegDamage& d : damage.legs) {
    const Leg& leg = model->legs[d.leg];
    switch (d.kind) {
      case DamageKind::kWeak:
        for (int s : leg.springs) {
          model->stiffness[s] *= d.factor;
          model->damping[s] *= d.factor;
        }
        break;
      case DamageKind::kLocked:
        for (int s : leg.springs) model->spring_locked[s] = 1;
        break;
      case DamageKind::kShort:
        // Every spring that reaches the foot, motor or not. A motor spring's rest length is
        // replaced by the program's table at its first instruction, so its scale also goes
        // into the table (motor/leg_targets.cc); rest_length covers the time before that and
        // a locked leg.
        for (int s = 0; s < model->num_springs(); ++s) {
          if (model->spring_a[s] != leg.foot && model->spring_b[s] != leg.foot) continue;
          model->rest_length[s] *= d.factor;
          if (model->spring_motor[s]) model->motor_length_scale[s] *= d.factor;
        }
        break;
      case DamageKind::kLost:
        for (int s = 0; s < model->num_springs(); ++s) {
          if (model->spring_a[s] != leg.foot && model->spring_b[s] != leg.foot) continue;
          model->stiffness[s] = 0;
          model->damping[s] = 0;
        }
        model->lost_legs |= 1u << d.leg;
        break;
    }
  }
}

}  // namespace hexgait
