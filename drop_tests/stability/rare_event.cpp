#include "drop_tests/stability/rare_event.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <boost/math/distributions/normal.hpp>

#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::stability {

namespace {

// Each estimator draws from its own family of streams, so one seed given to two methods does not
// hand them the same numbers.
enum class Method : uint64_t { kMonteCarlo = 1, kSubset = 2, kImportance = 3 };
// What a draw is for, within a method and level.
enum class Purpose : uint64_t { kSample = 0, kProposal = 1, kAccept = 2 };

// The stream of one component's draw: method, level, purpose and component packed into disjoint
// bits (components below 2^32, levels below 2^16).
uint64_t Stream(Method m, uint64_t level, Purpose p, uint64_t component) {
  return (static_cast<uint64_t>(m) << 56) | (level << 40) | (static_cast<uint64_t>(p) << 32) | component;
}

Eigen::VectorXd NormalPoint(int dimension, uint64_t seed, uint64_t sample, Method m, uint64_t level) {
  Eigen::VectorXd u(dimension);
  for (int j = 0; j < dimension; ++j)
    u[j] = StandardNormal(seed, sample, Stream(m, level, Purpose::kSample, static_cast<uint64_t>(j)));
  return u;
}

// The two-sided normal quantile of a confidence: 1.96 at 0.95.
double NormalZ(double confidence) { return boost::math::quantile(boost::math::normal(), 0.5 + confidence / 2.0); }

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

void CheckConfidence(double confidence) {
  Require(confidence > 0.0 && confidence < 1.0,
          "confidence = " + std::to_string(confidence) + ": must lie in (0, 1)");
}

void CheckDimension(int dimension) {
  Require(dimension >= 1, "dimension = " + std::to_string(dimension) + ": must be at least 1");
}

void CheckSamples(int64_t samples, const char* name) {
  Require(samples >= 10, std::string(name) + " = " + std::to_string(samples) + ": must be at least 10");
}

// Calls g on the points and checks what came back; keeps the count of evaluations and the failing
// point of smallest norm.
class Evaluator {
 public:
  Evaluator(const LimitStateBatch& g, RareEventEstimate& result) : g_(g), result_(result) {
    Require(static_cast<bool>(g), "the limit state function is empty");
  }
  std::vector<double> operator()(const std::vector<Eigen::VectorXd>& points) {
    std::vector<double> values;
    if (points.empty()) return values;
    g_(points, values);
    Require(values.size() == points.size(), "the limit state returned " + std::to_string(values.size()) +
                                                " values for " + std::to_string(points.size()) + " points");
    for (size_t i = 0; i < points.size(); ++i) {
      Require(!std::isnan(values[i]), "the limit state returned NaN (return +-inf for a failed evaluation)");
      if (values[i] <= 0.0) {
        const double norm = points[i].norm();
        if (result_.design_point.size() == 0 || norm < best_norm_) best_norm_ = norm, result_.design_point = points[i];
      }
    }
    result_.evaluations += static_cast<int64_t>(points.size());
    return values;
  }

