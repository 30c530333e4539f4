#include "drop_tests/scenario/lander_scenario.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "drop_tests/io/output_path.h"
#include "drop_tests/io/dataset_csv.h"  // io::FormatNumber
#include "drop_tests/io/field_table.h"
#include "drop_tests/scenario/lander_plots.h"
#include "drop_tests/scenario/lander_trace_columns.h"
#include "drop_tests/scenario/lander_vtk.h"
#include "drop_tests/io/paths_in_outputs.h"
#include "drop_tests/io/yaml_fields.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/pad/release.h"
#include "rft/bekker_law.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
using units::kDeg;
using units::kMm;
// Pads clockwise seen from above, pad 1 front-left (x forward, y left).
constexpr double kPadAzimuthDeg[lander::kNumLegs] = {45.0, -45.0, -135.0, 135.0};

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
  std::vector<std::string> known{"kind"};
  for (const std::string& key : io::FieldKeys(AbsorberFields(a.kind))) known.push_back(key);
  f.RequireOnly(known);
  io::ReadFields(f, AbsorberFields(a.kind), a);
  return a;
}

void WriteAbsorber(YAML::Emitter& y, const lander::ShockAbsorber& a) {
  y << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << AbsorberKindName(a.kind);
  io::WriteFields(y, AbsorberFields(a.kind), a);
  y << YAML::EndMap;
}

Eigen::Matrix3d AxisRotation(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}
}  // namespace

namespace {
// The body's mass and CoM and the legs' joints and hips from the pad and the leg layout; "" or
// "field: reason" when they do not fit.
std::string PlaceLegs(LanderSpec& s) {
  const geom::PadBody& pad = s.pad.body;
  s.body_mass_kg = s.total_mass_kg - lander::kNumLegs * pad.mass_kg;
  if (!(s.body_mass_kg > 0.0)) return "total_mass_kg: must exceed the four pads' mass";
  // Standing level on the pad bottoms: the joint centre is -lowest_z_B above the bottom, the pad
  // CoM com_B.z above the joint; the body CoM height follows from the whole lander's CoG height.
  const double joint_height = -pad.lowest_z_B;
  const double pad_com_height = joint_height + pad.com_B.z();
  const double body_com_height =
      (s.total_mass_kg * s.cog_height_m - lander::kNumLegs * pad.mass_kg * pad_com_height) / s.body_mass_kg;
  if (!(body_com_height > joint_height)) return "cog_height_mm: puts the body's centre of mass below the joints";
  if (!(s.layout.hip_height_m > joint_height)) return "hip_height_mm: must be above the ball-joint centres";
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const double az = kPadAzimuthDeg[i] * kDeg;
    const Eigen::Vector3d dir(std::cos(az), std::sin(az), 0.0);
    s.legs[i].joint_B = s.layout.joint_radius_m * dir + Eigen::Vector3d(0, 0, joint_height - body_com_height);
    s.legs[i].hip_B = s.layout.hip_radius_m * dir + Eigen::Vector3d(0, 0, s.layout.hip_height_m - body_com_height);
    s.legs[i].absorber = s.layout.absorber;
    s.legs[i].cone = s.layout.cone;
  }
  return "";
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
  if (const std::string why = PlaceLegs(s); !why.empty()) {
    const bool hips = why.starts_with("hip_height_mm");
    (hips ? legs : f).Fail(why.substr(0, why.find(':')), why.substr(why.find(':') + 2));
  }
  return s;
}

LanderSpec LanderSpecWithPad(const LanderSpec& spec, const io::PadSpec& pad) {
  LanderSpec s = spec;
  s.pad = pad;
  if (const std::string why = PlaceLegs(s); !why.empty())
    throw InputError("pad " + pad.name + " does not fit lander " + spec.name + " (its " + why + "; pad file " +
                     pad.source + ")");
  return s;
}

