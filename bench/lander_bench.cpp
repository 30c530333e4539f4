// A case-A lander drop (the paper's Table II, LP under all four pads): 1 s of simulated time
// from release 10 cm above the bed, four meshed pads of about 2k triangles each (data/landers,
// 64 segments around the rim). Target: faster than 50x real time on one core, i.e. under 20 ms
// per iteration. The counter `realtime_factor` reports simulated seconds per wall second.
#include <benchmark/benchmark.h>
#include <cstdlib>

#include "tests/lander/multibody/paper_lander.h"

namespace {

using namespace touchdown;

void BM_LanderCaseA_1s(benchmark::State& state) {
  // The paper's lander built in code from the catalogue's values (data/landers, data/soils,
  // data/scenarios/lander_case_A.yaml), at the catalogue's 64 segments.
  const test::PaperLander setup = test::MakePaperLander('A', 64);
  lander::LanderRunOptions options;
  options.duration_s = 1.0;
  options.sample_rate_hz = 1000.0;  // lander_case_A.yaml: simulation
  if (getenv("TD_RTOL")) options.integrator.rtol = atof(getenv("TD_RTOL"));
  if (getenv("TD_ATOL")) options.integrator.atol = atof(getenv("TD_ATOL"));
  if (getenv("TD_ADAMS")) options.integrator.stiff = false;
  touchdown::lander::LanderRunResult last;
  for (auto _ : state) {
    const touchdown::lander::LanderRunResult r = touchdown::lander::SimulateLander(setup.model, setup.terrain, setup.initial, options);
    benchmark::DoNotOptimize(r.final_penetration_m[0]);
    last = r;
  }
  state.counters["triangles_per_pad"] = setup.model.legs[0].pad->surface.size();
  state.counters["solver_steps"] = static_cast<double>(last.solver.steps);
  state.counters["rhs_evals"] = static_cast<double>(last.solver.rhs_evaluations);
  state.counters["jac_rhs_evals"] = static_cast<double>(last.solver.jacobian_rhs_evaluations);
  state.counters["root_evals"] = static_cast<double>(last.solver.root_evaluations);
  state.counters["jac_evals"] = static_cast<double>(last.solver.jacobian_evaluations);
  state.counters["ncfn"] = static_cast<double>(last.solver.nonlinear_convergence_failures);
  state.counters["etf"] = static_cast<double>(last.solver.error_test_failures);
  state.counters["pen0_mm"] = last.final_penetration_m[0]*1e3;
  state.counters["energy_err"] = last.initial_energy_J - last.dissipated_J - last.final_kinetic_J - last.final_potential_J;
  state.counters["rest_time_s"] = last.rest_time_s.value_or(-1.0);
  state.counters["realtime_factor"] =
      benchmark::Counter(options.duration_s * state.iterations(), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_LanderCaseA_1s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
