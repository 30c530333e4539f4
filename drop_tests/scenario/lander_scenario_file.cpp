#include "drop_tests/scenario/lander_scenario_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <variant>

#include "drop_tests/formats/dataset_csv.h"  // io::FormatNumber
#include "drop_tests/formats/output_path.h"
#include "drop_tests/catalog/paths_in_outputs.h"
#include "drop_tests/formats/yaml_diff.h"
#include "drop_tests/scenario/lander_scenario_yaml.h"
#include "drop_tests/scenario/lander_setup.h"
#include "drop_tests/model/model_file.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

// The lander scenario file (type: lander) and its resolved copy (type: lander_resolved).
namespace touchdown::scenario {

namespace fs = std::filesystem;

const char* PadAttitudeName(PadAttitude attitude) { return NameIn(kPadAttitudeNames, attitude); }

namespace {
using namespace file_yaml;
using units::kDeg;

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
    const double h = io::ReadNumber(p, kPatchHalfWidthKey);
    patch.name = "under_pad_" + std::to_string(pad);
    patch.area = UnderPadSquare{pad, h};  // placed by ResolveLander, once the release pose is known
  }
  if (p.Has("name")) patch.name = p.Name("name");
  return patch;
}

// `ground.soil_field` (soil_field.h): soils checked like any patch's, probabilities summing to 1,
// at most 400 cells a side.
const std::vector<std::string> kSoilFieldKeys{"soils", "probabilities", "cell_size_m", "half_extent_m", "seed"};
SoilFieldSpec ReadSoilField(const io::YamlFields& f, const SoilCheck& check_soil) {
  f.RequireOnly(kSoilFieldKeys);
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
  field.cell_size_m = io::ReadNumber(f, kCellSizeKey);
  field.half_extent_m = io::ReadNumber(f, kHalfExtentKey);
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

// `ground.terrain` (lander_terrain.h): the raster's path relative to the scenario's folder (or
// $TOUCHDOWN_DATA_DIR/...), an optional window [x_min, y_min, x_max, y_max] and origin [x, y] in the
// raster's coordinates.
TerrainFileSpec ReadTerrain(const io::YamlFields& t) {
  t.RequireOnly(kTerrainKeys);
  TerrainFileSpec terrain;
  terrain.file = io::PathFromOutput(t.String("file"), fs::path(t.file()).parent_path().string());
  if (t.Has("window_m")) {
    const std::vector<double> w = FixedList(t, "window_m", 4);
    if (!(w[0] < w[2] && w[1] < w[3]))
      t.Fail("window_m", "must be [x_min, y_min, x_max, y_max] with x_min < x_max and y_min < y_max");
    terrain.window = io::RasterWindow{w[0], w[1], w[2], w[3]};
  }
  if (t.Has("origin_m")) {
    const std::vector<double> o = FixedList(t, "origin_m", 2);
    terrain.origin_m = Eigen::Vector2d(o[0], o[1]);
  }
  return terrain;
}

// `ground.craters` (lander_terrain.h, rft/crater_population.h): the grid's size only without a
// terrain file (with one, the craters go onto its grid); at most 5001 nodes a side.
CraterFieldSpec ReadCraters(const io::YamlFields& c, bool on_terrain) {
  c.RequireOnly(io::FieldKeys(CraterFields()));
  CraterFieldSpec craters;
  io::ReadFields(c, CraterFields(), craters);
  if (!(craters.seed <= 9.0e15 && craters.seed == std::floor(craters.seed)))
    c.Fail("seed", "must be a whole number from 0 to 9e15");
  if (!(craters.min_diameter_m < craters.max_diameter_m))
    c.Fail("max_diameter_m", "must be above min_diameter_m (" + io::FormatNumber(craters.min_diameter_m) + " m)");
  if (!(craters.degradation_min <= craters.degradation_max && craters.degradation_max < 1.0))
    c.Fail("degradation_max", "must satisfy degradation_min <= degradation_max < 1");
  for (const char* key : {"cell_size_m", "half_extent_m"}) {
    if (on_terrain && c.Has(key)) c.Fail(key, "only without a terrain file (the craters go onto its grid)");
    if (!on_terrain && !c.Has(key)) c.Fail(key, "missing (the craters' grid without a terrain file)");
  }
  if (!on_terrain && !(craters.half_extent_m / craters.cell_size_m <= 2500.0))
    c.Fail("half_extent_m", "makes more than 5001 nodes a side (half_extent_m / cell_size_m at most 2500)");
  return craters;
}

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
  // Each soil read once, kept in the ground (LanderGroundSpec::soils).
  const auto soil_of = [&](const std::string& ref) -> const rft::SoilParameters& {
    auto it = ground.soils.find(ref);
    if (it == ground.soils.end()) it = ground.soils.emplace(ref, io::LoadSoil(ref)).first;
    return it->second;
  };
  try {
    // No `law`: the default soil's own (li2013 for every RFT soil file, bekker for a Bekker soil).
    ground.law = g.Has("law") ? rft::ParseLawKind(g.String("law"), "", "") : soil_of(ground.default_soil).rft_law_3d;
  } catch (const InputError& e) {
    g.Fail(g.Has("law") ? "law" : "soil", e.what());
  }
  const SoilCheck check_soil = [&](const io::YamlFields& where, const std::string& key, const std::string& soil) {
    try {
      rft::CheckSoilTakesLaw(ground.law, soil_of(soil), gravity_m_s2);
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
  // The height field, built once here for every landing of the scenario (lander_terrain.h).
  LanderHeightField& field = ground.height_field;
  if (g.Has("terrain")) field.terrain = ReadTerrain(g.Child("terrain"));
  if (g.Has("craters")) field.craters = ReadCraters(g.Child("craters"), field.terrain.has_value());
  if (field.terrain && (ground.slope_rad != 0.0 || ground.downhill_azimuth_rad != 0.0))
    g.Fail(ground.slope_rad != 0.0 ? "slope_deg" : "downhill_azimuth_deg",
           "only without a terrain file (the terrain gives the slopes)");
  if (field.has_height_field()) {
    const double t = std::tan(ground.slope_rad), az = ground.downhill_azimuth_rad;
    field.built_for = {ground.height_m, -t * std::cos(az), -t * std::sin(az)};
    try {
      field.surface = BuildHeightField(field, field.built_for[0], field.built_for[1], field.built_for[2], g.file());
    } catch (const InputError& e) {
      g.Fail(field.terrain ? "terrain" : "craters", e.what());
    }
  }
  return ground;
}

// The release: drop height or touchdown speed, velocities, attitude and the pads' attitude.
// A resolved copy's release also states the body's position (checked by the caller).
LanderInitialSpec ReadInitial(const io::YamlFields& in, bool resolved) {
  LanderInitialSpec ic;
  in.RequireOnly(resolved ? io::Keys(InitialKeys()) : io::Keys(InitialKeys(), {kReleaseBodyComKey}));
  if (in.Has(kDropHeightKey.key) == in.Has(kTouchdownSpeedKey.key))
    in.Fail("drop_height_m", "give exactly one of drop_height_m and touchdown_speed_m_s");
  if (in.Has(kDropHeightKey.key)) ic.drop_height_m = io::ReadNumber(in, kDropHeightKey);
  if (in.Has(kTouchdownSpeedKey.key)) ic.touchdown_speed_m_s = io::ReadNumber(in, kTouchdownSpeedKey);
  if (in.Has(kReleaseVerticalSpeedKey.key)) {
    if (!in.Has(kDropHeightKey.key)) in.Fail("release_vertical_speed_m_s", "only with drop_height_m");
    ic.release_vertical_speed_m_s = io::ReadNumber(in, kReleaseVerticalSpeedKey);
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
  if (in.Has("align_to_slope")) ic.align_to_slope = in.Bool("align_to_slope");
  if (in.Has("angular_rate_deg_s")) {
    const std::vector<double> w = FixedList(in, "angular_rate_deg_s", 3);
    for (size_t k = 0; k < w.size(); ++k)
      limits::Require(limits::kAngularRate_deg_s, w[k], in.file(),
                      in.Path("angular_rate_deg_s") + "[" + std::to_string(k) + "]");
    ic.angular_rate_B = Eigen::Vector3d(w[0], w[1], w[2]) * kDeg;
  }
  const std::string attitude = in.StringOr("pad_attitude", PadAttitudeName(PadAttitude::kBody));
  if (const std::optional<PadAttitude> a = FindName(kPadAttitudeNames, attitude))
    ic.pad_attitude = *a;
  else
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
  if (sim.Has("max_evaluations")) {
    const double n = sim.Positive("max_evaluations");
    if (n != std::floor(n) || n > limits::kMaxRunEvaluations)
      sim.Fail("max_evaluations", "must be a whole number of right-hand-side evaluations from 1 to " +
                                      io::FormatNumber(limits::kMaxRunEvaluations) + ", got " + io::FormatNumber(n));
    options.integrator.max_rhs_evaluations = static_cast<long>(n);
  }
  if (sim.Has("rtol")) options.integrator.rtol = sim.Positive("rtol");
  if (sim.Has("atol")) {
    options.integrator.atol = sim.Positive("atol");
    options.scale_tolerances = false;
    // One scalar for every state has no per-state scale for the factor to multiply.
    if (sim.Has("pad_spin_tolerance_factor"))
      sim.Fail("pad_spin_tolerance_factor", "needs the scaled tolerances: give rtol only, not atol");
  }
  if (sim.Has(kMaxStepKey.key)) options.integrator.max_step = io::ReadNumber(sim, kMaxStepKey);
  if (sim.Has("stiff")) options.integrator.stiff = sim.Bool("stiff");
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

std::vector<io::BlockDoc> LanderScenarioSchema() {
  const std::string read_by = "drop_tests/scenario/lander_scenario_file.cpp";
  return {io::MakeBlock("lander_scenario", read_by, io::DocsOf(LanderScenarioKeys(), {"source"})),
          io::MakeBlock("lander_scenario.ground", read_by, io::DocsOf(GroundKeys(), {"soils", "model"})),
          io::MakeBlock("lander_scenario.ground.patches", read_by, io::DocsOf(PatchKeys())),
          io::MakeBlock("lander_scenario.ground.soil_field", read_by,
                        io::DocsWith(kSoilFieldKeys, {kCellSizeKey, kHalfExtentKey})),
          io::MakeBlock("lander_scenario.ground.terrain", read_by, io::PlainKeyDocs(kTerrainKeys)),
          io::MakeBlock("lander_scenario.ground.craters", read_by, io::DocsOf(CraterFields())),
          io::MakeBlock("lander_scenario.initial", read_by, io::DocsOf(InitialKeys(), {kReleaseBodyComKey})),
          io::MakeBlock("lander_scenario.simulation", read_by, io::DocsOf(SimulationKeys())),
          io::MakeBlock("lander_scenario.paper", read_by, io::DocsOf(PaperKeys()))};
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
  s.name = f.Name("name", fs::path(path).stem().string());
  s.description = f.StringOr("description", "");
  s.gravity_m_s2 = io::ReadNumberOr(f, kScenarioGravityKey, rft::kEarthGravity_m_s2);
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
    if (p.Has(kRollPitchWithinKey.key))
      s.paper = LanderPaperCheck{io::ReadNumber(p, kRollPitchWithinKey), p.StringOr("source", ""),
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

void WriteResolvedLanderScenario(const LanderScenario& s, const std::string& path, const std::string& output_dir) {
  WriteResolvedLanderScenario(s, ResolveLander(s), path, output_dir);
}

void WriteResolvedLanderScenario(const LanderScenario& s, const lander::LanderSetup& setup, const std::string& path,
                                 const std::string& output_dir) {
  const FileName file = [&](const std::string& p) { return io::PathForOutput(p, output_dir); };
  YAML::Emitter y;
  io::WriteMap(y, LanderScenarioKeys(), ResolvedToWrite{s, setup, file});
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

void WriteResolvedLander(const LanderSpec& lander, const std::string& path, const std::string& output_dir) {
  const FileName file = [&](const std::string& p) { return io::PathForOutput(p, output_dir); };
  YAML::Emitter y;
  WriteLanderBlock(y, lander, file);
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

}  // namespace touchdown::scenario
