#include "drop_tests/scenario/lander_scenario_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <variant>

#include "drop_tests/formats/dataset_csv.h"  // io::FormatNumber
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/catalog/paths_in_outputs.h"
#include "drop_tests/formats/yaml_diff.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/model/model_file.h"
#include "lander/multibody/leg_placement.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

const char* PadAttitudeName(PadAttitude attitude) { return attitude == PadAttitude::kLevel ? "level" : "body"; }

namespace {
using units::kDeg;
using units::kMm;
// A list of exactly n finite numbers (any sign).
std::vector<double> FixedList(const io::YamlFields& f, const std::string& key, size_t n) {
  const YAML::Node list = f.node()[key];
  if (!list.IsSequence() || list.size() != n)
    f.Fail(key, "must be a list of " + std::to_string(n) + " numbers");
  std::vector<double> out;
  for (size_t i = 0; i < n; ++i) {
    double v = 0.0;
    if (!list[i].IsScalar() || !YAML::convert<double>::decode(list[i], v) || !std::isfinite(v))
      f.Fail(key + "[" + std::to_string(i) + "]", "must be a finite number, got '" + list[i].Scalar() + "'");
    out.push_back(v);
  }
  return out;
}

std::string ResolveRelative(const io::YamlFields& f, const std::string& kind, const std::string& name) {
  try {
    return io::ResolveCatalogFileNear(f.file(), kind, name);
  } catch (const InputError& e) {
    f.Fail(kind == "pads" ? "pad" : kind, e.what());
  }
}

// The absorber kinds as files name them (read and written).
const char* AbsorberKindName(lander::ShockAbsorber::Kind kind) {
  return kind == lander::ShockAbsorber::Kind::kSpringDamper ? "spring_damper" : "crushable";
}

// The number fields of each absorber kind and of the cone limit, read from a lander file and
// written into a resolved copy (every field, defaults included).
const io::FieldTable<lander::ShockAbsorber>& AbsorberFields(lander::ShockAbsorber::Kind kind) {
  using A = lander::ShockAbsorber;
  static const io::FieldTable<A> spring_damper{
      {"stiffness_N_m", &A::stiffness_N_m, 1.0, io::Sign::kPositive, false, false, &limits::kStiffness_N_m},
      {"damping_N_s_m", &A::damping_N_s_m, 1.0, io::Sign::kNonNegative, true, false, &limits::kDamping_N_s_m},
  };
  static const io::FieldTable<A> crushable{
      {"crush_force_N", &A::crush_force_N, 1.0, io::Sign::kPositive, false, false, &limits::kForce_N},
      {"stroke_mm", &A::stroke_limit_m, kMm, io::Sign::kPositive, false, false, &limits::kLanderSize_mm},
  };
  return kind == A::Kind::kSpringDamper ? spring_damper : crushable;
}

const io::FieldTable<lander::ConeLimit>& ConeFields() {
  using C = lander::ConeLimit;
  static const io::FieldTable<C> fields{
      {"half_angle_deg", &C::half_angle_rad, kDeg, io::Sign::kPositive, false, false, &limits::kConeHalfAngle_deg},
      {"stiffness_N_m_rad", &C::stiffness_N_m_rad, 1.0, io::Sign::kPositive, false, false,
       &limits::kTorsionStiffness_N_m_rad},
      {"damping_N_m_s_rad", &C::damping_N_m_s_rad, 1.0, io::Sign::kNonNegative, true, false,
       &limits::kTorsionDamping_N_m_s_rad},
  };
  return fields;
}

// An absorber block's keys for its kind, in the order a resolved copy writes them.
io::KeyTable<lander::ShockAbsorber> AbsorberKeys(lander::ShockAbsorber::Kind kind) {
  using A = lander::ShockAbsorber;
  io::KeyTable<A> k{{"kind", io::Always<A>, [](YAML::Emitter& y, const A& a) { y << AbsorberKindName(a.kind); }}};
  io::AppendNumberKeys(k, AbsorberFields(kind));
  return k;
}

lander::ShockAbsorber ReadAbsorber(const io::YamlFields& f) {
  lander::ShockAbsorber a;
  const std::string kind = f.String("kind");
  if (kind == AbsorberKindName(lander::ShockAbsorber::Kind::kSpringDamper)) {
    a.kind = lander::ShockAbsorber::Kind::kSpringDamper;
  } else if (kind == AbsorberKindName(lander::ShockAbsorber::Kind::kCrushable)) {
    a.kind = lander::ShockAbsorber::Kind::kCrushable;
  } else {
    f.Fail("kind", "unknown absorber kind '" + kind + "' (spring_damper, crushable)");
  }
  f.RequireOnly(io::Keys(AbsorberKeys(a.kind)));
  io::ReadFields(f, AbsorberFields(a.kind), a);
  return a;
}

void WriteAbsorber(YAML::Emitter& y, const lander::ShockAbsorber& a) {
  y << YAML::BeginMap;
  io::WriteKeys(y, AbsorberKeys(a.kind), a);
  y << YAML::EndMap;
}

}  // namespace

namespace {
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
  }
  return std::nullopt;
}
}  // namespace

LanderSpec LoadLanderSpec(const std::string& name_or_path) {
  return LoadLanderSpec(io::YamlFields::LoadFile(io::ResolveCatalogFile("landers", name_or_path)));
}

