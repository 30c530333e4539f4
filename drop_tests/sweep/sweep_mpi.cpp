#include "drop_tests/sweep/sweep_mpi.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "drop_tests/sweep/sweep_engine.h"
#include "drop_tests/util/work_pool.h"
#include "rft/input_error.h"

#ifdef TOUCHDOWN_HAVE_MPI
#include <mpi.h>
#endif

namespace touchdown::sweep {

namespace {
int EnvInt(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : 0;
}
}  // namespace

int RankFromMpirun() {
  if (!LaunchedByMpirun()) return 0;
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (std::getenv(name)) return EnvInt(name);
  return 0;
}

bool LaunchedByMpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (EnvInt(name) > 1) return true;
  return false;
}

#ifndef TOUCHDOWN_HAVE_MPI
SweepRunSummary RunSweepMpi(const SweepPlan&, const std::string&, const SweepRunOptions&, int*) {
  throw MakeInputError("", "mpirun", "this touchdown was built without MPI (TOUCHDOWN_WITH_MPI=OFF)");
}
std::string BroadcastFromRankZero(const std::string& text) { return text; }
#else
namespace {
constexpr int kTagResults = 1;  // rank -> 0: serialised records
constexpr int kTagDone = 2;     // rank -> 0: no more results; payload: the stop signal (int), or empty
constexpr int kTagRequest = 3;  // rank -> 0: uint64 count of indices wanted
constexpr int kTagWork = 4;     // 0 -> rank: int64 drop indices (none: no more work)
constexpr size_t kRankFeedLow = 256;  // a rank's queue length below which it asks for more

// One MPI session per process: MPI may be initialised and finalised once only, and a rare-event
// study runs many sweeps. Started by the first RunSweepMpi, finalised at exit.
class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);  // only this thread calls MPI
  }
  ~MpiSession() { MPI_Finalize(); }
};

// Whether this process has started MPI (BroadcastFromRankZero is the identity before).
bool& MpiStarted() {
  static bool started = false;
  return started;
}

void StartMpi() {
  static const MpiSession session;
  MpiStarted() = true;
}

// Rank 0 sends an error message (or "" for go-ahead) to every rank, so all stop together.
std::string BroadcastText(std::string text, int rank) {
  uint64_t n = text.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  if (rank != 0) text.resize(n);
  if (n > 0) MPI_Bcast(text.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}

bool StopRequested(const SweepRunOptions& options) { return options.stop && options.stop->load() != 0; }

// A rank other than 0: asks for work, computes it, sends the records.
void RunWorkerRank(DropEngine& engine, const SweepRunOptions& options, SweepRunSummary& summary) {
  const size_t want = std::max<size_t>(2 * kRankFeedLow, 16 * static_cast<size_t>(summary.threads));
  EngineDriver driver;
  driver.feed_low = kRankFeedLow;
  driver.next = [&] {
    const uint64_t n = want;
    MPI_Send(&n, 1, MPI_UINT64_T, 0, kTagRequest, MPI_COMM_WORLD);
    MPI_Status status;
    MPI_Probe(0, kTagWork, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_INT64_T, &count);
    std::vector<int64_t> indices(static_cast<size_t>(count));
    MPI_Recv(indices.data(), count, MPI_INT64_T, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return indices;
  };
  driver.commit = [&](std::vector<DropRecord> batch) {
    if (batch.empty()) return;
    const std::string bytes = SerializeRecords(batch);
    MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, kTagResults, MPI_COMM_WORLD);
    summary.computed += static_cast<int64_t>(batch.size());
  };
  driver.batch_size = options.batch_size;
  driver.commit_interval_s = options.commit_interval_s;
  driver.stop = options.stop;
  RunEngine(engine, driver);
  const int signal = options.stop ? options.stop->load() : 0;
  MPI_Send(&signal, 1, MPI_INT, 0, kTagDone, MPI_COMM_WORLD);
  summary.stop_signal = signal;
}
}  // namespace

