// The endurance study into a folder, what `hexgait endurance` runs: how long evolved open-loop
// gaits last past their test, and how fragile they are (study/endurance.h), written as CSVs, a
// survival figure and Markdown tables (report/endurance_report.h) and endurance.json, the folder
// replaced whole. Printing is the caller's, through EnduranceObserver.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "run/scene.h"
#include "study/endurance.h"

namespace hexgait {

struct EnduranceRunSettings {
  SceneOptions scene;
  // The gaits: genome files, evolve folders (their best.genome; default out/run when none of the
  // three is given) and sweep folders (every seed's), grouped by budget.
  std::vector<std::string> genomes, runs, sweeps;
  int random = 20;  // also this many random genomes that stood the test
  int random_tries = 5000;
  double time = kPaperDuration;  // the test
  std::string other_integrator = "symplectic-euler";
  EnduranceSettings settings;
  std::string out_dir = "out/endurance";
};

// What the study reports as it goes; every member may be left empty.
struct EnduranceObserver {
  std::function<void(int wanted, double test_time)> drawing;  // random genomes, before
  std::function<void(size_t found, int tried)> drew;          // and after
  std::function<void(size_t gaits, const std::vector<EnduranceCondition>& conditions, int threads)>
      started;
  Progress progress;  // the study's time units simulated
};

struct EnduranceOutcome {
  std::string tables;  // table.md's text
  double seconds = 0;
};

// Throws InputError on bad input (before any run), Stopped on Ctrl-C (nothing written).
EnduranceOutcome RunEnduranceStudy(EnduranceRunSettings settings,
                                   const EnduranceObserver& observer = {});

}  // namespace hexgait
