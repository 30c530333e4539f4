// Lander landings of 1 s simulated time from release 10 cm above the bed, four meshed pads of about
// 2k triangles each (data/landers, 64 segments around the rim), ball joints with the lander file's
// 30 deg range, one core. The symmetric case A on this default model is the yardstick (issue 30: "case
// A costs 27 ms"). BM_LanderFast_*: the same landings under the studies' fast model, read from the
// shipped lab study's scenario (data/studies/lab_paper_lander_scenario.yaml: its pads' rim segments and
// rim, rtol and pads' spin tolerance factor; the TD_ knobs do not apply to them), the model the
// stability studies land; the target is each of them within 3x the default model's case A in the same
// run (docs/stability_studies.md, "Fast model and re-checks"):
//   CaseA                 the paper's Table II case A (LP under every pad)
//   CaseB, CaseC          CP under pad 1 (B), pads 1 and 2 (C)
//   CaseA_Attitude        case A rolled and pitched 5 deg at release, 0.5 m/s horizontally
//   Slope10_Sideways      LP on a 10 deg slope (downhill +x), level lander, 0.5 m/s across it (+y)
// Counters: the solver's (steps, right-hand sides, Jacobians, failures), the outcome (pad 1's
// final depths, final roll and pitch), and `realtime_factor` (simulated seconds per wall second).
// TD_RTOL / TD_ATOL / TD_ADAMS (Adams instead of BDF) / TD_MSBJ (most steps between Jacobians) /
// TD_NLCOEF (Newton's convergence coefficient; 0.1 is CVODE's, the lander's default 0.03) /
// TD_ATTJAC (the Jacobian's contact derivatives with respect to the pads' attitude too) /
// TD_SOIL_RAMP (pad or element: where the soil's low-speed ramp acts, lander::SoilRamp) /
// TD_SUNDIALS_LU (SUNDIALS' dense LU for the Newton matrix instead of Eigen's, integ::DenseSolver) /
// TD_SPIN_FACTOR (the pads' spins' absolute tolerance times this, LanderRunOptions::
// pad_spin_tolerance_factor) / TD_STOP_BY_ANGLE (the joints' stops switched on inside the steps,
// LanderRunOptions::joint_stops_as_modes false) / TD_HELD_CONTACT (the held pads' slide checks from
// their contact at every call, LanderRunOptions::held_capacity_from_integrals false) / TD_NO_CREEP_REST (rest by
// holds only, LanderRunOptions::rest_at_creep false)
// override the integrator for convergence studies, and TD_PRINT prints each landing's final depths,
// roll and pitch to stderr at full precision; TD_PADI scales the pads' rotational inertia (an
// experiment: how much of the step count the pads' fast rotation in the soil causes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "rft/bekker_law.h"
#include "rft/gravity_constants.h"
#include "rft/stress_law_3d_factory.h"
#include "rft/units.h"
#include "fixtures/paper_lander.h"

