// CMA-ES (the covariance matrix adaptation evolution strategy) over the continuous rest-length
// offsets, one generation of lambda candidates per ask and tell: the distribution of
// search/cma_distribution.h with its default parameters for n = 120 offsets (or 60 with
// --symmetric), bounded to the genes' range [-8, 7] gene steps; the update uses the candidates
// as evaluated. Fitness is the distance walked, maximised. Debian packages no C++ CMA-ES, so it
// is written here on Eigen.
//
// The normal samples of generation g come from the stream (seed, g) (ga/rng.h, Box-Muller), so
// a checkpoint holds only the distribution (mean, step size, covariance, evolution paths) and
// the history, and a resumed run gives the same bits as one never interrupted.
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "ga/checkpoint.h"
#include "ga/checkpoint_json.h"
#include "ga/rng.h"
#include "search/cma_distribution.h"
#include "search/generational.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {

extern const OptimizerKind kCmaEsOptimizer;

namespace {

using nlohmann::json;
using Vector = Eigen::VectorXd;

constexpr const char* kFormat = "hexgait cmaes checkpoint";
constexpr int kVersion = 1;
const ParamTable kParams = {
    {"sigma", false, 2.0, 0.001, 16, "Initial step size, in gene steps"},
};

void CheckSearchParams(const EvolutionParams& p, int n) {
  if (p.population != 0 && p.population < 4) {
    throw InputError("--population must be at least 4 for cmaes (0: the default, " +
                     std::to_string(DefaultCmaLambda(n)) + ")");
  }
  if (p.population > 100000) throw InputError("--population must be at most 100000");
  if (p.generations < 1) throw InputError("--generations must be at least 1");
  if (p.generations > 100000) throw InputError("--generations must be at most 100000");
  CheckParams(kParams, p.settings, "cmaes");
  if (!p.start.empty()) throw InputError("cmaes starts from the unoptimised program, not a genome");
  CheckEvaluatorConfig(EvaluatorConfigOf(p));
}

class CmaEsOptimizer final : public GenerationalOptimizer {
 public:
  CmaEsOptimizer(const SearchScene& scene, const EvolutionParams& params)
      : params_(params),
        layout_(MakeGenomeLayout(scene.model, scene.program, params.symmetric)),
        n_(layout_->num_genes()),
        step_(scene.program.gene_length_step),
        lower_(kGeneMin * step_),
        upper_(kGeneMax * step_),
        fingerprint_(SceneFingerprint(scene.model, scene.program)),
        creature_(scene.creature),
        damage_(scene.model.damage) {
    CheckSearchParams(params_, n_);
    if (params_.population == 0) params_.population = DefaultCmaLambda(n_);
    lambda_ = params_.population;
    // The unoptimised program is the start: mean zero offsets, sigma in gene steps.
    cma_ = std::make_unique<CmaDistribution>(lambda_, Vector::Zero(n_),
                                             params_.settings.Get("sigma") * step_);
  }

  const Candidates& Ask() override {
    if (asked_) return candidates_;
    start_ = Clock::now();
    Rng rng = Rng::ForStream(params_.seed, static_cast<uint64_t>(generation_ + 1));
    candidates_.dims = n_;
    candidates_.offsets.assign(static_cast<size_t>(lambda_) * n_, 0.0);
    for (int k = 0; k < lambda_; ++k) {
      const Vector x = cma_->Sample(rng, lower_, upper_);
      std::copy(x.data(), x.data() + n_, candidates_.offsets.data() + static_cast<size_t>(k) * n_);
    }
    asked_ = true;
    return candidates_;
  }

