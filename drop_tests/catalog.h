#pragma once
// The pads and soils a user names on the command line: a name from the bundled data/
// directory (`flat`, `fjs1_lp`) or a path to a YAML file. Loading validates everything,
// so the physics never sees a bad number.
#include <string>

#include "footpad_geom/axisymmetric_profile.h"
#include "rft/soil.h"

namespace touchdown::drop {

struct PadSpec {
  std::string name;
  std::string source;  // the YAML file it came from
  geom::AxisymmetricProfile profile;
  double mass_kg = 0.0;
};

// data/ of this build, or $TOUCHDOWN_DATA_DIR when set.
std::string DataDirectory();
// `kind` is a data/ subfolder ("pads", "soils", "scenarios"). A name with a '/' or a
// ".yaml"/".yml" ending is a path; otherwise data/<kind>/<name>.yaml.
std::string ResolveCatalogFile(const std::string& kind, const std::string& name_or_path);

PadSpec LoadPad(const std::string& name_or_path);
rft::SoilParameters LoadSoil(const std::string& name_or_path);

}  // namespace touchdown::drop