namespace {

using namespace touchdown;

// Which model a landing runs: the default one (64 segments, the scenario defaults, the TD_ knobs) or
// the stability studies' fast model as the shipped study scenario states it.
enum class Model { kDefault, kStudiesFast };

// The shipped lab study's scenario (the 1/6 model at 1 g, the benchmark landings' lander), read once.
const scenario::LanderScenario& StudyScenario() {
  static const scenario::LanderScenario study =
      scenario::LoadLanderScenario(io::DataDirectory() + "/studies/lab_paper_lander_scenario.yaml");
  return study;
}

// The benchmark's protocol (1 s, sampled at 1 kHz as lander_case_A.yaml) on a model's settings.
lander::LanderRunOptions Options(Model model) {
  lander::LanderRunOptions options = model == Model::kStudiesFast ? StudyScenario().options : lander::LanderRunOptions{};
  options.duration_s = 1.0;
  options.sample_rate_hz = 1000.0;  // lander_case_A.yaml: simulation
  if (model == Model::kStudiesFast) return options;
  if (getenv("TD_RTOL")) options.integrator.rtol = atof(getenv("TD_RTOL"));
  if (getenv("TD_ATOL")) options.integrator.atol = atof(getenv("TD_ATOL"));
  if (getenv("TD_ADAMS")) options.integrator.stiff = false;
  if (getenv("TD_MSBJ")) options.integrator.max_steps_between_jacobians = atol(getenv("TD_MSBJ"));
  if (getenv("TD_NLCOEF")) options.integrator.nonlinear_convergence_coefficient = atof(getenv("TD_NLCOEF"));
  if (getenv("TD_ATTJAC")) options.jacobian_attitude_sensitivity = true;
  if (getenv("TD_SPIN_FACTOR")) options.pad_spin_tolerance_factor = atof(getenv("TD_SPIN_FACTOR"));
  if (getenv("TD_STOP_BY_ANGLE")) options.joint_stops_as_modes = false;
  if (getenv("TD_HELD_CONTACT")) options.held_capacity_from_integrals = false;
  if (getenv("TD_NO_CREEP_REST")) options.rest_at_creep = false;
  if (getenv("TD_SUNDIALS_LU")) options.integrator.dense_solver = integ::DenseSolver::kSundials;
  return options;
}

void RunLanding(benchmark::State& state, const test::PaperLander& setup_in, const char* name, Model model) {
  test::PaperLander setup = setup_in;
  setup.options = Options(model);
  if (model == Model::kDefault && getenv("TD_PADI")) {
    auto body = std::make_shared<geom::PadBody>(*setup.model.legs[0].pad);
    body->inertia_com_B *= atof(getenv("TD_PADI"));
    for (auto& leg : setup.model.legs) leg.pad = body;
  }
  if (model == Model::kDefault && getenv("TD_SOIL_RAMP"))  // pad or element (lander::SoilRamp)
    setup.model.soil_ramp = std::string(getenv("TD_SOIL_RAMP")) == "pad" ? lander::SoilRamp::kPad : lander::SoilRamp::kElement;
  lander::LanderRunResult last;
  for (auto _ : state) {
    lander::LanderRunResult r = lander::SimulateLander(setup);
    benchmark::DoNotOptimize(r.final_penetration_m);
    last = std::move(r);
  }
  if (getenv("TD_PRINT"))  // full precision for convergence studies
    std::fprintf(stderr, "%s depths_mm %.9f %.9f %.9f %.9f roll_deg %.9f pitch_deg %.9f\n", name,
                 last.final_penetration_m[0] * 1e3, last.final_penetration_m[1] * 1e3, last.final_penetration_m[2] * 1e3,
                 last.final_penetration_m[3] * 1e3, last.final_attitude.roll_rad / units::kDeg,
                 last.final_attitude.pitch_rad / units::kDeg);
  state.counters["triangles_per_pad"] = setup.model.legs[0].pad->surface.size();
  state.counters["solver_steps"] = static_cast<double>(last.solver.steps);
  state.counters["rhs_evals"] = static_cast<double>(last.solver.rhs_evaluations);
  state.counters["jac_rhs_evals"] = static_cast<double>(last.solver.jacobian_rhs_evaluations);
  state.counters["jac_pad_contacts"] = static_cast<double>(last.jacobian_pad_contacts);
  state.counters["rhs_pad_contacts"] = static_cast<double>(last.rhs_pad_contacts);
  state.counters["root_pad_contacts"] = static_cast<double>(last.root_pad_contacts);
  state.counters["events"] = static_cast<double>(last.events.size());
  state.counters["root_evals"] = static_cast<double>(last.solver.root_evaluations);
  state.counters["jac_evals"] = static_cast<double>(last.solver.jacobian_evaluations);
  state.counters["ncfn"] = static_cast<double>(last.solver.nonlinear_convergence_failures);
  state.counters["etf"] = static_cast<double>(last.solver.error_test_failures);
  for (int i = 0; i < lander::kNumLegs; ++i)
    state.counters["pen" + std::to_string(i + 1) + "_mm"] = last.final_penetration_m[i] * 1e3;
  state.counters["roll_deg"] = last.final_attitude.roll_rad / units::kDeg;
  state.counters["pitch_deg"] = last.final_attitude.pitch_rad / units::kDeg;
  state.counters["max_tilt_deg"] = last.max_tilt_rad / units::kDeg;
  state.counters["energy_err"] = last.initial_energy_J - last.dissipated_J - last.final_kinetic_J - last.final_potential_J;
  state.counters["rest_time_s"] = last.rest_time_s.value_or(-1.0);
  state.counters["realtime_factor"] =
      benchmark::Counter(setup.options.duration_s * state.iterations(), benchmark::Counter::kIsRate);
}

// The paper's lander built in code from the catalogue's values (data/landers, data/soils,
// data/scenarios/lander_case_*.yaml), at the catalogue's 64 segments, on the soils as shipped
// (their dynamic term included; TD_QUASI_STATIC=1: without it, as the lander tests pin).
// The legs' ball joints have data/landers/sutoh2017_lander.yaml's 30 deg range (TD_FREE_JOINT=1: none);
// TD_SEGMENTS meshes the pads at another number of rim segments (a study's pad_angular_segments),
// TD_AREA_RIM=1 with the area-preserving rim (a study's pad_rim: area_preserving). The fast model
// takes the study scenario's segments and rim, the soils as shipped and the joint range.
test::PaperLander ShippedLanding(char ground_case, Model model) {
  const bool fast = model == Model::kStudiesFast;
  int segments = getenv("TD_SEGMENTS") ? atoi(getenv("TD_SEGMENTS")) : 64;
  geom::RimPolygon rim = getenv("TD_AREA_RIM") ? geom::RimPolygon::kAreaPreserving : geom::RimPolygon::kInscribed;
  if (fast) {
    segments = StudyScenario().pad_angular_segments;
    rim = StudyScenario().pad_rim;
  }
  test::PaperLander setup =
      test::MakePaperLander(ground_case, segments, 0.10, fast || getenv("TD_QUASI_STATIC") == nullptr, rim);
  if (fast || !getenv("TD_FREE_JOINT"))
    for (lander::Leg& leg : setup.model.legs)
      leg.cone = lander::ConeLimit{.half_angle_rad = 30.0 * units::kDeg, .stiffness_N_m_rad = 200.0, .damping_N_m_s_rad = 0.16};
  return setup;
}

test::PaperLander AttitudeLanding(Model model) {
  test::PaperLander setup = ShippedLanding('A', model);
  lander::LanderInitialState& s = setup.initial;
  s.R_WB = (Eigen::AngleAxisd(5.0 * units::kDeg, Eigen::Vector3d::UnitX()) *
            Eigen::AngleAxisd(5.0 * units::kDeg, Eigen::Vector3d::UnitY()))
               .toRotationMatrix();
  for (Eigen::Matrix3d& R_WP : s.R_WP) R_WP = s.R_WB;
  s.v_WB_W = Eigen::Vector3d(0.5, 0.0, 0.0);
  s.p_WB.z() = lander::BodyHeightForClearance(setup.model, setup.terrain, s, setup.drop_height_m);
  return setup;
}

test::PaperLander SlopeLanding(Model model) {
  test::PaperLander setup = ShippedLanding('A', model);
  setup.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, -std::tan(10.0 * units::kDeg), 0.0);
  lander::LanderInitialState& s = setup.initial;
  s.v_WB_W = Eigen::Vector3d(0.0, 0.5, 0.0);
  s.p_WB.z() = lander::BodyHeightForClearance(setup.model, setup.terrain, s, setup.drop_height_m);
  return setup;
}

