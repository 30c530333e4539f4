// One axisymmetric single-footpad drop (target: under 1 ms per drop on one core).
#include <benchmark/benchmark.h>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

namespace {

using namespace touchdown;

void RunDrop(benchmark::State& state, const char* pad_name, bool with_trace_rest) {
  const touchdown::io::PadSpec pad = touchdown::io::LoadPad(pad_name);
  const rft::SoilParameters soil = touchdown::io::LoadSoil("fjs1_lp");
  touchdown::drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  touchdown::pad::RigDropOptions options;
  if (!with_trace_rest) options.rest_duration_s = 0.0;  // summary only, as in a sweep
  for (auto _ : state) {
    touchdown::drop::PadDrop d = touchdown::drop::RunDrop(touchdown::drop::ResolveDrop(pad, soil, c, {.rig = options}));
    benchmark::DoNotOptimize(d.result.final_penetration_m);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_DropFlatSummary(benchmark::State& s) { RunDrop(s, "flat", false); }
void BM_DropCurvedSummary(benchmark::State& s) { RunDrop(s, "curved", false); }
void BM_DropFlatWithRestTrace(benchmark::State& s) { RunDrop(s, "flat", true); }

// The shipped default (the soil's dynamic term) against the quasi-static model, full drops (rest
// included) on both shipped soils: steps and right-hand sides per drop as counters beside the time.
void RunDefaultVsQuasiStatic(benchmark::State& state, const char* pad_name, const char* soil_name, bool dynamic) {
  const touchdown::io::PadSpec pad = touchdown::io::LoadPad(pad_name);
  rft::SoilParameters soil = touchdown::io::LoadSoil(soil_name);
  soil.dynamic_term = soil.dynamic_term && dynamic;
  touchdown::drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  long steps = 0, rhs = 0;
  for (auto _ : state) {
    touchdown::drop::PadDrop d = touchdown::drop::RunDrop(touchdown::drop::ResolveDrop(pad, soil, c));
    steps = d.result.solver.steps;
    rhs = d.result.solver.rhs_evaluations;
    benchmark::DoNotOptimize(d.result.final_penetration_m);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["rhs"] = static_cast<double>(rhs);
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_DropFlatSummary)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DropCurvedSummary)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DropFlatWithRestTrace)->Unit(benchmark::kMicrosecond);

#define TOUCHDOWN_DEFAULT_VS_QS(pad, soil)                                                                     \
  BENCHMARK_CAPTURE(RunDefaultVsQuasiStatic, pad##_##soil##_default, #pad, #soil, true)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_CAPTURE(RunDefaultVsQuasiStatic, pad##_##soil##_quasi_static, #pad, #soil, false)->Unit(benchmark::kMicrosecond)
TOUCHDOWN_DEFAULT_VS_QS(flat, fjs1_lp);
TOUCHDOWN_DEFAULT_VS_QS(c4, fjs1_lp);
TOUCHDOWN_DEFAULT_VS_QS(curved, fjs1_lp);
TOUCHDOWN_DEFAULT_VS_QS(flat, fjs1_cp);
TOUCHDOWN_DEFAULT_VS_QS(c4, fjs1_cp);
TOUCHDOWN_DEFAULT_VS_QS(curved, fjs1_cp);

}  // namespace
