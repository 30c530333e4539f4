#include "drop_tests/gap/fit_objective.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "drop_tests/dataset/compare.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/util/work_pool.h"
#include "lander/pad/effect_soil_response.h"
#include "rft/units.h"

namespace touchdown::gap::fit {

namespace {
// What a drop's simulation depends on: its soil's strength and its impact speed with the drop's
// nuisances, and the physical terms' values. The sensor, the common offsets, a sensor_offset term
// and the drop's time nuisance change only what is recorded from it.
std::vector<double> SimulationKey(const FitDrop& d, const ModelValues& m, const DropNuisance& b) {
  std::vector<double> key{m.zeta_N_m3[d.soil] * std::exp(b.log_zeta), d.speed_m_s * std::exp(b.log_speed)};
  for (const model::Effect& e : m.effects)
    if (!model::FindEffect(e.id).measurement_only) key.insert(key.end(), e.values.begin(), e.values.end());
  return key;
}

}  // namespace

// A fitted model's values (its nuisances apart, which are per drop).
ModelValues ValuesOf(const FitResult& f) {
  ModelValues m{f.zeta_N_m3, f.effects, f.sensor, {}};
  m.offset_dt_s = f.offset_dt_s;
  m.offset_dz_m = f.offset_dz_m;
  return m;
}

double SampleRate(const FitProblem& p) {
  double period = 0.0;
  for (const FitDrop& d : p.drops) period = std::max(period, d.sample_period_s);
  return period > 0.0 ? 1.0 / period : 1000.0;
}

ModelValues Unscale(const FitProblem& p, const Layout& L, const Eigen::VectorXd& x) {
  ModelValues m;
  int k = 0;
  for (int s = 0; s < L.soils; ++s) m.zeta_N_m3.push_back(x[k++] * p.soils[s].zeta_N_m3);
  for (const CandidateTerm* e : L.infos) {
    model::Effect effect{model::FindEffect(e->effect).id, {}};
    for (const model::EffectParameterInfo& q : e->parameters) effect.values.push_back(x[k++] * q.scale);
    m.effects.push_back(effect);
  }
  m.sensor = p.sensor;
  if (p.sensor_fit.cutoff) m.sensor.lowpass_cutoff_hz = x[k++] * SampleRate(p);
  if (p.sensor_fit.load_cell) {
    m.sensor.load_cell_hz = x[k++] * units::kKilo;
    m.sensor.load_cell_damping = x[k++];
  }
  if (p.sensor_fit.offsets) {
    m.offset_dt_s = x[k++] * kOffsetTimeScale_s;
    m.offset_dz_m = x[k++] * kOffsetDepthScale_m;
  }
  if (L.nuisances)
    for (int t = 0; t < L.train; ++t) {
      DropNuisance b;
      b.log_zeta = x[k++] * p.spreads.log_zeta;
      b.log_speed = x[k++] * p.spreads.log_speed;
      b.time_s = x[k++] * p.spreads.time_s;
      m.nuisances.push_back(b);
    }
  return m;
}

void Bounds(const FitProblem& p, const Layout& L, Eigen::VectorXd* lo, Eigen::VectorXd* hi) {
  const int n = L.size();
  lo->resize(n);
  hi->resize(n);
  int k = 0;
  for (int s = 0; s < L.soils; ++s) (*lo)[k] = 0.02, (*hi)[k] = 50.0, ++k;
  for (const CandidateTerm* e : L.infos)
    for (const model::EffectParameterInfo& q : e->parameters) (*lo)[k] = q.lower / q.scale, (*hi)[k] = q.upper / q.scale, ++k;
  if (p.sensor_fit.cutoff) (*lo)[k] = 0.05, (*hi)[k] = 0.5, ++k;
  if (p.sensor_fit.load_cell) {
    // 100 Hz to 5 kHz, and under the Nyquist frequency: a ring above it aliases, and a fit there
    // follows the noise.
    (*lo)[k] = 0.1, (*hi)[k] = std::min(5.0, 0.5 * SampleRate(p) / units::kKilo), ++k;
    (*lo)[k] = 0.005, (*hi)[k] = 0.9, ++k;
  }
  if (p.sensor_fit.offsets) {  // sensor_offset's ranges: 50 ms and 50 mm
    (*lo)[k] = -0.05 / kOffsetTimeScale_s, (*hi)[k] = 0.05 / kOffsetTimeScale_s, ++k;
    (*lo)[k] = -0.05 / kOffsetDepthScale_m, (*hi)[k] = 0.05 / kOffsetDepthScale_m, ++k;
  }
  // Nuisances: within 8 spreads (a drop that far out is another condition, not scatter).
  for (; k < n; ++k) (*lo)[k] = -8.0, (*hi)[k] = 8.0;
}

// One drop's simulation with the model's values and its nuisances, or nullopt when it fails.
std::optional<pad::RigDropResult> Simulate(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                           const rft::EffectTerms& terms, const DropNuisance& b) {
  rft::SoilParameters soil =
      drop::DropSoil(p.soils[d.soil], m.zeta_N_m3[d.soil] * std::exp(b.log_zeta), d.atmosphere);
  if (p.bekker_base) {  // zeta is the scale of the Bekker soil's moduli
    soil.bekker.k_c_N_m_n1 *= m.zeta_N_m3[d.soil] * std::exp(b.log_zeta);
    soil.bekker.k_phi_N_m_n2 *= m.zeta_N_m3[d.soil] * std::exp(b.log_zeta);
  }
  try {
    const pad::EffectSoilResponse response =
        p.bekker_base ? drop::MakeBekkerRigResponse(*p.bekker_intrusions[d.pad], soil, terms)
                      : drop::MakeRigResponse(*p.intrusions[d.pad], soil, d.gravity_m_s2, terms);
    return pad::RunRigDrop({{d.mass_kg}, &response, {d.gravity_m_s2, d.speed_m_s * std::exp(b.log_speed)}, p.rig});
  } catch (const integ::IntegrationFailure&) {
    return std::nullopt;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

const std::optional<pad::RigDropResult>& SimulationCache::Get(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                             const rft::EffectTerms& terms, const DropNuisance& b) {
  std::vector<double> key = SimulationKey(d, m, b);
  ++clock_;
  for (Entry& e : entries_)
    if (e.key == key) {
      e.used = clock_;
      return e.result;
    }
  ++misses_;
  Entry* slot = nullptr;
  if (entries_.size() < kEntries) {
    slot = &entries_.emplace_back();
  } else {
    slot = &entries_.front();
    for (Entry& e : entries_)
      if (e.used < slot->used) slot = &e;
  }
  slot->key = std::move(key);
  slot->used = clock_;
  slot->result = Simulate(p, d, m, terms, b);
  return slot->result;
}

// What the sensor records of a simulation (nullopt for a failed one), the drop's time nuisance
// added to the recording's time offset.
std::optional<dataset::DatasetTrace> Record(const FitDrop& d, const ModelValues& m, rft::EffectTerms terms, const DropNuisance& b,
                                            const std::optional<pad::RigDropResult>& sim) {
  if (!sim) return std::nullopt;
  terms.sensor_dt_s += b.time_s;
  try {
    dataset::DatasetTrace recorded =
        dataset::RecordedTrace(*sim, d.gravity_m_s2, terms, d.trace->t_s, m.sensor, d.sample_period_s);
    if (d.penetration_zero == dataset::PenetrationZero::kTouchdown) {
      // Zeroed where the free fall put the pad at the recorded t = 0, dt after the true touchdown
      // (before it for dt < 0): v dt + g dt^2 / 2 below the surface, v the drop's impact speed.
      const double dt = terms.sensor_dt_s, v = d.speed_m_s * std::exp(b.log_speed);
      const double zero = v * dt + 0.5 * d.gravity_m_s2 * dt * dt;
      for (double& z : recorded.penetration_m) z -= zero;
    }
    return recorded;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

// The model's recorded trace for one drop with its nuisances, through `cache`.
std::optional<dataset::DatasetTrace> Recorded(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                              const rft::EffectTerms& terms, const DropNuisance& b,
                                              SimulationCache& cache) {
  return Record(d, m, terms, b, cache.Get(p, d, m, terms, b));
}

// A drop's weighted residual rows: 2 per sample (force, penetration), each over sqrt(samples).
// A failed simulation costs as much as predicting nothing at all, times ten.
void DropRows(const FitDrop& d, const std::optional<dataset::DatasetTrace>& sim, double* r, double* unweighted) {
  const dataset::DatasetTrace& tr = *d.trace;
  const long n = static_cast<long>(tr.size());
  const double w = 1.0 / std::sqrt(static_cast<double>(n));
  for (long i = 0; i < n; ++i) {
    const double ef = !sim ? 10.0 : d.ForceCounted(static_cast<size_t>(i)) ? (sim->force_N[i] - tr.force_N[i]) / d.force_scale_N : 0.0;
    const double ep = sim ? (sim->penetration_m[i] - tr.penetration_m[i]) / d.penetration_scale_m : 10.0;
    r[2 * i] = w * ef;
    r[2 * i + 1] = w * ep;
    if (unweighted) unweighted[2 * i] = ef, unweighted[2 * i + 1] = ep;
  }
}

// The time nuisance at which drop d's record, simulated once (`sim`), fits best with its other
// nuisances in `b` held: a scan of shifts (steps of a quarter of the time spread, at least a
// sample, out to 8 spreads or 8 ms), then a tenth of that step around the best, each a
// re-recording. Levenberg-Marquardt in time alone stalls: a record's sharp stop and a load cell's
// ring make the misfit in time many-valleyed, and a trigger that fired milliseconds late puts the
// optimum valleys away (the independent blind sets' curved pad: 2.3-3.1 ms).
double AlignedTime(const FitProblem& p, const FitDrop& d, const ModelValues& m, const rft::EffectTerms& terms,
                   DropNuisance b, const std::optional<pad::RigDropResult>& sim) {
  if (!sim) return b.time_s;
  const double spread = p.spreads.time_s;
  const double step = std::max(0.25 * spread, d.sample_period_s);
  const double reach = std::min(8.0 * spread, 8e-3);
  const long n = static_cast<long>(d.trace->size());
  const double w = p.residual_sigma / std::sqrt(static_cast<double>(n));
  std::vector<double> r(2 * n);
  const auto cost = [&](double t) {
    b.time_s = t;
    DropRows(d, Record(d, m, terms, b, sim), r.data(), nullptr);
    double c = 0.0;
    for (double v : r) c += v * v;
    return c + (w * t / spread) * (w * t / spread);
  };
  double best = b.time_s, best_cost = cost(b.time_s);
  const auto consider = [&](double t) {
    if (std::abs(t) > 8.0 * spread) return;
    const double c = cost(t);
    if (c < best_cost) best_cost = c, best = t;
  };
  for (double t = -reach; t <= reach + 1e-15; t += step) consider(t);
  const double centre = best;
  for (int j = -5; j <= 5; ++j)
    if (j != 0) consider(centre + 0.1 * step * j);
  return best;
}

void Objective::AlignTimes(Eigen::VectorXd& x) {
  const ModelValues m = Unscale(p_, L_, x);
  const rft::EffectTerms terms = m.Terms();
  io::ParallelFor(train_.size(), p_.threads, [&](size_t k) {
    const FitDrop& d = p_.drops[train_[k]];
    const DropNuisance& b = m.nuisances[k];
    const double t = AlignedTime(p_, d, m, terms, b, caches_[k].Get(p_, d, m, terms, b));
    x[L_.Nuisance(static_cast<int>(k), 2)] = t / p_.spreads.time_s;
  });
}


void Objective::Evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* r, Eigen::VectorXd* unweighted) {
  const ModelValues m = Unscale(p_, L_, x);
  const rft::EffectTerms terms = m.Terms();
  r->resize(rows());
  if (unweighted) unweighted->resize(data_rows_);
  io::ParallelFor(train_.size(), p_.threads, [&](size_t k) {
    const FitDrop& d = p_.drops[train_[k]];
    const DropNuisance b = L_.nuisances ? m.nuisances[k] : DropNuisance{};
    DropRows(d, Recorded(p_, d, m, terms, b, caches_[k]), r->data() + offset_[k],
             unweighted ? unweighted->data() + offset_[k] : nullptr);
    if (L_.nuisances) {
      const double w = p_.residual_sigma / std::sqrt(static_cast<double>(d.trace->size()));
      for (int c = 0; c < kDropNuisances; ++c) (*r)[PenaltyRow(static_cast<int>(k), c)] = w * x[L_.Nuisance(static_cast<int>(k), c)];
    }
  });
}


Layout MakeLayout(const FitProblem& p, const std::vector<std::string>& ids) {
  Layout L;
  L.effect_ids = ids;
  L.soils = static_cast<int>(p.soils.size());
  for (const std::string& id : ids) L.infos.push_back(&FindTerm(p, id));
  L.sensor = p.sensor_fit.count();
  for (const FitDrop& d : p.drops) L.train += d.train;
  L.nuisances = p.drop_nuisances;
  return L;
}

}  // namespace touchdown::gap::fit
