// Speed target: a diagnose run over 27 drops and the whole effect library in under a
// minute on a 2-core machine. 27 synthetic drops: flat, C4 and curved pads x 0.7/1.0/1.5 m/s x
// three trials (the first in air, two in vacuum) on loose FJS-1, a gas cushion hidden in the air
// drops, the same noise as the shipped dataset; full traces (stop + 30 ms of rest).
#include <benchmark/benchmark.h>

#include <thread>

#include "drop_tests/gap/diagnose.h"
#include "drop_tests/dataset/synth.h"
#include "rft/gravity_constants.h"

namespace {

touchdown::dataset::Dataset Campaign27() {
  touchdown::dataset::SynthSpec s;
  s.name = "bench27";
  s.source = "bench";
  s.seed = 27;
  s.rest_duration_s = 0.03;
  for (const char* pad : {"flat", "c4", "curved"})
    for (double v : {0.7, 1.0, 1.5})
      for (int trial = 0; trial < 3; ++trial)
        s.drops.push_back({pad, "fjs1_lp", trial == 0 ? touchdown::rft::Atmosphere::kAir : touchdown::rft::Atmosphere::kVacuum, v, std::nullopt, touchdown::rft::kEarthGravity_m_s2, trial});
  s.noise = touchdown::dataset::SynthNoise{1.5, 3e-5, 2.0, 5e-5, 0.25, 1e-5};
  s.hidden_effect = touchdown::model::Effect{"gas_cushion", {0.3, 3000.0}};
  touchdown::dataset::Dataset ds = touchdown::dataset::Synthesize(s);
  ds.directory = "bench27";
  return ds;
}

void BM_Diagnose27Drops(benchmark::State& state) {
  const touchdown::dataset::Dataset ds = Campaign27();
  touchdown::gap::DiagnoseOptions o;
  o.threads = static_cast<int>(state.range(0));
  long simulations = 0;
  std::string named;
  for (auto _ : state) {
    const touchdown::gap::Diagnosis d = touchdown::gap::RunDiagnosis(ds, o);
    simulations = d.simulations;
    named = d.named_effect;
    benchmark::DoNotOptimize(d.winner);
  }
  state.counters["simulated_drops"] = static_cast<double>(simulations);
  state.counters["named_gas_cushion"] = named == "gas_cushion" ? 1 : 0;
}
BENCHMARK(BM_Diagnose27Drops)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
