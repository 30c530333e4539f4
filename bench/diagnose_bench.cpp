// Speed targets: a diagnose run over 27 drops and the whole effect library in under a
// minute on a 2-core machine; a 30-drop run with the sensor inferred and the per-drop nuisances
// (the defaults) within 3x the same run with the sensor given and no nuisances (the workflow
// before both existed).
#include <benchmark/benchmark.h>

#include <thread>

#include "drop_tests/gap/diagnose.h"
#include "drop_tests/dataset/synth.h"
#include "rft/gravity_constants.h"

namespace {

// A synthetic campaign of `drops` with the shipped dataset's noise, full traces (stop + 30 ms of
// rest) and `hidden` in it.
touchdown::dataset::Dataset Campaign(const std::string& name, unsigned seed,
                                     std::vector<touchdown::dataset::SynthDrop> drops,
                                     touchdown::model::Effect hidden) {
  touchdown::dataset::SynthSpec s;
  s.name = name;
  s.source = "bench";
  s.seed = seed;
  s.rest_duration_s = 0.03;
  s.drops = std::move(drops);
  s.noise = touchdown::dataset::SynthNoise{1.5, 3e-5, 2.0, 5e-5, 0.25, 1e-5};
  s.hidden_effect = std::move(hidden);
  touchdown::dataset::Dataset ds = touchdown::dataset::Synthesize(s);
  ds.directory = name;
  return ds;
}

// Times RunDiagnosis; counts the drops simulated and whether `expected` was named.
void TimeDiagnosis(benchmark::State& state, const touchdown::dataset::Dataset& ds,
                   const touchdown::gap::DiagnoseOptions& o, const std::string& expected) {
  long simulations = 0;
  std::string named;
  for (auto _ : state) {
    const touchdown::gap::Diagnosis d = touchdown::gap::RunDiagnosis(ds, o);
    simulations = d.simulations;
    named = d.named_effect;
    benchmark::DoNotOptimize(d.winner);
  }
  state.counters["simulated_drops"] = static_cast<double>(simulations);
  state.counters["named_" + expected] = named == expected ? 1 : 0;
}

// 27 drops: flat, C4 and curved pads x 0.7/1.0/1.5 m/s x three trials (the first in air, two in
// vacuum) on loose FJS-1, a gas cushion hidden in the air drops.
void BM_Diagnose27Drops(benchmark::State& state) {
  std::vector<touchdown::dataset::SynthDrop> drops;
  for (const char* pad : {"flat", "c4", "curved"})
    for (double v : {0.7, 1.0, 1.5})
      for (int trial = 0; trial < 3; ++trial)
        drops.push_back({pad, "fjs1_lp", trial == 0 ? touchdown::rft::Atmosphere::kAir : touchdown::rft::Atmosphere::kVacuum,
                         v, std::nullopt, touchdown::rft::kEarthGravity_m_s2, trial});
  const touchdown::dataset::Dataset ds = Campaign("bench27", 27, drops, {"gas_cushion", {0.3, 3000.0}});
  touchdown::gap::DiagnoseOptions o;
  o.threads = static_cast<int>(state.range(0));
  TimeDiagnosis(state, ds, o, "gas_cushion");
}
BENCHMARK(BM_Diagnose27Drops)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// 30 drops as a rig campaign gives them: three pads x five speeds x two replicates in vacuum on
// loose FJS-1, a rate damping hidden; drop-to-drop scatter left to the per-drop nuisances (the
// synthesiser draws none: the run times the work, not the finding). Arg 1: the defaults (sensor
// inferred, per-drop nuisances, each training drop's nuisances fitted again after every full fit);
// arg 0: the sensor given (the synthesiser's period mean) and no nuisances; arg 2: the defaults
// without the training drops' refit (--no-refit-drops), what the refit costs.
void BM_Diagnose30Drops(benchmark::State& state) {
  std::vector<touchdown::dataset::SynthDrop> drops;
  for (const char* pad : {"flat", "c4", "curved"})
    for (double v : {0.7, 0.9, 1.1, 1.3, 1.5})
      for (int trial = 0; trial < 2; ++trial)
        drops.push_back({pad, "fjs1_lp", touchdown::rft::Atmosphere::kVacuum, v, std::nullopt,
                         touchdown::rft::kEarthGravity_m_s2, trial});
  const touchdown::dataset::Dataset ds = Campaign("bench30", 30, drops, {"rate_damping", {4000.0}});
  touchdown::gap::DiagnoseOptions o;
  o.threads = 2;
  if (state.range(0) == 0) {
    o.sensor_sampling = touchdown::pad::SensorSampling::kPeriodMean;
    o.drop_nuisances = false;
  }
  if (state.range(0) == 2) o.refit_drops = false;
  TimeDiagnosis(state, ds, o, "rate_damping");
}
BENCHMARK(BM_Diagnose30Drops)->Arg(0)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
