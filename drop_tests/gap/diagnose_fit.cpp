#include "drop_tests/gap/diagnose_fit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <iomanip>
#include <stdexcept>

#include <Eigen/Dense>

#include "drop_tests/dataset/compare.h"
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
  const SampleRange stop = StopSamples(f);
  first = std::max(first, stop.end > 0 ? stop.end : static_cast<size_t>(std::max_element(f.begin(), f.end()) - f.begin()) + 2);
  std::vector<double> d2;
  for (size_t i = first + 1; i + 1 < n; ++i) d2.push_back(std::abs(f[i + 1] - 2 * f[i] + f[i - 1]));
  return d2;
}

}  // namespace

SampleRange StopSamples(const std::vector<double>& f) {
  if (f.size() < 2) return {};
  size_t fall = static_cast<size_t>(std::max_element(f.begin(), f.end()) - f.begin());
  double steepest = 0.0;
  for (size_t i = fall; i + 1 < f.size(); ++i)
    if (f[i + 1] - f[i] < steepest) steepest = f[i + 1] - f[i], fall = i;
  if (steepest == 0.0) return {};  // no fall: the record ends before the stop
  return {fall, fall + 2};
}

namespace {

double StrokeNoiseEstimate(const std::vector<double>& y) {
  std::vector<double> d3;
  for (size_t i = 3; i < y.size(); ++i) d3.push_back(std::abs(y[i] - 3 * y[i - 1] + 3 * y[i - 2] - y[i - 3]));
  return RobustScale(std::move(d3), 20.0);
}

constexpr size_t kMinRestDifferences = 20;

// The fitted parameters, scaled (diagnose_fit.h): zeta per soil (as a factor of the catalogue's),
// the terms' parameters (each over its typical scale), the sensor's free parameters, then three
// nuisances per training drop (each over its spread, so its penalty row is sigma/sqrt(n) x).
struct Layout {
  std::vector<std::string> effect_ids;
  std::vector<const CandidateTerm*> infos;
  int soils = 0;
  int sensor = 0;      // the sensor's free parameters: 0, 1 (low-pass cutoff) or 2 (load cell)
  int train = 0;       // training drops, each with kDropNuisances nuisances when they are on
  bool nuisances = false;
  int effects() const {
    int n = 0;
    for (const CandidateTerm* e : infos) n += static_cast<int>(e->parameters.size());
    return n;
  }
  int globals() const { return soils + effects() + sensor; }  // the model's and the sensor's
  int size() const { return globals() + (nuisances ? kDropNuisances * train : 0); }
  int Nuisance(int k, int c) const { return globals() + kDropNuisances * k + c; }  // training drop k
};

struct ModelValues {
  std::vector<double> zeta_N_m3;
  std::vector<model::Effect> effects;
  dataset::SensorModel sensor;
  std::vector<DropNuisance> nuisances;  // per training drop (empty without them)
  double offset_dt_s = 0.0, offset_dz_m = 0.0;
  // The effects' terms with the common offsets added to a sensor_offset's.
  rft::EffectTerms Terms() const {
    rft::EffectTerms t = model::MakeEffectTerms(effects);
    t.sensor_dt_s += offset_dt_s;
    t.sensor_dz_m += offset_dz_m;
    return t;
  }
};

// A fitted model's values (its nuisances apart, which are per drop).
ModelValues ValuesOf(const FitResult& f) {
  ModelValues m{f.zeta_N_m3, f.effects, f.sensor, {}};
  m.offset_dt_s = f.offset_dt_s;
  m.offset_dz_m = f.offset_dz_m;
  return m;
}

// The common offsets' scales: a tenth of a millisecond, a tenth of a millimetre.
constexpr double kOffsetTimeScale_s = 1e-4, kOffsetDepthScale_m = 1e-4;

// The sensor's free parameters in the scaled vector: the low-pass cutoff over the sample rate
// (a fraction in [0.05, 0.5]); or the load cell's frequency over 1 kHz and its damping ratio.
struct SensorScale {
  double cutoff_per_rate = 1.0, frequency_kHz = 1e3;
};

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
    m.sensor.load_cell_hz = x[k++] * 1e3;
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
    (*lo)[k] = 0.1, (*hi)[k] = std::min(5.0, 0.5 * SampleRate(p) / 1e3), ++k;
    (*lo)[k] = 0.005, (*hi)[k] = 0.9, ++k;
  }
  if (p.sensor_fit.offsets) {  // sensor_offset's ranges: 50 ms and 50 mm
    (*lo)[k] = -0.05 / kOffsetTimeScale_s, (*hi)[k] = 0.05 / kOffsetTimeScale_s, ++k;
    (*lo)[k] = -0.05 / kOffsetDepthScale_m, (*hi)[k] = 0.05 / kOffsetDepthScale_m, ++k;
  }
  // Nuisances: within 8 spreads (a drop that far out is another condition, not scatter).
  for (; k < n; ++k) (*lo)[k] = -8.0, (*hi)[k] = 8.0;
}

