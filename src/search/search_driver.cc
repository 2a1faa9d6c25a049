#include "search/search_driver.h"

#include <chrono>

#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "util/clock.h"
#include "util/stop_signal.h"

namespace hexgait {

CandidateDecoder::CandidateDecoder(const CreatureModel& model, const MotorProgram& program,
                                   std::shared_ptr<const GenomeLayout> layout)
    : model_(model), layout_(std::move(layout)), geometric_(GeometricRestLengths(model, program)) {}

std::vector<RestLengthTable> CandidateDecoder::Decode(const Candidates& candidates) const {
  std::vector<RestLengthTable> tables;
  tables.reserve(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) {
    tables.push_back(OffsetRestLengths(geometric_, model_, *layout_, candidates.row(i)));
  }
  return tables;
}

uint64_t EvaluationFingerprint(const CreatureModel& model, const MotorProgram& program,
                               const RunOptions& run, Precision precision,
                               const std::vector<RestLengthTable>& tables) {
  Fingerprint f;
  f.Add(static_cast<long long>(SceneFingerprint(model, program)));
  f.Add(run.duration);
  f.Add(run.dt);
  f.Add(static_cast<long long>(run.integrator));
  f.Add(static_cast<long long>(run.stop_at_fall));
  f.Add(static_cast<long long>(precision));
  for (const RestLengthTable& table : tables) f.AddAll(table.length);
  return f.value();
}

void SearchStep(Optimizer& optimizer, Evaluator& evaluator, const CandidateDecoder& decoder,
                const Progress& on_progress) {
  const std::vector<RestLengthTable> tables = decoder.Decode(optimizer.Ask());
  FollowUps* follow_ups = optimizer.follow_ups();
  optimizer.Tell(follow_ups ? evaluator.EvaluateWithFollowUps(tables, *follow_ups, on_progress)
                            : evaluator.Evaluate(tables, on_progress));
}

void RunSearch(Optimizer& optimizer, Evaluator& evaluator, const CandidateDecoder& decoder,
               const SearchHooks& hooks) {
  auto last_save = Clock::now();
  // The evaluator counts within its batch; the run's progress adds the evaluations told before.
  Progress in_batch;
  if (hooks.on_progress) {
    in_batch = [&](std::string_view stage, long long done, long long) {
      hooks.on_progress(stage, optimizer.evaluations() + done, optimizer.budget());
    };
  }
  while (!optimizer.Done()) {
    try {
      SearchStep(optimizer, evaluator, decoder, in_batch);
    } catch (const EvaluationStopped& stopped) {
      // Stopped within the population: nothing was told, so the saved state is the one after
      // the last Tell, and a resumed run asks for the same population again. Before the first
      // Tell there is no state to keep: the same command starts the run again.
      if (optimizer.evaluations() == 0) {
        throw Stopped("before the first " + std::to_string(stopped.total) +
                      " simulations were done; nothing to keep: run the same command again");
      }
      if (hooks.save) hooks.save(optimizer.Save());
      throw Stopped(optimizer.Position() + "; the " + std::to_string(stopped.total) +
                    " simulations under way were dropped and run again on resume" +
                    (hooks.save ? hooks.resume_hint : std::string()));
    }
    if (hooks.after_tell) hooks.after_tell();
    const bool stop = StopRequested();
    const double since_save = SecondsSince(last_save);
    if (hooks.save && (optimizer.Done() || stop || since_save >= hooks.save_every_seconds)) {
      hooks.save(optimizer.Save());
      last_save = Clock::now();
    }
    if (stop && !optimizer.Done()) {
      throw Stopped(optimizer.Position() + (hooks.save ? hooks.resume_hint : std::string()));
    }
  }
}

}  // namespace hexgait
