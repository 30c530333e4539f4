// Sweep throughput of axisymmetric single-pad drops with summaries only (traces: none), written
// to SQLite as `touchdown sweep` does. Target: >= 2,000 drops/s on both cores.
//   BM_Sweep/threads:1, BM_Sweep/threads:2   in-process RunSweep (items_per_second = drops/s)
//   BM_SweepShippedVsQuasiStatic/shipped:1, /shipped:0   the same plan on 2 threads on the soils
//                                            as shipped and on their quasi-static twins (target:
//                                            the shipped default within 1.3x of quasi-static)
//   BM_SweepMpirun/ranks:2                   `mpirun -np 2 touchdown sweep --threads 1`, whole
//                                            process wall time (MPI start-up included)
//   BM_SweepStartPeakRss/drops_log10:N       `touchdown sweep` of a 10^N-drop plan: start it, let
//                                            it commit 2,000 drops, stop it with SIGTERM; counter
//                                            peak_rss_MB (the child's ru_maxrss). Target: a
//                                            1e10-drop plan starts in constant memory, the same
//                                            peak as a 1e4-drop one (the plan is streamed, never
//                                            held whole).
// The plan mixes the paper's three pads, two soils and speeds 0.3-2.0 m/s (random samples).
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"

namespace {

namespace fs = std::filesystem;
using namespace touchdown::sweep;
using namespace touchdown::sweep;

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

// Times RunSweep of the kDrops-drop plan into `out` (emptied before each iteration, untimed).
void TimeSweep(benchmark::State& state, const SweepPlan& plan, int threads, const fs::path& out) {
  SweepRunOptions options;
  options.threads = threads;
  options.progress = ProgressMode::kNone;
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

void BM_Sweep(benchmark::State& state) {
  const SweepPlan plan = LoadSweepPlan((BenchDir() / "sweep.yaml").string());  // once, outside the loop
  TimeSweep(state, plan, static_cast<int>(state.range(0)), BenchDir() / ("out_" + std::to_string(state.range(0))));
}
BENCHMARK(BM_Sweep)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// The same 6,000 drops on the soils as shipped (Li 2013 with dynamic RFT's inertial term) and on
// their quasi-static twins (copies of the soil files with `dynamic_term: false`, named *_qs): the
// cost of the shipped default's term in a rig sweep. Arg 1: as shipped; 0: quasi-static.
std::string QuasiStaticTwin(const std::string& soil) {
  const fs::path shipped = fs::path(TOUCHDOWN_SOURCE_DIR) / "data" / "soils" / (soil + ".yaml");
  std::ifstream in(shipped);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"name: " + soil + "\n", "name: " + soil + "_qs\n"},
                                 {"dynamic_term: true\n", "dynamic_term: false\n"}}) {
    const size_t at = yaml.find(from);
    if (at == std::string::npos) return "";  // the shipped file changed: the benchmark says so below
    yaml.replace(at, from.size(), to);
  }
  const fs::path twin = BenchDir() / (soil + "_qs.yaml");
  std::ofstream(twin) << yaml;
  return twin.string();
}

void BM_SweepShippedVsQuasiStatic(benchmark::State& state) {
  const bool shipped = state.range(0) == 1;
  std::string soils = "fjs1_lp, fjs1_cp";
  if (!shipped) {
    const std::string lp = QuasiStaticTwin("fjs1_lp"), cp = QuasiStaticTwin("fjs1_cp");
    if (lp.empty() || cp.empty()) {
      state.SkipWithError("the shipped soil files no longer hold `name:` and `dynamic_term: true` lines");
      return;
    }
    soils = lp + ", " + cp;
  }
  const fs::path file = BenchDir() / (shipped ? "sweep_shipped.yaml" : "sweep_qs.yaml");
  std::ofstream(file) << "schema_version: 1\ntype: sweep\nname: bench\ntraces: none\n"
                         "grid: {pad: [flat, c4, curved]}\n"
                         "random: {samples: " << kDrops / 3 << ", seed: 1, "
                         "soil: {choice: [" << soils << "]}, impact_speed_m_s: {uniform: [0.3, 2.0]}}\n";
  TimeSweep(state, LoadSweepPlan(file.string()), 2, BenchDir() / (shipped ? "out_shipped" : "out_qs"));
}
BENCHMARK(BM_SweepShippedVsQuasiStatic)->ArgName("shipped")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

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
// A plan of 10^N drops: two grid axes of 10^(N/2) values each (at most 100,000 per axis).
std::string HugeSweep(int drops_log10) {
  long count = 1;
  for (int i = 0; i < drops_log10 / 2; ++i) count *= 10;
  std::ostringstream yaml;
  yaml << "schema_version: 1\ntype: sweep\nname: huge\ntraces: none\nfixed: {pad: flat, soil: fjs1_lp}\n"
       << "grid:\n  impact_speed_m_s: {from: 0.3, to: 2.0, count: " << count << "}\n"
       << "  pad_mass_kg: {from: 1.0, to: 2.0, count: " << count << "}\n";
  return yaml.str();
}

void BM_SweepStartPeakRss(benchmark::State& state) {
  const int drops_log10 = static_cast<int>(state.range(0));
  const fs::path file = BenchDir() / ("huge_" + std::to_string(drops_log10) + ".yaml");
  std::ofstream(file) << HugeSweep(drops_log10);
  const fs::path out = BenchDir() / ("out_huge_" + std::to_string(drops_log10));
  constexpr int64_t kFirstDrops = 2000;
  double peak_mb = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(out);
    state.ResumeTiming();
    const pid_t pid = ::fork();
    if (pid == 0) {
      std::vector<std::string> args = {TOUCHDOWN_BINARY, "sweep", file.string(), "--out", out.string(),
                                       "--threads", "2", "--progress", "none"};
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    // Until the first drops are committed (or the child ended: it could not start).
    int status = 0;
    rusage usage{};
    bool ended = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!ended && std::chrono::steady_clock::now() < deadline) {
      if (::wait4(pid, &status, WNOHANG, &usage) == pid) {
        ended = true;
        break;
      }
      int64_t rows = 0;
      if (fs::exists(ResultsDbPath(out.string()))) {
        try {
          rows = ResultsDb(ResultsDbPath(out.string())).Count();
        } catch (const std::exception&) {
        }
      }
      if (rows >= kFirstDrops) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (!ended) {
      ::kill(pid, SIGTERM);
      ::wait4(pid, &status, 0, &usage);
    }
    peak_mb = std::max(peak_mb, usage.ru_maxrss / 1024.0);  // ru_maxrss: kB on Linux
    if (ended || !WIFEXITED(status) || WEXITSTATUS(status) != 128 + SIGTERM) {
      state.SkipWithError("the sweep did not run until stopped with SIGTERM (exit 143)");
      break;
    }
  }
  state.counters["peak_rss_MB"] = peak_mb;
}
BENCHMARK(BM_SweepStartPeakRss)->ArgName("drops_log10")->Arg(4)->Arg(8)->Arg(10)->Unit(benchmark::kMillisecond)
    ->UseRealTime()->Iterations(1);

BENCHMARK(BM_SweepMpirun)->ArgName("ranks")->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
