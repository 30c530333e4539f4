#pragma once
// Raw DAQ files and their mapping, written for the importer's tests from a drop with a known
// answer (daq_test_drop.h): a force channel in ADC counts with a bias, a displacement channel that
// reads up from a zero off the surface, or an accelerometer; `;`-separated, metadata first.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/drop_tests/dataset/daq_test_drop.h"

namespace touchdown::dataset::testing_drop {

// Counts of the channels the mapping below converts back: force = 0.05 (counts - 2048) with a
// 4.2 N bias in it; displacement = -1e-5 (counts - 1000), its zero 7 mm above the surface;
// acceleration = 0.01 (counts - 0), specific force (a - g) when `specific_force`.
inline std::string RawDropText(const DropRecord& r, bool acceleration, bool time_column, bool specific_force = false) {
  std::ostringstream out;
  out.precision(12);
  out << "# test rig export\n# units: counts\n";
  out << (time_column ? "Time;" : "") << "Fz;" << (acceleration ? "Acc" : "Pos") << ";Status\n";
  for (size_t i = 0; i < r.t_s.size(); ++i) {
    if (time_column) out << r.t_s[i] * 1e3 << ';';
    out << std::lround((r.force_N[i] + 4.2) / 0.05 + 2048) << ';';
    if (acceleration)
      out << std::lround((r.acceleration_m_s2[i] - (specific_force ? 9.81 : 0.0)) / 0.01);
    else
      out << std::lround(-(r.depth_m[i] + 0.007) / 1e-5 + 1000);
    out << ";OK\n";
  }
  return out.str();
}

inline std::string MappingText(bool acceleration, const std::string& time, const std::string& drops,
                               const std::string& acceleration_zero = "none") {
  return "schema_version: 1\ntype: import\nname: unit_rig\ndescription: Test drops made in code.\n"
         "daq:\n  delimiter: \";\"\n  comment: \"#\"\n  time: " + time + "\n"
         "channels:\n  force: {column: Fz, gain: 0.05, offset: 2048}\n" +
         (acceleration ? "  acceleration: {column: Acc, gain: 0.01, offset: 0, zero: " + acceleration_zero + "}\n"
                       : "  displacement: {column: Pos, gain: -1e-5, offset: 1000}\n") +
         "drops:\n" + drops;
}

inline std::string DropLine(const std::string& id, const std::string& pad, double speed, const std::string& extra = "") {
  std::ostringstream s;
  s << "  - {file: raw/" << id << ".csv, drop_id: " << id << ", pad: " << pad
    << ", soil: fjs1_lp, atmosphere: vacuum, impact_speed_m_s: " << speed << ", pad_mass_kg: 1.6, gravity_m_s2: 9.81"
    << extra << "}\n";
  return s.str();
}

}  // namespace touchdown::dataset::testing_drop