constexpr Model kDefault = Model::kDefault, kFast = Model::kStudiesFast;
void BM_LanderCaseA_1s(benchmark::State& state) { RunLanding(state, ShippedLanding('A', kDefault), "A", kDefault); }
void BM_LanderCaseB_1s(benchmark::State& state) { RunLanding(state, ShippedLanding('B', kDefault), "B", kDefault); }
void BM_LanderCaseC_1s(benchmark::State& state) { RunLanding(state, ShippedLanding('C', kDefault), "C", kDefault); }
void BM_LanderCaseA_Attitude_1s(benchmark::State& state) { RunLanding(state, AttitudeLanding(kDefault), "attitude", kDefault); }
void BM_LanderSlope10_Sideways_1s(benchmark::State& state) { RunLanding(state, SlopeLanding(kDefault), "slope", kDefault); }
void BM_LanderFast_CaseA_1s(benchmark::State& state) { RunLanding(state, ShippedLanding('A', kFast), "fast A", kFast); }
void BM_LanderFast_CaseB_1s(benchmark::State& state) { RunLanding(state, ShippedLanding('B', kFast), "fast B", kFast); }
void BM_LanderFast_CaseC_1s(benchmark::State& state) { RunLanding(state, ShippedLanding('C', kFast), "fast C", kFast); }
void BM_LanderFast_CaseA_Attitude_1s(benchmark::State& state) { RunLanding(state, AttitudeLanding(kFast), "fast attitude", kFast); }
void BM_LanderFast_Slope10_Sideways_1s(benchmark::State& state) { RunLanding(state, SlopeLanding(kFast), "fast slope", kFast); }

