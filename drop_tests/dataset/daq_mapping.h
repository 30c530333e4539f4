#pragma once
// The mapping file of `touchdown import` (docs/import.md): which DAQ columns hold time, force
// and displacement or acceleration, their units, gains, offsets, filters and zeroing, and each
// drop's raw file and conditions.
//
//   schema_version: 1
//   type: import
//   name: NAME                     # the dataset's name (it names files)
//   description: TEXT              # optional, into the dataset's README.md
//   daq:
//     delimiter: ","               # one character; " " splits on runs of blanks (default ",")
//     comment: "#"                 # lines starting with it are skipped (default "#")
//     decimal: "."                 # or "," for a decimal comma (default ".")
//     time: {column: NAME, unit: s|ms|us}   or   {sample_rate_hz: RATE}
//   channels:
//     force: {column, gain, offset, filter, zero}      # physical = gain (raw - offset), N, up
//     displacement: {...} | acceleration: {...}        # m positive down | m/s^2 positive down
//   touchdown: {channel: force, threshold_N: X}        # optional: a fixed trigger level
//   drops:
//     - {file: raw/ID.csv, drop_id, pad, soil, atmosphere, impact_speed_m_s, pad_mass_kg,
//        gravity_m_s2, ...}        # further keys become columns of drops.csv
//
// A channel's `filter` is cfc60|cfc180|cfc600|cfc1000|none (default none), its `zero`
// pre_trigger|none (force: default pre_trigger; others: none), or for acceleration also
// free_fall (the pre-trigger's mean set to +g: an accelerometer reading specific force).
// `offset` defaults to 0. Paths are relative to the mapping file. Everything is checked here,
// raw files readable included, before a single raw file is read.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "drop_tests/dataset/channel_filter.h"
#include "drop_tests/formats/schema_doc.h"
#include "drop_tests/dataset/daq_csv.h"
#include "rft/atmosphere.h"
#include "rft/enum_names.h"

namespace touchdown::dataset {

enum class ChannelZero { kNone, kPreTrigger, kFreeFall };
inline constexpr std::array<EnumName<ChannelZero>, 3> kChannelZeroNames{
    {{ChannelZero::kNone, "none"}, {ChannelZero::kPreTrigger, "pre_trigger"}, {ChannelZero::kFreeFall, "free_fall"}}};
const char* ChannelZeroName(ChannelZero zero);

struct DaqChannel {
  std::string column;
  double gain = 1.0;    // SI units per raw unit
  double offset = 0.0;  // raw units
  ChannelFilter filter = ChannelFilter::kNone;
  ChannelZero zero = ChannelZero::kNone;
  std::string field;    // "channels.force", for messages
};

enum class MotionChannel { kDisplacement, kAcceleration };
inline constexpr std::array<EnumName<MotionChannel>, 2> kMotionChannelNames{
    {{MotionChannel::kDisplacement, "displacement"}, {MotionChannel::kAcceleration, "acceleration"}}};
const char* MotionChannelName(MotionChannel kind);

struct DaqDropEntry {
  std::string field;    // "drops[3]", for messages
  std::string file;     // as the mapping gives it
  std::string path;     // resolved against the mapping's folder
  std::string drop_id, pad, soil;
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;
  double impact_speed_m_s = 0.0, pad_mass_kg = 0.0, gravity_m_s2 = 0.0;
  std::vector<std::string> extra;  // cells of DaqMapping::extra_columns ("" where the drop has none)
};

struct DaqMapping {
  std::string source;  // the mapping file
  std::string name, description;
  DaqTextFormat text;
  std::string time_column;  // "" when the time is the row index / sample_rate_hz
  double time_unit_s = 1.0;
  double sample_rate_hz = 0.0;
  DaqChannel force, motion;
  MotionChannel motion_kind = MotionChannel::kDisplacement;
  double threshold_N = 0.0;  // touchdown.threshold_N; 0: automatic
  std::vector<std::string> extra_columns;  // the drops' further keys, in order of first appearance
  std::vector<DaqDropEntry> drops;
};

// The keys a drop entry must have.
extern const std::vector<std::string> kDaqDropKeys;
// The columns import adds to drops.csv after the drops' further keys, what it measured per drop
// (docs/import.md, "Output"); a drop's further key may not take one of these names. The first
// list is every drop's, the second a displacement's, the third an acceleration's.
extern const std::vector<std::string> kImportColumns;
extern const std::vector<std::string> kImportDisplacementColumns;
extern const std::vector<std::string> kImportAccelerationColumns;

// Reads and checks the mapping at `path`; throws InputError naming the file, the field and the value.
DaqMapping LoadDaqMapping(const std::string& path);
// The reference of an import mapping's keys (schema_doc.h; `touchdown schema`, docs/reference.md).
std::vector<io::BlockDoc> DaqMappingSchema();

}  // namespace touchdown::dataset