 private:
  const LimitStateBatch& g_;
  RareEventEstimate& result_;
  double best_norm_ = std::numeric_limits<double>::infinity();
};

// [P e^(s^2/2 - z s), P e^(s^2/2 + z s)], s^2 = ln(1 + cov^2): the interval of a lognormal estimate
// whose mean is the true P.
BinomialInterval LognormalInterval(double p, double cov, double z) {
  if (!(p > 0.0) || !std::isfinite(cov)) return {0.0, 1.0};
  const double s = std::sqrt(std::log1p(cov * cov));
  return {p * std::exp(0.5 * s * s - z * s), std::min(1.0, p * std::exp(0.5 * s * s + z * s))};
}

// Au & Beck's gamma_i (2001, eq. 29): the correlation of the level's chains' failure indicators,
// chain j's l-th sample at fail[j * length + l]. Negative estimates (noise of nearly independent
// chains) count as 0.
double ChainCorrelationFactor(const std::vector<char>& fail, int64_t chains, int64_t length, double p) {
  const double n = static_cast<double>(chains * length);
  const double r0 = p * (1.0 - p);
  if (!(r0 > 0.0)) return 0.0;
  double gamma = 0.0;
  for (int64_t k = 1; k < length; ++k) {
    int64_t pairs = 0;
    for (int64_t j = 0; j < chains; ++j)
      for (int64_t l = 0; l + k < length; ++l) pairs += fail[j * length + l] && fail[j * length + l + k];
    const double r = static_cast<double>(pairs) / (n - static_cast<double>(k * chains)) - p * p;
    gamma += 2.0 * (1.0 - static_cast<double>(k * chains) / n) * (r / r0);
  }
  return std::max(0.0, gamma);
}

// One level's samples, chain-major (chain j's step l at j * length + l; the first level: any order).
struct LevelSamples {
  std::vector<Eigen::VectorXd> u;
  std::vector<double> g;
};

// The modified Metropolis step of every chain at once: component-wise candidates, then one batch
// of g for the chains whose candidate moved; a candidate outside g <= threshold leaves its chain
// where it was.
LevelSamples RunChains(Evaluator& evaluate, const LevelSamples& seeds, int64_t length, double threshold,
                       const SubsetOptions& o, uint64_t level, int64_t& accepted) {
  const int64_t chains = static_cast<int64_t>(seeds.u.size());
  const int dimension = static_cast<int>(seeds.u.front().size());
  LevelSamples out;
  out.u.resize(static_cast<size_t>(chains * length));
  out.g.resize(out.u.size());
  std::vector<Eigen::VectorXd> x = seeds.u;
  std::vector<double> gx = seeds.g;
  for (int64_t j = 0; j < chains; ++j) out.u[j * length] = x[j], out.g[j * length] = gx[j];
  for (int64_t l = 1; l < length; ++l) {
    std::vector<Eigen::VectorXd> candidates;
    std::vector<int64_t> moved;
    for (int64_t j = 0; j < chains; ++j) {
      const uint64_t sample = static_cast<uint64_t>(l * chains + j);
      Eigen::VectorXd xi = x[j];
      bool changed = false;
      for (int c = 0; c < dimension; ++c) {
        const uint64_t cc = static_cast<uint64_t>(c);
        const double proposal =
            x[j][c] + o.proposal_spread * StandardNormal(o.seed, sample, Stream(Method::kSubset, level, Purpose::kProposal, cc));
        const double ratio = std::exp(0.5 * (x[j][c] * x[j][c] - proposal * proposal));  // phi(proposal) / phi(x)
        if (OpenUniform(o.seed, sample, Stream(Method::kSubset, level, Purpose::kAccept, cc)) < ratio)
          xi[c] = proposal, changed = true;
      }
      if (!changed) continue;  // the candidate is the current state: g is known
      candidates.push_back(std::move(xi));
      moved.push_back(j);
    }
    const std::vector<double> g = evaluate(candidates);
    for (size_t k = 0; k < moved.size(); ++k) {
      if (g[k] > threshold) continue;
      x[moved[k]] = candidates[k];
      gx[moved[k]] = g[k];
      ++accepted;
    }
    for (int64_t j = 0; j < chains; ++j) out.u[j * length + l] = x[j], out.g[j * length + l] = gx[j];
  }
  return out;
}

void CheckSubsetOptions(int dimension, const SubsetOptions& o) {
  CheckDimension(dimension);
  CheckSamples(o.samples_per_level, "samples_per_level");
  CheckConfidence(o.confidence);
  Require(o.p0 > 0.0 && o.p0 <= 0.5, "p0 = " + std::to_string(o.p0) + ": must lie in (0, 0.5]");
  const double chains = o.p0 * static_cast<double>(o.samples_per_level);
  const int64_t nc = std::llround(chains);
  Require(nc >= 1 && std::abs(chains - static_cast<double>(nc)) < 1e-9 && o.samples_per_level % nc == 0,
          "samples_per_level = " + std::to_string(o.samples_per_level) + ", p0 = " + std::to_string(o.p0) +
              ": samples_per_level * p0 must be a whole number of chains that divides samples_per_level");
  Require(o.proposal_spread > 0.0 && std::isfinite(o.proposal_spread),
          "proposal_spread = " + std::to_string(o.proposal_spread) + ": must be positive");
  Require(o.max_levels >= 1 && o.max_levels < (1 << 16),
          "max_levels = " + std::to_string(o.max_levels) + ": must lie in [1, 65535]");
}

}  // namespace

double OpenUniform(uint64_t seed, uint64_t sample, uint64_t stream) {
  return sweep::CounterUniform(seed, sample, stream) + 0x1.0p-54;
}