// What a drop's simulation depends on: its soil's strength and its impact speed with the drop's
// nuisances, and the physical terms' values. The sensor, the common offsets, a sensor_offset term
// and the drop's time nuisance change only what is recorded from it.
std::vector<double> SimulationKey(const FitDrop& d, const ModelValues& m, const DropNuisance& b) {
  std::vector<double> key{m.zeta_N_m3[d.soil] * std::exp(b.log_zeta), d.speed_m_s * std::exp(b.log_speed)};
  for (const model::Effect& e : m.effects)
    if (!model::FindEffect(e.id).measurement_only) key.insert(key.end(), e.values.begin(), e.values.end());
  return key;
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

// The last few simulations of one drop, by SimulationKey. A Jacobian column in the sensor's
// parameters, the common offsets or a drop's time nuisance re-records the simulation at the
// current point instead of repeating it. A simulation is a pure function of its key, so a cached
// result is the one a new run would give, bit for bit.
class SimulationCache {
 public:
  const std::optional<pad::RigDropResult>& Get(const FitProblem& p, const FitDrop& d, const ModelValues& m,
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
  long misses() const { return misses_; }

 private:
  static constexpr size_t kEntries = 4;  // the current point, and the columns that moved it
  struct Entry {
    std::vector<double> key;
    std::optional<pad::RigDropResult> result;
    long used = 0;
  };
  std::vector<Entry> entries_;
  long clock_ = 0, misses_ = 0;
};

// What the sensor records of a simulation (nullopt for a failed one), the drop's time nuisance
// added to the recording's time offset.
std::optional<dataset::DatasetTrace> Record(const FitDrop& d, const ModelValues& m, rft::EffectTerms terms, const DropNuisance& b,
                                            const std::optional<pad::RigDropResult>& sim) {
  if (!sim) return std::nullopt;
  terms.sensor_dt_s += b.time_s;
  try {
    return dataset::RecordedTrace(*sim, d.gravity_m_s2, terms, d.trace->t_s, m.sensor, d.sample_period_s);
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

class Objective {
 public:
  Objective(const FitProblem& p, const Layout& L) : p_(p), L_(L) {
    for (size_t i = 0; i < p.drops.size(); ++i)
      if (p.drops[i].train) {
        train_.push_back(static_cast<int>(i));
        offset_.push_back(data_rows_);
        data_rows_ += 2 * static_cast<long>(p.drops[i].trace->size());
      }
    caches_.resize(train_.size());
  }
  // Data rows, then (with the nuisances) kDropNuisances penalty rows per training drop.
  long rows() const { return data_rows_ + (L_.nuisances ? kDropNuisances * static_cast<long>(train_.size()) : 0); }
  long data_rows() const { return data_rows_; }
  const std::vector<int>& train() const { return train_; }
  const std::vector<long>& offsets() const { return offset_; }
  long PenaltyRow(int k, int c) const { return data_rows_ + kDropNuisances * k + c; }
  int max_iterations() const { return max_iterations_ > 0 ? max_iterations_ : p_.max_iterations; }
  void LimitIterations(int n) { max_iterations_ = n; }
  // The drops simulated so far (a re-recorded simulation not counted).
  long simulations() const {
    long n = 0;
    for (const SimulationCache& c : caches_) n += c.misses();
    return n;
  }

  // Every training drop's time nuisance in x set by AlignedTime, the rest of x held.
  void AlignTimes(Eigen::VectorXd& x) {
    const ModelValues m = Unscale(p_, L_, x);
    const rft::EffectTerms terms = m.Terms();
    io::ParallelFor(train_.size(), p_.threads, [&](size_t k) {
      const FitDrop& d = p_.drops[train_[k]];
      const DropNuisance& b = m.nuisances[k];
      const double t = AlignedTime(p_, d, m, terms, b, caches_[k].Get(p_, d, m, terms, b));
      x[L_.Nuisance(static_cast<int>(k), 2)] = t / p_.spreads.time_s;
    });
  }

  // Weighted residuals (as minimised) and the unweighted data rows (for the information criterion).
  void Evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* r, Eigen::VectorXd* unweighted = nullptr) {
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

 private:
  const FitProblem& p_;
  const Layout& L_;
  std::vector<int> train_;
  std::vector<long> offset_;
  std::vector<SimulationCache> caches_;  // per training drop
  long data_rows_ = 0;
  int max_iterations_ = 0;
};

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
    // Fitted as the rig's nuisance in every model (SensorFit::offsets), not a candidate of the soil's.
    if (p.sensor_fit.offsets && e.kind == model::EffectId::kSensorOffset) continue;
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

FitProblem MakeFitProblem(const dataset::Dataset& ds, const std::vector<bool>& held_out, int threads,
                          bool skip_stop_samples) {
  FitProblem p;
  p.threads = threads;
  p.stop_samples_skipped = skip_stop_samples;
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
    if (skip_stop_samples) {
      const SampleRange stop = StopSamples(dd.trace.force_N);
      d.stop_skip_begin = stop.begin, d.stop_skip_end = stop.end;
    }
    p.drops.push_back(d);
  }
  // Enough rest samples for a pooled estimate (its median's relative error about 1.2/sqrt(count)):
  // every drop gets the one sensor's noise; otherwise each keeps its own stroke estimate.
  if (rest_differences.size() >= kMinRestDifferences) {
    const double sigma_N = RobustScale(std::move(rest_differences), 6.0);
    for (FitDrop& d : p.drops) d.noise_force_N = sigma_N;
  }
  p.rig.sample_rate_hz = dataset::RecordingSimulationRate_Hz(ds);  // as compare records
  p.rig.peaks_between_samples = false;  // the fits read the trace only
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
    x[k++] = sensor.load_cell_hz / 1e3;
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
      estimate(out.estimates, "", "zeta_N_cm3:" + soil.name, soil.zeta_N_m3, units::kN_m3_per_N_cm3, "N/m^3");
  }
  for (const CandidateTerm* e : L.infos)
    for (const model::EffectParameterInfo& q : e->parameters)
      estimate(out.estimates, e->name, q.key, q.scale, q.file_to_si, q.unit);
  if (p.sensor_fit.cutoff) estimate(out.sensor_estimates, "sensor", "lowpass_cutoff_hz", SampleRate(p), 1.0, "Hz");
  if (p.sensor_fit.load_cell) {
    estimate(out.sensor_estimates, "sensor", "load_cell_hz", 1e3, 1.0, "Hz");
    estimate(out.sensor_estimates, "sensor", "load_cell_damping", 1.0, 1.0, "-");
  }
  if (p.sensor_fit.offsets) {
    estimate(out.sensor_estimates, "sensor_offset", "dt_ms", kOffsetTimeScale_s, 1e-3, "s");
    estimate(out.sensor_estimates, "sensor_offset", "dz_mm", kOffsetDepthScale_m, 1e-3, "m");
  }
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

DropNuisance FitDropNuisance(const FitProblem& p, const FitDrop& d, const FitResult& model) {
  if (!p.drop_nuisances) return {};
  // The model's values held, the drop's three nuisances free, with their penalty rows.
  const ModelValues held = ValuesOf(model);
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
  return {x[0] * p.spreads.log_zeta, x[1] * p.spreads.log_speed, x[2] * p.spreads.time_s};
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

std::string ConditionKey(const FitDrop& d) {
  std::ostringstream key;
  key << d.pad << '|' << d.soil << '|' << static_cast<int>(d.atmosphere) << '|' << std::setprecision(6) << d.speed_m_s
      << '|' << d.mass_kg << '|' << d.gravity_m_s2;
  return key.str();
}

int TrainingReplicateDf(const FitProblem& p) {
  std::map<std::string, int> drops;
  for (const FitDrop& d : p.drops)
    if (d.train) ++drops[ConditionKey(d)];
  int df = 0;
  for (const auto& [key, n] : drops) df += n - 1;
  return df;
}

void CountStopSamples(FitProblem& p) {
  for (FitDrop& d : p.drops) d.stop_skip_begin = d.stop_skip_end = 0;
  p.stop_samples_skipped = false;
}

int EstimateNuisanceSpreads(FitProblem& p, const FitResult& fit) {
  // Within conditions only: replicates of one condition differ by scatter alone, while a common or
  // a condition's own deviation is the model's to explain (a nuisance spread estimated over all
  // drops would take in a missing effect, and the nuisances then absorb it).
  std::map<std::string, std::vector<size_t>> conditions;
  for (size_t i = 0; i < p.drops.size(); ++i)
    if (p.drops[i].train) conditions[ConditionKey(p.drops[i])].push_back(i);
  double sum[kDropNuisances] = {0, 0, 0};
  int df = 0;
  for (const auto& [key, drops] : conditions) {
    if (drops.size() < 2) continue;
    DropNuisance mean;
    for (size_t i : drops)
      mean.log_zeta += fit.nuisances[i].log_zeta, mean.log_speed += fit.nuisances[i].log_speed,
          mean.time_s += fit.nuisances[i].time_s;
    const double n = double(drops.size());
    mean.log_zeta /= n, mean.log_speed /= n, mean.time_s /= n;
    for (size_t i : drops) {
      const DropNuisance& b = fit.nuisances[i];
      sum[0] += (b.log_zeta - mean.log_zeta) * (b.log_zeta - mean.log_zeta);
      sum[1] += (b.log_speed - mean.log_speed) * (b.log_speed - mean.log_speed);
      sum[2] += (b.time_s - mean.time_s) * (b.time_s - mean.time_s);
    }
    df += static_cast<int>(drops.size()) - 1;
  }
  double period = 0.0;
  for (const FitDrop& d : p.drops) period = std::max(period, d.sample_period_s);
  // Floors: the scatter a drop test cannot avoid, so that a spread estimated near zero on
  // well-repeated drops does not pin every nuisance to zero (a tenth of what the independent
  // generator's realism draws at most: 5 % strength, 2 % speed). In time the floor is wide, 2 ms
  // or 2 samples: a record's t = 0 is where a trigger fired, and a threshold on a slowly rising
  // force fires late by an amount that is the same for the replicates of a condition but not
  // across pads (measured on the independent blind sets: 0.1 ms on the flat pad, 2.3-3.1 ms on
  // the curved one), so the within-condition spread misses it. The pre-contact penetration and the
  // stop pin each drop's time; a free time takes no effect's shape.
  // Without replicates (fewer than kMinNuisanceDf degrees of freedom) the floors are the spreads.
  const double floor[kDropNuisances] = {0.005, 0.002, std::max(2e-3, 2.0 * period)};
  double spread[kDropNuisances];
  for (int c = 0; c < kDropNuisances; ++c)
    spread[c] = std::max(df >= kMinNuisanceDf ? std::sqrt(sum[c] / df) : 0.0, floor[c]);
  p.spreads.log_zeta = spread[0];
  p.spreads.log_speed = spread[1];
  p.spreads.time_s = spread[2];
  // The residual's per-sample scale: the training data rows' RMS.
  p.residual_sigma = fit.samples > 0 ? std::max(std::sqrt(fit.rss / double(fit.samples)), 1e-6) : p.residual_sigma;
  return df;
}

}  // namespace touchdown::gap
