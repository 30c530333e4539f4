#pragma once
// `touchdown export DIR --to DATASET_DIR`: a sweep's results as a dataset (dataset.h), so a
// simulated sweep can be compared with measured drops like any other dataset.
//
// drops.csv gets the required columns, final_penetration_m and peak_force_N, and the further
// parameters and metrics as extra columns (tilt_deg, horizontal_speed_m_s, zeta_N_cm3,
// time_to_rest_s, ..., final_tilt_deg, horizontal_travel_m: 0 for rig drops); each trace
// t_s,penetration_m,force_N,velocity_m_s. A lander sweep's drops are not single-pad drops:
// SweepToDataset refuses them, and ExportSweep writes DATASET_DIR/lander_drops.csv instead (one
// row per successful lander drop: its parameters, the soil under each pad and the paper's ground
// case, and the lander summary; kLanderExportColumns) with failed.csv beside it. Traces are those
// stored in the database; drops stored without one (traces: none), or every drop with
// `full_traces`, are simulated again from the sweep file (checked against the database's
// digest), which reproduces them bit for bit. Failed drops have no trace: they are listed in
// failed.csv (drop_id,reason) beside drops.csv and left out of drops.csv.
#include <string>
#include <vector>

#include "drop_tests/util/progress.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/sweep/results_db.h"

namespace touchdown::sweep {

struct ExportOptions {
  bool full_traces = false;  // simulate every drop again for its full trace
  int threads = 0;
  io::ProgressOptions progress{io::ProgressMode::kNone};  // of the drops written
};

struct ExportSummary {
  int64_t exported = 0, failed = 0, resimulated = 0;
  bool lander = false;  // a lander sweep: lander_drops.csv, no drops.csv
};

// The columns of lander_drops.csv, in order.
extern const std::vector<std::string> kLanderExportColumns;

// The dataset in memory (traces included): for tests and small sweeps; ExportSweep streams instead.
dataset::Dataset SweepToDataset(const std::string& sweep_dir, const ExportOptions& options, ExportSummary* summary = nullptr,
                       std::vector<DropRecord>* failed = nullptr);
ExportSummary ExportSweep(const std::string& sweep_dir, const io::OutputTarget& dataset, const ExportOptions& options);

}  // namespace touchdown::sweep
