// One axisymmetric single-footpad drop (target: under 1 ms per drop on one core).
#include <benchmark/benchmark.h>

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
    touchdown::drop::PadDrop d = touchdown::drop::RunPadDrop(pad, soil, c, options);
    benchmark::DoNotOptimize(d.result.final_penetration_m);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_DropFlatSummary(benchmark::State& s) { RunDrop(s, "flat", false); }
void BM_DropCurvedSummary(benchmark::State& s) { RunDrop(s, "curved", false); }
void BM_DropFlatWithRestTrace(benchmark::State& s) { RunDrop(s, "flat", true); }

BENCHMARK(BM_DropFlatSummary)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DropCurvedSummary)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DropFlatWithRestTrace)->Unit(benchmark::kMicrosecond);

}  // namespace
