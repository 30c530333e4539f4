#include "drop_tests/gap/diagnose_fit.h"

#include "drop_tests/dataset/sensor_sampling.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <Eigen/Dense>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/util/student_t.h"
#include "drop_tests/util/work_pool.h"
#include "lander/pad/effect_soil_response.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace touchdown::gap {

namespace {

// Sensor noise. The force sensor's noise is read where the recorded force is constant: at rest,
// after the pad has stopped, where second differences leave only noise (a linear drift cancels).
// One sensor is assumed per dataset, so the rest phases of all drops are pooled: a 1 kHz record
// holds only 5-8 rest samples a drop. Second differences of the whole stroke carry the signal's own
// curvature (1-5x the noise on 20-30 sample strokes); third differences, the fallback for data with
// no rest phase, carry less of it. Robust scale: 1.4826 x the median absolute value.
double RobustScale(std::vector<double> v, double difference_variance) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return 1.4826 * v[v.size() / 2] / std::sqrt(difference_variance);
}

// |second differences| of the force at rest: the trailing samples whose penetration stays within
// 1 % of the stroke of its final value, and that come two samples after the force's steepest fall
// past its peak (the stop; a period mean may straddle it). The penetration band alone also takes in
// the last samples of the stroke, where the pad still decelerates under the peak force.
std::vector<double> RestSecondDifferences(const dataset::DatasetTrace& tr) {
  const std::vector<double>& z = tr.penetration_m;
  const std::vector<double>& f = tr.force_N;
  const size_t n = z.size(), tail = std::max<size_t>(1, std::min<size_t>(5, n / 4));
  std::vector<double> last(z.end() - static_cast<std::ptrdiff_t>(tail), z.end());
  std::nth_element(last.begin(), last.begin() + last.size() / 2, last.end());
  const double z_final = last[last.size() / 2];
  const double band = 0.01 * std::max(*std::max_element(z.begin(), z.end()), 1e-9);
  size_t first = n;
  while (first > 0 && std::abs(z[first - 1] - z_final) <= band) --first;
  size_t fall = static_cast<size_t>(std::max_element(f.begin(), f.end()) - f.begin());
  double steepest = 0.0;
  for (size_t i = fall; i + 1 < n; ++i)
    if (f[i + 1] - f[i] < steepest) steepest = f[i + 1] - f[i], fall = i;
  first = std::max(first, fall + 2);
  std::vector<double> d2;
  for (size_t i = first + 1; i + 1 < n; ++i) d2.push_back(std::abs(f[i + 1] - 2 * f[i] + f[i - 1]));
  return d2;
}

double StrokeNoiseEstimate(const std::vector<double>& y) {
  std::vector<double> d3;
  for (size_t i = 3; i < y.size(); ++i) d3.push_back(std::abs(y[i] - 3 * y[i - 1] + 3 * y[i - 2] - y[i - 3]));
  return RobustScale(std::move(d3), 20.0);
}

constexpr size_t kMinRestDifferences = 20;

struct Layout {
  std::vector<std::string> effect_ids;
  std::vector<const CandidateTerm*> infos;
  int soils = 0;
  int size() const {
    int n = soils;
    for (const CandidateTerm* e : infos) n += static_cast<int>(e->parameters.size());
    return n;
  }
};

struct ModelValues {
  std::vector<double> zeta_N_m3;
  std::vector<model::Effect> effects;
};

ModelValues Unscale(const FitProblem& p, const Layout& L, const Eigen::VectorXd& x) {
  ModelValues m;
  int k = 0;
  for (int s = 0; s < L.soils; ++s) m.zeta_N_m3.push_back(x[k++] * p.soils[s].zeta_N_m3);
  for (const CandidateTerm* e : L.infos) {
    model::Effect effect{model::FindEffect(e->effect).id, {}};
    for (const model::EffectParameterInfo& q : e->parameters) effect.values.push_back(x[k++] * q.scale);
    m.effects.push_back(effect);
  }
  return m;
}

