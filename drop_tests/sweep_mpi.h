#pragma once
// `mpirun -np N touchdown sweep ...`: every rank loads the plan; rank 0 opens the results
// database, finds the drops still missing (so a restart works with any N) and broadcasts
// them; rank r computes the r-th of every N remaining drops on its threads and sends finished
// batches to rank 0, which commits them exactly as a single process would. The database is
// therefore the same whatever N is, and bit-identical to a single-process run.
#include <string>

#include "drop_tests/sweep.h"

namespace touchdown::drop {

// True when this process was started by mpirun with more than one rank (OpenMPI, PMI or
// PMIx environment variables), so the sweep should run on MPI.
bool LaunchedByMpirun();
bool MpiSupported();  // built with TOUCHDOWN_WITH_MPI

// Initialises MPI, runs the sweep over all ranks, finalises MPI. On ranks other than 0 the
// returned summary only counts that rank's own drops. Throws InputError on every rank when
// the plan or the database is refused.
SweepRunSummary RunSweepMpi(const SweepPlan& plan, const std::string& out_dir, const SweepRunOptions& options,
                            int* rank = nullptr);

}  // namespace touchdown::drop
