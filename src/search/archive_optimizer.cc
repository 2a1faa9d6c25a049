#include "search/archive_optimizer.h"

#include <algorithm>
#include <chrono>

#include "ga/checkpoint.h"
#include "ga/map_elites_checkpoint.h"
#include "ga/rng.h"
#include "ga/variation.h"
#include "search/search_driver.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"

namespace hexgait {

ArchiveOptimizer::ArchiveOptimizer(const ArchiveOptimizerKind& kind, const SearchScene& scene,
                                   MapElitesState state)
    : model_(scene.model),
      program_(scene.program),
      state_(std::move(state)),
      layout_(MakeGenomeLayout(scene.model, scene.program, state_.params.symmetric)),
      descriptor_(FindBehaviourDescriptor(state_.params.descriptor)),
      kind_(kind),
      creature_(scene.creature),
      damage_(scene.model.damage),
      fingerprint_(SceneFingerprint(scene.model, scene.program)),
      step_(scene.program.gene_length_step) {
  ValidateMapElitesParams(state_.params, model_);
  CheckParams(*kind.params, state_.params.settings, kind.name);
}

const Candidates& ArchiveOptimizer::Ask() {
  if (asked_) return candidates_;
  start_ = Clock::now();
  const MapElitesParams& params = state_.params;
  const int count =
      static_cast<int>(std::min<long long>(params.batch, params.evaluations - state_.evaluations));
  Rng rng = Rng::ForStream(params.seed, static_cast<uint64_t>(state_.batches));
  children_ = MakeChildren(std::max(count, 0), rng);
  const int dims = layout_->num_genes();
  candidates_.dims = dims;
  candidates_.offsets.assign(children_.size() * static_cast<size_t>(dims), 0.0);
  for (size_t k = 0; k < children_.size(); ++k) {
    for (int g = 0; g < dims; ++g) {
      candidates_.offsets[k * static_cast<size_t>(dims) + static_cast<size_t>(g)] =
          children_[k].Offset(g, step_);
    }
  }
  follow_ups_.in_double.clear();
  follow_ups_.ran.clear();
  asked_ = true;
  return candidates_;
}

FollowUps* ArchiveOptimizer::follow_ups() {
  if (!asked_ || !state_.params.confirm_in_double || !in_double_) return nullptr;
  // The same test Tell applies: against the archive as the batch began, which nothing changes
  // before Tell, so it may run on any thread while the batch is evaluated.
  follow_ups_.wanted = [this](const RunResult& r) {
    return WouldEnterArchive(state_.archive, descriptor_, model_, r);
  };
  return &follow_ups_;
}

void ArchiveOptimizer::Tell(const std::vector<RunResult>& results) {
  if (!asked_) throw InputError("tell: no batch was asked for");
  if (results.size() != children_.size()) {
    throw InputError("tell: " + std::to_string(results.size()) + " results for " +
                     std::to_string(children_.size()) + " candidates");
  }
  // Under confirm_in_double, the children float would let in (judged against the archive as
  // the batch began) are run again in double before anything changes, and offered with their
  // double results. A child float keeps out is kept out either way: within a batch an elite
  // is only ever replaced by one walking farther, so no cell's bar is lower than it was.
  std::vector<RunResult> offered = results;
  std::vector<char> offer(children_.size(), 1);
  long long confirmed = 0, refuted = 0;
  if (state_.params.confirm_in_double) {
    if (!in_double_) {
      throw InputError("tell: this search confirms admissions in double: no evaluator");
    }
    // Those the evaluator already ran in double beside the batch (follow_ups()) are taken as
    // they are: the same bits as running them here.
    std::vector<size_t> entering;
    Candidates again;
    again.dims = candidates_.dims;
    for (size_t k = 0; k < children_.size(); ++k) {
      if (!WouldEnterArchive(state_.archive, descriptor_, model_, results[k])) {
        offer[k] = 0;
        continue;
      }
      ++confirmed;
      if (k < follow_ups_.ran.size() && follow_ups_.ran[k]) {
        offered[k] = follow_ups_.in_double[k];
        refuted += IsStandingGait(offered[k]) ? 0 : 1;
        continue;
      }
      entering.push_back(k);
      again.offsets.insert(again.offsets.end(), candidates_.row(k),
                           candidates_.row(k) + candidates_.dims);
    }
    if (!entering.empty()) {
      std::vector<RunResult> in_double;
      try {
        in_double = in_double_->Evaluate(decoder_->Decode(again));
      } catch (const EvaluationStopped&) {
        // Nothing is told: the whole batch is what a resumed run evaluates again.
        const int batch = static_cast<int>(children_.size());
        throw EvaluationStopped(batch, batch);
      }
      if (in_double.size() != entering.size()) {
        throw InputError("tell: the confirming evaluator returned the wrong number of results");
      }
      for (size_t i = 0; i < entering.size(); ++i) {
        offered[entering[i]] = in_double[i];
        refuted += IsStandingGait(in_double[i]) ? 0 : 1;
      }
    }
  }
  Learn(offered);
  for (size_t k = 0; k < children_.size(); ++k) {
    if (!offer[k]) continue;
    const RunResult& r = offered[k];
    OfferToArchive(state_.archive, descriptor_, model_,
                   Elite{std::move(children_[k]), r, Fitness(r),
                         state_.evaluations + static_cast<long long>(k) + 1});
  }
  // Taken now, so the state saved between an ask and its tell is the one after the last tell.
  state_.algorithm_state = AlgorithmState();
  state_.evaluations += static_cast<long long>(children_.size());
  ++state_.batches;
  const ArchiveStats before = state_.history.empty() ? ArchiveStats{} : state_.history.back();
  state_.history.push_back(StatsOf(state_.archive, state_.evaluations, SecondsSince(start_)));
  state_.history.back().diverged = before.diverged;
  state_.history.back().confirmed = before.confirmed + confirmed;
  state_.history.back().refuted = before.refuted + refuted;
  for (const RunResult& r : results) state_.history.back().diverged += r.diverged ? 1 : 0;
  children_.clear();
  follow_ups_.in_double.clear();
  follow_ups_.ran.clear();
  asked_ = false;
}

ArchiveOptimizer::~ArchiveOptimizer() = default;

void ArchiveOptimizer::ConfirmWith(Evaluator& in_double) {
  in_double_ = &in_double;
  decoder_ = std::make_unique<CandidateDecoder>(model_, program_, layout_);
}

std::unique_ptr<Evaluator> MakeDoubleEvaluator(const CreatureModel& model,
                                               const MotorProgram& program,
                                               const MapElitesParams& params) {
  EvaluatorConfig config = EvaluatorConfigFor(params);
  config.precision = Precision::kDouble;
  return MakeLocalEvaluator(model, program, config);
}

std::string ArchiveOptimizer::Position() const {
  return "after evaluation " + std::to_string(state_.evaluations) + " of " +
         std::to_string(state_.params.evaluations);
}

std::string ArchiveOptimizer::Save() const {
  return FormatArchive(state_, fingerprint_, creature_, damage_);
}

MapElitesState StartArchiveSearch(MapElitesParams params, const CreatureModel& model) {
  const ArchiveOptimizerKind& kind = FindArchiveOptimizerKind(params.algorithm);
  params.settings = ParamValues::Defaults(*kind.params, params.settings);
  CheckParams(*kind.params, params.settings, kind.name);
  return StartMapElites(params, model);
}

std::unique_ptr<ArchiveOptimizer> MakeArchiveOptimizer(const SearchScene& scene,
                                                       MapElitesState state) {
  const ArchiveOptimizerKind& kind = FindArchiveOptimizerKind(state.params.algorithm);
  return kind.make(scene, std::move(state));
}

void RunArchiveSearch(const CreatureModel& model, const MotorProgram& program, Evaluator& evaluator,
                      MapElitesState& state, const ArchiveCallbacks& callbacks,
                      Evaluator* in_double) {
  const std::unique_ptr<ArchiveOptimizer> optimizer =
      MakeArchiveOptimizer(SearchScene{model, program, ""}, state);
  if (in_double) optimizer->ConfirmWith(*in_double);
  SearchHooks hooks;
  hooks.on_progress = callbacks.on_progress;
  // The caller's state follows every batch, so a callback that throws leaves it current.
  hooks.after_tell = [&] {
    state = optimizer->state();
    if (callbacks.on_batch) callbacks.on_batch(state);
  };
  RunSearch(*optimizer, evaluator, CandidateDecoder(model, program, optimizer->layout()), hooks);
}

std::vector<Genome> ArchiveOptimizer::BreedChildren(
    int count, Rng& rng, const std::function<std::vector<uint8_t>(Rng&)>& breed) const {
  const bool nothing_stands = state_.archive.filled().empty();
  const double initial_mutation_rate = state_.params.settings.Get("initial_mutation_rate");
  std::vector<Genome> children;
  children.reserve(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) {
    std::vector<uint8_t> bits;
    if (!nothing_stands) {
      bits = breed(rng);
    } else {
      bits = Genome(layout_).ToBits();
      // The very first child is the unoptimised program itself.
      if (state_.evaluations + k > 0) MutateBits(bits, initial_mutation_rate, rng);
    }
    Genome child(layout_);
    child.FromBits(bits);
    children.push_back(std::move(child));
  }
  return children;
}

const Genome& ArchiveOptimizer::RandomElite(Rng& rng) const {
  const std::vector<int>& filled = state_.archive.filled();
  return state_.archive.at(filled[rng.NextBelow(static_cast<uint32_t>(filled.size()))])->genome;
}

}  // namespace hexgait