void Bounds(const FitProblem&, const Layout& L, Eigen::VectorXd* lo, Eigen::VectorXd* hi) {
  const int n = L.size();
  lo->resize(n);
  hi->resize(n);
  int k = 0;
  for (int s = 0; s < L.soils; ++s) (*lo)[k] = 0.02, (*hi)[k] = 50.0, ++k;
  for (const CandidateTerm* e : L.infos)
    for (const model::EffectParameterInfo& q : e->parameters) (*lo)[k] = q.lower / q.scale, (*hi)[k] = q.upper / q.scale, ++k;
}

// The model's recorded trace for one drop, or nullopt when the simulation fails.
std::optional<dataset::DatasetTrace> Recorded(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                     const rft::EffectTerms& terms) {
  rft::SoilParameters soil = drop::DropSoil(p.soils[d.soil], m.zeta_N_m3[d.soil], d.atmosphere);
  if (p.bekker_base) {  // zeta is the scale of the Bekker soil's moduli
    soil.bekker.k_c_N_m_n1 *= m.zeta_N_m3[d.soil];
    soil.bekker.k_phi_N_m_n2 *= m.zeta_N_m3[d.soil];
  }
  try {
    const pad::EffectSoilResponse response =
        p.bekker_base ? drop::MakeBekkerRigResponse(*p.bekker_intrusions[d.pad], soil, terms)
                      : drop::MakeRigResponse(*p.intrusions[d.pad], soil, d.gravity_m_s2, terms);
    const pad::RigDropResult r = pad::RunRigDrop({{d.mass_kg}, &response, {d.gravity_m_s2, d.speed_m_s}, p.rig});
    return dataset::RecordedTrace(r, d.gravity_m_s2, terms, d.trace->t_s, p.sensor_sampling, d.sample_period_s);
  } catch (const integ::IntegrationFailure&) {
    return std::nullopt;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

class Objective {
 public:
  Objective(const FitProblem& p, const Layout& L) : p_(p), L_(L) {
    for (size_t i = 0; i < p.drops.size(); ++i)
      if (p.drops[i].train) {
        train_.push_back(static_cast<int>(i));
        offset_.push_back(rows_);
        rows_ += 2 * static_cast<long>(p.drops[i].trace->size());
      }
  }
  long rows() const { return rows_; }
  const std::vector<int>& train() const { return train_; }
  const std::vector<long>& offsets() const { return offset_; }
  long simulations = 0;

  // Weighted residuals (as minimised) and the unweighted ones (for the information criterion).
  void Evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* r, Eigen::VectorXd* unweighted = nullptr) {
    const ModelValues m = Unscale(p_, L_, x);
    const rft::EffectTerms terms = model::MakeEffectTerms(m.effects);
    r->resize(rows_);
    if (unweighted) unweighted->resize(rows_);
    io::ParallelFor(train_.size(), p_.threads, [&](size_t k) {
      const FitDrop& d = p_.drops[train_[k]];
      const std::optional<dataset::DatasetTrace> sim = Recorded(p_, d, m, terms);
      const dataset::DatasetTrace& tr = *d.trace;
      const long n = static_cast<long>(tr.size()), o = offset_[k];
      const double w = 1.0 / std::sqrt(static_cast<double>(n));
      for (long i = 0; i < n; ++i) {
        // A failed simulation costs as much as predicting nothing at all, times ten.
        const double ef = sim ? (sim->force_N[i] - tr.force_N[i]) / d.force_scale_N : 10.0;
        const double ep = sim ? (sim->penetration_m[i] - tr.penetration_m[i]) / d.penetration_scale_m : 10.0;
        (*r)[o + 2 * i] = w * ef;
        (*r)[o + 2 * i + 1] = w * ep;
        if (unweighted) (*unweighted)[o + 2 * i] = ef, (*unweighted)[o + 2 * i + 1] = ep;
      }
    });
    simulations += static_cast<long>(train_.size());
  }

 private:
  const FitProblem& p_;
  const Layout& L_;
  std::vector<int> train_;
  std::vector<long> offset_;
  long rows_ = 0;
};

Layout MakeLayout(const FitProblem& p, const std::vector<std::string>& ids) {
  Layout L;
  L.effect_ids = ids;
  L.soils = static_cast<int>(p.soils.size());
  for (const std::string& id : ids) L.infos.push_back(&FindTerm(p, id));
  return L;
}
}  // namespace

rft::EffectTerms FitResult::terms() const { return model::MakeEffectTerms(effects); }

