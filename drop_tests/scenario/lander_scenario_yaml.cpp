#include "drop_tests/scenario/lander_scenario_yaml.h"

#include <cmath>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/catalog/paths_in_outputs.h"
#include "drop_tests/model/model_file.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::scenario::file_yaml {

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

const char* AbsorberKindName(lander::ShockAbsorber::Kind kind) { return NameIn(kAbsorberKindNames, kind); }

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

void WriteAbsorber(YAML::Emitter& y, const lander::ShockAbsorber& a) {
  io::WriteMap(y, AbsorberKeys(a.kind), a);
}

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

const io::FieldTable<CraterFieldSpec>& CraterFields() {
  using C = CraterFieldSpec;
  using io::Sign;
  static const io::FieldTable<C> fields{
      {"cumulative_per_m2", &C::cumulative_per_m2, 1.0, Sign::kNonNegative, false},
      {"exponent", &C::exponent, 1.0, Sign::kPositive},
      {"min_diameter_m", &C::min_diameter_m, 1.0, Sign::kPositive, false},
      {"max_diameter_m", &C::max_diameter_m, 1.0, Sign::kPositive, false},
      {"degradation_min", &C::degradation_min, 1.0, Sign::kNonNegative},
      {"degradation_max", &C::degradation_max, 1.0, Sign::kNonNegative},
      {"cell_size_m", &C::cell_size_m, 1.0, Sign::kPositive, true, true, nullptr, "without `terrain`: *required*"},
      {"half_extent_m", &C::half_extent_m, 1.0, Sign::kPositive, true, true, nullptr, "without `terrain`: *required*"},
      {"seed", &C::seed, 1.0, Sign::kNonNegative, false},
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
      {"pad_spin_tolerance_factor", &R::pad_spin_tolerance_factor, 1.0, io::Sign::kPositive, true, true,
       &limits::kPadSpinToleranceFactor},
  };
  return fields;
}

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
      {kPatchHalfWidthKey.key, {}, {}, io::DocOf(kPatchHalfWidthKey)},
  };
  return keys;
}

namespace {
void WritePatch(YAML::Emitter& y, const rft::SoilPatch& patch, const std::string& soil) {
  io::WriteMap(y, PatchKeys(), PatchToWrite{patch, soil});
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
}  // namespace

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
    k.push_back({"terrain", [](const W& w) { return w.s.ground.height_field.terrain.has_value(); },
                 [](Y& y, const W& w) {
                   const TerrainFileSpec& t = *w.s.ground.height_field.terrain;
                   y << YAML::BeginMap << YAML::Key << "file" << YAML::Value << w.file(t.file);
                   if (t.window)
                     y << YAML::Key << "window_m" << YAML::Value << YAML::Flow << YAML::BeginSeq << t.window->x_min_m
                       << t.window->y_min_m << t.window->x_max_m << t.window->y_max_m << YAML::EndSeq;
                   if (t.origin_m)
                     y << YAML::Key << "origin_m" << YAML::Value << YAML::Flow << YAML::BeginSeq << t.origin_m->x()
                       << t.origin_m->y() << YAML::EndSeq;
                   y << YAML::EndMap;
                 }});
    k.push_back({"craters", [](const W& w) { return w.s.ground.height_field.craters.has_value(); },
                 [](Y& y, const W& w) {
                   y << YAML::BeginMap;
                   io::WriteFields(y, CraterFields(), *w.s.ground.height_field.craters);
                   y << YAML::EndMap;
                 }});
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
        {kDropHeightKey.key, from_height, [](Y& y, const W& w) { y << *w.s.initial.drop_height_m; },
         io::DocOf(kDropHeightKey)},
        {kReleaseVerticalSpeedKey.key, from_height,
         [](Y& y, const W& w) { y << w.s.initial.release_vertical_speed_m_s; }, io::DocOf(kReleaseVerticalSpeedKey)},
        {kTouchdownSpeedKey.key, [](const W& w) { return w.s.initial.touchdown_speed_m_s.has_value(); },
         [](Y& y, const W& w) { y << *w.s.initial.touchdown_speed_m_s; }, io::DocOf(kTouchdownSpeedKey)},
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
    k.push_back({"max_evaluations",
                 [](const W& w) { return w.s.options.integrator.max_rhs_evaluations != limits::kDefaultMaxRunEvaluations; },
                 [](Y& y, const W& w) { y << w.s.options.integrator.max_rhs_evaluations; }});
    k.push_back({"rtol", io::Always<W>, [](Y& y, const W& w) { y << w.s.options.integrator.rtol; }});
    // Without `atol` the absolute tolerances are rtol times each state's scale (lander_simulation.h).
    k.push_back({"atol", [](const W& w) { return !w.s.options.scale_tolerances; },
                 [](Y& y, const W& w) { y << w.s.options.integrator.atol; }});
    k.push_back({kMaxStepKey.key, [](const W& w) { return w.s.options.integrator.max_step != R{}.integrator.max_step; },
                 [](Y& y, const W& w) { y << w.s.options.integrator.max_step; }, io::DocOf(kMaxStepKey)});
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
      {kRollPitchWithinKey.key, check, [](Y& y, const W& w) { y << w.s.paper->roll_pitch_within_deg; },
       io::DocOf(kRollPitchWithinKey)},
      {"source", [](const W& w) { return w.s.paper && !w.s.paper->source.empty(); },
       [](Y& y, const W& w) { y << w.s.paper->source; }},
      {"used_for_fit", fitted, [](Y& y, const W&) { y << true; }},
      {"fit_by", fitted, [](Y& y, const W& w) { y << w.s.paper->fit_by; }},
      {"reading", [](const W& w) { return w.s.paper && w.s.paper->reading.has_value(); },
       [](Y& y, const W& w) { y << std::string(PaperReadingName(*w.s.paper->reading)); }},
  };
  return keys;
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
      {kScenarioGravityKey.key, io::Always<W>, [](Y& y, const W& w) { y << w.s.gravity_m_s2; },
       io::DocOf(kScenarioGravityKey)},
      {"lander", io::Always<W>, [](Y& y, const W& w) { WriteLanderBlock(y, w.s.lander, w.file); }},
      {"ground", io::Always<W>, io::MapOf(GroundKeys)},
      {"initial", io::Always<W>, io::MapOf(InitialKeys)},
      {"simulation", io::Always<W>, io::MapOf(SimulationKeys)},
      {"paper", [](const W& w) { return !w.s.paper_ground_case.empty() || w.s.paper.has_value(); }, io::MapOf(PaperKeys)},
      {"provenance"},
  };
  return keys;
}

