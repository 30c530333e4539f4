#include "drop_tests/gap/diagnose_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "drop_tests/dataset/compare.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/util/student_t.h"
#include "drop_tests/util/work_pool.h"
#include "lander/pad/effect_soil_response.h"
#include "rft/units.h"

namespace touchdown::gap {

using namespace fit;  // the objective (fit_objective.h)

rft::EffectTerms FitResult::terms() const { return model::MakeEffectTerms(effects); }

namespace {
// The starting point: zeta from `start` (or the catalogue), effect parameters at their starting
// values, each multi-modal one (EffectParameterInfo::scan) set by a coarse scan, one at a time;
// the sensor's free parameters from `start` or the problem's sensor; the nuisances from `start`
// (a model that extends it shares its drops), else zero.
Eigen::VectorXd StartingPoint(const FitProblem& p, const Layout& L, const FitResult* start, Objective& obj) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(L.size());
  int k = 0;
  for (int s = 0; s < L.soils; ++s)
    x[k++] = start && !start->zeta_N_m3.empty() ? start->zeta_N_m3[s] / p.soils[s].zeta_N_m3 : 1.0;
  std::vector<bool> seeded;
  for (const CandidateTerm* e : L.infos) {
    // A term the starting model already has starts at its fitted values (forward selection).
    const model::Effect* from = nullptr;
    if (start)
      for (size_t j = 0; j < start->effect_ids.size(); ++j)
        if (start->effect_ids[j] == e->name) from = &start->effects[j];
    for (size_t i = 0; i < e->parameters.size(); ++i) {
      x[k++] = (from ? from->values[i] : e->parameters[i].start) / e->parameters[i].scale;
      seeded.push_back(from != nullptr);
    }
  }
  const dataset::SensorModel& sensor = start && start->sensor.HasFilters() ? start->sensor : p.sensor;
  if (p.sensor_fit.cutoff) x[k++] = sensor.lowpass_cutoff_hz / SampleRate(p);
  if (p.sensor_fit.load_cell) {
    x[k++] = sensor.load_cell_hz / units::kKilo;
    x[k++] = sensor.load_cell_damping;
  }
  if (p.sensor_fit.offsets) {
    x[k++] = start ? start->offset_dt_s / kOffsetTimeScale_s : 0.0;
    x[k++] = start ? start->offset_dz_m / kOffsetDepthScale_m : 0.0;
  }
  if (L.nuisances && start && start->nuisances.size() == p.drops.size()) {
    int t = 0;
    for (const FitDrop& d : p.drops) {
      if (!d.train) continue;
      const DropNuisance& b = start->nuisances[static_cast<size_t>(&d - p.drops.data())];
      x[L.Nuisance(t, 0)] = b.log_zeta / p.spreads.log_zeta;
      x[L.Nuisance(t, 1)] = b.log_speed / p.spreads.log_speed;
      x[L.Nuisance(t, 2)] = b.time_s / p.spreads.time_s;
      ++t;
    }
  } else if (L.nuisances) {
    obj.AlignTimes(x);  // a first fit: each drop's trigger time found before the descent
  }
  Eigen::VectorXd r;
  k = L.soils;
  for (const CandidateTerm* e : L.infos)
    for (const model::EffectParameterInfo& q : e->parameters) {
      if (!q.scan.empty() && !seeded[k - L.soils]) {
        double best_cost = 0.0, best = x[k];
        for (size_t i = 0; i < q.scan.size(); ++i) {
          Eigen::VectorXd xs = x;
          xs[k] = q.scan[i] / q.scale;
          obj.Evaluate(xs, &r);
          if (i == 0 || r.squaredNorm() < best_cost) best_cost = r.squaredNorm(), best = xs[k];
        }
        x[k] = best;
      }
      ++k;
    }
  return x;
}

// The Levenberg-Marquardt state: the scaled parameters, their weighted residuals, the cost and
// the Jacobian there.
struct Solution {
  Eigen::VectorXd x, r;
  double cost = 0.0;
  Eigen::MatrixXd J;
};

double Step(const Eigen::VectorXd& x, const Eigen::VectorXd& hi, int j) {
  double h = 1e-4 * std::max(std::abs(x[j]), 0.1);
  return x[j] + h > hi[j] ? -h : h;
}

// Forward-difference Jacobian of the weighted residuals at s.x, a step inside the upper bound. A
// drop's nuisances move only its own rows: each of the kDropNuisances columns of every drop comes
// from one evaluation with that nuisance stepped in every drop at once.
void UpdateJacobian(Objective& obj, const Layout& L, const Eigen::VectorXd& hi, Solution& s) {
  s.J.setZero();
  Eigen::VectorXd rp;
  for (int j = 0; j < L.globals(); ++j) {
    const double h = Step(s.x, hi, j);
    Eigen::VectorXd xp = s.x;
    xp[j] += h;
    obj.Evaluate(xp, &rp);
    s.J.col(j) = (rp - s.r) / h;
  }
  if (!L.nuisances) return;
  for (int c = 0; c < kDropNuisances; ++c) {
    Eigen::VectorXd xp = s.x;
    std::vector<double> h(L.train);
    for (int t = 0; t < L.train; ++t) h[t] = Step(s.x, hi, L.Nuisance(t, c)), xp[L.Nuisance(t, c)] += h[t];
    obj.Evaluate(xp, &rp);
    for (int t = 0; t < L.train; ++t) {
      const long o = obj.offsets()[t];
      const long rows = (t + 1 < L.train ? obj.offsets()[t + 1] : obj.data_rows()) - o;
      const int j = L.Nuisance(t, c);
      s.J.col(j).segment(o, rows) = (rp.segment(o, rows) - s.r.segment(o, rows)) / h[t];
      s.J(obj.PenaltyRow(t, c), j) = (rp[obj.PenaltyRow(t, c)] - s.r[obj.PenaltyRow(t, c)]) / h[t];
    }
  }
}

// Levenberg-Marquardt from s.x within [lo, hi]; counts the iterations and says whether it
// converged. Leaves the Jacobian at the optimum (for the intervals).
void Minimise(Objective& obj, const Layout& L, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Solution& s,
              FitResult& out, bool final_jacobian) {
  const long n = s.x.size();
  obj.Evaluate(s.x, &s.r);
  s.cost = s.r.squaredNorm();
  s.J.resize(obj.rows(), n);
  Eigen::VectorXd r_new;
  double lambda = 1e-3;
  for (int it = 0; it < obj.max_iterations(); ++it) {
    out.iterations = it + 1;
    UpdateJacobian(obj, L, hi, s);
    const Eigen::MatrixXd A = s.J.transpose() * s.J;
    const Eigen::VectorXd g = s.J.transpose() * s.r;
    bool improved = false;
    double step_norm = 0.0;
    for (int attempt = 0; attempt < 10 && lambda < 1e10; ++attempt) {  // damping up to x5^10 per iteration
      Eigen::MatrixXd M = A;
      for (int j = 0; j < n; ++j) M(j, j) += lambda * std::max(A(j, j), 1e-12);
      Eigen::VectorXd dx = M.ldlt().solve(-g);
      Eigen::VectorXd x_new = (s.x + dx).cwiseMax(lo).cwiseMin(hi);
      obj.Evaluate(x_new, &r_new);
      const double c_new = r_new.squaredNorm();
      if (c_new < s.cost) {
        step_norm = (x_new - s.x).norm();
        const double gain = (s.cost - c_new) / s.cost;
        s.x = x_new;
        s.r = r_new;
        s.cost = c_new;
        lambda = std::max(lambda / 4, 1e-9);
        improved = true;
        // Converged when a step no longer changes the cost meaningfully (1e-6 of it) or moves
        // the parameters by less than 1e-7 of their (scaled) size.
        if (gain < 1e-6 || step_norm < 1e-7 * (s.x.norm() + 1e-7)) out.converged = true;
        break;
      }
      lambda *= 5;
    }
    if (!improved) {
      out.converged = true;  // no descent left at any damping: a minimum (to the solver's accuracy)
      break;
    }
    if (out.converged) break;
  }
  if (final_jacobian) UpdateJacobian(obj, L, hi, s);
}

// The force residual in newtons per soil (the unweighted force rows are (F_sim - F) / max F).
void ForceResidualsPerSoil(const FitProblem& p, const Layout& L, const Objective& obj,
                           const Eigen::VectorXd& unweighted, FitResult& out) {
  out.residual_rms_N.assign(L.soils, 0.0);
  out.force_samples.assign(L.soils, 0);
  for (size_t c = 0; c < obj.train().size(); ++c) {
    const FitDrop& d = p.drops[obj.train()[c]];
    const long o = obj.offsets()[c], n = static_cast<long>(d.trace->size());
    for (long i = 0; i < n; ++i) {
      const double e = unweighted[o + 2 * i] * d.force_scale_N;
      out.residual_rms_N[d.soil] += e * e;
    }
    out.force_samples[d.soil] += n;
  }
  for (int s = 0; s < L.soils; ++s)
    out.residual_rms_N[s] = out.force_samples[s] > 0 ? std::sqrt(out.residual_rms_N[s] / out.force_samples[s]) : 0.0;
}

// The rows of training drop c: its data rows and its penalty rows.
std::vector<long> RowsOf(const Objective& obj, const Layout& L, int c) {
  std::vector<long> rows;
  const long o = obj.offsets()[c];
  const long end = c + 1 < static_cast<int>(obj.offsets().size()) ? obj.offsets()[c + 1] : obj.data_rows();
  for (long i = o; i < end; ++i) rows.push_back(i);
  if (L.nuisances)
    for (int k = 0; k < kDropNuisances; ++k) rows.push_back(obj.PenaltyRow(c, k));
  return rows;
}

// The parameters' covariance at the optimum: cluster-robust (drops as clusters, CR1 small-sample
// factor G / (G - 1)), each variance widened to the classical one where that is larger.
Eigen::MatrixXd Covariance(const Objective& obj, const Layout& L, const Solution& s) {
  const long n = s.x.size();
  const Eigen::MatrixXd& J = s.J;
  const Eigen::VectorXd& r = s.r;
  const Eigen::MatrixXd A = J.transpose() * J;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  const int G = static_cast<int>(obj.train().size());
  for (int c = 0; c < G; ++c) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
    for (const long i : RowsOf(obj, L, c)) g += J.row(i).transpose() * r[i];
    B += g * g.transpose();
  }
  const Eigen::MatrixXd Ainv = A.completeOrthogonalDecomposition().pseudoInverse();
  const Eigen::MatrixXd sandwich = Ainv * B * Ainv * (G > 1 ? double(G) / (G - 1) : 1.0);
  // The classical covariance s^2 (J^T J)^-1 with s^2 from the residuals and the sample count cut
  // to its effective size by the lag-1 autocorrelation (n_eff = n (1 - rho) / (1 + rho)); with few
  // drops the sandwich alone is known to be too narrow, so each interval takes the wider of the two.
  double rho_num = 0.0, rho_den = 0.0;
  for (int c = 0; c < G; ++c) {
    const long o = obj.offsets()[c];
    const long end = c + 1 < G ? obj.offsets()[c + 1] : obj.data_rows();
    for (long i = o; i < end; ++i) {
      rho_den += r[i] * r[i];
      if (i >= o + 2) rho_num += r[i] * r[i - 2];  // same channel, one sample earlier
    }
  }
  const double rho = rho_den > 0 ? std::clamp(rho_num / rho_den, 0.0, 0.99) : 0.0;
  const double inflation = (1 + rho) / (1 - rho);
  const double s2 = r.squaredNorm() / std::max<long>(obj.rows() - n, 1);
  const Eigen::MatrixXd naive = Ainv * s2 * inflation;
  Eigen::MatrixXd cov = sandwich;
  for (int j = 0; j < n; ++j) cov(j, j) = std::max(sandwich(j, j), naive(j, j));
  return cov;
}

