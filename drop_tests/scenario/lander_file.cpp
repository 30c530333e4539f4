#include <cstdio>
#include <filesystem>
#include <optional>
#include <variant>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_scenario_yaml.h"
#include "lander/multibody/leg_placement.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

// The lander file (data/landers): the lander's masses, its pad and its legs, placed.
namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
using namespace file_yaml;
using units::kMm;

lander::ShockAbsorber ReadAbsorber(const io::YamlFields& f) {
  lander::ShockAbsorber a;
  const std::string kind = f.String("kind");
  if (const std::optional<lander::ShockAbsorber::Kind> k = FindName(kAbsorberKindNames, kind))
    a.kind = *k;
  else
    f.Fail("kind", "unknown absorber kind '" + kind + "' (spring_damper, crushable)");
  f.RequireOnly(io::Keys(AbsorberKeys(a.kind)));
  io::ReadFields(f, AbsorberFields(a.kind), a);
  return a;
}
// A lander file's number fields, and its `legs` block's (placed by PlaceLegs).
const io::FieldTable<LanderSpec>& LanderNumberFields() {
  static const io::FieldTable<LanderSpec> fields{
      {"total_mass_kg", &LanderSpec::total_mass_kg, 1.0, io::Sign::kPositive, false, false, &limits::kMass_kg},
      {"cog_height_mm", &LanderSpec::cog_height_m, kMm, io::Sign::kPositive, false, false, &limits::kLanderSize_mm},
  };
  return fields;
}
const io::FieldTable<LanderLegLayout>& LegNumberFields() {
  using L = LanderLegLayout;
  static const io::FieldTable<L> fields{
      {"joint_radius_mm", &L::joint_radius_m, kMm, io::Sign::kPositive, false, false, &limits::kLanderSize_mm},
      {"hip_radius_mm", &L::hip_radius_m, kMm, io::Sign::kNonNegative, false, false, &limits::kLanderSize_mm},
      {"hip_height_mm", &L::hip_height_m, kMm, io::Sign::kPositive, false, false, &limits::kLanderSize_mm},
      {"load_limit_N", &L::load_limit_N, 1.0, io::Sign::kPositive, true, true, &limits::kForce_N, "none"},
  };
  return fields;
}
// A lander file's keys, and its `legs` block's (a person writes them; a resolved lander scenario
// states what they resolve to).
const io::KeyTable<LanderSpec>& LanderFileKeys() {
  static const io::KeyTable<LanderSpec> keys = [] {
    io::KeyTable<LanderSpec> k{{"schema_version"}, {"name"}, {"description"}};
    io::AppendNumberKeys(k, LanderNumberFields());
    for (const char* key : {"body_inertia_kg_m2", "pad", "legs", "provenance"}) k.push_back({key});
    return k;
  }();
  return keys;
}
const io::KeyTable<LanderLegLayout>& LegKeys() {
  static const io::KeyTable<LanderLegLayout> keys = [] {
    io::KeyTable<LanderLegLayout> k;
    io::AppendNumberKeys(k, LegNumberFields());
    k.push_back({"absorber"});
    k.push_back({"cone_limit"});
    return k;
  }();
  return keys;
}

// The lander file's key that a leg placement's error names.
const char* PlacementKey(lander::LegPlacementError::Field field) {
  switch (field) {
    case lander::LegPlacementError::Field::kTotalMass: return "total_mass_kg";
    case lander::LegPlacementError::Field::kCogHeight: return "cog_height_mm";
    case lander::LegPlacementError::Field::kHipHeight: return "hip_height_mm";
  }
  return "";
}

// The body's mass and CoM and the legs' joints and hips from the pad and the leg layout
// (lander/multibody/leg_placement.h); the error when they do not fit.
std::optional<lander::LegPlacementError> PlaceLegs(LanderSpec& s) {
  const lander::LegLayout layout{s.layout.joint_radius_m, s.layout.hip_radius_m, s.layout.hip_height_m};
  const auto placed = lander::PlaceLegs(s.pad.body, s.total_mass_kg, s.cog_height_m, layout);
  if (const auto* error = std::get_if<lander::LegPlacementError>(&placed)) return *error;
  const lander::LegPlacement& p = std::get<lander::LegPlacement>(placed);
  s.body_mass_kg = p.body_mass_kg;
  for (int i = 0; i < lander::kNumLegs; ++i) {
    s.legs[i].joint_B = p.joint_B[i];
    s.legs[i].hip_B = p.hip_B[i];
    s.legs[i].absorber = s.layout.absorber;
    s.legs[i].cone = s.layout.cone;
    s.legs[i].load_limit_N = s.layout.load_limit_N;
  }
  return std::nullopt;
}
// Why the joints' stop is too stiff for the pad (lander::MaxStopStiffness), or "".
std::string StopStiffnessProblem(const LanderSpec& s) {
  if (!s.layout.cone) return "";
  const double k_max = lander::MaxStopStiffness(s.pad.body);
  if (s.layout.cone->stiffness_N_m_rad <= k_max) return "";
  char text[256];
  std::snprintf(text, sizeof text,
                "must be at most %.3g N m/rad for this pad, got %.6g (the pad would ring on its stop faster than %g "
                "kHz, which the integrator resolves step by step: lander::MaxStopStiffness)",
                k_max, s.layout.cone->stiffness_N_m_rad, lander::kMaxStopRingingHz / units::kKilo);
  return text;
}
}  // namespace