void WriteVector(YAML::Emitter& y, const Eigen::Vector3d& v, double scale) {
  y << YAML::Flow << YAML::BeginSeq << v.x() * scale << v.y() * scale << v.z() * scale << YAML::EndSeq;
}

// The resolved copy's `lander` block: the lander file and what it resolves to (masses, pad, legs).
void WriteLanderBlock(YAML::Emitter& y, const LanderSpec& l, const FileName& file) {
  y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << l.name << YAML::Key << "file" << YAML::Value
    << file(l.source) << YAML::Key << "total_mass_kg" << YAML::Value << l.total_mass_kg << YAML::Key
    << "body_mass_kg" << YAML::Value << l.body_mass_kg << YAML::Key << "cog_height_mm" << YAML::Value
    << l.cog_height_m * units::kMmPerM << YAML::Key << "body_inertia_kg_m2" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) y << l.body_inertia_B(r, c);
  y << YAML::EndSeq << YAML::Key << "pad" << YAML::Value << YAML::BeginMap << YAML::Key << "name" << YAML::Value
    << l.pad.name << YAML::Key << "file" << YAML::Value << file(l.pad.source) << YAML::Key << "mass_kg" << YAML::Value
    << l.pad.body.mass_kg << YAML::Key << "triangles" << YAML::Value << l.pad.body.surface.size() << YAML::Key
    << "com_from_joint_mm" << YAML::Value;
  WriteVector(y, l.pad.body.com_B, units::kMmPerM);
  y << YAML::Key << "lowest_point_from_joint_mm" << YAML::Value << l.pad.body.lowest_z_B * units::kMmPerM << YAML::EndMap;
  y << YAML::Key << "legs" << YAML::Value << YAML::BeginSeq;
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const LanderLegSpec& leg = l.legs[i];
    y << YAML::BeginMap << YAML::Key << "pad_number" << YAML::Value << i + 1 << YAML::Key << "joint_from_body_com_mm"
      << YAML::Value;
    WriteVector(y, leg.joint_B, units::kMmPerM);
    y << YAML::Key << "hip_from_body_com_mm" << YAML::Value;
    WriteVector(y, leg.hip_B, units::kMmPerM);
    if (leg.absorber) {
      y << YAML::Key << "absorber" << YAML::Value;
      WriteAbsorber(y, *leg.absorber);
    }
    if (std::isfinite(leg.load_limit_N)) y << YAML::Key << "load_limit_N" << YAML::Value << leg.load_limit_N;
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
    const auto loaded = s.ground.soils.find(soil.name);  // as the scenario read it, else its file
    const rft::SoilParameters file_soil = loaded != s.ground.soils.end() ? loaded->second : io::LoadSoil(soil.name);
    const rft::SoilParameters p = s.model ? model::ApplyModel(*s.model, file_soil) : file_soil;
    y << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "zeta_N_cm3_at_gravity"
      << YAML::Value << units::ZetaToN_cm3(p.ZetaAtGravity(s.gravity_m_s2)) << YAML::Key << "atmosphere" << YAML::Value
      << rft::AtmosphereName(p.atmosphere) << YAML::Key << "gravity_scaling" << YAML::Value
      << rft::GravityScalingName(p.gravity_scaling) << YAML::Key << "law_3d" << YAML::Value << soil.contact.name()
      << YAML::EndMap;
  }
  y << YAML::EndSeq;
}

}  // namespace touchdown::scenario::file_yaml