// Each parameter's value and 95 % interval (Student's t on drops - 1), clipped to its bounds.
void Estimates(const FitProblem& p, const Layout& L, const Objective& obj, const Solution& s,
               const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, FitResult& out) {
  const Eigen::MatrixXd cov = Covariance(obj, L, s);
  const int G = static_cast<int>(obj.train().size());
  const double t = io::StudentTTwoSided(0.95, std::max(G - 1, 1));
  const Eigen::VectorXd& x = s.x;
  int k = 0;
  auto estimate = [&](std::vector<ParameterEstimate>& into, const std::string& effect, const std::string& key,
                      double scale, double file_to_si, const std::string& unit) {
    const double half = t * std::sqrt(std::max(cov(k, k), 0.0));
    ParameterEstimate e{effect, key, x[k] * scale, std::max(x[k] - half, lo[k]) * scale,
                        std::min(x[k] + half, hi[k]) * scale, file_to_si, unit, lo[k] * scale, hi[k] * scale};
    into.push_back(e);
    ++k;
  };
  for (const rft::SoilParameters& soil : p.soils) {
    if (p.bekker_base)
      estimate(out.estimates, "", "bekker_modulus_scale:" + soil.name, 1.0, 1.0, "-");
    else
      estimate(out.estimates, "", "zeta_N_cm3:" + soil.name, soil.zeta_N_m3, units::kN_m3_per_N_cm3, "N/cm^3");
  }
  for (const CandidateTerm* e : L.infos)
    for (const model::EffectParameterInfo& q : e->parameters)
      estimate(out.estimates, e->name, q.key, q.scale, q.file_to_si, q.FileUnit());
  if (p.sensor_fit.cutoff) estimate(out.sensor_estimates, "sensor", "lowpass_cutoff_hz", SampleRate(p), 1.0, "Hz");
  if (p.sensor_fit.load_cell) {
    estimate(out.sensor_estimates, "sensor", "load_cell_hz", units::kKilo, 1.0, "Hz");
    estimate(out.sensor_estimates, "sensor", "load_cell_damping", 1.0, 1.0, "-");
  }
  if (p.sensor_fit.offsets) {
    estimate(out.sensor_estimates, "sensor_offset", "dt_ms", kOffsetTimeScale_s, units::kMs, "ms");
    estimate(out.sensor_estimates, "sensor_offset", "dz_mm", kOffsetDepthScale_m, units::kMm, "mm");
  }
}
// Drop d's nuisances fitted alone with the model held (defined with FitDropNuisance below).
DropNuisance FitOneDrop(const FitProblem& p, const FitDrop& d, const ModelValues& held, double* cost_out);

