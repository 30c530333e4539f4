// Memory and time that must not grow with the size of the input. Each case
// runs the touchdown executable as a child process (as a user does) and reports its wall time and
// peak resident set size (wait4's ru_maxrss) as counters:
//   BM_Campaign10000Drops   `touchdown campaign` over 10,000 rig drops      target: < 500 MB peak
//   BM_Compare10MRows       `touchdown compare` of one drop with a ten-million-row measured trace
//                            target: < 20 s (the plot decimation is part of it)
//   BM_Calibrate10MRows     `touchdown calibrate` on that dataset            target: well under 2 GB
// The inputs are generated once in a temporary directory (the 10M-row trace: ~0.4 GB of CSV, a
// simulated flat-pad drop resampled at 10M points). Run: build/bench/bench_resources
// (or a single case with --benchmark_filter=Compare); the same figures by hand:
//   /usr/bin/time -v build/apps/touchdown compare DIR --out OUT   ("Maximum resident set size").
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::drop;
using namespace touchdown::io;
using namespace touchdown::pad;

// $TOUCHDOWN_BENCH_DIR (kept, so the generated inputs can be reused, e.g. by another binary), or a
// temporary directory removed at exit.
fs::path BenchDir() {
  static const char* kept = std::getenv("TOUCHDOWN_BENCH_DIR");
  static const fs::path dir = [] {
    fs::path d = kept && *kept ? fs::path(kept)
                               : fs::temp_directory_path() / ("touchdown_resources_bench_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  static const struct Cleanup {
    ~Cleanup() {
      if (!(kept && *kept)) fs::remove_all(dir);
    }
  } cleanup;
  return dir;
}

struct ChildRun {
  int status = -1;
  double wall_s = 0.0;
  double peak_rss_MB = 0.0;
};

// Runs touchdown with `args` (no shell), stdout and stderr to /dev/null.
ChildRun RunTouchdown(const std::vector<std::string>& arguments) {
  std::vector<std::string> args{TOUCHDOWN_BINARY};
  args.insert(args.end(), arguments.begin(), arguments.end());
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  ChildRun r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_rss_MB = usage.ru_maxrss / 1024.0;  // kB on Linux
  return r;
}

void Report(benchmark::State& state, const ChildRun& r) {
  if (r.status != 0) state.SkipWithError(("touchdown exited with " + std::to_string(r.status)).c_str());
  state.SetIterationTime(r.wall_s);
  state.counters["peak_rss_MB"] = r.peak_rss_MB;
  state.counters["wall_s"] = r.wall_s;
}

// 10,000 rig drops: the paper's three pads on both beds, 1,667 speeds 0.20-16.86 m/s each.
fs::path CampaignScenario() {
  const fs::path path = BenchDir() / "campaign10k.yaml";
  if (fs::exists(path)) return path;
  std::ofstream out(path);
  out << "schema_version: 1\ntype: campaign\nname: bench10k\nreference_speed_m_s: 1.0\ndrops:\n";
  for (const char* pad : {"flat", "c4", "curved"})
    for (const char* soil : {"fjs1_lp", "fjs1_cp"}) {
      out << "  - {pad: " << pad << ", soil: " << soil << ", impact_speeds_m_s: [";
      for (int k = 0; k < 1667; ++k) out << (k ? ", " : "") << FormatNumber((20 + k) / 100.0);
      out << "]}\n";
    }
  return path;
}

void BM_Campaign10000Drops(benchmark::State& state) {
  const fs::path scenario = CampaignScenario();
  for (auto _ : state) {
    fs::remove_all(BenchDir() / "campaign_out");
    Report(state, RunTouchdown({"campaign", scenario.string(), "--out", (BenchDir() / "campaign_out").string()}));
  }
  state.counters["drops"] = 6 * 1667;
}
BENCHMARK(BM_Campaign10000Drops)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

// One measured drop (flat pad, fjs1_lp, 1 m/s) with `rows` samples: the simulated rig trace,
// resampled linearly over touchdown to rest.
fs::path BigTraceDataset(long rows) {
  const fs::path dir = BenchDir() / ("dataset_" + std::to_string(rows));
  if (fs::exists(dir / "drops.csv")) return dir;
  fs::create_directories(dir / "traces");
  DropConditions c;
  c.impact_speed_m_s = 1.0;
  const RigDropResult sim = RunDrop(ResolveDrop(LoadPad("flat"), LoadSoil("fjs1_lp"), c)).result;
  std::ofstream(dir / "drops.csv")
      << "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace\n"
      << "big,flat,fjs1_lp,vacuum,1,1.6,9.81,traces/big.csv\n";
  std::ofstream out(dir / "traces" / "big.csv");
  out << "t_s,penetration_m,force_N\n";
  const double t_end = sim.trace.back().t_s;
  size_t k = 1;
  for (long i = 0; i < rows; ++i) {
    const double t = t_end * static_cast<double>(i) / static_cast<double>(rows - 1);
    while (k + 1 < sim.trace.size() && sim.trace[k].t_s < t) ++k;
    const DropSample &a = sim.trace[k - 1], &b = sim.trace[k];
    const double w = std::clamp((t - a.t_s) / (b.t_s - a.t_s), 0.0, 1.0);
    out << FormatNumber(t) << ',' << FormatNumber(a.penetration_m + w * (b.penetration_m - a.penetration_m)) << ','
        << FormatNumber(a.force_N + w * (b.force_N - a.force_N)) << '\n';
  }
  return dir;
}

void BM_Compare10MRows(benchmark::State& state) {
  const fs::path dataset = BigTraceDataset(state.range(0));
  for (auto _ : state) {
    fs::remove_all(BenchDir() / "compare_out");
    Report(state, RunTouchdown({"compare", dataset.string(), "--out", (BenchDir() / "compare_out").string()}));
  }
}
BENCHMARK(BM_Compare10MRows)->Arg(10'000'000)->ArgName("rows")->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

void BM_Calibrate10MRows(benchmark::State& state) {
  const fs::path dataset = BigTraceDataset(state.range(0));
  for (auto _ : state) {
    Report(state, RunTouchdown({"calibrate", dataset.string(), "--out", (BenchDir() / "model.yaml").string()}));
  }
}
BENCHMARK(BM_Calibrate10MRows)->Arg(10'000'000)->ArgName("rows")->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace
