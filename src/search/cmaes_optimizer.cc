// CMA-ES (the covariance matrix adaptation evolution strategy) over the continuous rest-length
// offsets, one generation of lambda candidates per ask and tell. It follows N. Hansen, "The CMA
// Evolution Strategy: A Tutorial" (arXiv:1604.00772, 2016), Algorithm 1 with positive weights
// only (the tutorial's default before its "active" variant), with its default parameters for
// n = 120 offsets (or 60 with --symmetric). Candidates are bounded to the genes' range
// [-8, 7] gene steps, as Debian's python3-cmaes bounds them: a sample outside is drawn again,
// and after 100 draws clipped; the update uses the candidates as evaluated. Fitness is the
// distance walked, maximised. Debian packages no C++ CMA-ES, so it is written here on Eigen.
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
#include "search/generational.h"
#include "sim/evaluate.h"
#include "util/clock.h"
#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {
namespace {

using nlohmann::json;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

constexpr const char* kFormat = "hexgait cmaes checkpoint";
constexpr int kVersion = 1;
constexpr int kMaxResamples = 100;

// Hansen's default population size for n dimensions.
int DefaultLambda(int n) {
  return 4 + static_cast<int>(std::floor(3 * std::log(n)));
}

// A standard normal number (Box-Muller; the second value of each pair is not kept, so a draw
// never depends on an earlier one's parity).
double Normal(Rng& rng) {
  const double u1 = 1.0 - rng.NextDouble();  // in (0, 1]
  const double u2 = rng.NextDouble();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

void CheckParams(const EvolutionParams& p, int n) {
  if (p.population != 0 && p.population < 4) {
    throw InputError("--population must be at least 4 for cmaes (0: the default, " +
                     std::to_string(DefaultLambda(n)) + ")");
  }
  if (p.population > 100000) throw InputError("--population must be at most 100000");
  if (p.generations < 1) throw InputError("--generations must be at least 1");
  if (p.generations > 100000) throw InputError("--generations must be at most 100000");
  if (!(p.sigma > 0 && p.sigma <= 16)) throw InputError("--sigma must be in (0, 16] gene steps");
  CheckEvaluatorConfig(EvaluatorConfigOf(p));
}

json VectorJson(const Vector& v) {
  json out = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(Number(v[i]));
  return out;
}

Vector ReadVector(const JsonReader& r, const std::string& key, Eigen::Index size) {
  const JsonReader a = r.Child(key);
  if (static_cast<Eigen::Index>(a.ArraySize()) != size) {
    a.Fail("must have " + std::to_string(size) + " numbers");
  }
  Vector v(size);
  for (Eigen::Index i = 0; i < size; ++i) v[i] = a.At(static_cast<size_t>(i)).AsNumber();
  return v;
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
    CheckParams(params_, n_);
    if (params_.population == 0) params_.population = DefaultLambda(n_);
    SetStrategyParameters();
    // The unoptimised program is the start: mean zero offsets, sigma in gene steps.
    mean_ = Vector::Zero(n_);
    sigma_ = params_.sigma * step_;
    c_ = Matrix::Identity(n_, n_);
    pc_ = ps_ = Vector::Zero(n_);
    Decompose();
  }

  // Adaptation constants of the tutorial's Table 1 for n and lambda.
  void SetStrategyParameters() {
    lambda_ = params_.population;
    mu_ = lambda_ / 2;
    weights_.resize(mu_);
    for (int i = 0; i < mu_; ++i) weights_[i] = std::log((lambda_ + 1) / 2.0) - std::log(i + 1.0);
    weights_ /= weights_.sum();
    mueff_ = 1.0 / weights_.squaredNorm();
    const double n = n_;
    cc_ = (4 + mueff_ / n) / (n + 4 + 2 * mueff_ / n);
    cs_ = (mueff_ + 2) / (n + mueff_ + 5);
    c1_ = 2 / ((n + 1.3) * (n + 1.3) + mueff_);
    cmu_ = std::min(1 - c1_, 2 * (mueff_ - 2 + 1 / mueff_) / ((n + 2) * (n + 2) + mueff_));
    damps_ = 1 + 2 * std::max(0.0, std::sqrt((mueff_ - 1) / (n + 1)) - 1) + cs_;
    chi_n_ = std::sqrt(n) * (1 - 1 / (4 * n) + 1 / (21 * n * n));
  }

  // C = B D^2 B^T. Eigen's solver is deterministic for the same matrix and build.
  void Decompose() {
    // Symmetric to the last bit, so a matrix read back from a checkpoint decomposes the same.
    // (A loop: `c_ = (c_ + c_.transpose()) / 2` would read entries it has already written.)
    for (int i = 0; i < n_; ++i) {
      for (int j = i + 1; j < n_; ++j) c_(i, j) = c_(j, i) = (c_(i, j) + c_(j, i)) / 2;
    }
    const Eigen::SelfAdjointEigenSolver<Matrix> solver(c_);
    if (solver.info() != Eigen::Success) throw std::runtime_error("CMA-ES: eigen solver failed");
    b_ = solver.eigenvectors();
    d_ = solver.eigenvalues().cwiseMax(1e-300).cwiseSqrt();
  }

  const Candidates& Ask() override {
    if (asked_) return candidates_;
    start_ = Clock::now();
    Rng rng = Rng::ForStream(params_.seed, static_cast<uint64_t>(generation_ + 1));
    candidates_.dims = n_;
    candidates_.offsets.assign(static_cast<size_t>(lambda_) * n_, 0.0);
    Vector z(n_), x(n_);
    for (int k = 0; k < lambda_; ++k) {
      bool inside = false;
      for (int attempt = 0; attempt < kMaxResamples && !inside; ++attempt) {
        for (int i = 0; i < n_; ++i) z[i] = Normal(rng);
        x = mean_ + sigma_ * (b_ * d_.cwiseProduct(z));
        inside = ((x.array() >= lower_) && (x.array() <= upper_)).all();
      }
      if (!inside) x = x.cwiseMax(lower_).cwiseMin(upper_);
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
    const auto x_of = [&](int k) {
      return Eigen::Map<const Vector>(candidates_.row(static_cast<size_t>(k)), n_);
    };
    const Vector old_mean = mean_;
    mean_.setZero();
    for (int i = 0; i < mu_; ++i) mean_ += weights_[i] * x_of(order[static_cast<size_t>(i)]);
    const Vector y_w = (mean_ - old_mean) / sigma_;
    // C^(-1/2) y_w = B D^-1 B^T y_w.
    const Vector c_inv_sqrt_y = b_ * (b_.transpose() * y_w).cwiseQuotient(d_);
    ps_ = (1 - cs_) * ps_ + std::sqrt(cs_ * (2 - cs_) * mueff_) * c_inv_sqrt_y;
    const int g = generation_ + 1;
    const double ps_norm = ps_.norm();
    const bool hsig =
        ps_norm / std::sqrt(1 - std::pow(1 - cs_, 2.0 * (g + 1))) < (1.4 + 2.0 / (n_ + 1)) * chi_n_;
    pc_ = (1 - cc_) * pc_ + (hsig ? std::sqrt(cc_ * (2 - cc_) * mueff_) : 0.0) * y_w;
    Matrix rank_mu = Matrix::Zero(n_, n_);
    for (int i = 0; i < mu_; ++i) {
      const Vector y = (x_of(order[static_cast<size_t>(i)]) - old_mean) / sigma_;
      rank_mu.noalias() += weights_[i] * y * y.transpose();
    }
    const double delta_h = hsig ? 0.0 : cc_ * (2 - cc_);
    c_ = (1 - c1_ - cmu_ + c1_ * delta_h) * c_ + c1_ * pc_ * pc_.transpose() + cmu_ * rank_mu;
    sigma_ *= std::exp((cs_ / damps_) * (ps_norm / chi_n_ - 1));
    if (!std::isfinite(sigma_) || !(sigma_ > 0)) {
      throw std::runtime_error("CMA-ES: the step size is no longer a positive number");
    }
    Decompose();

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
  std::string Describe() const override {
    char text[192];
    std::snprintf(text, sizeof text,
                  "CMA-ES: lambda %d, mu %d, %d generations, sigma %g gene steps, seed %llu, %d "
                  "offsets",
                  lambda_, mu_, params_.generations, params_.sigma,
                  static_cast<unsigned long long>(params_.seed), n_);
    return text;
  }

  std::string Save() const override {
    json j;
    AddFormatHeader(j, kFormat, kVersion);
    j["scene_fingerprint"] = Hex(fingerprint_);
    if (!creature_.empty()) j["creature"] = creature_;
    if (!damage_.empty()) j["damage"] = damage_;
    json p = {{"seed", std::to_string(params_.seed)},
              {"population", params_.population},
              {"generations", params_.generations},
              {"sigma", params_.sigma},
              {"symmetric", params_.symmetric}};
    AddRunOptionsJson(p, params_.run, params_.precision);
    j["params"] = p;
    j["generation"] = generation_;
    j["total_evaluations"] = result_.total_evaluations;
    j["step_size"] = Number(sigma_);
    j["mean"] = VectorJson(mean_);
    j["path_c"] = VectorJson(pc_);
    j["path_sigma"] = VectorJson(ps_);
    j["covariance"] = VectorJson(Eigen::Map<const Vector>(c_.data(), c_.size()));
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
    sigma_ = ReadNumber(r, "step_size");
    if (!std::isfinite(sigma_) || !(sigma_ > 0)) r.Fail("'step_size' must be positive");
    mean_ = ReadVector(r, "mean", n_);
    pc_ = ReadVector(r, "path_c", n_);
    ps_ = ReadVector(r, "path_sigma", n_);
    const Vector c = ReadVector(r, "covariance", static_cast<Eigen::Index>(n_) * n_);
    c_ = Eigen::Map<const Matrix>(c.data(), n_, n_);
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
    Decompose();
  }

 private:
  EvolutionParams params_;
  std::shared_ptr<const GenomeLayout> layout_;
  int n_;
  double step_, lower_, upper_;
  uint64_t fingerprint_;
  std::string creature_;
  std::string damage_;  // the creature's --damage, recorded beside it

  int lambda_ = 0, mu_ = 0;
  Vector weights_;
  double mueff_ = 0, cc_ = 0, cs_ = 0, c1_ = 0, cmu_ = 0, damps_ = 0, chi_n_ = 0;

  int generation_ = -1;  // last told
  Vector mean_, pc_, ps_, d_;
  Matrix c_, b_;
  double sigma_ = 0;
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
  const JsonReader p = r.Child("params");
  p.RequireOnlyKeys({"seed", "population", "generations", "sigma", "symmetric", "time", "dt",
                     "integrator", "check_interval", "divergence_speed", "early_stop",
                     "rest_kinetic_energy", "stop_at_fall", "precision"});
  EvolutionParams params;
  params.seed = ReadSeed(p);
  params.population = p.Integer("population");
  params.generations = p.Integer("generations");
  params.sigma = p.Number("sigma");
  params.symmetric = p.Bool("symmetric");
  ReadRunOptionsJson(p, &params.run, &params.precision);
  return params;
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

extern const OptimizerKind kCmaEsOptimizer;
const OptimizerKind kCmaEsOptimizer = {
    "cmaes", "CMA-ES over the continuous rest-length offsets (Hansen's tutorial)", kFormat,
    StartCmaEs, ResumeCmaEs};

}  // namespace hexgait
