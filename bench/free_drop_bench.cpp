// A free 6-DOF pad drop (3D contact) with a meshed pad of about 5k triangles: the flat pad revolved
// at 96 rim segments. Target: under 50 ms per drop on one core. Counters report the
// mesh size and the integrator's work so a slow case shows why it is slow. TD_RTOL overrides the
// relative tolerance (convergence studies), TD_SEGMENTS the rim segments (mesh convergence),
// TD_AREA_RIM=1 makes those rings area-preserving (geom::RimPolygon), TD_PROFILE_SEGMENTS a curved
// profile's pieces and TD_REMESH_EDGE_MM a mesh pad's remeshing edge (the pad file's read again with
// it); TD_MSBJ sets the most steps between Jacobians; TD_DQ_JACOBIAN=1 takes CVODE's difference-quotient Jacobian instead of the structured one.
// BM_FreeDropHexTiltedSideways: the mesh pad hex as its file meshes it (4.6k triangles; the rim
// knobs do not apply to it). BM_FreeDropFast*: the same drops under the shipped fast model (drop::FreeDropModel::kFast, as
// `touchdown drop --free --fast` runs them; the knobs do not apply), target 10 ms a drop.
#include <benchmark/benchmark.h>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/formats/yaml_fields.h"
#include "lander/pad/free_drop.h"
#include "footpad_geom/revolve.h"
#include "rft/gravity_constants.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"

namespace {

using namespace touchdown;

constexpr int kRimSegments = 96;  // about 5k triangles for the flat pad

void ReportDrop(benchmark::State& state, const geom::PadBody& body, const touchdown::pad::FreeDropResult& r);

void RunFreeDrop(benchmark::State& state, const char* pad_name, double tilt_deg, double horizontal_m_s,
                 double spin_rad_s) {
  const touchdown::io::PadSpec pad = touchdown::io::LoadPad(pad_name);
  const int segments = getenv("TD_SEGMENTS") ? atoi(getenv("TD_SEGMENTS")) : kRimSegments;
  geom::PadBody body;
  if (pad.is_axisymmetric() && (getenv("TD_PROFILE_SEGMENTS") || getenv("TD_AREA_RIM"))) {
    // The pad file read again with the knobs' fields, as io::PadWithAngularSegments re-meshes a pad.
    YAML::Node node = YAML::Clone(touchdown::io::YamlFields::LoadFile(pad.source).node());
    if (getenv("TD_PROFILE_SEGMENTS")) node["profile"]["segments"] = atoi(getenv("TD_PROFILE_SEGMENTS"));
    node["angular_segments"] = segments;
    body = touchdown::io::LoadPad(touchdown::io::YamlFields(node, pad.source, ""),
                                  getenv("TD_AREA_RIM") ? geom::RimPolygon::kAreaPreserving : geom::RimPolygon::kInscribed)
               .body;
  } else if (pad.is_axisymmetric()) {
    body = geom::RevolveProfileToBody(pad.profile, segments, pad.mass_kg,
                                      Eigen::Vector3d(0.0, 0.0, pad.profile.thickness_m()));
  } else if (getenv("TD_REMESH_EDGE_MM")) {
    YAML::Node node = YAML::Clone(touchdown::io::YamlFields::LoadFile(pad.source).node());
    node["mesh"]["remesh_edge_mm"] = atof(getenv("TD_REMESH_EDGE_MM"));
    node["mesh"]["file"] = pad.mesh_file;
    body = touchdown::io::LoadPad(touchdown::io::YamlFields(node, pad.source, "")).body;
  } else {
    body = pad.body;  // a mesh pad as its file meshes it
  }
  const rft::SoilParameters soil = touchdown::io::LoadSoil("fjs1_lp");
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, soil, rft::kEarthGravity_m_s2, {});
  const rft::Terrain bed = rft::UniformTerrain(soil.name, law);
  touchdown::pad::FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.tilt_rad = units::DegToRad(tilt_deg);  // as `touchdown drop --free --tilt` converts it
  in.horizontal_speed_m_s = horizontal_m_s;
  in.omega_W = Eigen::Vector3d(0.0, 0.0, spin_rad_s);
  touchdown::pad::FreeDropResult r;
  touchdown::pad::FreeDropOptions opt;  // the defaults `touchdown drop --free` uses
  if (getenv("TD_RTOL")) opt.integrator.rtol = atof(getenv("TD_RTOL"));
  if (getenv("TD_MSBJ")) opt.integrator.max_steps_between_jacobians = atol(getenv("TD_MSBJ"));
  if (getenv("TD_DQ_JACOBIAN")) opt.structured_jacobian = false;  // CVODE's difference quotients
  const touchdown::pad::FreeDropSetup setup{&body, bed, in, opt};
  for (auto _ : state) {
    r = touchdown::pad::RunFreeDrop(setup);
    benchmark::DoNotOptimize(r.final_penetration_m);
  }
  ReportDrop(state, body, r);
}