// After a full fit, each training drop's nuisances fitted again alone from a fresh trigger-time
// scan (as a held-out drop's, the model held) and kept where that lowers the drop's own rows: a
// drop whose joint descent settled a sample or a load cell's period off in time is a local
// minimum the joint fit cannot leave, and its residual would count as the replicates' scatter.
// Each kept change lowers the total cost. Returns whether any drop changed (s.x and s.r updated).
bool RefitDropNuisances(const FitProblem& p, const Layout& L, Objective& obj, Solution& s) {
  const ModelValues held = Unscale(p, L, s.x);
  const int n = static_cast<int>(obj.train().size());
  std::vector<DropNuisance> fresh(n);
  std::vector<double> fresh_cost(n, 0.0);
  io::ParallelFor(static_cast<size_t>(n), p.threads, [&](size_t t) {
    fresh[t] = FitOneDrop(p, p.drops[obj.train()[t]], held, &fresh_cost[t]);
  });
  bool changed = false;
  for (int t = 0; t < n; ++t) {
    double now = 0.0;
    for (const long i : RowsOf(obj, L, t)) now += s.r[i] * s.r[i];
    if (!(fresh_cost[t] < now * (1.0 - 1e-6))) continue;
    s.x[L.Nuisance(t, 0)] = fresh[t].log_zeta / p.spreads.log_zeta;
    s.x[L.Nuisance(t, 1)] = fresh[t].log_speed / p.spreads.log_speed;
    s.x[L.Nuisance(t, 2)] = fresh[t].time_s / p.spreads.time_s;
    changed = true;
  }
  if (changed) {
    obj.Evaluate(s.x, &s.r);
    s.cost = s.r.squaredNorm();
  }
  return changed;
}
}  // namespace