LanderSpec LoadLanderSpec(const io::YamlFields& f) {
  const std::string& path = f.file();
  f.RequireSchemaVersion(1);
  f.RequireOnly({"schema_version", "name", "description", "total_mass_kg", "cog_height_mm", "body_inertia_kg_m2",
                 "pad", "legs", "provenance"});
  LanderSpec s;
  s.source = path;
  s.name = f.StringOr("name", fs::path(path).stem().string());
  s.total_mass_kg = io::ReadNumber(f, "total_mass_kg", io::Sign::kPositive, &limits::kMass_kg);
  s.cog_height_m = io::ReadNumber(f, "cog_height_mm", io::Sign::kPositive, &limits::kLanderSize_mm) * kMm;
  s.body_inertia_B = io::ReadInertia(f.Child("body_inertia_kg_m2"));
  try {
    s.pad = io::LoadPad(ResolveRelative(f, "pads", f.String("pad")));
  } catch (const InputError& e) {
    f.Fail("pad", e.what());
  }
  const io::YamlFields legs = f.Child("legs");
  legs.RequireOnly({"joint_radius_mm", "hip_radius_mm", "hip_height_mm", "absorber", "cone_limit"});
  const auto size = [&](const char* key, io::Sign sign) {
    return io::ReadNumber(legs, key, sign, &limits::kLanderSize_mm) * kMm;
  };
  s.layout.joint_radius_m = size("joint_radius_mm", io::Sign::kPositive);
  s.layout.hip_radius_m = size("hip_radius_mm", io::Sign::kNonNegative);
  s.layout.hip_height_m = size("hip_height_mm", io::Sign::kPositive);
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
  return s;
}