  void Tell(const std::vector<RunResult>& results) override {
    if (!asked_) throw InputError("tell: no batch was asked for");
    if (results.size() != static_cast<size_t>(lambda_)) {
      throw InputError("tell: " + std::to_string(results.size()) + " results for " +
                       std::to_string(lambda_) + " candidates");
    }
    population_.clear();
    for (int k = 0; k < lambda_; ++k) {
      Individual ind{Genome::FromOffsets(layout_, candidates_.row(static_cast<size_t>(k))),
                     results[static_cast<size_t>(k)], 0};
      ind.fitness = Fitness(ind.result);
      population_.push_back(std::move(ind));
    }
    // Best first; ties keep the lower index first.
    std::vector<int> order(static_cast<size_t>(lambda_));
    for (int k = 0; k < lambda_; ++k) order[static_cast<size_t>(k)] = k;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return population_[static_cast<size_t>(a)].fitness >
             population_[static_cast<size_t>(b)].fitness;
    });
    std::vector<const double*> best_first;
    for (int k : order) best_first.push_back(candidates_.row(static_cast<size_t>(k)));
    const int g = generation_ + 1;
    if (!cma_->Update(best_first, g)) {
      throw std::runtime_error("CMA-ES: the step size is no longer a positive number");
    }

    generation_ = g;
    GenerationStats stats = SummariseGeneration(g, population_);
    stats.evaluations = lambda_;
    for (const RunResult& r : results) stats.diverged += r.diverged ? 1 : 0;
    stats.seconds = SecondsSince(start_);
    result_.total_evaluations += lambda_;
    if (!result_.best ||
        population_[static_cast<size_t>(stats.best_index)].fitness > result_.best->fitness) {
      result_.best = population_[static_cast<size_t>(stats.best_index)];
    }
    result_.history.push_back(stats);
    asked_ = false;
  }

  bool Done() const override { return generation_ >= params_.generations; }
  long long evaluations() const override { return result_.total_evaluations; }
  long long budget() const override {
    return static_cast<long long>(lambda_) * (params_.generations + 1);
  }
  std::string Position() const override {
    char text[64];
    std::snprintf(text, sizeof text, "after generation %d of %d", generation_, params_.generations);
    return text;
  }
  const std::shared_ptr<const GenomeLayout>& layout() const override { return layout_; }
  const EvolutionResult& result() const override { return result_; }
  const std::vector<Individual>& generation() const override { return population_; }
  size_t first_new() const override { return 0; }
  const EvolutionParams& params() const override { return params_; }
  const RunResult* unoptimized() const override { return nullptr; }
  const OptimizerKind& kind() const override { return kCmaEsOptimizer; }
  std::string Describe() const override {
    char text[192];
    std::snprintf(text, sizeof text,
                  "CMA-ES: lambda %d, mu %d, %d generations, sigma %g gene steps, seed %llu, %d "
                  "offsets",
                  lambda_, cma_->mu(), params_.generations, params_.settings.Get("sigma"),
                  static_cast<unsigned long long>(params_.seed), n_);
    return text;
  }

  std::string Save() const override {
    json j;
    AddFormatHeader(j, kFormat, kVersion);
    j["scene_fingerprint"] = Hex(fingerprint_);
    if (!creature_.empty()) j["creature"] = creature_;
    if (!damage_.empty()) j["damage"] = damage_;
    j["params"] = EvolutionParamsJson(params_);
    j["generation"] = generation_;
    j["total_evaluations"] = result_.total_evaluations;
    cma_->Save(j);
    j["history"] = HistoryJson(result_.history);
    const auto individual = [](const Individual& ind) {
      json offsets = json::array();
      for (double v : ind.genome.offsets()) offsets.push_back(Number(v));
      return json{{"offsets", offsets},
                  {"fitness", Number(ind.fitness)},
                  {"result", ResultJson(ind.result)}};
    };
    j["best"] = result_.best ? individual(*result_.best) : json(nullptr);
    j["checksum"] = Checksum(j);
    return j.dump(1) + "\n";
  }

  void Load(const std::string& text, const std::string& source) {
    const json root = ParseJson(text, source, kMaxCheckpointBytes);
    const JsonReader r(root, source, "");
    if (!root.is_object()) r.Fail("not a checkpoint (expected a JSON object)");
    std::vector<std::string> keys = FormatHeaderKeys();
    keys.insert(keys.end(), {"scene_fingerprint", "creature", "damage", "params", "generation",
                             "total_evaluations", "step_size", "mean", "path_c", "path_sigma",
                             "covariance", "history", "best", "checksum"});
    r.RequireOnlyKeys(keys);
    if (r.String("format") != kFormat) r.Fail("not a hexgait cmaes checkpoint");
    if (ReadFormatVersion(r) != kVersion) r.Fail("checkpoint version is not supported");
    if (r.Has("creature")) r.String("creature");
    if (r.Has("damage")) r.String("damage");
    if (r.String("scene_fingerprint") != Hex(fingerprint_)) {
      r.Fail(
          "was made with a different creature or motor program (pass the same --creature, "
          "--damage and "
          "--motor as the interrupted run)");
    }
    generation_ = r.Integer("generation");
    if (generation_ < 0 || generation_ > params_.generations) {
      r.Fail("'generation' must be in [0, " + std::to_string(params_.generations) + "]");
    }
    result_.total_evaluations = r.Integer("total_evaluations");
    if (result_.total_evaluations != lambda_ * (generation_ + 1)) {
      r.Fail("'total_evaluations' does not match the generations");
    }
    cma_->Load(r);
    result_.history = ReadHistory(r.Child("history"), generation_ + 1);
    for (size_t i = 0; i < result_.history.size(); ++i) {
      if (result_.history[i].generation != static_cast<int>(i) ||
          result_.history[i].evaluations != lambda_) {
        r.Fail("history[" + std::to_string(i) + "]: generation or evaluations do not match");
      }
    }
    const JsonReader best = r.Child("best");
    best.RequireOnlyKeys({"offsets", "fitness", "result"});
    const Vector offsets = ReadVector(best, "offsets", n_);
    Individual ind{Genome::FromOffsets(layout_, offsets.data()), ReadResult(best.Child("result")),
                   ReadNumber(best, "fitness")};
    if (ind.fitness != Fitness(ind.result)) best.Fail("fitness does not match its result");
    result_.best = std::move(ind);
    if (r.String("checksum") != Checksum(root)) {
      r.Fail(
          "checksum does not match the content (the file was edited or damaged); resume "
          "from an unedited checkpoint or start a new run");
    }
  }

 private:
  EvolutionParams params_;
  std::shared_ptr<const GenomeLayout> layout_;
  int n_;
  double step_, lower_, upper_;
  uint64_t fingerprint_;
  std::string creature_;
  std::string damage_;  // the creature's --damage, recorded beside it

  int lambda_ = 0;
  std::unique_ptr<CmaDistribution> cma_;
  int generation_ = -1;  // last told
  EvolutionResult result_;
  std::vector<Individual> population_;

  bool asked_ = false;
  Candidates candidates_;
  Clock::time_point start_;
};