FitResult FitCandidate(const FitProblem& p, const std::vector<std::string>& ids, const FitResult* start,
                       int screen_iterations) {
  const Layout L = MakeLayout(p, ids);
  Eigen::VectorXd lo, hi;
  Bounds(p, L, &lo, &hi);
  Objective obj(p, L);
  obj.LimitIterations(screen_iterations);
  FitResult out;
  out.screening = screen_iterations > 0;
  Solution s;
  s.x = StartingPoint(p, L, start, obj).cwiseMax(lo).cwiseMin(hi);
  Minimise(obj, L, lo, hi, s, out, !out.screening);
  if (!out.screening && L.nuisances && p.refit_drop_nuisances) {
    for (int round = 0; round < 2; ++round) {
      if (!RefitDropNuisances(p, L, obj, s)) break;
      FitResult more;
      Minimise(obj, L, lo, hi, s, more, true);
      out.iterations += more.iterations;
      out.converged = more.converged;
    }
  }
  Eigen::VectorXd unweighted;
  obj.Evaluate(s.x, &s.r, &unweighted);

  const ModelValues m = Unscale(p, L, s.x);
  out.effect_ids = ids;
  out.zeta_N_m3 = m.zeta_N_m3;
  out.effects = m.effects;
  out.sensor = m.sensor;
  out.offset_dt_s = m.offset_dt_s;
  out.offset_dz_m = m.offset_dz_m;
  out.nuisances.assign(p.drops.size(), DropNuisance{});
  for (int t = 0; t < static_cast<int>(m.nuisances.size()); ++t) out.nuisances[obj.train()[t]] = m.nuisances[t];
  out.cost = s.cost;
  out.rss = unweighted.squaredNorm();
  out.penalty = L.nuisances ? s.r.tail(obj.rows() - obj.data_rows()).squaredNorm() : 0.0;
  out.samples = obj.data_rows();
  out.parameters = L.globals();
  // The penalty rows are in the weighted cost's units; the information criterion's sum is of
  // unweighted rows, each drop's weight sqrt(n_d) apart: the penalty enters with the data's
  // average weight (cost / rss), so that a nuisance pulled one spread costs what it costs the fit.
  const double data_cost = s.cost - out.penalty;
  const double penalty_rss = data_cost > 0 ? out.penalty * out.rss / data_cost : 0.0;
  out.bic = out.samples * std::log(std::max(out.rss + penalty_rss, 1e-300) / out.samples) +
            out.parameters * std::log(double(out.samples));
  out.simulations = obj.simulations();
  ForceResidualsPerSoil(p, L, obj, unweighted, out);
  if (!out.screening) Estimates(p, L, obj, s, lo, hi, out);
  return out;
}

