#pragma once
// One dataset format for measured and simulated drops, so that a measurement and a
// simulation compare column by column. A dataset is a directory:
//
//   drops.csv   one row per drop, the columns
//                 drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace
//               optionally final_penetration_m,peak_force_N,penetration_zero, then any further parameter
//               columns (tilt_deg, horizontal_speed_m_s, ...). `atmosphere` is vacuum or air;
//               `trace` is a path relative to the directory.
//   each trace  t_s,penetration_m,force_N (+ extra columns): t = 0 at touchdown (earlier,
//               negative times are allowed), penetration positive downward from the
//               undisturbed surface, force = soil reaction on the pad, positive upward.
//               `penetration_zero: touchdown` (an imported record's): the penetration is
//               zeroed instead where the pad's free fall puts it at the recorded t = 0, so a
//               touchdown detected late by dt moves it by the free fall's v dt + g dt^2 / 2.
//
// Reading validates everything (columns, numbers, strictly increasing time, pads and soils
// known to the catalogue, unique drop ids, trace files present) before returning, and throws
// InputError naming file, line and column on the first problem: a dataset is read whole or
// not at all. Writing goes to a staged directory that appears only when complete. Numbers are
// written in shortest round-trip form, so write -> read gives back identical values.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/drop/drop_row.h"
#include "drop_tests/formats/output_path.h"
#include "rft/atmosphere.h"
#include "rft/enum_names.h"

namespace touchdown::dataset {

// The required drops.csv columns, in the order the writer uses.
extern const std::vector<std::string> kDatasetDropColumns;
// The required trace columns.
extern const std::vector<std::string> kDatasetTraceColumns;

// Where a trace's penetration is zero: the undisturbed surface, or the free-fall path's point at
// the recorded touchdown (t = 0), which is the surface only when the touchdown is found exactly.
enum class PenetrationZero { kSurface, kTouchdown };
inline constexpr std::array<EnumName<PenetrationZero>, 2> kPenetrationZeroNames{
    {{PenetrationZero::kSurface, "surface"}, {PenetrationZero::kTouchdown, "touchdown"}}};

struct DatasetTrace {
  std::vector<double> t_s;
  std::vector<double> penetration_m;
  std::vector<double> force_N;
  std::vector<std::string> extra_columns;   // further columns, in file order
  std::vector<std::vector<double>> extra;   // extra[k][i]: column k, sample i
  size_t size() const { return t_s.size(); }
  bool operator==(const DatasetTrace&) const = default;
};

// The trace's sample period: the median spacing of its sample times (0 with fewer than two).
double SamplePeriod(const DatasetTrace& trace);

struct DatasetDrop {
  std::string drop_id;
  std::string pad;         // catalogue name or pad YAML path (relative paths: to the dataset directory)
  std::string soil;        // likewise for soils
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;
  double impact_speed_m_s = 0.0;
  double pad_mass_kg = 0.0;
  double gravity_m_s2 = 0.0;
  std::string trace_file;  // relative to the dataset directory
  std::optional<double> final_penetration_m;
  std::optional<double> peak_force_N;
  PenetrationZero penetration_zero = PenetrationZero::kSurface;
  std::vector<std::string> extra;  // cells of Dataset::extra_columns, as written ("" = empty)
  DatasetTrace trace;              // empty when read with load_traces = false

  // Measured (or simulated) final penetration: the column if given, else the trace's last sample.
  double FinalPenetration() const;
  // The column if given, else the largest force in the trace.
  double PeakForce() const;
  bool operator==(const DatasetDrop&) const = default;
};

struct Dataset {
  std::string directory;                   // where it was read from (not compared)
  std::vector<std::string> extra_columns;  // parameter columns after the required/optional ones
  std::vector<DatasetDrop> drops;

  const DatasetDrop* Find(const std::string& drop_id) const;
  // A numeric extra parameter of a drop; nullopt if the column is absent or the cell empty.
  // Throws InputError if the cell is not a number.
  std::optional<double> ExtraNumber(const DatasetDrop& drop, const std::string& column) const;
  // Pad/soil references resolved for LoadPad/LoadSoil (relative paths against `directory`).
  std::string PadReference(const DatasetDrop& drop) const;
  std::string SoilReference(const DatasetDrop& drop) const;
  // The drop's stated conditions as the one row type every drop is resolved from: speed, mass,
  // gravity, atmosphere, and the optional columns tilt_deg and horizontal_speed_m_s (0 if absent).
  drop::DropRow Row(const DatasetDrop& drop) const;
  bool operator==(const Dataset& o) const { return extra_columns == o.extra_columns && drops == o.drops; }
};

struct DatasetReadOptions {
  bool load_traces = true;
  bool check_catalog = true;  // pads and soils must resolve to catalogue entries or files
};

// Why `id` cannot be a drop id, or "" if it can. A drop id names files (traces, plots), so it
// must be a file name: not empty, "." or "..", no '/', '\\' or control character, valid UTF-8,
// at most 200 bytes.
std::string DropIdProblem(const std::string& id);

Dataset ReadDataset(const std::string& directory, const DatasetReadOptions& options = {});
// Writes drops.csv and every trace as one whole output (drop_tests/formats/output_path.h). Throws
// InputError on a drop that could not be read back (bad id, path, numbers).
void WriteDataset(const Dataset& dataset, const io::OutputTarget& target);
// The same, into `directory` of an output being written (e.g. a comparison's simulated/).
void WriteDatasetFiles(const Dataset& dataset, const std::string& directory);

}  // namespace touchdown::dataset
