#pragma once
// Internal to drop_tests/gap (not a public header): the objective diagnose's fits minimise
// (diagnose_fit.cpp), in its own file so that the minimiser and the model's residuals each read
// alone. The parameter layout, the model's values unscaled from it, each drop's simulation (cached
// by what it depends on) and what the sensor records of it, the residual rows, and the Objective
// that evaluates them over the training drops.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "drop_tests/gap/diagnose_fit.h"
#include "lander/pad/rig_drop.h"

namespace touchdown::gap::fit {

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
ModelValues ValuesOf(const FitResult& f);

// The common offsets' scales: a tenth of a millisecond, a tenth of a millimetre.
constexpr double kOffsetTimeScale_s = 1e-4, kOffsetDepthScale_m = 1e-4;

// The records' sample rate [Hz]: 1 over the longest sample period (1 kHz without one).
double SampleRate(const FitProblem& p);

// The model's values at the scaled point x (Layout), and the scaled bounds of each parameter.
ModelValues Unscale(const FitProblem& p, const Layout& L, const Eigen::VectorXd& x);
void Bounds(const FitProblem& p, const Layout& L, Eigen::VectorXd* lo, Eigen::VectorXd* hi);

// One drop's simulation with the model's values and its nuisances, or nullopt when it fails.
std::optional<pad::RigDropResult> Simulate(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                           const rft::EffectTerms& terms, const DropNuisance& b);

// The last few simulations of one drop, by SimulationKey. A Jacobian column in the sensor's
// parameters, the common offsets or a drop's time nuisance re-records the simulation at the
// current point instead of repeating it. A simulation is a pure function of its key, so a cached
// result is the one a new run would give, bit for bit.
class SimulationCache {
 public:
  const std::optional<pad::RigDropResult>& Get(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                               const rft::EffectTerms& terms, const DropNuisance& b);
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
                                            const std::optional<pad::RigDropResult>& sim);

// The model's recorded trace for one drop with its nuisances, through `cache`.
std::optional<dataset::DatasetTrace> Recorded(const FitProblem& p, const FitDrop& d, const ModelValues& m,
                                              const rft::EffectTerms& terms, const DropNuisance& b,
                                              SimulationCache& cache);

// A drop's weighted residual rows: 2 per sample (force, penetration), each over sqrt(samples).
// A failed simulation costs as much as predicting nothing at all, times ten.
void DropRows(const FitDrop& d, const std::optional<dataset::DatasetTrace>& sim, double* r, double* unweighted);

// The time nuisance at which drop d's record, simulated once (`sim`), fits best with its other
// nuisances in `b` held: a scan of shifts (steps of a quarter of the time spread, at least a
// sample, out to 8 spreads or 8 ms), then a tenth of that step around the best, each a
// re-recording. Levenberg-Marquardt in time alone stalls: a record's sharp stop and a load cell's
// ring make the misfit in time many-valleyed, and a trigger that fired milliseconds late puts the
// optimum valleys away (the independent blind sets' curved pad: 2.3-3.1 ms).
double AlignedTime(const FitProblem& p, const FitDrop& d, const ModelValues& m, const rft::EffectTerms& terms,
                   DropNuisance b, const std::optional<pad::RigDropResult>& sim);

// The fits' objective over the training drops: weighted residual rows of force and penetration
// per drop (DropRows), then the nuisances' penalty rows; one SimulationCache per drop.
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
  void AlignTimes(Eigen::VectorXd& x);

  // Weighted residuals (as minimised) and the unweighted data rows (for the information criterion).
  void Evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* r, Eigen::VectorXd* unweighted = nullptr);

 private:
  const FitProblem& p_;
  const Layout& L_;
  std::vector<int> train_;
  std::vector<long> offset_;
  std::vector<SimulationCache> caches_;  // per training drop
  long data_rows_ = 0;
  int max_iterations_ = 0;
};

// The layout of the model with the candidate terms `ids` (FindTerm) on problem p.
Layout MakeLayout(const FitProblem& p, const std::vector<std::string>& ids);

}  // namespace touchdown::gap::fit