LanderSpec LoadLanderSpec(const std::string& name_or_path) {
  return LoadLanderSpec(io::YamlFields::LoadFile(io::ResolveCatalogFile("landers", name_or_path)));
}

LanderSpec LoadLanderSpec(const io::YamlFields& f) {
  const std::string& path = f.file();
  f.RequireSchemaVersion(1);
  f.RequireOnly(io::Keys(LanderFileKeys()));
  LanderSpec s;
  s.source = path;
  s.name = f.Name("name", fs::path(path).stem().string());
  io::ReadFields(f, LanderNumberFields(), s);
  s.body_inertia_B = io::ReadInertia(f.Child("body_inertia_kg_m2"));
  try {
    s.pad = io::LoadPad(ResolveRelative(f, "pads", f.String("pad")));
  } catch (const InputError& e) {
    f.Fail("pad", e.what());
  }
  const io::YamlFields legs = f.Child("legs");
  legs.RequireOnly(io::Keys(LegKeys()));
  io::ReadFields(legs, LegNumberFields(), s.layout);
  if (legs.Has("absorber")) s.layout.absorber = ReadAbsorber(legs.Child("absorber"));
  if (legs.Has("cone_limit")) {
    const io::YamlFields c = legs.Child("cone_limit");
    c.RequireOnly(io::FieldKeys(ConeFields()));
    s.layout.cone.emplace();
    io::ReadFields(c, ConeFields(), *s.layout.cone);
  }
  if (const auto error = PlaceLegs(s)) {
    const bool hips = error->field == lander::LegPlacementError::Field::kHipHeight;
    (hips ? legs : f).Fail(PlacementKey(error->field), error->reason);
  }
  if (const std::string problem = StopStiffnessProblem(s); !problem.empty())
    legs.Child("cone_limit").Fail("stiffness_N_m_rad", problem);
  return s;
}

std::vector<io::BlockDoc> LanderFileSchema() {
  const std::string read_by = "drop_tests/scenario/lander_file.cpp";
  std::vector<io::BlockDoc> blocks{io::MakeBlock("lander", read_by, io::DocsOf(LanderFileKeys())),
                                   io::MakeBlock("lander.legs", read_by, io::DocsOf(LegKeys()))};
  for (const auto& [kind, name] : kAbsorberKindNames)
    blocks.push_back(io::MakeBlock("lander.legs.absorber." + std::string(name), read_by, io::DocsOf(AbsorberKeys(kind))));
  blocks.push_back(io::MakeBlock("lander.legs.cone_limit", read_by, io::DocsOf(ConeFields())));
  return blocks;
}

LanderSpec LanderSpecWithPad(const LanderSpec& spec, const io::PadSpec& pad) {
  LanderSpec s = spec;
  s.pad = pad;
  if (const auto error = PlaceLegs(s))
    throw InputError("pad " + pad.name + " does not fit lander " + spec.name + " (its " + PlacementKey(error->field) +
                     ": " + error->reason + "; pad file " + pad.source + ")");
  if (const std::string problem = StopStiffnessProblem(s); !problem.empty())
    throw InputError("pad " + pad.name + " does not fit lander " + spec.name + " (its legs.cone_limit.stiffness_N_m_rad " +
                     problem + "; pad file " + pad.source + ")");
  return s;
}

LanderScenario AtPadFileMesh(const LanderScenario& scenario) {
  if (scenario.pad_angular_segments == 0) return scenario;
  LanderScenario out = scenario;
  out.lander = LanderSpecWithPad(scenario.lander,
                                 io::PadWithAngularSegments(scenario.lander.pad, scenario.pad_file_angular_segments));
  out.pad_angular_segments = 0;
  out.pad_file_angular_segments = 0;
  out.pad_rim = geom::RimPolygon::kInscribed;
  return out;
}

}  // namespace touchdown::scenario