std::vector<double> TrainingCostsUnder(const FitProblem& p, const FitResult& model,
                                       const std::vector<Recording>& sensors) {
  ModelValues m = ValuesOf(model);
  const rft::EffectTerms terms = m.Terms();
  std::vector<std::vector<double>> cost(p.drops.size(), std::vector<double>(sensors.size(), 0.0));
  io::ParallelFor(p.drops.size(), p.threads, [&](size_t i) {
    const FitDrop& d = p.drops[i];
    if (!d.train) return;
    const DropNuisance b = i < model.nuisances.size() ? model.nuisances[i] : DropNuisance{};
    const std::optional<pad::RigDropResult> sim = Simulate(p, d, m, terms, b);  // once, recorded many times
    std::vector<double> r(2 * d.trace->size());
    ModelValues under = m;
    for (size_t k = 0; k < sensors.size(); ++k) {
      under.sensor = sensors[k].sensor;
      rft::EffectTerms shifted = terms;
      shifted.sensor_dt_s += sensors[k].extra_dt_s;
      DropRows(d, Record(d, under, shifted, b, sim), r.data(), nullptr);
      for (double v : r) cost[i][k] += v * v;
    }
  });
  std::vector<double> sum(sensors.size(), 0.0);
  for (const std::vector<double>& c : cost)  // in drop order: the same sum on any thread count
    for (size_t k = 0; k < c.size(); ++k) sum[k] += c[k];
  return sum;
}