void SetCandidateTerms(FitProblem& p) {
  // The soils' own dynamic term in inertial_drag's units, when they all share one.
  p.shipped_lambda = 0.0;
  for (size_t s = 0; s < p.soils.size(); ++s) {
    const rft::SoilParameters& soil = p.soils[s];
    const double lambda = soil.dynamic_term && soil.bulk_density_kg_m3 > 0.0
                              ? rft::WithSoilDynamicTerm({}, soil).inertial_lambda
                              : 0.0;
    if (s > 0 && lambda != p.shipped_lambda) {
      p.shipped_lambda = 0.0;
      break;
    }
    p.shipped_lambda = lambda;
  }
  p.terms.clear();
  const model::EffectInfo& inertial = model::FindEffect(model::EffectId::kInertialDrag);
  CandidateTerm weaker{kWeakerDynamicTerm, inertial.kind, inertial.parameters};
  model::EffectParameterInfo& w = weaker.parameters[0];
  w.upper = std::max(p.shipped_lambda, 0.0);
  w.start = 0.5 * p.shipped_lambda;
  w.scan = {0.0, 0.5 * p.shipped_lambda, p.shipped_lambda};
  p.terms.push_back(weaker);
  for (const model::EffectInfo& e : model::EffectLibrary()) {
    CandidateTerm t{e.id, e.kind, e.parameters};
    if (e.kind == inertial.kind && p.shipped_lambda > 0.0) {  // more of the soil's own term
      t.parameters[0].lower = p.shipped_lambda;
      t.parameters[0].start = std::max(t.parameters[0].start, p.shipped_lambda);
    }
    p.terms.push_back(t);
  }
}

const CandidateTerm& FindTerm(const FitProblem& p, const std::string& name) {
  for (const CandidateTerm& t : p.terms)
    if (t.name == name) return t;
  throw std::logic_error("diagnose: no candidate term '" + name + "'");
}

FitProblem MakeFitProblem(const dataset::Dataset& ds, const std::vector<bool>& held_out, int threads) {
  FitProblem p;
  p.threads = threads;
  p.rig.rest_duration_s = 0.003;  // at rest the record holds its last value (RecordedAt)
  p.rig.max_stroke_duration_s = 2.0;
  p.rig.integrator.rtol = 1e-8;
  p.rig.integrator.atol = 1e-13;
  std::map<std::string, int> pads, soils;
  std::vector<double> rest_differences;
  for (size_t i = 0; i < ds.drops.size(); ++i) {
    const dataset::DatasetDrop& dd = ds.drops[i];
    const std::string pad_ref = ds.PadReference(dd), soil_ref = ds.SoilReference(dd);
    if (!pads.count(pad_ref)) {
      pads[pad_ref] = static_cast<int>(p.pads.size());
      p.pads.push_back(io::LoadPad(pad_ref));
      if (!p.pads.back().is_axisymmetric())
        throw MakeInputError(ds.directory, "drop " + dd.drop_id,
                             "pad '" + dd.pad + "' is a mesh; diagnose fits rig drops, which need an axisymmetric pad");
      p.intrusions.push_back(drop::MakeRigIntrusion(p.pads.back().profile));
    }
    if (!soils.count(soil_ref)) {
      soils[soil_ref] = static_cast<int>(p.soils.size());
      p.soils.push_back(io::LoadSoil(soil_ref));
    }
    for (const char* column : {"tilt_deg", "horizontal_speed_m_s"}) {
      const std::optional<double> v = ds.ExtraNumber(dd, column);
      if (v && *v != 0.0)
        throw MakeInputError(ds.directory, "drop " + dd.drop_id,
                             std::string("diagnose simulates the vertical rig only; ") + column + " must be 0");
    }
    if (dd.trace.size() < 5) throw MakeInputError(ds.directory, "drop " + dd.drop_id, "trace has fewer than 5 samples");
    FitDrop d;
    d.dataset_index = i;
    d.drop_id = dd.drop_id;
    d.pad = pads[pad_ref];
    d.soil = soils[soil_ref];
    d.atmosphere = dd.atmosphere;
    p.has_air |= d.atmosphere == rft::Atmosphere::kAir;
    p.has_vacuum |= d.atmosphere == rft::Atmosphere::kVacuum;
    d.train = !held_out[i];
    d.speed_m_s = dd.impact_speed_m_s;
    d.mass_kg = dd.pad_mass_kg;
    d.gravity_m_s2 = dd.gravity_m_s2;
    d.trace = &dd.trace;
    d.force_scale_N = std::max(*std::max_element(dd.trace.force_N.begin(), dd.trace.force_N.end()), 1e-9);
    d.penetration_scale_m =
        std::max(*std::max_element(dd.trace.penetration_m.begin(), dd.trace.penetration_m.end()), 1e-9);
    d.noise_force_N = StrokeNoiseEstimate(dd.trace.force_N);
    for (double r : RestSecondDifferences(dd.trace)) rest_differences.push_back(r);
    d.sample_period_s = dataset::SamplePeriod(dd.trace);
    p.drops.push_back(d);
  }
  // Enough rest samples for a pooled estimate (its median's relative error about 1.2/sqrt(count)):
  // every drop gets the one sensor's noise; otherwise each keeps its own stroke estimate.
  if (rest_differences.size() >= kMinRestDifferences) {
    const double sigma_N = RobustScale(std::move(rest_differences), 6.0);
    for (FitDrop& d : p.drops) d.noise_force_N = sigma_N;
  }
  SetCandidateTerms(p);
  return p;
}

