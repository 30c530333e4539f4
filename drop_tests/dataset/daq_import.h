#pragma once
// `touchdown import MAPPING.yaml --out DATASET_DIR` (docs/import.md): raw DAQ files of drop tests,
// named by a mapping file (daq_mapping.h), into the dataset format (dataset.h).
//
// Per drop: read the requested columns (daq_csv.h); time in seconds, uniform; channels converted
// (gain (raw - offset)); the CFC filter where asked (channel_filter.h); touchdown found on the
// force (touchdown_onset.h), t = 0 there, the pre-trigger kept as negative times; the force zeroed
// on the pre-trigger; the penetration from displacement or acceleration (daq_penetration.h). The
// drop's trace is t_s, penetration_m, force_N; drops.csv carries the mapping's further keys, then
// what import measured (kImportColumns). Every drop is read and processed before anything is
// written, and the dataset (with README.md and a copy of the mapping, import.yaml) appears whole
// or not at all.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/dataset/daq_mapping.h"
#include "drop_tests/dataset/dataset.h"
#include "drop_tests/dataset/touchdown_onset.h"
#include "drop_tests/formats/output_path.h"

namespace touchdown::dataset {

// What import holds in memory before it writes (three doubles a sample, plus the traces'):
// 2e7 samples in all, about 1 GB at most.
inline constexpr double kMaxImportSamples = 2e7;

struct ImportedDrop {
  std::string drop_id, raw_path;
  size_t samples = 0;
  double sample_rate_hz = 0.0;
  TouchdownOnset onset;
  double force_zero_N = 0.0;           // subtracted from the force (0 with zero: none)
  double displacement_at_touchdown_m = 0.0, measured_impact_speed_m_s = 0.0;  // from displacement
  double acceleration_bias_m_s2 = 0.0, rest_velocity_m_s = 0.0, pretrigger_acceleration_m_s2 = 0.0;  // from acceleration
};

struct ImportRun {
  DaqMapping mapping;
  Dataset dataset;
  std::vector<ImportedDrop> drops;
};

// Reads the mapping and every raw file and processes them; writes nothing. Throws InputError
// naming the mapping (file, field, value) or the raw file (line, column) on the first problem.
ImportRun ImportRaw(const std::string& mapping_path);
// Writes the run's dataset with README.md and import.yaml into `out` (whole or not at all).
void WriteImportedDataset(const ImportRun& run, const io::OutputTarget& out);
// Checks `out` first, then ImportRaw, then writes; the raw files and the mapping join out's inputs
// (a target equal to, inside or around one is refused).
ImportRun ImportToDirectory(const std::string& mapping_path, const io::OutputTarget& out);

// What the command prints: the dataset's name, folder and drops, and per drop its touchdown.
nlohmann::json ImportSummaryJson(const ImportRun& run, const std::string& out);

}  // namespace touchdown::dataset
