#include "drop_tests/scenario/lander_setup.h"

#include <cmath>
#include <memory>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/contact_model.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/multibody/lander_simulation.h"
#include "lander/pad/release.h"
#include "rft/bekker_law.h"
#include "rft/input_error.h"

namespace touchdown::scenario {

namespace {
Eigen::Matrix3d AxisRotation(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

// The soil `name` refers to: from the catalogue when it holds it, else as the scenario's ground
// read it, else from its file (a ground built in memory).
rft::SoilParameters SoilFor(const std::string& name, const LanderSoilCatalog* soils, const LanderGroundSpec& ground) {
  if (soils)
    if (const auto it = soils->find(name); it != soils->end()) return it->second;
  if (const auto it = ground.soils.find(name); it != ground.soils.end()) return it->second;
  return io::LoadSoil(name);
}
}  // namespace

LanderSoilCatalog LoadLanderSoils(const LanderScenario& sc, const std::vector<std::string>& more) {
  std::vector<std::string> refs{sc.ground.default_soil};
  for (const LanderPatchSpec& p : sc.ground.patches) refs.push_back(p.soil);
  if (sc.ground.soil_field) refs.insert(refs.end(), sc.ground.soil_field->soils.begin(), sc.ground.soil_field->soils.end());
  refs.insert(refs.end(), more.begin(), more.end());
  LanderSoilCatalog out;
  for (const std::string& ref : refs)
    if (!out.count(ref)) out.emplace(ref, SoilFor(ref, nullptr, sc.ground));
  return out;
}

double TouchdownSpeed(const LanderScenario& s) {
  const LanderInitialSpec& ic = s.initial;
  if (!ic.drop_height_m) return *ic.touchdown_speed_m_s;
  return pad::TouchdownSpeed(ic.release_vertical_speed_m_s, s.gravity_m_s2, *ic.drop_height_m);
}

lander::LanderModel BuildLanderModel(const LanderScenario& sc) {
  lander::LanderModel m;
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
  return m;
}

lander::LanderSetup ResolveLander(const LanderScenario& sc, const LanderSoilCatalog* soils) {
  lander::LanderSetup out;
  out.model = BuildLanderModel(sc);
  out.options = sc.options;
  const lander::LanderModel& m = out.model;

  // Ground: z = h0 - tan(slope) (x cos(az) + y sin(az)), or the scenario's height field.
  const double t = std::tan(sc.ground.slope_rad), az = sc.ground.downhill_azimuth_rad;
  out.terrain.surface =
      GroundSurfaceOf(sc.ground.height_field, sc.ground.height_m, -t * std::cos(az), -t * std::sin(az), sc.source);
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
  for (int i = 0; i < lander::kNumLegs; ++i) s.R_WP[i] = ic.pad_attitude == PadAttitude::kLevel ? Eigen::Matrix3d::Identity() : R_WB;
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
  if (sc.ground.height_field.has_height_field()) {  // every pad starts over the field, a pad's width inside
    std::vector<Eigen::Vector2d> joints_W;
    for (int i = 0; i < lander::kNumLegs; ++i) joints_W.push_back((s.p_WB + R_WB * m.legs[i].joint_B).head<2>());
    const double pad_reach = m.legs[0].pad->vertices_B.topRows<2>().colwise().norm().maxCoeff();
    RequireOnHeightField(sc.ground.height_field, *out.terrain.surface, joints_W, pad_reach, sc.source);
  }

  for (const LanderPatchSpec& p : sc.ground.patches) {
    rft::SoilPatch patch{p.name, {}, soil_index(p.soil)};
    if (const auto* square = std::get_if<UnderPadSquare>(&p.area)) {  // centred below that pad's joint at release
      const double h = square->half_width_m;
      const Eigen::Vector3d c = s.p_WB + R_WB * m.legs[square->pad_number - 1].joint_B;
      patch.polygon_W = rft::RectanglePolygon(c.x() - h, c.y() - h, c.x() + h, c.y() + h);
    } else {
      patch.polygon_W = std::get<std::vector<Eigen::Vector2d>>(p.area);
    }
    out.terrain.patches.push_back(patch);
  }
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
    out.terrain.soils.push_back({name, model::MakeContactModel({.law = sc.ground.law, .soil = SoilFor(name, soils, sc.ground),
                                                                .gravity_m_s2 = g, .model = sc.model ? &*sc.model : nullptr,
                                                                .pad_surface = &sc.lander.pad.body.surface})});  // one pad on every leg
  return out;
}

LanderRun RunLanderScenario(const LanderScenario& scenario) {
  if (scenario.ground.soil_field && scenario.ground.soil_field->seed_per_landing)
    throw MakeInputError(scenario.source, "ground.soil_field.seed",
                         "per_landing draws a field for each landing of a study; a single landing needs a number");
  return RunLanderScenario(scenario, ResolveLander(scenario));
}

LanderRun RunLanderScenario(const LanderScenario& scenario, lander::LanderSetup setup) {
  if (scenario.ground.soil_field && scenario.ground.soil_field->seed_per_landing)
    throw MakeInputError(scenario.source, "ground.soil_field.seed",
                         "per_landing draws a field for each landing of a study; a single landing needs a number");
  LanderRun run;
  run.scenario = scenario;
  run.setup = std::move(setup);
  // A failed landing names its scenario (the integrator's message names only the failure).
  const std::string which = "lander scenario " + scenario.name + " (" + scenario.source + "): ";
  try {
    run.result = lander::SimulateLander(run.setup);
  } catch (const integ::LimitExceeded& e) {
    throw integ::LimitExceeded(which + e.what(), e.limit(), e.value());
  } catch (const integ::IntegrationFailure& e) {
    throw integ::IntegrationFailure(which + e.what());
  }
  const lander::StateLayout L = lander::RunStateLayout(run.setup.model, run.setup.terrain);
  const lander::LanderPose pose = lander::ComputePose(run.setup.model, L, run.result.final_state);
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const Eigen::Vector3d& p = pose.pads[i].p_WJ;
    run.soil_under_pad[i] = run.setup.terrain.soils[run.setup.terrain.SoilAt(p.x(), p.y())].name;
  }
  return run;
}

}  // namespace touchdown::scenario