// The paper's lander at lunar gravity on a Bekker soil (docs/bekker_soil.md): 4 deg slope,
// 0.22 m/s downhill, 3 deg roll. fjs1_lp_bekker's values (n = 1.018, k_c = 0, k_phi = 3888
// kN/m^(n+2), c = 0.17 kPa, phi = 35 deg, K = 18 mm); state.range(0) = 1 takes n = 1 instead, which
// runs the linear depth law: the cost of the z^n path is the difference.
void BM_LanderBekker_Slope4_1s(benchmark::State& state) {
  test::PaperLander setup = test::MakePaperLander('A', 64);
  setup.model.gravity_m_s2 = rft::kMoonGravity_m_s2;
  rft::SoilParameters soil;
  soil.name = "fjs1_lp_bekker";
  soil.rft_law_3d = rft::LawKind::kBekker;
  soil.bekker = {state.range(0) == 1 ? 1.0 : 1.018, 0.0, 3888e3, 170.0, 35.0 * units::kDeg, 0.018};
  setup.terrain.soils = {{soil.name, rft::MakeSoilContactModel(rft::LawKind::kBekker, soil, rft::kMoonGravity_m_s2, {}, &setup.model.legs[0].pad->surface)}};
  setup.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, -std::tan(4.0 * units::kDeg), 0.0);
  lander::LanderInitialState& s = setup.initial;
  s.R_WB = Eigen::AngleAxisd(3.0 * units::kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (Eigen::Matrix3d& R_WP : s.R_WP) R_WP = s.R_WB;
  s.v_WB_W = Eigen::Vector3d(0.22, 0.0, 0.0);
  s.p_WB.z() = lander::BodyHeightForClearance(setup.model, setup.terrain, s, setup.drop_height_m);
  RunLanding(state, setup, "bekker", kDefault);
}

BENCHMARK(BM_LanderCaseA_1s)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_LanderCaseB_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderCaseC_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderCaseA_Attitude_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderSlope10_Sideways_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderFast_CaseA_1s)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_LanderFast_CaseB_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderFast_CaseC_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderFast_CaseA_Attitude_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderFast_Slope10_Sideways_1s)->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(BM_LanderBekker_Slope4_1s)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->MinTime(0.5);

}  // namespace
