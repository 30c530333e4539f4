#include "drop_tests/gap/diagnose_fit.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/drop/drop_factory.h"
#include "rft/input_error.h"
#include "rft/stress_law_3d_factory.h"

// The fit problem of diagnose_fit.h as the data set it up: the drops with their noise and stop
// samples, the candidate terms and where they apply, the replicates and the nuisances' spreads.
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
}  // namespace

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
    d.penetration_zero = dd.penetration_zero;
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

std::string ConditionKey(const FitDrop& d) {
  std::ostringstream key;
  key << d.pad << '|' << d.soil << '|' << static_cast<int>(d.atmosphere) << '|' << std::setprecision(6) << d.speed_m_s
      << '|' << d.mass_kg << '|' << d.gravity_m_s2;
  return key.str();
}

namespace {
// The training drops by condition (ConditionKey): replicates of one condition share a key.
std::map<std::string, std::vector<size_t>> TrainingConditions(const FitProblem& p) {
  std::map<std::string, std::vector<size_t>> conditions;
  for (size_t i = 0; i < p.drops.size(); ++i)
    if (p.drops[i].train) conditions[ConditionKey(p.drops[i])].push_back(i);
  return conditions;
}
}  // namespace

int TrainingReplicateDf(const FitProblem& p) {
  int df = 0;
  for (const auto& [key, drops] : TrainingConditions(p)) df += static_cast<int>(drops.size()) - 1;
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
  const std::map<std::string, std::vector<size_t>> conditions = TrainingConditions(p);
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