bool CandidateApplies(const FitProblem& p, const std::vector<std::string>& ids, std::string* why) {
  for (size_t i = 0; i < ids.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (FindTerm(p, ids[i]).effect == FindTerm(p, ids[j]).effect) {
        *why = ids[i] + " and " + ids[j] + " set the same term";
        return false;
      }
  for (const std::string& name : ids) {
    const model::EffectInfo& e = model::FindEffect(FindTerm(p, name).effect);
    const std::string& id = e.id;
    if (name == kWeakerDynamicTerm && !(p.shipped_lambda > 0.0)) {
      *why = "the soils carry no common dynamic term to weaken";
      return false;
    }
    if (p.bekker_base && e.kind == model::EffectId::kDepthExponent) {
      *why = "depth_exponent does not apply to the Bekker base (its depth exponent is the soil's fitted n)";
      return false;
    }
    if (e.air_only && !(p.has_air && p.has_vacuum)) {
      *why = id + " needs drops in air and in vacuum (otherwise it is confounded with zeta)";
      return false;
    }
    if (e.needs_bulk_density)
      for (const rft::SoilParameters& s : p.soils)
        if (!(s.bulk_density_kg_m3 > 0.0)) {
          *why = id + " needs the bulk density of soil " + s.name;
          return false;
        }
  }
  return true;
}

namespace {
// The starting point: zeta from `start` (or the catalogue), effect parameters at their starting
// values, each multi-modal one (EffectParameterInfo::scan) set by a coarse scan, one at a time.
Eigen::VectorXd StartingPoint(const FitProblem& p, const Layout& L, const FitResult* start, Objective& obj) {
  Eigen::VectorXd x(L.size());
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

// Forward-difference Jacobian of the weighted residuals at s.x, a step inside the upper bound.
void UpdateJacobian(Objective& obj, const Eigen::VectorXd& hi, Solution& s) {
  for (int j = 0; j < s.x.size(); ++j) {
    double h = 1e-4 * std::max(std::abs(s.x[j]), 0.1);
    if (s.x[j] + h > hi[j]) h = -h;
    Eigen::VectorXd xp = s.x;
    xp[j] += h;
    Eigen::VectorXd rp;
    obj.Evaluate(xp, &rp);
    s.J.col(j) = (rp - s.r) / h;
  }
}

// Levenberg-Marquardt from s.x within [lo, hi]; counts the iterations and says whether it
// converged. Leaves the Jacobian at the optimum (for the intervals).
void Minimise(Objective& obj, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Solution& s, FitResult& out) {
  const long n = s.x.size();
  obj.Evaluate(s.x, &s.r);
  s.cost = s.r.squaredNorm();
  s.J.resize(obj.rows(), n);
  Eigen::VectorXd r_new;
  double lambda = 1e-3;
  const int max_iterations = 30;
  for (int it = 0; it < max_iterations; ++it) {
    out.iterations = it + 1;
    UpdateJacobian(obj, hi, s);
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
        // the parameters by less than 1e-6 of their (scaled) size.
        if (gain < 1e-8 || step_norm < 1e-7 * (s.x.norm() + 1e-7)) out.converged = true;
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
  UpdateJacobian(obj, hi, s);
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

// The parameters' covariance at the optimum: cluster-robust (drops as clusters, CR1 small-sample
// factor G / (G - 1)), each variance widened to the classical one where that is larger.
Eigen::MatrixXd Covariance(const FitProblem& p, const Objective& obj, const Solution& s) {
  const long n = s.x.size();
  const Eigen::MatrixXd& J = s.J;
  const Eigen::VectorXd& r = s.r;
  const Eigen::MatrixXd A = J.transpose() * J;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  const int G = static_cast<int>(obj.train().size());
  for (int c = 0; c < G; ++c) {
    const long o = obj.offsets()[c];
    const long rows = 2 * static_cast<long>(p.drops[obj.train()[c]].trace->size());
    const Eigen::VectorXd g = J.middleRows(o, rows).transpose() * r.segment(o, rows);
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
    const long rows = 2 * static_cast<long>(p.drops[obj.train()[c]].trace->size());
    for (long i = 0; i < rows; ++i) {
      rho_den += r[o + i] * r[o + i];
      if (i >= 2) rho_num += r[o + i] * r[o + i - 2];  // same channel, one sample earlier
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
  const Eigen::MatrixXd cov = Covariance(p, obj, s);
  const int G = static_cast<int>(obj.train().size());
  const double t = io::StudentTTwoSided(0.95, std::max(G - 1, 1));
  const Eigen::VectorXd& x = s.x;
  int k = 0;
  auto estimate = [&](const std::string& effect, const std::string& key, double scale, double file_to_si,
                      const std::string& unit) {
    const double half = t * std::sqrt(std::max(cov(k, k), 0.0));
    ParameterEstimate e{effect, key, x[k] * scale, std::max(x[k] - half, lo[k]) * scale,
                        std::min(x[k] + half, hi[k]) * scale, file_to_si, unit, lo[k] * scale, hi[k] * scale};
    out.estimates.push_back(e);
    ++k;
  };
  for (const rft::SoilParameters& soil : p.soils) {
    if (p.bekker_base)
      estimate("", "bekker_modulus_scale:" + soil.name, 1.0, 1.0, "-");
    else
      estimate("", "zeta_N_cm3:" + soil.name, soil.zeta_N_m3, units::kN_m3_per_N_cm3, "N/m^3");
  }
  for (const CandidateTerm* e : L.infos)
    for (const model::EffectParameterInfo& q : e->parameters) estimate(e->name, q.key, q.scale, q.file_to_si, q.unit);
}
}  // namespace

FitResult FitCandidate(const FitProblem& p, const std::vector<std::string>& ids, const FitResult* start) {
  const Layout L = MakeLayout(p, ids);
  const int n = L.size();
  Eigen::VectorXd lo, hi;
  Bounds(p, L, &lo, &hi);
  Objective obj(p, L);
  FitResult out;
  Solution s;
  s.x = StartingPoint(p, L, start, obj);
  Minimise(obj, lo, hi, s, out);
  Eigen::VectorXd unweighted;
  obj.Evaluate(s.x, &s.r, &unweighted);

  const ModelValues m = Unscale(p, L, s.x);
  out.effect_ids = ids;
  out.zeta_N_m3 = m.zeta_N_m3;
  out.effects = m.effects;
  out.cost = s.cost;
  out.rss = unweighted.squaredNorm();
  out.samples = obj.rows();
  out.parameters = n;
  out.bic = out.samples * std::log(std::max(out.rss, 1e-300) / out.samples) + n * std::log(double(out.samples));
  out.simulations = obj.simulations;
  ForceResidualsPerSoil(p, L, obj, unweighted, out);
  Estimates(p, L, obj, s, lo, hi, out);
  return out;
}

std::optional<dataset::DatasetTrace> SimulateRecorded(const FitProblem& p, const FitDrop& d, const FitResult& model) {
  ModelValues m{model.zeta_N_m3, model.effects};
  return Recorded(p, d, m, model.terms());
}

}  // namespace touchdown::gap