double StandardNormal(uint64_t seed, uint64_t sample, uint64_t stream) {
  return boost::math::quantile(boost::math::normal(), OpenUniform(seed, sample, stream));
}

MonteCarloEstimate EstimateMonteCarlo(const LimitStateBatch& g, int dimension, const MonteCarloOptions& o) {
  CheckDimension(dimension);
  CheckSamples(o.samples, "samples");
  CheckConfidence(o.confidence);
  Require(o.batch >= 1, "batch = " + std::to_string(o.batch) + ": must be at least 1");
  MonteCarloEstimate r;
  Evaluator evaluate(g, r);
  for (int64_t start = 0; start < o.samples; start += o.batch) {
    const int64_t end = std::min(o.samples, start + o.batch);
    std::vector<Eigen::VectorXd> points;
    for (int64_t i = start; i < end; ++i)
      points.push_back(NormalPoint(dimension, o.seed, static_cast<uint64_t>(i), Method::kMonteCarlo, 0));
    for (double v : evaluate(points)) r.failures += v <= 0.0;
  }
  const double n = static_cast<double>(o.samples);
  r.probability = static_cast<double>(r.failures) / n;
  r.interval = ClopperPearson(r.failures, o.samples, o.confidence);
  r.cov = r.failures > 0 ? std::sqrt((1.0 - r.probability) / (n * r.probability)) : std::numeric_limits<double>::infinity();
  return r;
}

SubsetEstimate EstimateSubset(const LimitStateBatch& g, int dimension, const SubsetOptions& o) {
  CheckSubsetOptions(dimension, o);
  const int64_t n = o.samples_per_level;
  const int64_t chains = std::llround(o.p0 * static_cast<double>(n));
  const int64_t length = n / chains;
  SubsetEstimate r;
  Evaluator evaluate(g, r);

  // The first level in chunks: its landings start (and a stop is seen between chunks) before a
  // large level's last point is drawn; the points and values are the same, chunked or not.
  constexpr int64_t kChunk = 100000;
  LevelSamples level;
  for (int64_t start = 0; start < n; start += kChunk) {
    std::vector<Eigen::VectorXd> chunk;
    for (int64_t i = start; i < std::min(n, start + kChunk); ++i)
      chunk.push_back(NormalPoint(dimension, o.seed, static_cast<uint64_t>(i), Method::kSubset, 0));
    const std::vector<double> g_chunk = evaluate(chunk);
    level.g.insert(level.g.end(), g_chunk.begin(), g_chunk.end());
    level.u.insert(level.u.end(), std::make_move_iterator(chunk.begin()), std::make_move_iterator(chunk.end()));
  }
  int64_t level_evaluations = r.evaluations, accepted = 0;

  double log_probability = 0.0, cov2 = 0.0, cov_sum = 0.0;
  double previous_threshold = std::numeric_limits<double>::infinity();
  for (int i = 0;; ++i) {
    std::vector<int64_t> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int64_t a, int64_t b) { return level.g[a] < level.g[b]; });
    const int64_t failing = std::count_if(level.g.begin(), level.g.end(), [](double v) { return v <= 0.0; });
    const double midpoint = 0.5 * (level.g[order[chains - 1]] + level.g[order[chains]]);
    const bool last = failing >= chains || i + 1 == o.max_levels || !(midpoint < previous_threshold);

    SubsetLevel s;
    s.threshold = last ? 0.0 : midpoint;
    s.conditional_probability = last ? static_cast<double>(failing) / static_cast<double>(n) : o.p0;
    s.evaluations = level_evaluations;
    if (i > 0) {
      std::vector<char> fail(static_cast<size_t>(n));
      for (int64_t k = 0; k < n; ++k) fail[k] = level.g[k] <= s.threshold;
      s.gamma = ChainCorrelationFactor(fail, chains, length, s.conditional_probability);
      s.acceptance_rate = static_cast<double>(accepted) / static_cast<double>(chains * (length - 1));
    }
    const double p = s.conditional_probability;
    s.cov = p > 0.0 ? std::sqrt((1.0 - p) / (static_cast<double>(n) * p) * (1.0 + s.gamma))
                    : std::numeric_limits<double>::infinity();
    r.levels.push_back(s);
    log_probability += p > 0.0 ? std::log(p) : -std::numeric_limits<double>::infinity();
    cov2 += s.cov * s.cov;
    cov_sum += s.cov;
    if (last) {
      r.reached_failure = failing >= chains;
      break;
    }

    LevelSamples seeds;
    for (int64_t k = 0; k < chains; ++k) seeds.u.push_back(level.u[order[k]]), seeds.g.push_back(level.g[order[k]]);
    const int64_t before = r.evaluations;
    accepted = 0;
    level = RunChains(evaluate, seeds, length, midpoint, o, static_cast<uint64_t>(i + 1), accepted);
    level_evaluations = r.evaluations - before;
    previous_threshold = midpoint;
  }
  r.probability = std::exp(log_probability);
  const double infinite = std::numeric_limits<double>::infinity();
  r.cov = r.probability > 0.0 ? std::sqrt(cov2) : infinite;
  r.cov_upper = r.probability > 0.0 ? cov_sum : infinite;
  r.interval = LognormalInterval(r.probability, r.cov_upper, NormalZ(o.confidence));
  return r;
}

