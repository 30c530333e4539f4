#include "drop_tests/sweep_mpi.h"

#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "drop_tests/sweep_engine.h"
#include "rft/input_error.h"

#ifdef TOUCHDOWN_HAVE_MPI
#include <mpi.h>
#endif

namespace touchdown::drop {

namespace {
int EnvInt(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : 0;
}
}  // namespace

bool LaunchedByMpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (EnvInt(name) > 1) return true;
  return false;
}

#ifndef TOUCHDOWN_HAVE_MPI
bool MpiSupported() { return false; }
SweepRunSummary RunSweepMpi(const SweepPlan&, const std::string&, const SweepRunOptions&, int*) {
  throw MakeInputError("", "mpirun", "this touchdown was built without MPI (TOUCHDOWN_WITH_MPI=OFF)");
}
#else
bool MpiSupported() { return true; }

namespace {
constexpr int kTagResults = 1;
constexpr int kTagDone = 2;

class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);  // only this thread calls MPI
  }
  ~MpiSession() { MPI_Finalize(); }
};

// Rank 0 sends an error message (or "" for go-ahead) to every rank, so all stop together.
std::string BroadcastText(std::string text, int rank) {
  uint64_t n = text.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  if (rank != 0) text.resize(n);
  if (n > 0) MPI_Bcast(text.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}
}  // namespace

SweepRunSummary RunSweepMpi(const SweepPlan& plan, const std::string& out_dir, const SweepRunOptions& options,
                            int* rank_out) {
  MpiSession session;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (rank_out) *rank_out = rank;
  SweepRunSummary summary;
  summary.ranks = ranks;
  summary.total = plan.size();
  summary.in_shard = (plan.size() - options.shard.index + options.shard.count - 1) / options.shard.count;
  const int local = EnvInt("OMPI_COMM_WORLD_LOCAL_SIZE");
  summary.threads = options.threads > 0 ? options.threads : DefaultThreads(local > 0 ? local : 1);
  const double start = MPI_Wtime();

  // Rank 0: open the database and find what is left; everyone learns the outcome.
  std::unique_ptr<ResultsDb> db;
  std::vector<int64_t> todo;
  std::string error;
  if (rank == 0) {
    try {
      db = OpenSweepDb(plan, out_dir, options.shard);
      todo = RemainingDrops(plan, *db, options.shard);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  error = BroadcastText(error, rank);
  if (!error.empty()) throw InputError(error);
  uint64_t remaining = todo.size();
  MPI_Bcast(&remaining, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  todo.resize(remaining);
  if (remaining > 0) MPI_Bcast(todo.data(), static_cast<int>(remaining), MPI_INT64_T, 0, MPI_COMM_WORLD);
  summary.already_done = summary.in_shard - static_cast<int64_t>(remaining);

  std::vector<int64_t> mine;
  for (size_t j = static_cast<size_t>(rank); j < todo.size(); j += static_cast<size_t>(ranks)) mine.push_back(todo[j]);
  const SweepModels models(plan);
  DropEngine engine(models, mine, summary.threads);

  if (rank != 0) {
    while (!engine.Finished()) {
      const std::vector<DropRecord> batch = engine.Take(options.batch_size, options.commit_interval_s);
      if (batch.empty()) continue;
      const std::string bytes = SerializeRecords(batch);
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, kTagResults, MPI_COMM_WORLD);
      summary.computed += static_cast<int64_t>(batch.size());
    }
    MPI_Send(nullptr, 0, MPI_CHAR, 0, kTagDone, MPI_COMM_WORLD);
    MPI_Barrier(MPI_COMM_WORLD);
    summary.seconds = MPI_Wtime() - start;
    return summary;
  }

  SweepProgress progress(options.log ? *options.log : std::cerr, options.progress, options.progress_interval_s,
                         summary.in_shard, summary.already_done);
  int ranks_running = ranks - 1;
  auto commit = [&](const std::vector<DropRecord>& batch) {
    db->Insert(batch);
    summary.computed += static_cast<int64_t>(batch.size());
    progress.Add(batch);
  };
  while (!engine.Finished() || ranks_running > 0) {
    // Messages from the other ranks first, without blocking.
    for (int flag = 1; flag;) {
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (!flag) break;
      int bytes = 0;
      MPI_Get_count(&status, MPI_CHAR, &bytes);
      std::string buffer(static_cast<size_t>(bytes), '\0');
      MPI_Recv(buffer.data(), bytes, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (status.MPI_TAG == kTagDone) --ranks_running;
      else commit(DeserializeRecords(buffer));
    }
    commit(engine.Take(options.batch_size, engine.Finished() ? 0.0 : 0.02));
    if (engine.Finished() && ranks_running > 0) {
      // Only remote work left: block until the next message arrives.
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    }
  }
  progress.Finish();
  MPI_Barrier(MPI_COMM_WORLD);
  summary.failed = db->CountFailed();
  summary.seconds = MPI_Wtime() - start;
  return summary;
}
#endif

}  // namespace touchdown::drop
