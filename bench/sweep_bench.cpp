// Sweep throughput of axisymmetric single-pad drops with summaries only (traces: none), written
// to SQLite as `touchdown sweep` does. Target: >= 2,000 drops/s on both cores.
//   BM_Sweep/threads:1, BM_Sweep/threads:2   in-process RunSweep (items_per_second = drops/s)
//   BM_SweepMpirun/ranks:2                   `mpirun -np 2 touchdown sweep --threads 1`, whole
//                                            process wall time (MPI start-up included)
// The plan mixes the paper's three pads, two soils and speeds 0.3-2.0 m/s (random samples).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "drop_tests/sweep.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::drop;

constexpr int kDrops = 6000;

fs::path BenchDir() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("touchdown_sweep_bench_" + std::to_string(::getpid()));
    fs::create_directories(d);
    std::ofstream(d / "sweep.yaml") << "schema_version: 1\ntype: sweep\nname: bench\ntraces: none\n"
                                       "grid: {pad: [flat, c4, curved]}\n"
                                       "random: {samples: " << kDrops / 3 << ", seed: 1, "
                                       "soil: {choice: [fjs1_lp, fjs1_cp]}, impact_speed_m_s: {uniform: [0.3, 2.0]}}\n";
    return d;
  }();
  static const struct Cleanup {
    ~Cleanup() { fs::remove_all(dir); }
  } cleanup;
  return dir;
}

void BM_Sweep(benchmark::State& state) {
  const SweepPlan plan = LoadSweepPlan((BenchDir() / "sweep.yaml").string());  // once, outside the loop
  SweepRunOptions options;
  options.threads = static_cast<int>(state.range(0));
  options.progress = ProgressMode::kNone;
  const fs::path out = BenchDir() / ("out_" + std::to_string(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(out);
    state.ResumeTiming();
    const SweepRunSummary s = RunSweep(plan, out.string(), options);
    if (s.computed != kDrops || s.failed != 0) state.SkipWithError("sweep did not run every drop");
  }
  state.SetItemsProcessed(state.iterations() * kDrops);
  state.counters["drops_per_s"] = benchmark::Counter(static_cast<double>(kDrops), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Sweep)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

void BM_SweepMpirun(benchmark::State& state) {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) {
    state.SkipWithError("mpirun not installed");
    return;
  }
  const fs::path out = BenchDir() / "out_mpi";
  const std::string command = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                              "OMPI_MCA_rmaps_base_oversubscribe=1 mpirun --allow-run-as-root -np " +
                              std::to_string(state.range(0)) + " " + TOUCHDOWN_BINARY + " sweep " +
                              (BenchDir() / "sweep.yaml").string() + " --out " + out.string() +
                              " --threads 1 --progress none >/dev/null 2>&1";
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(out);
    state.ResumeTiming();
    if (std::system(command.c_str()) != 0) state.SkipWithError("mpirun failed");
  }
  state.SetItemsProcessed(state.iterations() * kDrops);
  state.counters["drops_per_s"] = benchmark::Counter(static_cast<double>(kDrops), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SweepMpirun)->ArgName("ranks")->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