std::unique_ptr<GenerationalOptimizer> StartCmaEs(const SearchScene& scene,
                                                  const EvolutionParams& params) {
  return std::make_unique<CmaEsOptimizer>(scene, params);
}

EvolutionParams ReadCmaEsParams(const std::string& text, const std::string& source) {
  const json root = ParseJson(text, source, kMaxCheckpointBytes);
  const JsonReader r(root, source, "");
  if (!root.is_object()) r.Fail("not a checkpoint (expected a JSON object)");
  return ReadEvolutionParams(r.Child("params"));
}

std::unique_ptr<GenerationalOptimizer> ResumeCmaEs(const SearchScene& scene,
                                                   const std::string& text,
                                                   const std::string& source, bool* unchecked) {
  EvolutionParams params;
  try {
    params = ReadCmaEsParams(text, source);
    if (params.population == 0) throw InputError("--population must not be 0 in a checkpoint");
    auto optimizer = std::make_unique<CmaEsOptimizer>(scene, params);
    optimizer->Load(text, source);
    if (unchecked) *unchecked = false;
    return optimizer;
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind(source, 0) == 0) throw;
    throw InputError(source + ": params: " + what);
  }
}

}  // namespace

const OptimizerKind kCmaEsOptimizer = {
    "cmaes",
    "CMA-ES over the continuous rest-length offsets (Hansen's tutorial)",
    kFormat,
    /*default_population=*/0,
    &kParams,
    StartCmaEs,
    ResumeCmaEs};

}  // namespace hexgait