LanderScenario AtPadFileMesh(const LanderScenario& scenario) {
  if (scenario.pad_angular_segments == 0) return scenario;
  LanderScenario out = scenario;
  out.lander = LanderSpecWithPad(scenario.lander,
                                 io::PadWithAngularSegments(scenario.lander.pad, scenario.pad_file_angular_segments));
  out.pad_angular_segments = 0;
  out.pad_file_angular_segments = 0;
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

using SoilCheck = std::function<void(const io::YamlFields&, const std::string&, const std::string&)>;

// One soil patch; an under_pad patch keeps (pad, half width) until the release pose is known.
LanderPatchSpec ReadPatch(const io::YamlFields& p, const SoilCheck& check_soil) {
  p.RequireOnly({"name", "soil", "rectangle_m", "polygon_m", "under_pad", "half_width_m"});
  LanderPatchSpec patch;
  patch.soil = p.String("soil");
  check_soil(p, "soil", patch.soil);
  const int given = int(p.Has("rectangle_m")) + int(p.Has("polygon_m")) + int(p.Has("under_pad"));
  if (given != 1) p.Fail("rectangle_m", "give exactly one of rectangle_m, polygon_m, under_pad");
  if (p.Has("rectangle_m")) {
    const std::vector<double> r = FixedList(p, "rectangle_m", 4);
    if (!(r[2] > r[0] && r[3] > r[1])) p.Fail("rectangle_m", "must be [x0, y0, x1, y1] with x1 > x0, y1 > y0");
    patch.polygon_W = rft::RectanglePolygon(r[0], r[1], r[2], r[3]);
  } else if (p.Has("polygon_m")) {
    const YAML::Node list = p.node()["polygon_m"];
    if (!list.IsSequence() || list.size() < 3) p.Fail("polygon_m", "must list at least three [x, y] corners");
    for (size_t k = 0; k < list.size(); ++k) {
      double x = 0, y = 0;
      if (!list[k].IsSequence() || list[k].size() != 2 || !YAML::convert<double>::decode(list[k][0], x) ||
          !YAML::convert<double>::decode(list[k][1], y) || !std::isfinite(x) || !std::isfinite(y))
        p.Fail("polygon_m[" + std::to_string(k) + "]", "must be a pair of finite numbers [x, y]");
      patch.polygon_W.emplace_back(x, y);
    }
    if (const std::string problem = rft::PolygonProblem(patch.polygon_W); !problem.empty())
      p.Fail("polygon_m", "must be a simple polygon with an area: " + problem);
  } else {
    const int pad = p.PositiveInt("under_pad");
    if (pad > lander::kNumLegs) p.Fail("under_pad", "must be 1..4, got " + std::to_string(pad));
    const double h = p.Positive("half_width_m");
    patch.name = "under_pad_" + std::to_string(pad);
    patch.polygon_W = {Eigen::Vector2d(pad, h)};  // resolved below, once the initial pose is known
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
  if (resolved)
    g.RequireOnly({"height_m", "slope_deg", "downhill_azimuth_deg", "law", "soil", "soils", "model", "patches"});
  else
    g.RequireOnly({"height_m", "slope_deg", "downhill_azimuth_deg", "law", "soil", "patches", "soil_field"});
  io::ReadFields(g, GroundNumberFields(), ground);
  if (ground.slope_rad >= 80 * kDeg) g.Fail("slope_deg", "must be below 80");
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
  std::vector<std::string> known{"drop_height_m", "touchdown_speed_m_s", "release_vertical_speed_m_s",
                                 "horizontal_velocity_m_s", "roll_deg", "pitch_deg", "yaw_relative_to_slope_deg",
                                 "align_to_slope", "angular_rate_deg_s", "pad_attitude"};
  if (resolved) known.push_back("release_body_com_m");
  in.RequireOnly(known);
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
  if (std::abs(ic.roll_rad) >= 80 * kDeg) in.Fail("roll_deg", "must be within +-80");
  if (std::abs(ic.pitch_rad) >= 80 * kDeg) in.Fail("pitch_deg", "must be within +-80");
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
  ic.pad_attitude = in.StringOr("pad_attitude", "body");
  if (ic.pad_attitude != "body" && ic.pad_attitude != "level")
    in.Fail("pad_attitude", "must be 'body' or 'level', got '" + ic.pad_attitude + "'");
  return ic;
}

// The run options: duration, sampling, capture speed and the integrator's tolerances.
void ReadSimulation(const io::YamlFields& sim, lander::LanderRunOptions& options) {
  sim.RequireOnly({"duration_s", "sample_rate_hz", "capture_speed_m_s", "soil_ramp_speed_m_s", "soil_ramp", "rtol",
                   "atol", "max_step_s", "stiff", "pad_angular_segments"});
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
    sim.Fail("duration_s", "must be at most 600 s, got " + io::FormatNumber(options.duration_s));
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

namespace {
void WriteLanderBlock(YAML::Emitter& y, const LanderSpec& l, const std::function<std::string(const std::string&)>& file);
void WriteSoilsBlock(YAML::Emitter& y, const LanderScenario& s, const LanderSetup& setup);
void WriteVector(YAML::Emitter& y, const Eigen::Vector3d& v, double scale);

// Where `given` (a block of a resolved copy) differs from `expected` (that block written again
// from the files it names), as a dotted path; empty when they agree. Numbers are compared as
// written (17 digits), so equal text is equal value.
std::string FirstDifference(const YAML::Node& given, const YAML::Node& expected, const std::string& at) {
  if (given.Type() != expected.Type()) return at;
  if (given.IsScalar()) return given.Scalar() == expected.Scalar() ? "" : at;
  if (given.size() != expected.size()) return at;
  if (given.IsSequence()) {
    for (size_t i = 0; i < given.size(); ++i)
      if (std::string d = FirstDifference(given[i], expected[i], at + "[" + std::to_string(i) + "]"); !d.empty()) return d;
    return "";
  }
  for (const auto& kv : expected) {
    const std::string key = kv.first.Scalar();
    if (!given[key]) return at + "." + key;
    if (std::string d = FirstDifference(given[key], kv.second, at + "." + key); !d.empty()) return d;
  }
  return "";
}

// The block `key` of `f` must be what `write` writes now.
void RequireSameBlock(const io::YamlFields& f, const std::string& key, const std::function<void(YAML::Emitter&)>& write) {
  if (!f.Has(key)) f.Fail(key, "missing (a resolved copy states it)");
  YAML::Emitter y;
  write(y);
  const std::string d = FirstDifference(f.node()[key], YAML::Load(y.c_str()), key);
  if (!d.empty())
    f.Fail(key, "differs at " + d + " from what the files it names give now (lander, pad, soils, model)");
}

// A resolved copy's derived values (the lander's masses, pad and legs, the soils as run, the
// release position) are read back against the files they came from.
void RequireResolvedValuesMatch(const io::YamlFields& f, const LanderScenario& s) {
  const std::string dir = fs::path(f.file()).parent_path().string();
  const auto file = [&](const std::string& p) { return io::PathForOutput(p, dir); };
  RequireSameBlock(f, "lander", [&](YAML::Emitter& y) { WriteLanderBlock(y, s.lander, file); });
  const LanderSetup setup = BuildLanderSetup(s);
  RequireSameBlock(f.Child("ground"), "soils", [&](YAML::Emitter& y) { WriteSoilsBlock(y, s, setup); });
  RequireSameBlock(f.Child("initial"), "release_body_com_m",
                   [&](YAML::Emitter& y) { WriteVector(y, setup.initial.p_WB, 1.0); });
}
}  // namespace

double TouchdownSpeed(const LanderScenario& s) {
  const LanderInitialSpec& ic = s.initial;
  if (!ic.drop_height_m) return *ic.touchdown_speed_m_s;
  return std::sqrt(std::pow(ic.release_vertical_speed_m_s, 2) + 2.0 * s.gravity_m_s2 * *ic.drop_height_m);
}

LanderScenario LoadLanderScenario(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  const std::string type = f.String("type");
  if (type != "lander" && type != "lander_resolved")
    f.Fail("type", "must be 'lander' or 'lander_resolved', got '" + type + "'");
  const bool resolved = type == "lander_resolved";
  if (resolved)
    f.RequireOnly({"schema_version", "type", "name", "description", "source", "lander", "gravity_m_s2", "ground",
                   "initial", "simulation", "paper"});
  else
    f.RequireOnly({"schema_version", "type", "name", "description", "lander", "gravity_m_s2", "ground", "initial",
                   "simulation", "paper", "provenance"});
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
    if (sim.Has("pad_angular_segments")) {
      s.pad_angular_segments = sim.PositiveInt("pad_angular_segments");
      s.pad_file_angular_segments = io::PadRimSegments(s.lander.pad);
      try {
        s.lander = LanderSpecWithPad(s.lander, io::PadWithAngularSegments(s.lander.pad, s.pad_angular_segments));
      } catch (const InputError& e) {
        sim.Fail("pad_angular_segments", e.what());
      }
    }
  }
  if (f.Has("paper")) {
    const io::YamlFields p = f.Child("paper");
    p.RequireOnly({"ground_case", "roll_pitch_within_deg", "source", "used_for_fit", "fit_by", "reading"});
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
  if (resolved) RequireResolvedValuesMatch(f, s);
  return s;
}

LanderSetup BuildLanderSetup(const LanderScenario& sc) {
  LanderSetup out;
  lander::LanderModel& m = out.model;
  m.body_mass_kg = sc.lander.body_mass_kg;
  m.body_inertia_B = sc.lander.body_inertia_B;
  m.gravity_m_s2 = sc.gravity_m_s2;
  m.soil_ramp_speed_m_s = sc.options.soil_ramp_speed_m_s;
  m.soil_ramp = sc.options.soil_ramp;
  auto pad = std::make_shared<const geom::PadBody>(sc.lander.pad.body);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    m.legs[i].hip_B = sc.lander.legs[i].hip_B;
    m.legs[i].joint_B = sc.lander.legs[i].joint_B;
    m.legs[i].absorber = sc.lander.legs[i].absorber;
    m.legs[i].cone = sc.lander.legs[i].cone;
    m.legs[i].pad = pad;
  }
  lander::FinishModel(m);

  // Ground: z = h0 - tan(slope) (x cos(az) + y sin(az)).
  const double t = std::tan(sc.ground.slope_rad), az = sc.ground.downhill_azimuth_rad;
  out.terrain.surface = std::make_shared<rft::PlaneGround>(sc.ground.height_m, -t * std::cos(az), -t * std::sin(az));
  std::vector<std::string> soil_names{sc.ground.default_soil};
  auto soil_index = [&](const std::string& name) {
    for (size_t k = 0; k < soil_names.size(); ++k)
      if (soil_names[k] == name) return int(k);
    soil_names.push_back(name);
    return int(soil_names.size() - 1);
  };

  // Attitude: optional slope alignment, then heading (downhill azimuth + relative yaw), then
  // aerospace pitch (nose up, about -y) and roll (right side down, about +x).
  const LanderInitialSpec& ic = sc.initial;
  const Eigen::Vector3d downhill(std::cos(az), std::sin(az), 0.0);
  Eigen::Matrix3d R_align = Eigen::Matrix3d::Identity();
  if (ic.align_to_slope && sc.ground.slope_rad > 0.0)
    R_align = AxisRotation(Eigen::Vector3d::UnitZ().cross(downhill).normalized(), sc.ground.slope_rad);
  const Eigen::Matrix3d R_WB = R_align * AxisRotation(Eigen::Vector3d::UnitZ(), az + ic.yaw_relative_to_slope_rad) *
                               AxisRotation(Eigen::Vector3d::UnitY(), -ic.pitch_rad) *
                               AxisRotation(Eigen::Vector3d::UnitX(), ic.roll_rad);
  lander::LanderInitialState& s = out.initial;
  s.R_WB = R_WB;
  for (int i = 0; i < lander::kNumLegs; ++i) s.R_WP[i] = ic.pad_attitude == "level" ? Eigen::Matrix3d::Identity() : R_WB;
  s.w_WB_W = R_WB * ic.angular_rate_B;
  const double g = sc.gravity_m_s2;
  double clearance = 0.0, vz_down = 0.0;
  if (ic.drop_height_m) {
    clearance = *ic.drop_height_m;
    vz_down = ic.release_vertical_speed_m_s;
  } else {
    // Release just above the surface so the first pad touches at the requested speed: at most half
    // the pad's height above it (5 mm for the paper's 10 mm pad). A length of the lander's own, so
    // that a geometrically similar lander is released at the homologous height and its landing is
    // the model's scaled (docs/lander_dynamics.md, "Similitude"); a fixed length would shift the
    // touchdown point and time of one of them against its patches.
    const double v = *ic.touchdown_speed_m_s;
    const double pad_height = m.legs[0].pad->vertices_B.row(2).maxCoeff() - m.legs[0].pad->lowest_z_B;
    const double release_gap = 0.5 * pad_height;
    clearance = pad::ReleaseClearance(release_gap, v, g);
    vz_down = pad::ReleaseSpeed(v, g, clearance);
  }
  s.v_WB_W = Eigen::Vector3d(ic.horizontal_velocity_m_s.x(), ic.horizontal_velocity_m_s.y(), -vz_down);
  s.p_WB.z() = lander::BodyHeightForClearance(m, out.terrain, s, clearance);

  for (const LanderPatchSpec& p : sc.ground.patches) {
    rft::SoilPatch patch{p.name, p.polygon_W, soil_index(p.soil)};
    if (p.polygon_W.size() == 1) {  // under_pad: a square centred below that pad's joint at release
      const int leg = int(p.polygon_W[0].x()) - 1;
      const double h = p.polygon_W[0].y();
      const Eigen::Vector3d c = s.p_WB + R_WB * m.legs[leg].joint_B;
      patch.polygon_W = rft::RectanglePolygon(c.x() - h, c.y() - h, c.x() + h, c.y() + h);
    }
    out.terrain.patches.push_back(patch);
  }
  // The bekker law's b is the lander's pad's (the same pad on every leg).
  const double plate_b_m = sc.ground.law == rft::LawKind::kBekker ? rft::BekkerPlateB(sc.lander.pad.body.surface) : 0.0;
  if (sc.ground.soil_field) {
    // After the explicit patches (first match wins); cells of the default soil need no patch.
    // seed: per_landing is a study's (its landings get their seeds, sweep_drop.cpp); a plan's
    // check of the scenario builds with the file's seed (0), RunLanderScenario refuses to run it.
    const SoilFieldSpec& field = *sc.ground.soil_field;
    const std::vector<SoilFieldCell> cells = DrawSoilField(field, s.p_WB.x(), s.p_WB.y());  // n x n, row by row
    rft::SoilGrid& grid = out.terrain.grid;
    grid.nx = grid.ny = static_cast<int>(std::lround(std::sqrt(static_cast<double>(cells.size()))));
    grid.x0_m = cells.front().x0;
    grid.y0_m = cells.front().y0;
    grid.cell_m = field.cell_size_m;
    for (const SoilFieldCell& cell : cells) grid.soil.push_back(soil_index(field.soils[cell.soil]));
  }
  for (const std::string& name : soil_names)
    out.terrain.soils.push_back({name, model::MakeModelStressLaw3D(sc.ground.law, io::LoadSoil(name), g,
                                                                   sc.model ? &*sc.model : nullptr, plate_b_m)});
  return out;
}

LanderRun RunLanderScenario(const LanderScenario& scenario) {
  if (scenario.ground.soil_field && scenario.ground.soil_field->seed_per_landing)
    throw MakeInputError(scenario.source, "ground.soil_field.seed",
                         "per_landing draws a field for each landing of a study; a single landing needs a number");
  LanderRun run;
  run.scenario = scenario;
  run.setup = BuildLanderSetup(scenario);
  // A failed landing names its scenario (the integrator's message names only the failure).
  const std::string which = "lander scenario " + scenario.name + " (" + scenario.source + "): ";
  try {
    run.result = lander::SimulateLander(run.setup.model, run.setup.terrain, run.setup.initial, scenario.options);
  } catch (const integ::LimitExceeded& e) {
    throw integ::LimitExceeded(which + e.what(), e.limit(), e.value());
  } catch (const integ::IntegrationFailure& e) {
    throw integ::IntegrationFailure(which + e.what());
  }
  const lander::StateLayout L(run.setup.model);
  const lander::LanderPose pose = lander::ComputePose(run.setup.model, L, run.result.final_state);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const Eigen::Vector3d& p = pose.pads[i].p_WJ;
    run.soil_under_pad[i] = run.setup.terrain.soils[run.setup.terrain.SoilAt(p.x(), p.y())].name;
  }
  return run;
}

nlohmann::json LanderSummaryJson(const LanderRun& run) {
  const lander::LanderRunResult& r = run.result;
  auto arr = [](const std::array<double, lander::kNumLegs>& a) { return nlohmann::json(std::vector<double>(a.begin(), a.end())); };
  // JSON numbers are never null: a pad that never touched down is absent from touchdown_pads, and
  // touchdown_time_s is aligned with it; a lander never at rest has no rest times (came_to_rest false).
  nlohmann::json touchdown = nlohmann::json::array(), touchdown_pads = nlohmann::json::array();
  for (size_t i = 0; i < r.touchdown_time_s.size(); ++i)
    if (r.touchdown_time_s[i]) {
      touchdown.push_back(*r.touchdown_time_s[i]);
      touchdown_pads.push_back(i + 1);
    }
  const double final_energy = r.final_kinetic_J + r.final_potential_J + r.dissipated_J;
  const double roll = r.final_attitude.roll_rad / kDeg, pitch = r.final_attitude.pitch_rad / kDeg;
  nlohmann::json j{
      {"scenario", run.scenario.name},
      {"lander", run.scenario.lander.name},
      {"pads_order", "clockwise from above, pad 1 front-left (paper numbering)"},
      {"soil_under_pad", run.soil_under_pad},
      {"gravity_m_s2", run.scenario.gravity_m_s2},
      {"final_penetration_m", arr(r.final_penetration_m)},
      {"final_roll_deg", roll},
      {"final_pitch_deg", pitch},
      {"max_tilt_deg", r.max_tilt_rad / kDeg},
      {"max_joint_swing_deg", r.max_joint_swing_rad / kDeg},
      {"tipped_over", r.tipped_over},
      {"peak_pad_force_N", arr(r.peak_pad_force_N)},
      {"max_body_deceleration_m_s2", r.max_body_deceleration_m_s2},
      {"came_to_rest", r.rest_time_s.has_value()},
      {"touchdown_pads", touchdown_pads},
      {"touchdown_time_s", touchdown},
      {"end_time_s", r.end_time_s},
      {"initial_energy_J", r.initial_energy_J},
      {"final_kinetic_energy_J", r.final_kinetic_J},
      {"final_potential_energy_J", r.final_potential_J},
      {"dissipated_energy_J", r.dissipated_J},
      {"capture_loss_J", r.capture_loss_J},
      {"energy_balance_error_J", final_energy - r.initial_energy_J},
      {"max_held_pad_drift_m", r.max_held_drift_m},
      {"events", r.events.size()},
      {"solver_steps", r.solver.steps},
      {"rhs_evaluations", r.solver.rhs_evaluations},
  };
  if (r.rest_time_s) {
    j["rest_time_since_release_s"] = *r.rest_time_s;
    if (r.first_touchdown_s) j["time_to_rest_s"] = *r.rest_time_s - *r.first_touchdown_s;
  }
  if (r.tipped_over) {  // the support edge it went over (pads clockwise) and the direction it fell
    j["tip_over_edge_pads"] = {r.tip_over_edge + 1, (r.tip_over_edge + 1) % lander::kNumLegs + 1};
    j["tip_over_azimuth_deg"] = r.tip_over_azimuth_rad / kDeg;
  }
  j["touchdown_speed_m_s"] = TouchdownSpeed(run.scenario);
  if (run.scenario.model) j["model"] = model::ModelEffectsJson(*run.scenario.model);
  if (!run.scenario.paper_ground_case.empty()) j["paper_ground_case"] = run.scenario.paper_ground_case;
  if (run.scenario.paper) j["paper_check"] = LanderPaperCheckJson(*run.scenario.paper, roll, pitch);
  return j;
}

nlohmann::json LanderPaperCheckJson(const LanderPaperCheck& check, double roll_deg, double pitch_deg) {
  const double within = check.roll_pitch_within_deg;
  nlohmann::json j{{"quantity", "final roll and pitch"},
                   {"paper_within_deg", within},
                   {"simulated_roll_deg", roll_deg},
                   {"simulated_pitch_deg", pitch_deg},
                   {"within_paper_band", std::abs(roll_deg) <= within && std::abs(pitch_deg) <= within},
                   {"source", check.source},
                   {"used_for_fit", check.used_for_fit}};
  if (check.used_for_fit) j["fit_by"] = check.fit_by;
  if (check.reading) j["reading"] = std::string(PaperReadingName(*check.reading));
  return j;
}

void WriteLanderTraceCsv(const LanderRun& run, const std::string& path) {
  const std::vector<LanderTraceColumn>& columns = LanderTraceColumns();
  io::WriteFileAtomically(path, [&](std::ostream& out) {
    for (size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].name;
    out << '\n' << std::setprecision(10);
    for (const lander::LanderSample& s : run.result.trace) {
      for (size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].value(s);
      out << '\n';
    }
  });
}

namespace {
using FileName = std::function<std::string(const std::string&)>;

void WriteVector(YAML::Emitter& y, const Eigen::Vector3d& v, double scale) {
  y << YAML::Flow << YAML::BeginSeq << v.x() * scale << v.y() * scale << v.z() * scale << YAML::EndSeq;
}

// The resolved copy's `lander` block: the lander file and what it resolves to (masses, pad, legs).
void WriteLanderBlock(YAML::Emitter& y, const LanderSpec& l, const std::function<std::string(const std::string&)>& file) {
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
void WriteSoilsBlock(YAML::Emitter& y, const LanderScenario& s, const LanderSetup& setup) {
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
  const FileName file = [&](const std::string& p) { return io::PathForOutput(p, output_dir); };
  YAML::Emitter y;
  y << YAML::BeginMap << YAML::Key << "schema_version" << YAML::Value << 1 << YAML::Key << "type" << YAML::Value
    << "lander_resolved" << YAML::Key << "name" << YAML::Value << s.name;
  if (!s.description.empty()) y << YAML::Key << "description" << YAML::Value << s.description;
  y << YAML::Key << "source" << YAML::Value << file(s.source) << YAML::Key << "gravity_m_s2" << YAML::Value
    << s.gravity_m_s2;
  y << YAML::Key << "lander" << YAML::Value;
  WriteLanderBlock(y, s.lander, file);
  y << YAML::Key << "ground" << YAML::Value << YAML::BeginMap;
  io::WriteFields(y, GroundNumberFields(), s.ground);
  y << YAML::Key << "law" << YAML::Value << std::string(rft::LawKindName(s.ground.law)) << YAML::Key << "soil" << YAML::Value << s.ground.default_soil;
  const LanderSetup setup = BuildLanderSetup(s);
  y << YAML::Key << "soils" << YAML::Value;
  WriteSoilsBlock(y, s, setup);
  if (s.model) y << YAML::Key << "model" << YAML::Value << file(s.model->source);
  y << YAML::Key << "patches" << YAML::Value << YAML::BeginSeq;
  auto write_patch = [&](const rft::SoilPatch& p) {
    y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "soil" << YAML::Value
      << setup.terrain.soils[p.soil].name << YAML::Key << "polygon_m" << YAML::Value << YAML::BeginSeq;
    for (const Eigen::Vector2d& c : p.polygon_W) y << YAML::Flow << YAML::BeginSeq << c.x() << c.y() << YAML::EndSeq;
    y << YAML::EndSeq << YAML::EndMap;
  };
  for (const rft::SoilPatch& p : setup.terrain.patches) write_patch(p);
  // A patch field's cells of another soil than the default, as patches: the resolved copy reads
  // back to the same ground.
  const rft::SoilGrid& grid = setup.terrain.grid;
  for (int k = 0; k < grid.nx * grid.ny; ++k) {
    if (grid.soil[k] == 0) continue;
    const double x0 = grid.x0_m + (k % grid.nx) * grid.cell_m, y0 = grid.y0_m + (k / grid.nx) * grid.cell_m;
    write_patch({"soil_field_" + std::to_string(k + 1), rft::RectanglePolygon(x0, y0, x0 + grid.cell_m, y0 + grid.cell_m),
                 grid.soil[k]});
  }
  y << YAML::EndSeq << YAML::EndMap;
  const LanderInitialSpec& ic = s.initial;
  y << YAML::Key << "initial" << YAML::Value << YAML::BeginMap;
  if (ic.drop_height_m)
    y << YAML::Key << "drop_height_m" << YAML::Value << *ic.drop_height_m << YAML::Key << "release_vertical_speed_m_s"
      << YAML::Value << ic.release_vertical_speed_m_s;
  else
    y << YAML::Key << "touchdown_speed_m_s" << YAML::Value << *ic.touchdown_speed_m_s;
  y << YAML::Key << "horizontal_velocity_m_s" << YAML::Value << YAML::Flow << YAML::BeginSeq
    << ic.horizontal_velocity_m_s.x() << ic.horizontal_velocity_m_s.y() << YAML::EndSeq;
  io::WriteFields(y, AttitudeNumberFields(), ic);
  y << YAML::Key << "align_to_slope" << YAML::Value << ic.align_to_slope << YAML::Key << "angular_rate_deg_s"
    << YAML::Value;
  WriteVector(y, ic.angular_rate_B, 1.0 / kDeg);
  y << YAML::Key << "pad_attitude" << YAML::Value << ic.pad_attitude << YAML::Key << "release_body_com_m" << YAML::Value;
  WriteVector(y, setup.initial.p_WB, 1.0);
  y << YAML::EndMap;
  y << YAML::Key << "simulation" << YAML::Value << YAML::BeginMap;
  io::WriteFields(y, RunNumberFields(), s.options);
  y << YAML::Key << "rtol" << YAML::Value << s.options.integrator.rtol;
  // Without `atol` the absolute tolerances are rtol times each state's scale (lander_simulation.h).
  if (!s.options.scale_tolerances) y << YAML::Key << "atol" << YAML::Value << s.options.integrator.atol;
  if (s.options.integrator.max_step != lander::LanderRunOptions{}.integrator.max_step) y << YAML::Key << "max_step_s" << YAML::Value << s.options.integrator.max_step;
  y << YAML::Key << "stiff" << YAML::Value << s.options.integrator.stiff;
  if (s.options.soil_ramp != lander::LanderRunOptions{}.soil_ramp)
    y << YAML::Key << "soil_ramp" << YAML::Value << (s.options.soil_ramp == lander::SoilRamp::kElement ? "element" : "pad");
  if (s.pad_angular_segments > 0) y << YAML::Key << "pad_angular_segments" << YAML::Value << s.pad_angular_segments;
  y << YAML::EndMap;
  if (!s.paper_ground_case.empty() || s.paper) {
    y << YAML::Key << "paper" << YAML::Value << YAML::BeginMap;
    if (!s.paper_ground_case.empty()) y << YAML::Key << "ground_case" << YAML::Value << s.paper_ground_case;
    if (s.paper) {
      y << YAML::Key << "roll_pitch_within_deg" << YAML::Value << s.paper->roll_pitch_within_deg;
      if (!s.paper->source.empty()) y << YAML::Key << "source" << YAML::Value << s.paper->source;
      if (s.paper->used_for_fit)
        y << YAML::Key << "used_for_fit" << YAML::Value << true << YAML::Key << "fit_by" << YAML::Value << s.paper->fit_by;
      if (s.paper->reading) y << YAML::Key << "reading" << YAML::Value << std::string(PaperReadingName(*s.paper->reading));
    }
    y << YAML::EndMap;
  }
  y << YAML::EndMap;
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

void WriteLanderOutputs(const LanderRun& run, const io::OutputTarget& out, const LanderOutputOptions& options) {
  io::WriteOutputDirectory(out, io::OutputKind::kLander, [&](const std::string& staging_dir) {
    const fs::path staging = staging_dir;
    WriteLanderTraceCsv(run, (staging / "trace.csv").string());
    io::WriteFileAtomically((staging / "events.csv").string(), [&](std::ostream& out) {
      out << "t_s,event,pad\n" << std::setprecision(12);
      for (const lander::LanderEvent& e : run.result.events)
        out << e.t_s << ',' << lander::LanderEventName(e.kind) << ',' << (e.leg >= 0 ? std::to_string(e.leg + 1) : std::string()) << '\n';
    });
    io::WriteFileAtomically((staging / "summary.json").string(),
                        [&](std::ostream& out) { out << LanderSummaryJson(run).dump(2) << '\n'; });
    WriteResolvedLanderScenario(run.scenario, (staging / "scenario_resolved.yaml").string(), out.path);
    WriteLanderPlots(run, staging.string());
    if (options.vtk) WriteLanderVtk(run, (staging / "vtk").string());
  });
}

}  // namespace touchdown::scenario