namespace {
// Drop d's nuisances with the model's values `held` (its own nuisances ignored) held: its trigger
// time scanned from zero, then the three fitted by Levenberg-Marquardt with their penalty rows.
// `cost`: the drop's weighted data and penalty rows' sum of squares there (as in the joint fit).
DropNuisance FitOneDrop(const FitProblem& p, const FitDrop& d, const ModelValues& held, double* cost_out) {
  const rft::EffectTerms terms = held.Terms();
  SimulationCache cache;
  auto residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    const DropNuisance b{x[0] * p.spreads.log_zeta, x[1] * p.spreads.log_speed, x[2] * p.spreads.time_s};
    const long n = 2 * static_cast<long>(d.trace->size());
    r.resize(n + kDropNuisances);
    DropRows(d, Recorded(p, d, held, terms, b, cache), r.data(), nullptr);
    const double w = p.residual_sigma / std::sqrt(static_cast<double>(d.trace->size()));
    for (int c = 0; c < kDropNuisances; ++c) r[n + c] = w * x[c];
  };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(kDropNuisances), r, rp, r_new;
  x[2] = AlignedTime(p, d, held, terms, DropNuisance{}, cache.Get(p, d, held, terms, DropNuisance{})) / p.spreads.time_s;
  residuals(x, r);
  double cost = r.squaredNorm(), lambda = 1e-3;
  Eigen::MatrixXd J(r.size(), kDropNuisances);
  for (int it = 0; it < 15; ++it) {
    for (int c = 0; c < kDropNuisances; ++c) {
      Eigen::VectorXd xp = x;
      const double h = 1e-4 * std::max(std::abs(x[c]), 0.1);
      xp[c] += h;
      residuals(xp, rp);
      J.col(c) = (rp - r) / h;
    }
    const Eigen::Matrix3d A = J.transpose() * J;
    const Eigen::Vector3d g = J.transpose() * r;
    bool improved = false;
    for (int attempt = 0; attempt < 10 && lambda < 1e10; ++attempt) {
      Eigen::Matrix3d M = A;
      for (int j = 0; j < 3; ++j) M(j, j) += lambda * std::max(A(j, j), 1e-12);
      const Eigen::VectorXd x_new = (x + M.ldlt().solve(-g)).cwiseMax(-8.0).cwiseMin(8.0);
      residuals(x_new, r_new);
      if (r_new.squaredNorm() < cost) {
        const bool small = (x_new - x).norm() < 1e-6 * (x.norm() + 1e-6) || cost - r_new.squaredNorm() < 1e-8 * cost;
        x = x_new, r = r_new, cost = r.squaredNorm(), lambda = std::max(lambda / 4, 1e-9), improved = true;
        if (small) it = 1 << 20;
        break;
      }
      lambda *= 5;
    }
    if (!improved) break;
  }
  if (cost_out) *cost_out = cost;
  return {x[0] * p.spreads.log_zeta, x[1] * p.spreads.log_speed, x[2] * p.spreads.time_s};
}
}  // namespace

DropNuisance FitDropNuisance(const FitProblem& p, const FitDrop& d, const FitResult& model) {
  if (!p.drop_nuisances) return {};
  return FitOneDrop(p, d, ValuesOf(model), nullptr);
}

std::optional<dataset::DatasetTrace> SimulateRecorded(const FitProblem& p, const FitDrop& d, const FitResult& model) {
  const ModelValues m = ValuesOf(model);
  DropNuisance b;
  if (p.drop_nuisances) {
    const size_t i = static_cast<size_t>(&d - p.drops.data());
    b = d.train && i < model.nuisances.size() ? model.nuisances[i] : FitDropNuisance(p, d, model);
  }
  SimulationCache cache;
  return Recorded(p, d, m, m.Terms(), b, cache);
}

}  // namespace touchdown::gap
