#pragma once
// `mpirun -np N touchdown sweep ...` (and `stability`, rare-event methods included): every rank loads the plan; rank 0 locks the output
// directory (the other ranks never touch it, so ranks of one run cannot refuse each other),
// opens the results database and finds the drops still missing a chunk at a time (so a restart
// works with any N, and memory does not grow with the plan). The other ranks ask rank 0 for
// chunks of drop indices as their queues run low, compute them on their threads and send the
// finished batches to rank 0, which commits them exactly as a single process would. The
// database is therefore the same whatever N is, and bit-identical to a single-process run.
// SIGINT/SIGTERM on any rank (mpirun forwards them to all) stop the whole run cleanly: rank 0
// hands out no more work, every rank finishes and sends its running drops, rank 0 commits them.
#include <string>

#include "drop_tests/sweep/sweep.h"

namespace touchdown::sweep {

// True when this process was started by mpirun with more than one rank (OpenMPI, PMI or
// PMIx environment variables), so the sweep should run on MPI.
bool LaunchedByMpirun();

// Runs the sweep over all ranks, starting MPI on the first call (it is finalised when the process
// exits, so a run of several sweeps, a rare-event study's batches, uses one session). With
// options.indices only those drops run (rank 0 hands them out). On ranks other than 0 the returned
// summary only counts that rank's own drops. Throws InputError on every rank when the plan or the
// database is refused.
SweepRunSummary RunSweepMpi(const SweepPlan& plan, const std::string& out_dir, const SweepRunOptions& options,
                            int* rank = nullptr);

// The rank mpirun gave this process (OMPI_COMM_WORLD_RANK, PMI_RANK or PMIX_RANK), known before
// MPI starts; 0 when not launched by mpirun.
int RankFromMpirun();
// Rank 0's `text` on every rank (collective: every rank calls it, in the same order); `text` itself
// when MPI has not been started.
std::string BroadcastFromRankZero(const std::string& text);

}  // namespace touchdown::sweep