LanderSpec LanderSpecWithPad(const LanderSpec& spec, const io::PadSpec& pad) {
  LanderSpec s = spec;
  s.pad = pad;
  if (const auto error = PlaceLegs(s))
    throw InputError("pad " + pad.name + " does not fit lander " + spec.name + " (its " + PlacementKey(error->field) +
                     ": " + error->reason + "; pad file " + pad.source + ")");
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

namespace {
// The number fields of the scenario's sections that the resolved copy writes back as given
// (in the order it writes them); fields that depend on each other stay with their readers.
const io::FieldTable<LanderGroundSpec>& GroundNumberFields() {
  using G = LanderGroundSpec;
  static const io::FieldTable<G> fields{
      {"height_m", &G::height_m, 1.0, io::Sign::kAny, true, false, &limits::kHeight_m},
      {"slope_deg", &G::slope_rad, kDeg, io::Sign::kNonNegative},
      {"downhill_azimuth_deg", &G::downhill_azimuth_rad, kDeg, io::Sign::kAny, true, false, &limits::kAzimuth_deg},
  };
  return fields;
}

const io::FieldTable<LanderInitialSpec>& AttitudeNumberFields() {
  using I = LanderInitialSpec;
  static const io::FieldTable<I> fields{
      {"roll_deg", &I::roll_rad, kDeg},
      {"pitch_deg", &I::pitch_rad, kDeg},
      {"yaw_relative_to_slope_deg", &I::yaw_relative_to_slope_rad, kDeg, io::Sign::kAny, true, false,
       &limits::kAzimuth_deg},
  };
  return fields;
}

constexpr const char* kReleaseBodyComKey = "release_body_com_m";

const io::FieldTable<lander::LanderRunOptions>& RunNumberFields() {
  using R = lander::LanderRunOptions;
  static const io::FieldTable<R> fields{
      {"duration_s", &R::duration_s, 1.0, io::Sign::kPositive},
      {"sample_rate_hz", &R::sample_rate_hz, 1.0, io::Sign::kPositive},
      {"capture_speed_m_s", &R::capture_speed_m_s, 1.0, io::Sign::kNonNegative, true, false, &limits::kSpeed_m_s},
      {"soil_ramp_speed_m_s", &R::soil_ramp_speed_m_s, 1.0, io::Sign::kPositive, true, true, &limits::kSpeed_m_s},
  };
  return fields;
}

using FileName = std::function<std::string(const std::string&)>;
void WriteLanderBlock(YAML::Emitter& y, const LanderSpec& l, const FileName& file);
void WriteSoilsBlock(YAML::Emitter& y, const LanderScenario& s, const lander::LanderSetup& setup);
void WriteVector(YAML::Emitter& y, const Eigen::Vector3d& v, double scale);

// A resolved copy to write: the scenario, the setup it resolves to, and how the files it names are
// written (relative to the folder the copy lives in).
struct ResolvedToWrite {
  const LanderScenario& s;
  const lander::LanderSetup& setup;
  FileName file;
};

// The tables below hold a scenario's keys, block by block, in the order a resolved copy writes
// them; a key with no writer is one only the user's scenario has (the resolved copy writes what
// it resolves to instead: a patch's polygon, a soil field's cells as patches).

struct PatchToWrite {
  const rft::SoilPatch& patch;
  const std::string& soil;
};

const io::KeyTable<PatchToWrite>& PatchKeys() {
  using P = PatchToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<P> keys{
      {"name", io::Always<P>, [](Y& y, const P& p) { y << p.patch.name; }},
      {"soil", io::Always<P>, [](Y& y, const P& p) { y << p.soil; }},
      {"rectangle_m"},
      {"polygon_m", io::Always<P>,
       [](Y& y, const P& p) {
         y << YAML::BeginSeq;
         for (const Eigen::Vector2d& c : p.patch.polygon_W) y << YAML::Flow << YAML::BeginSeq << c.x() << c.y() << YAML::EndSeq;
         y << YAML::EndSeq;
       }},
      {"under_pad"},
      {"half_width_m"},
  };
  return keys;
}

void WritePatch(YAML::Emitter& y, const rft::SoilPatch& patch, const std::string& soil) {
  y << YAML::BeginMap;
  io::WriteKeys(y, PatchKeys(), PatchToWrite{patch, soil});
  y << YAML::EndMap;
}

// The ground's patches as a resolved copy states them: the scenario's, then a patch field's cells
// of another soil than the default (the copy reads back to the same ground).
void WritePatches(YAML::Emitter& y, const rft::Terrain& terrain) {
  y << YAML::BeginSeq;
  for (const rft::SoilPatch& p : terrain.patches) WritePatch(y, p, terrain.soils[p.soil].name);
  const rft::SoilGrid& grid = terrain.grid;
  for (int k = 0; k < grid.nx * grid.ny; ++k) {
    if (grid.soil[k] == 0) continue;
    const double x0 = grid.x0_m + (k % grid.nx) * grid.cell_m, y0 = grid.y0_m + (k / grid.nx) * grid.cell_m;
    WritePatch(y,
               {"soil_field_" + std::to_string(k + 1), rft::RectanglePolygon(x0, y0, x0 + grid.cell_m, y0 + grid.cell_m),
                grid.soil[k]},
               terrain.soils[grid.soil[k]].name);
  }
  y << YAML::EndSeq;
}

const io::KeyTable<ResolvedToWrite>& GroundKeys() {
  using W = ResolvedToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys = [] {
    io::KeyTable<W> k;
    io::AppendNumberKeys<W, LanderGroundSpec>(k, GroundNumberFields(), [](const W& w) -> const LanderGroundSpec& { return w.s.ground; });
    k.push_back({"law", io::Always<W>, [](Y& y, const W& w) { y << std::string(rft::LawKindName(w.s.ground.law)); }});
    k.push_back({"soil", io::Always<W>, [](Y& y, const W& w) { y << w.s.ground.default_soil; }});
    k.push_back({"soils", io::Always<W>, [](Y& y, const W& w) { WriteSoilsBlock(y, w.s, w.setup); }});
    k.push_back({"model", [](const W& w) { return w.s.model.has_value(); },
                 [](Y& y, const W& w) { y << w.file(w.s.model->source); }});
    k.push_back({"patches", io::Always<W>, [](Y& y, const W& w) { WritePatches(y, w.setup.terrain); }});
    k.push_back({"soil_field"});
    return k;
  }();
  return keys;
}

const io::KeyTable<ResolvedToWrite>& InitialKeys() {
  using W = ResolvedToWrite;
  using Y = YAML::Emitter;
  const auto from_height = [](const W& w) { return w.s.initial.drop_height_m.has_value(); };
  static const io::KeyTable<W> keys = [&] {
    io::KeyTable<W> k{
        {"drop_height_m", from_height, [](Y& y, const W& w) { y << *w.s.initial.drop_height_m; }},
        {"release_vertical_speed_m_s", from_height, [](Y& y, const W& w) { y << w.s.initial.release_vertical_speed_m_s; }},
        {"touchdown_speed_m_s", [](const W& w) { return w.s.initial.touchdown_speed_m_s.has_value(); },
         [](Y& y, const W& w) { y << *w.s.initial.touchdown_speed_m_s; }},
        {"horizontal_velocity_m_s", io::Always<W>,
         [](Y& y, const W& w) {
           const Eigen::Vector2d& v = w.s.initial.horizontal_velocity_m_s;
           y << YAML::Flow << YAML::BeginSeq << v.x() << v.y() << YAML::EndSeq;
         }},
    };
    io::AppendNumberKeys<W, LanderInitialSpec>(k, AttitudeNumberFields(),
                                               [](const W& w) -> const LanderInitialSpec& { return w.s.initial; });
    k.push_back({"align_to_slope", io::Always<W>, [](Y& y, const W& w) { y << w.s.initial.align_to_slope; }});
    k.push_back({"angular_rate_deg_s", io::Always<W>,
                 [](Y& y, const W& w) { WriteVector(y, w.s.initial.angular_rate_B, 1.0 / kDeg); }});
    k.push_back({"pad_attitude", io::Always<W>, [](Y& y, const W& w) { y << PadAttitudeName(w.s.initial.pad_attitude); }});
    k.push_back({kReleaseBodyComKey, io::Always<W>, [](Y& y, const W& w) { WriteVector(y, w.setup.initial.p_WB, 1.0); }});
    return k;
  }();
  return keys;
}

const io::KeyTable<ResolvedToWrite>& SimulationKeys() {
  using W = ResolvedToWrite;
  using Y = YAML::Emitter;
  using R = lander::LanderRunOptions;
  static const io::KeyTable<W> keys = [] {
    io::KeyTable<W> k;
    io::AppendNumberKeys<W, R>(k, RunNumberFields(), [](const W& w) -> const R& { return w.s.options; });
    k.push_back({"rtol", io::Always<W>, [](Y& y, const W& w) { y << w.s.options.integrator.rtol; }});
    // Without `atol` the absolute tolerances are rtol times each state's scale (lander_simulation.h).
    k.push_back({"atol", [](const W& w) { return !w.s.options.scale_tolerances; },
                 [](Y& y, const W& w) { y << w.s.options.integrator.atol; }});
    k.push_back({"max_step_s", [](const W& w) { return w.s.options.integrator.max_step != R{}.integrator.max_step; },
                 [](Y& y, const W& w) { y << w.s.options.integrator.max_step; }});
    k.push_back({"stiff", io::Always<W>, [](Y& y, const W& w) { y << w.s.options.integrator.stiff; }});
    k.push_back({"soil_ramp", [](const W& w) { return w.s.options.soil_ramp != R{}.soil_ramp; },
                 [](Y& y, const W& w) { y << (w.s.options.soil_ramp == lander::SoilRamp::kElement ? "element" : "pad"); }});
    k.push_back({"pad_angular_segments", [](const W& w) { return w.s.pad_angular_segments > 0; },
                 [](Y& y, const W& w) { y << w.s.pad_angular_segments; }});
    k.push_back({"pad_rim", [](const W& w) { return w.s.pad_rim == geom::RimPolygon::kAreaPreserving; },
                 [](Y& y, const W&) { y << "area_preserving"; }});
    return k;
  }();
  return keys;
}

const io::KeyTable<ResolvedToWrite>& PaperKeys() {
  using W = ResolvedToWrite;
  using Y = YAML::Emitter;
  const auto check = [](const W& w) { return w.s.paper.has_value(); };
  const auto fitted = [](const W& w) { return w.s.paper && w.s.paper->used_for_fit; };
  static const io::KeyTable<W> keys{
      {"ground_case", [](const W& w) { return !w.s.paper_ground_case.empty(); },
       [](Y& y, const W& w) { y << w.s.paper_ground_case; }},
      {"roll_pitch_within_deg", check, [](Y& y, const W& w) { y << w.s.paper->roll_pitch_within_deg; }},
      {"source", [](const W& w) { return w.s.paper && !w.s.paper->source.empty(); },
       [](Y& y, const W& w) { y << w.s.paper->source; }},
      {"used_for_fit", fitted, [](Y& y, const W&) { y << true; }},
      {"fit_by", fitted, [](Y& y, const W& w) { y << w.s.paper->fit_by; }},
      {"reading", [](const W& w) { return w.s.paper && w.s.paper->reading.has_value(); },
       [](Y& y, const W& w) { y << std::string(PaperReadingName(*w.s.paper->reading)); }},
  };
  return keys;
}

// A block written from its table.
std::function<void(YAML::Emitter&, const ResolvedToWrite&)> Block(const io::KeyTable<ResolvedToWrite>& (*table)()) {
  return [table](YAML::Emitter& y, const ResolvedToWrite& w) {
    y << YAML::BeginMap;
    io::WriteKeys(y, table(), w);
    y << YAML::EndMap;
  };
}

// A scenario's top-level keys (`source` only in a resolved copy, `provenance` only in the user's).
const io::KeyTable<ResolvedToWrite>& LanderScenarioKeys() {
  using W = ResolvedToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys{
      {"schema_version", io::Always<W>, [](Y& y, const W&) { y << 1; }},
      {"type", io::Always<W>, [](Y& y, const W&) { y << "lander_resolved"; }},
      {"name", io::Always<W>, [](Y& y, const W& w) { y << w.s.name; }},
      {"description", [](const W& w) { return !w.s.description.empty(); }, [](Y& y, const W& w) { y << w.s.description; }},
      {"source", io::Always<W>, [](Y& y, const W& w) { y << w.file(w.s.source); }},
      {"gravity_m_s2", io::Always<W>, [](Y& y, const W& w) { y << w.s.gravity_m_s2; }},
      {"lander", io::Always<W>, [](Y& y, const W& w) { WriteLanderBlock(y, w.s.lander, w.file); }},
      {"ground", io::Always<W>, Block(GroundKeys)},
      {"initial", io::Always<W>, Block(InitialKeys)},
      {"simulation", io::Always<W>, Block(SimulationKeys)},
      {"paper", [](const W& w) { return !w.s.paper_ground_case.empty() || w.s.paper.has_value(); }, Block(PaperKeys)},
      {"provenance"},
  };
  return keys;
}

using SoilCheck = std::function<void(const io::YamlFields&, const std::string&, const std::string&)>;

// One soil patch: its corners, or an under_pad square placed once the release pose is known.
LanderPatchSpec ReadPatch(const io::YamlFields& p, const SoilCheck& check_soil) {
  p.RequireOnly(io::Keys(PatchKeys()));
  LanderPatchSpec patch;
  patch.soil = p.String("soil");
  check_soil(p, "soil", patch.soil);
  const int given = int(p.Has("rectangle_m")) + int(p.Has("polygon_m")) + int(p.Has("under_pad"));
  if (given != 1) p.Fail("rectangle_m", "give exactly one of rectangle_m, polygon_m, under_pad");
  if (p.Has("rectangle_m")) {
    const std::vector<double> r = FixedList(p, "rectangle_m", 4);
    if (!(r[2] > r[0] && r[3] > r[1])) p.Fail("rectangle_m", "must be [x0, y0, x1, y1] with x1 > x0, y1 > y0");
    patch.area = rft::RectanglePolygon(r[0], r[1], r[2], r[3]);
  } else if (p.Has("polygon_m")) {
    std::vector<Eigen::Vector2d> polygon_W;
    const YAML::Node list = p.node()["polygon_m"];
    if (!list.IsSequence() || list.size() < 3) p.Fail("polygon_m", "must list at least three [x, y] corners");
    for (size_t k = 0; k < list.size(); ++k) {
      double x = 0, y = 0;
      if (!list[k].IsSequence() || list[k].size() != 2 || !YAML::convert<double>::decode(list[k][0], x) ||
          !YAML::convert<double>::decode(list[k][1], y) || !std::isfinite(x) || !std::isfinite(y))
        p.Fail("polygon_m[" + std::to_string(k) + "]", "must be a pair of finite numbers [x, y]");
      polygon_W.emplace_back(x, y);
    }
    if (const std::string problem = rft::PolygonProblem(polygon_W); !problem.empty())
      p.Fail("polygon_m", "must be a simple polygon with an area: " + problem);
    patch.area = std::move(polygon_W);
  } else {
    const int pad = p.PositiveInt("under_pad");
    if (pad > lander::kNumLegs) p.Fail("under_pad", "must be 1..4, got " + std::to_string(pad));
    const double h = p.Positive("half_width_m");
    patch.name = "under_pad_" + std::to_string(pad);
    patch.area = UnderPadSquare{pad, h};  // placed by ResolveLander, once the release pose is known
  }
  if (p.Has("name")) patch.name = p.String("name");
  return patch;
}

// `ground.soil_field` (soil_field.h): soils checked like any patch's, probabilities summing to 1,
// at most 400 cells a side.
SoilFieldSpec ReadSoilField(const io::YamlFields& f, const SoilCheck& check_soil) {
  f.RequireOnly({"soils", "probabilities", "cell_size_m", "half_extent_m", "seed"});
  SoilFieldSpec field;
  const YAML::Node soils = f.node()["soils"];
  if (!soils || !soils.IsSequence() || soils.size() < 1 || soils.size() > 8)
    f.Fail("soils", "must be a list of 1 to 8 soils");
  for (size_t k = 0; k < soils.size(); ++k) {
    field.soils.push_back(soils[k].as<std::string>());
    check_soil(f, "soils[" + std::to_string(k) + "]", field.soils.back());
  }
  field.probabilities = f.NumberList("probabilities", /*allow_zero=*/true);
  if (field.probabilities.size() != field.soils.size())
    f.Fail("probabilities", "must give one probability per soil (" + std::to_string(field.soils.size()) + ")");
  double sum = 0.0;
  for (double p : field.probabilities) {
    if (!(p >= 0.0 && p <= 1.0)) f.Fail("probabilities", "each must be in [0, 1], got " + io::FormatNumber(p));
    sum += p;
  }
  if (!(std::abs(sum - 1.0) <= 1e-9)) f.Fail("probabilities", "must sum to 1, got " + io::FormatNumber(sum));
  field.cell_size_m = f.Positive("cell_size_m");
  field.half_extent_m = f.Positive("half_extent_m");
  if (!(field.half_extent_m / field.cell_size_m <= 200.0))
    f.Fail("half_extent_m", "makes more than 400 cells a side (half_extent_m / cell_size_m at most 200)");
  if (f.node()["seed"] && f.node()["seed"].IsScalar() && f.node()["seed"].Scalar() == "per_landing") {
    field.seed_per_landing = true;
  } else {
    const double seed = f.Number("seed");
    if (!(seed >= 0.0 && seed <= 9.0e15 && seed == std::floor(seed)))
      f.Fail("seed", "must be a whole number from 0 to 9e15, or per_landing (in a study)");
    field.seed = static_cast<uint64_t>(seed);
  }
  return field;
}

// A footprint dimension for checking a soil against the bekker law before the pad is placed.
constexpr double kAnyPlateB_m = 1.0;

// The ground: plane or slope, the 3D law, the default soil and the soil patches (every soil
// loaded and checked against the law at `gravity_m_s2`).
// A resolved copy's ground also has its `soils` and `model` (checked and read by the caller).
LanderGroundSpec ReadGround(const io::YamlFields& g, double gravity_m_s2, bool resolved) {
  LanderGroundSpec ground;
  g.RequireOnly(resolved ? io::Keys(GroundKeys(), {"soil_field"}) : io::Keys(GroundKeys(), {"soils", "model"}));
  io::ReadFields(g, GroundNumberFields(), ground);
  if (ground.slope_rad >= limits::kGroundSlopeBelow_deg * kDeg)
    g.Fail("slope_deg", "must be below " + std::to_string(limits::kGroundSlopeBelow_deg));
  ground.default_soil = g.String("soil");
  try {
    // No `law`: the default soil's own (li2013 for every RFT soil file, bekker for a Bekker soil).
    ground.law = g.Has("law") ? rft::ParseLawKind(g.String("law"), "", "")
                              : io::LoadSoil(ground.default_soil).rft_law_3d;
  } catch (const InputError& e) {
    g.Fail(g.Has("law") ? "law" : "soil", e.what());
  }
  const SoilCheck check_soil = [&](const io::YamlFields& where, const std::string& key, const std::string& soil) {
    try {
      // The pad is not known yet: any b checks the soil (its checks do not depend on b).
      rft::MakeStressLaw3D(ground.law, io::LoadSoil(soil), gravity_m_s2, kAnyPlateB_m);
    } catch (const InputError& e) {
      where.Fail(key, e.what());
    }
  };
  check_soil(g, "soil", ground.default_soil);
  // `patches: []` is how a resolved copy writes a ground without patches; in a user's scenario it
  // says nothing (a list emptied by mistake?), so it is refused there.
  const bool no_patches =
      g.Has("patches") && g.node()["patches"].IsSequence() && g.node()["patches"].size() == 0;
  if (no_patches && !resolved)
    g.Fail("patches", "is an empty list: give at least one patch, or leave patches out for one soil everywhere");
  if (g.Has("patches") && !no_patches) {
    for (const io::YamlFields& p : g.List("patches")) {
      LanderPatchSpec patch = ReadPatch(p, check_soil);
      if (patch.name.empty()) patch.name = "patch_" + std::to_string(ground.patches.size() + 1);
      ground.patches.push_back(patch);
    }
  }
  if (g.Has("soil_field")) ground.soil_field = ReadSoilField(g.Child("soil_field"), check_soil);
  return ground;
}

// The release: drop height or touchdown speed, velocities, attitude and the pads' attitude.
// A resolved copy's release also states the body's position (checked by the caller).
LanderInitialSpec ReadInitial(const io::YamlFields& in, bool resolved) {
  LanderInitialSpec ic;
  in.RequireOnly(resolved ? io::Keys(InitialKeys()) : io::Keys(InitialKeys(), {kReleaseBodyComKey}));
  if (in.Has("drop_height_m") == in.Has("touchdown_speed_m_s"))
    in.Fail("drop_height_m", "give exactly one of drop_height_m and touchdown_speed_m_s");
  if (in.Has("drop_height_m"))
    ic.drop_height_m = io::ReadNumber(in, "drop_height_m", io::Sign::kNonNegative, &limits::kDropHeight_m);
  if (in.Has("touchdown_speed_m_s"))
    ic.touchdown_speed_m_s = io::ReadNumber(in, "touchdown_speed_m_s", io::Sign::kNonNegative, &limits::kSpeed_m_s);
  if (in.Has("release_vertical_speed_m_s")) {
    if (!in.Has("drop_height_m")) in.Fail("release_vertical_speed_m_s", "only with drop_height_m");
    ic.release_vertical_speed_m_s =
        io::ReadNumber(in, "release_vertical_speed_m_s", io::Sign::kAny, &limits::kAbsSpeed_m_s);
  }
  if (in.Has("horizontal_velocity_m_s")) {
    const std::vector<double> v = FixedList(in, "horizontal_velocity_m_s", 2);
    ic.horizontal_velocity_m_s = Eigen::Vector2d(v[0], v[1]);
    limits::Require(limits::kSpeed_m_s, ic.horizontal_velocity_m_s.stableNorm(), in.file(),
                    in.Path("horizontal_velocity_m_s") + " (its magnitude)");
  }
  io::ReadFields(in, AttitudeNumberFields(), ic);
  const std::string within = "must be within +-" + std::to_string(limits::kInitialRollPitchWithin_deg);
  if (std::abs(ic.roll_rad) >= limits::kInitialRollPitchWithin_deg * kDeg) in.Fail("roll_deg", within);
  if (std::abs(ic.pitch_rad) >= limits::kInitialRollPitchWithin_deg * kDeg) in.Fail("pitch_deg", within);
  if (in.Has("align_to_slope")) {
    const std::string a = in.String("align_to_slope");
    if (a != "true" && a != "false") in.Fail("align_to_slope", "must be true or false, got '" + a + "'");
    ic.align_to_slope = a == "true";
  }
  if (in.Has("angular_rate_deg_s")) {
    const std::vector<double> w = FixedList(in, "angular_rate_deg_s", 3);
    for (size_t k = 0; k < w.size(); ++k)
      limits::Require(limits::kAngularRate_deg_s, w[k], in.file(),
                      in.Path("angular_rate_deg_s") + "[" + std::to_string(k) + "]");
    ic.angular_rate_B = Eigen::Vector3d(w[0], w[1], w[2]) * kDeg;
  }
  const std::string attitude = in.StringOr("pad_attitude", PadAttitudeName(PadAttitude::kBody));
  if (attitude == PadAttitudeName(PadAttitude::kLevel))
    ic.pad_attitude = PadAttitude::kLevel;
  else if (attitude != PadAttitudeName(PadAttitude::kBody))
    in.Fail("pad_attitude", "must be 'body' or 'level', got '" + attitude + "'");
  return ic;
}

// The run options: duration, sampling, capture speed and the integrator's tolerances.
void ReadSimulation(const io::YamlFields& sim, lander::LanderRunOptions& options) {
  sim.RequireOnly(io::Keys(SimulationKeys()));
  io::ReadFields(sim, RunNumberFields(), options);
  if (sim.Has("soil_ramp")) {
    const std::string v = sim.String("soil_ramp");
    if (v != "pad" && v != "element") sim.Fail("soil_ramp", "must be 'pad' or 'element', got '" + v + "'");
    options.soil_ramp = v == "element" ? lander::SoilRamp::kElement : lander::SoilRamp::kPad;
  }
  // A pad is offered a capture when it slows below either speed; a ramp above the capture speed
  // would scale the soil's force down on pads the soil is still stopping.
  if (options.soil_ramp_speed_m_s >= options.capture_speed_m_s && options.capture_speed_m_s > 0.0)
    sim.Fail("soil_ramp_speed_m_s", "must be below capture_speed_m_s (" + io::FormatNumber(options.capture_speed_m_s) +
                                        " m/s), got " + io::FormatNumber(options.soil_ramp_speed_m_s));
  // Resolution caps (the trace keeps duration x rate samples; a hand-written 1e9 must not
  // exhaust memory or run for days).
  if (options.duration_s > limits::kMaxLanderDuration_s)
    sim.Fail("duration_s", "must be at most " + io::FormatNumber(limits::kMaxLanderDuration_s) + " s, got " +
                               io::FormatNumber(options.duration_s));
  if (options.sample_rate_hz > limits::kMaxLanderSampleRate_Hz)
    sim.Fail("sample_rate_hz", "must be at most 1e6 Hz, got " + io::FormatNumber(options.sample_rate_hz));
  // The whole trace is held in memory until it is written (rft/physical_limits.h).
  if (options.duration_s * options.sample_rate_hz > limits::kMaxLanderTraceSamples)
    sim.Fail("sample_rate_hz", "duration_s x sample_rate_hz is " +
                                   io::FormatNumber(options.duration_s * options.sample_rate_hz) +
                                   " trace samples, at most " + io::FormatNumber(limits::kMaxLanderTraceSamples) +
                                   " (lower the rate or the duration)");
  if (sim.Has("rtol")) options.integrator.rtol = sim.Positive("rtol");
  if (sim.Has("atol")) {
    options.integrator.atol = sim.Positive("atol");
    options.scale_tolerances = false;
  }
  if (sim.Has("max_step_s")) options.integrator.max_step = sim.Positive("max_step_s");
  if (sim.Has("stiff")) {
    const std::string v = sim.String("stiff");
    if (v != "true" && v != "false") sim.Fail("stiff", "must be true or false, got '" + v + "'");
    options.integrator.stiff = v == "true";
  }
  std::string why;
  if (!options.integrator.IsValid(&why)) sim.Fail("rtol", why);
}
}  // namespace

const std::vector<std::string>& LanderInitialKeys() {
  static const std::vector<std::string> keys = io::Keys(InitialKeys());
  return keys;
}

namespace {

// The block `key` of `f` must be what `write` writes now.
void RequireSameBlock(const io::YamlFields& f, const std::string& key, const std::function<void(YAML::Emitter&)>& write) {
  if (!f.Has(key)) f.Fail(key, "missing (a resolved copy states it)");
  YAML::Emitter y;
  write(y);
  const std::string d = io::FirstYamlDifference(f.node()[key], YAML::Load(y.c_str()), key);
  if (!d.empty())
    f.Fail(key, "differs at " + d + " from what the files it names give now (lander, pad, soils, model)");
}

// A resolved copy's derived values (the lander's masses, pad and legs, the soils as run, the
// release position) are read back against the files they came from, on `setup` built from it.
void RequireResolvedValuesMatch(const io::YamlFields& f, const LanderScenario& s, const lander::LanderSetup& setup) {
  const std::string dir = fs::path(f.file()).parent_path().string();
  const auto file = [&](const std::string& p) { return io::PathForOutput(p, dir); };
  RequireSameBlock(f, "lander", [&](YAML::Emitter& y) { WriteLanderBlock(y, s.lander, file); });
  RequireSameBlock(f.Child("ground"), "soils", [&](YAML::Emitter& y) { WriteSoilsBlock(y, s, setup); });
  RequireSameBlock(f.Child("initial"), "release_body_com_m",
                   [&](YAML::Emitter& y) { WriteVector(y, setup.initial.p_WB, 1.0); });
}
}  // namespace

LanderScenario LoadLanderScenario(const std::string& path) {
  std::optional<lander::LanderSetup> setup;
  return LoadLanderScenarioWithSetup(path, setup);
}

LanderScenario LoadLanderScenarioWithSetup(const std::string& path, std::optional<lander::LanderSetup>& setup) {
  setup.reset();
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  const std::string type = f.String("type");
  if (type != "lander" && type != "lander_resolved")
    f.Fail("type", "must be 'lander' or 'lander_resolved', got '" + type + "'");
  const bool resolved = type == "lander_resolved";
  f.RequireOnly(resolved ? io::Keys(LanderScenarioKeys(), {"provenance"}) : io::Keys(LanderScenarioKeys(), {"source"}));
  const std::string dir = fs::path(path).parent_path().string();
  LanderScenario s;
  // A resolved copy names the scenario it was resolved from, and stands for it.
  s.source = resolved ? io::PathFromOutput(f.String("source"), dir) : path;
  s.name = f.StringOr("name", fs::path(path).stem().string());
  s.description = f.StringOr("description", "");
  s.gravity_m_s2 = f.Has("gravity_m_s2") ? io::ReadNumber(f, "gravity_m_s2", io::Sign::kPositive, &limits::kGravity_m_s2)
                                         : rft::kEarthGravity_m_s2;
  try {
    s.lander = resolved ? LoadLanderSpec(io::PathFromOutput(f.Child("lander").String("file"), dir))
                        : LoadLanderSpec(ResolveRelative(f, "landers", f.String("lander")));
  } catch (const InputError& e) {
    f.Fail("lander", e.what());
  }

  s.ground = ReadGround(f.Child("ground"), s.gravity_m_s2, resolved);
  if (resolved && f.Child("ground").Has("model")) {
    const io::YamlFields g = f.Child("ground");
    try {
      s.model = model::LoadModelFile(io::PathFromOutput(g.String("model"), dir));
    } catch (const InputError& e) {
      g.Fail("model", e.what());
    }
  }
  s.initial = ReadInitial(f.Child("initial"), resolved);
  if (s.initial.drop_height_m)  // a height and a gravity each in range can still make too fast a landing
    limits::Require(limits::kSpeed_m_s, TouchdownSpeed(s), path, "initial.drop_height_m (the touchdown speed it gives)");
  // A landing gets the deterministic work limit a sweep's landing has by default: a stiff or
  // chattering one fails (exit 3) instead of running for hours, the same on every machine.
  s.options.integrator.max_rhs_evaluations = limits::kDefaultMaxRunEvaluations;
  if (f.Has("simulation")) {
    const io::YamlFields sim = f.Child("simulation");
    ReadSimulation(sim, s.options);
    if (sim.Has("pad_rim")) {
      const std::string rim = sim.String("pad_rim");
      if (rim != "inscribed" && rim != "area_preserving")
        sim.Fail("pad_rim", "must be 'inscribed' or 'area_preserving', got '" + rim + "'");
      // The pad file's own mesh is inscribed: another rim is a re-meshing, like another count.
      if (!sim.Has("pad_angular_segments")) sim.Fail("pad_rim", "needs pad_angular_segments (the pads' re-meshing)");
      if (rim == "area_preserving") s.pad_rim = geom::RimPolygon::kAreaPreserving;
    }
    if (sim.Has("pad_angular_segments")) {
      s.pad_angular_segments = sim.PositiveInt("pad_angular_segments");
      s.pad_file_angular_segments = io::PadRimSegments(s.lander.pad);
      try {
        s.lander = LanderSpecWithPad(s.lander,
                                     io::PadWithAngularSegments(s.lander.pad, s.pad_angular_segments, s.pad_rim));
      } catch (const InputError& e) {
        sim.Fail("pad_angular_segments", e.what());
      }
    }
  }
  if (f.Has("paper")) {
    const io::YamlFields p = f.Child("paper");
    p.RequireOnly(io::Keys(PaperKeys()));
    s.paper_ground_case = p.StringOr("ground_case", "");
    if (p.Has("roll_pitch_within_deg"))
      s.paper = LanderPaperCheck{p.Positive("roll_pitch_within_deg"), p.StringOr("source", ""),
                                 p.Has("used_for_fit") && p.Bool("used_for_fit"), p.StringOr("fit_by", ""),
                                 ReadPaperReading(p)};
    const bool used = s.paper && s.paper->used_for_fit, by = p.Has("fit_by");
    if ((p.Has("used_for_fit") || by) && !s.paper) p.Fail("used_for_fit", "needs roll_pitch_within_deg (the check it marks)");
    if (p.Has("reading") && !s.paper) p.Fail("reading", "needs roll_pitch_within_deg (the check it marks)");
    if (used && !by) p.Fail("fit_by", "missing (used_for_fit: true names the fit that used it)");
    if (by && !used) p.Fail("fit_by", "only with used_for_fit: true");
  }
  if (resolved) {
    setup = ResolveLander(s);
    RequireResolvedValuesMatch(f, s, *setup);
  }
  return s;
}

namespace {
void WriteVector(YAML::Emitter& y, const Eigen::Vector3d& v, double scale) {
  y << YAML::Flow << YAML::BeginSeq << v.x() * scale << v.y() * scale << v.z() * scale << YAML::EndSeq;
}

// The resolved copy's `lander` block: the lander file and what it resolves to (masses, pad, legs).
void WriteLanderBlock(YAML::Emitter& y, const LanderSpec& l, const FileName& file) {
  y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << l.name << YAML::Key << "file" << YAML::Value
    << file(l.source) << YAML::Key << "total_mass_kg" << YAML::Value << l.total_mass_kg << YAML::Key
    << "body_mass_kg" << YAML::Value << l.body_mass_kg << YAML::Key << "cog_height_mm" << YAML::Value
    << l.cog_height_m * 1e3 << YAML::Key << "body_inertia_kg_m2" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) y << l.body_inertia_B(r, c);
  y << YAML::EndSeq << YAML::Key << "pad" << YAML::Value << YAML::BeginMap << YAML::Key << "name" << YAML::Value
    << l.pad.name << YAML::Key << "file" << YAML::Value << file(l.pad.source) << YAML::Key << "mass_kg" << YAML::Value
    << l.pad.body.mass_kg << YAML::Key << "triangles" << YAML::Value << l.pad.body.surface.size() << YAML::Key
    << "com_from_joint_mm" << YAML::Value;
  WriteVector(y, l.pad.body.com_B, 1e3);
  y << YAML::Key << "lowest_point_from_joint_mm" << YAML::Value << l.pad.body.lowest_z_B * 1e3 << YAML::EndMap;
  y << YAML::Key << "legs" << YAML::Value << YAML::BeginSeq;
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const LanderLegSpec& leg = l.legs[i];
    y << YAML::BeginMap << YAML::Key << "pad_number" << YAML::Value << i + 1 << YAML::Key << "joint_from_body_com_mm"
      << YAML::Value;
    WriteVector(y, leg.joint_B, 1e3);
    y << YAML::Key << "hip_from_body_com_mm" << YAML::Value;
    WriteVector(y, leg.hip_B, 1e3);
    if (leg.absorber) {
      y << YAML::Key << "absorber" << YAML::Value;
      WriteAbsorber(y, *leg.absorber);
    }
    if (leg.cone) {
      y << YAML::Key << "cone_limit" << YAML::Value << YAML::BeginMap;
      io::WriteFields(y, ConeFields(), *leg.cone);
      y << YAML::EndMap;
    }
    y << YAML::EndMap;
  }
  y << YAML::EndSeq << YAML::EndMap;
}