DesignPointRefinement RefineDesignPoint(const LimitStateBatch& g, const Eigen::VectorXd& failing, int rounds) {
  Require(failing.size() >= 1 && failing.allFinite(), "the failing point must be a finite vector of dimension >= 1");
  Require(rounds >= 1, "rounds = " + std::to_string(rounds) + ": must be at least 1");
  constexpr int kInterior = 7;
  RareEventEstimate counter;
  Evaluator evaluate(g, counter);
  double safe = 0.0, fail = 1.0;
  for (int round = 0; round < rounds; ++round) {
    std::vector<double> t;
    if (round == 0) t.push_back(0.0);
    for (int k = 1; k <= kInterior; ++k) t.push_back(safe + (fail - safe) * k / (kInterior + 1));
    std::vector<Eigen::VectorXd> points;
    for (double tk : t) points.push_back(tk * failing);
    const std::vector<double> values = evaluate(points);
    if (round == 0 && values[0] <= 0.0) return {Eigen::VectorXd::Zero(failing.size()), counter.evaluations};
    double lo = safe, hi = fail;
    for (size_t k = round == 0 ? 1 : 0; k < t.size(); ++k) {
      if (values[k] <= 0.0) {
        hi = t[k];
        break;
      }
      lo = t[k];
    }
    safe = lo, fail = hi;
  }
  return {fail * failing, counter.evaluations};
}

RareEventEstimate EstimateImportance(const LimitStateBatch& g, const Eigen::VectorXd& centre, const ImportanceOptions& o) {
  Require(centre.size() >= 1 && centre.allFinite(), "the centre must be a finite vector of dimension >= 1");
  CheckSamples(o.samples, "samples");
  CheckConfidence(o.confidence);
  Require(o.batch >= 1, "batch = " + std::to_string(o.batch) + ": must be at least 1");
  const int dimension = static_cast<int>(centre.size());
  const double half_c2 = 0.5 * centre.squaredNorm();
  RareEventEstimate r;
  Evaluator evaluate(g, r);
  std::vector<double> weighted;  // 1[g <= 0] phi(u) / h(u), per sample (grown as they run)
  for (int64_t start = 0; start < o.samples; start += o.batch) {
    const int64_t end = std::min(o.samples, start + o.batch);
    std::vector<Eigen::VectorXd> points;
    for (int64_t i = start; i < end; ++i)
      points.push_back(centre + NormalPoint(dimension, o.seed, static_cast<uint64_t>(i), Method::kImportance, 0));
    const std::vector<double> values = evaluate(points);
    for (size_t k = 0; k < points.size(); ++k)
      weighted.push_back(values[k] <= 0.0 ? std::exp(half_c2 - centre.dot(points[k])) : 0.0);
  }
  const double n = static_cast<double>(o.samples);
  const double mean = std::accumulate(weighted.begin(), weighted.end(), 0.0) / n;
  double ss = 0.0;
  for (double w : weighted) ss += (w - mean) * (w - mean);
  const double standard_error = std::sqrt(ss / (n - 1.0) / n);
  r.probability = mean;
  r.cov = mean > 0.0 ? standard_error / mean : std::numeric_limits<double>::infinity();
  const double z = NormalZ(o.confidence);
  r.interval = {std::max(0.0, mean - z * standard_error), std::min(1.0, mean + z * standard_error)};
  return r;
}

}  // namespace touchdown::stability