SweepRunSummary RunSweepMpi(const SweepPlan& plan, const std::string& out_dir, const SweepRunOptions& options,
                            int* rank_out) {
  StartMpi();
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (rank_out) *rank_out = rank;
  SweepRunSummary summary;
  summary.ranks = ranks;
  summary.total = plan.size();
  const int local = EnvInt("OMPI_COMM_WORLD_LOCAL_SIZE");
  summary.threads = io::ThreadsFor(options.threads, local);
  const double start = MPI_Wtime();

  // Rank 0: lock the directory and open the database; everyone learns the outcome.
  SweepStore store;
  std::string error;
  std::optional<DropsToRun> todo;
  if (rank == 0) {
    try {
      store = OpenSweepStore(plan, out_dir, options.shard);
      todo.emplace(plan.size(), *store.db, options);
      summary.in_shard = todo->in_shard();
      summary.already_done = todo->already_done();
      summary.retried = store.retried;
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  error = BroadcastText(error, rank);
  if (!error.empty()) throw InputError(error);

  const SweepModels models(plan);
  DropEngine engine(models, summary.threads);
  if (rank != 0) {
    RunWorkerRank(engine, options, summary);
    MPI_Barrier(MPI_COMM_WORLD);
    summary.seconds = MPI_Wtime() - start;
    return summary;
  }

  ResultsDb& db = *store.db;
  SweepProgress progress(options.log ? *options.log : std::cerr, options.progress, options.progress_interval_s,
                         summary.in_shard, summary.already_done, options.progress_quiet_s, options.progress_counts);
  int ranks_running = ranks - 1;
  bool stopping = false;
  auto commit = [&](const std::vector<DropRecord>& batch) {
    db.Insert(batch);
    summary.computed += static_cast<int64_t>(batch.size());
    progress.Add(batch);
  };
  auto stop = [&](int signal) {
    if (stopping) return;
    stopping = true;
    if (summary.stop_signal == 0) summary.stop_signal = signal;
    engine.Stop();
  };
  // No rank takes more than its share of the drops to run at a time, so a small list (a rare-event
  // batch: N / 10 landings) is spread over the ranks rather than queued on rank 0 before the others
  // ask; a large sweep's shares exceed the chunks, which then decide alone.
  const size_t share = static_cast<size_t>(std::max<int64_t>(1, (todo->in_shard() - todo->already_done() + ranks - 1) / ranks));
  auto feed = [&] { engine.Feed(std::min(kRankFeedLow, share), [&] { return todo->Next(std::min(4 * kRankFeedLow, share)); }); };
  feed();
  while (!engine.Finished() || ranks_running > 0) {
    if (StopRequested(options)) stop(options.stop->load());
    // Messages from the other ranks first, without blocking.
    for (int flag = 1; flag;) {
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (!flag) break;
      int bytes = 0;
      MPI_Get_count(&status, MPI_CHAR, &bytes);
      std::string buffer(static_cast<size_t>(bytes), '\0');
      MPI_Recv(buffer.data(), bytes, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (status.MPI_TAG == kTagDone) {
        --ranks_running;
        int signal = 0;
        if (buffer.size() == sizeof signal) std::memcpy(&signal, buffer.data(), sizeof signal);
        if (signal != 0) stop(signal);  // a rank was stopped: the whole run stops
      } else if (status.MPI_TAG == kTagRequest) {
        uint64_t want = 0;
        if (buffer.size() == sizeof want) std::memcpy(&want, buffer.data(), sizeof want);
        // Rank 0's own queue and the cursor share one order; the split between ranks never
        // shows in the results (each is a function of its index alone).
        const std::vector<int64_t> work = stopping ? std::vector<int64_t>{} : todo->Next(std::min(static_cast<size_t>(want), share));
        MPI_Send(work.data(), static_cast<int>(work.size()), MPI_INT64_T, status.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
      } else {
        commit(DeserializeRecords(buffer));
      }
    }
    feed();
    commit(engine.Take(options.batch_size, engine.Finished() ? 0.0 : 0.02, kRankFeedLow,
                       stopping ? nullptr : options.stop));
    if (engine.Finished() && ranks_running > 0) {
      // Only remote work left: block until the next message arrives.
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    }
  }
  progress.Finish();
  MPI_Barrier(MPI_COMM_WORLD);
  summary.failed = db.CountFailed();
  summary.seconds = MPI_Wtime() - start;
  return summary;
}

std::string BroadcastFromRankZero(const std::string& text) {
  if (!MpiStarted()) return text;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return BroadcastText(text, rank);
}
#endif

}  // namespace touchdown::sweep