// The ground's `soils` block: every soil of the terrain as the run sees it (model applied).
void WriteSoilsBlock(YAML::Emitter& y, const LanderScenario& s, const lander::LanderSetup& setup) {
  y << YAML::BeginSeq;
  for (const rft::TerrainSoil& soil : setup.terrain.soils) {
    const rft::SoilParameters p = s.model ? model::ApplyModel(*s.model, io::LoadSoil(soil.name)) : io::LoadSoil(soil.name);
    y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "zeta_N_cm3_at_gravity"
      << YAML::Value << units::ZetaToN_cm3(p.ZetaAtGravity(s.gravity_m_s2)) << YAML::Key << "atmosphere" << YAML::Value
      << rft::AtmosphereName(p.atmosphere) << YAML::Key << "gravity_scaling" << YAML::Value
      << rft::GravityScalingName(p.gravity_scaling) << YAML::Key << "law_3d" << YAML::Value << soil.contact.name()
      << YAML::EndMap;
  }
  y << YAML::EndSeq;
}
}  // namespace

void WriteResolvedLanderScenario(const LanderScenario& s, const std::string& path, const std::string& output_dir) {
  WriteResolvedLanderScenario(s, ResolveLander(s), path, output_dir);
}

void WriteResolvedLanderScenario(const LanderScenario& s, const lander::LanderSetup& setup, const std::string& path,
                                 const std::string& output_dir) {
  const FileName file = [&](const std::string& p) { return io::PathForOutput(p, output_dir); };
  YAML::Emitter y;
  y << YAML::BeginMap;
  io::WriteKeys(y, LanderScenarioKeys(), ResolvedToWrite{s, setup, file});
  y << YAML::EndMap;
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

}  // namespace touchdown::scenario
