// One colour per leg, shared by footprints, the footfall strip and the swinging-leg highlight,
// so a mark on the ground, a row of the strip and a lifted leg can be matched by eye. Six
// colours of the Okabe-Ito palette (distinguishable with the common colour-vision
// deficiencies), yellow left out because it vanishes on the light ground.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <string>

#include "model/creature.h"

namespace hexgait {

inline Eigen::Vector3f LegColour(int leg) {
  static const Eigen::Vector3f kColours[6] = {
      {0.835f, 0.369f, 0.000f},  // vermillion
      {0.902f, 0.624f, 0.000f},  // orange
      {0.800f, 0.475f, 0.655f},  // reddish purple
      {0.000f, 0.447f, 0.698f},  // blue
      {0.337f, 0.706f, 0.914f},  // sky blue
      {0.000f, 0.620f, 0.451f},  // bluish green
  };
  return kColours[((leg % 6) + 6) % 6];
}

// A damaged leg (--damage) is drawn in this colour in stills, filmstrips, movies and the replay
// page; red, which no leg cue uses, so that it reads as an injury at a glance.
inline Eigen::Vector3f DamagedLegColour() {
  return {0.90f, 0.12f, 0.12f};
}

// How every caption and page title names a damaged creature and says how it is drawn, from
// its --damage text ("damaged (red): right_front:weak=0.2"; a lost leg is not drawn at all:
// "damaged (lost legs not drawn): left_rear:lost"); "" for an intact one.
inline std::string DamageNote(const std::string& damage) {
  if (damage.empty()) return {};
  bool red = false, lost = false;
  for (size_t begin = 0; begin <= damage.size();) {
    const size_t end = std::min(damage.find(',', begin), damage.size());
    const std::string entry = damage.substr(begin, end - begin);
    (entry.ends_with(":lost") ? lost : red) = true;
    begin = end + 1;
  }
  const std::string how = red && lost ? "red; lost legs not drawn"
                          : red       ? "red"
                                      : "lost legs not drawn";
  return "damaged (" + how + "): " + damage;
}
inline std::string DamageNote(const CreatureModel& model) {
  return DamageNote(model.damage);
}

}  // namespace hexgait
