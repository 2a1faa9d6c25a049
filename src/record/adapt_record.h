// adapt.json as its readers need it (the report page's section on adapting to damage): the
// checked reader, so a file edited by hand, cut short or of another program is refused with a
// one-line error naming the file and the member, never read as undefined or wrapped numbers.
// `hexgait adapt` writes the file (run/adapt_run.cc), with more members than read here.
#pragma once

#include <string>

namespace hexgait {

// The intact scene of the repertoire an adaptation started from (run/folder_scene.h reads it).
struct AdaptScene {
  std::string creature;  // a built-in name or a file
  std::string motor;     // "" for the creature's built-in program
  double dt = 0;
  std::string integrator;
  std::string fingerprint;  // SceneFingerprint in hex
};

struct AdaptSummary {
  std::string repertoire;  // the folder adapted from, as it was given
  bool has_scene = false;  // adapt.json written before it kept its scene has none
  AdaptScene scene;
  std::string damage;        // as ParseDamage reads it back
  double time = 0;           // each trial's run length
  int elites = 0;            // the repertoire's elites, every one run once on the damaged creature
  int trials = 0;            // trials adaptation used
  double stop_fraction = 0;  // of the best prediction, where it stopped
  double adapted = 0;        // the best trial's distance
  double intact_best = 0;    // the intact best gait's distance on the damaged creature
  double best_elite = 0;     // the best elite's distance on the damaged creature
  double random_best = 0;    // the best of as many random elites as trials
  double ga_best = 0;        // the paper's GA from the intact best gait
  int ga_evaluations = 0;
};

// Throws InputError naming `source` and the member when the text is not an adapt.json hexgait
// wrote (not JSON, a member missing or of the wrong type, a count out of range).
AdaptSummary ParseAdaptSummary(const std::string& text, const std::string& source);

}  // namespace hexgait