void ReportDrop(benchmark::State& state, const geom::PadBody& body, const touchdown::pad::FreeDropResult& r) {
  state.counters["triangles"] = body.surface.size();
  state.counters["steps"] = r.solver.steps;
  state.counters["rhs"] = r.solver.rhs_evaluations;
  state.counters["err_fails"] = r.solver.error_test_failures;
  state.counters["jac"] = r.solver.jacobian_evaluations;
  state.counters["jac_rhs"] = r.solver.jacobian_rhs_evaluations;
  state.counters["conv_fails"] = r.solver.nonlinear_convergence_failures;
  state.counters["roots"] = r.solver.root_evaluations;
  state.counters["depth_mm"] = r.final_penetration_m * 1e3;
  state.counters["tilt_deg"] = r.final_tilt_deg;
  state.counters["rest_s"] = r.time_to_rest_s;
  state.counters["samples"] = static_cast<double>(r.trace.size());
  // The energy balance's residual relative to the energy put in (impact and gravity's work).
  const double input = r.impact_energy_J + r.gravity_work_J;
  state.counters["energy_rel"] = (input - r.dissipated_energy_J - r.final_kinetic_energy_J) / input;
}

// The fast model's drop: its pad and options from drop_factory.h, nothing else changed.
void RunFastDrop(benchmark::State& state, const char* pad_name, double tilt_deg, double horizontal_m_s,
                 double spin_rad_s) {
  const touchdown::io::PadSpec pad = touchdown::drop::FreeDropPad(
      touchdown::io::LoadPad(pad_name), touchdown::drop::FreeDropModel::kFast, "bench", "fast");
  const rft::SoilParameters soil = touchdown::io::LoadSoil("fjs1_lp");
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, soil, rft::kEarthGravity_m_s2, {});
  const rft::Terrain bed = rft::UniformTerrain(soil.name, law);
  touchdown::pad::FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.tilt_rad = units::DegToRad(tilt_deg);
  in.horizontal_speed_m_s = horizontal_m_s;
  in.omega_W = Eigen::Vector3d(0.0, 0.0, spin_rad_s);
  const touchdown::pad::FreeDropOptions opt = touchdown::drop::FreeDropOptionsFor(touchdown::drop::FreeDropModel::kFast);
  const touchdown::pad::FreeDropSetup setup{&pad.body, bed, in, opt};
  touchdown::pad::FreeDropResult r;
  for (auto _ : state) {
    r = touchdown::pad::RunFreeDrop(setup);
    benchmark::DoNotOptimize(r.final_penetration_m);
  }
  ReportDrop(state, pad.body, r);
}

void BM_FreeDropFlatVertical(benchmark::State& s) { RunFreeDrop(s, "flat", 0.0, 0.0, 0.0); }
void BM_FreeDropFlatTilted5(benchmark::State& s) { RunFreeDrop(s, "flat", 5.0, 0.0, 0.0); }
void BM_FreeDropFlatSideways(benchmark::State& s) { RunFreeDrop(s, "flat", 0.0, 0.5, 0.0); }
void BM_FreeDropCurvedTiltedSideways(benchmark::State& s) { RunFreeDrop(s, "curved", 10.0, 0.3, 0.0); }
void BM_FreeDropFlatSpinning(benchmark::State& s) { RunFreeDrop(s, "flat", 5.0, 0.3, 3.0); }
void BM_FreeDropCurvedSpinning(benchmark::State& s) { RunFreeDrop(s, "curved", 5.0, 0.3, 3.0); }
void BM_FreeDropHexTiltedSideways(benchmark::State& s) { RunFreeDrop(s, "hex", 5.0, 0.3, 0.0); }

void BM_FreeDropFastFlatVertical(benchmark::State& s) { RunFastDrop(s, "flat", 0.0, 0.0, 0.0); }
void BM_FreeDropFastFlatTilted5(benchmark::State& s) { RunFastDrop(s, "flat", 5.0, 0.0, 0.0); }
void BM_FreeDropFastFlatSideways(benchmark::State& s) { RunFastDrop(s, "flat", 0.0, 0.5, 0.0); }
void BM_FreeDropFastCurvedTiltedSideways(benchmark::State& s) { RunFastDrop(s, "curved", 10.0, 0.3, 0.0); }
void BM_FreeDropFastFlatSpinning(benchmark::State& s) { RunFastDrop(s, "flat", 5.0, 0.3, 3.0); }
void BM_FreeDropFastCurvedSpinning(benchmark::State& s) { RunFastDrop(s, "curved", 5.0, 0.3, 3.0); }

BENCHMARK(BM_FreeDropFlatVertical)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFlatTilted5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFlatSideways)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropCurvedTiltedSideways)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFlatSpinning)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropCurvedSpinning)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropHexTiltedSideways)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_FreeDropFastFlatVertical)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFastFlatTilted5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFastFlatSideways)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFastCurvedTiltedSideways)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFastFlatSpinning)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeDropFastCurvedSpinning)->Unit(benchmark::kMillisecond);

}  // namespace
