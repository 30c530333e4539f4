#pragma once
// A sweep file (SWEEP.yaml) defines a set of drops by fixed values, grids (cartesian products)
// and seeded random samples over the drop parameters:
//
//   schema_version: 1
//   type: sweep
//   name: pad_trade
//   model: model.yaml            # optional model file (relative paths: to this file)
//   traces: decimated            # none | decimated | full  (stored in the results database)
//   trace_max_samples: 64        # for `decimated`: at most this many samples per drop
//   rest_duration_s: 0           # time simulated after the stop (0: summaries only)
//   max_drop_evaluations: 2000000  # work limit per drop: right-hand-side evaluations of its
//                                # integrator (0: none; default kDefaultMaxDropEvaluations); a drop
//                                # over it is recorded as failed, naming the limit and its value
//                                # (`sweep --max-drop-evaluations`). Deterministic: the same drops
//                                # fail on every machine, under any load, at any thread count.
//   max_drop_wall_time_s: 0      # opt-in wall-clock limit per drop (0: none, the default); it
//                                # depends on machine load, and the database says so
//                                # (`sweep --max-drop-wall-time`)
//   simulation: {free_drop_model: fast}  # reference (default) | fast: the free drops' model
//                                # (drop::FreeDropModel, `touchdown drop --free --fast`); rig
//                                # drops are unchanged; refused with a mesh pad or a lander
//   fixed:  {soil: fjs1_lp, gravity_m_s2: 9.81}
//   grid:   {pad: [flat, c4, curved], impact_speed_m_s: {from: 0.5, to: 2.0, count: 7}}
//   random: {samples: 100, seed: 7, pad_mass_kg: {uniform: [1.2, 2.0]}, soil: {choice: [fjs1_lp, fjs1_cp]}}
//
// Parameters: pad, soil (catalogue names or YAML paths), impact_speed_m_s, pad_mass_kg
// (default: each pad's mass), gravity_m_s2 (default 9.81), tilt_deg and horizontal_speed_m_s
// (default 0; a drop with either non-zero is a free 6-DOF drop: tilt about the world x axis,
// horizontal speed along +x, see sweep_drop.h), zeta_N_cm3 (default: the soil's, or the
// model's). Each parameter is set in at most one block.
//
// A lander sweep names a lander scenario instead of pads (data/scenarios/lander_case_A.yaml style,
// drop_tests/scenario/lander_scenario_types.h) and varies some of its parameters; each drop is a whole lander run:
//
//   lander: {scenario: lander_case_A}   # a name in data/scenarios or a path (relative: to this file)
//   traces: none                        # lander sweeps store summaries only (the default for them)
//   grid:   {impact_speed_m_s: [1.0, 1.4], pitch_deg: [0, 2]}
//
// Lander parameters, each defaulting to the scenario's value: impact_speed_m_s (the first pad's
// vertical touchdown speed; replaces the scenario's drop height), horizontal_speed_m_s (body
// velocity along world +x, y = 0), roll_deg and pitch_deg (initial attitude, aerospace signs as in
// the scenario), gravity_m_s2, soil (the ground's default soil; soil patches keep theirs) and
// pad_soils (the soil under each pad, pads numbered clockwise from pad 1 front-left as in the
// scenarios). A pad_soils value is a ground case of the paper's Table II, `A` (LP LP LP LP), `B`
// (CP LP LP LP) or `C` (CP CP LP LP) with LP = fjs1_lp and CP = fjs1_cp, or a list of four soils
// (names or paths):
//
//   grid: {pad_soils: [A, B, C]}
//   grid: {pad_soils: [[fjs1_cp, fjs1_lp, fjs1_lp, fjs1_lp], [fjs1_lp, fjs1_cp, fjs1_cp, fjs1_lp]]}
//
// or, in the random block, a soil drawn independently for each pad (with optional probabilities,
// default uniform; deterministic from the seed and the sample, like every random parameter):
//
//   random: {samples: 100, seed: 1, pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp], probabilities: [0.5, 0.5]}}
//
// (`choice` takes `probabilities` too.) The ground and the touchdown relative to it, each
// defaulting to the scenario's: slope_deg (0 to 80) and downhill_azimuth_deg (from world +x
// towards +y), yaw_relative_to_slope_deg (body x from the downhill direction),
// horizontal_azimuth_deg (the direction of horizontal_speed_m_s, world azimuth as
// downhill_azimuth_deg; a drop that sets only the speed moves along +x as before, one that sets
// only the azimuth keeps the scenario's speed), and the body-axis angular rates at release
// angular_rate_x_deg_s, angular_rate_y_deg_s, angular_rate_z_deg_s (the scenario's
// initial.angular_rate_deg_s). Every lander drop records them all (results_db.h).
//
// It replaces the scenario's soil patches: the ground keeps the scenario's default soil, and each
// pad whose soil differs from it gets a square patch of its soil centred below its ball joint at
// release (half width `lander: {pad_patch_half_width_m}`, default: the scenario's own under_pad
// patches' half width, else 0.08 m as in data/scenarios/lander_case_B.yaml), so `A`, `B`, `C`
// on lander_case_A reproduce the scenarios lander_case_A, _B, _C. soil and pad_soils are
// exclusive. `pad` is the pad design on all four legs (scenario::LanderSpecWithPad: the lander's
// total mass and CoG height stay, the joints sit at the pad's joint height; each pad is checked
// against the lander at load). pad_mass_kg, tilt_deg and zeta_N_cm3 are single-pad parameters and
// refused there; roll_deg, pitch_deg and pad_soils are refused in single-pad sweeps. The model
// (`model:`/--model) applies to the lander's soils as in `touchdown lander --model`.
//
// A stability study (`type: stability`, docs/stability_studies.md) is a lander sweep with a
// `study` block that `touchdown stability` reads (drop_tests/stability/study.h); here it is a
// sweep like any other, so `touchdown sweep STUDY.yaml` runs the same landings.
//
// Pads may be axisymmetric or `kind: mesh` (data/pads/hex.yaml). A mesh pad has no profile for
// the rig's integral, so each of its drops is a free 6-DOF drop (lander/pad/free_drop.h), level
// and straight down unless tilted or sliding; model effects without a 3D form are refused at load
// when the sweep has a mesh pad.
//
// Drop i is grid point g = i / S and random sample s = i % S (S = samples, 1 without random);
// the grid's first-listed parameter varies slowest. Random sample s draws the same values at
// every grid point (common random numbers, so pads are compared under identical conditions),
// from a counter-based generator keyed by (seed, s, parameter): any drop's parameters follow
// from its index alone, independent of threads, ranks or shards.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_row.h"
#include "drop_tests/scenario/lander_scenario_types.h"
#include "drop_tests/model/model_file.h"
#include "lander/pad/rig_drop.h"
#include "rft/gravity_constants.h"
#include "rft/physical_limits.h"
#include "rft/enum_names.h"

namespace touchdown::sweep {

// Appended only: a parameter's enum value is its random stream (CounterUniform), so reordering
// would change every random sweep's drops.
enum class SweepParam {
  kPad, kSoil, kImpactSpeed, kMass, kGravity, kTilt, kHorizontalSpeed, kZeta, kRoll, kPitch, kPadSoils,
  // Lander sweeps (stability studies, docs/stability_studies.md): the ground's slope and the
  // touchdown conditions relative to it.
  kSlope, kDownhillAzimuth, kYawToSlope, kHorizontalAzimuth, kRateX, kRateY, kRateZ
};
inline constexpr int kSweepParamCount = 18;
const char* SweepParamKey(SweepParam p);  // the YAML key, e.g. "impact_speed_m_s"
std::optional<SweepParam> SweepParamFromKey(const std::string& key);
// A value of `p` from SI (radians, N/m^3) into the file's units (degrees, N/cm^3), and back.
double SweepParamFromSi(SweepParam p, double si);
double SweepParamToSi(SweepParam p, double file_value);
// Whether `p` is a lander sweep's number (not a pad, soil or pad_soils index, nor single-pad only).
bool IsLanderNumber(SweepParam p);

enum class TraceStorage { kNone, kDecimated, kFull };
// As a sweep file names them.
inline constexpr std::array<EnumName<TraceStorage>, 3> kTraceStorageNames{
    {{TraceStorage::kNone, "none"}, {TraceStorage::kDecimated, "decimated"}, {TraceStorage::kFull, "full"}}};
const char* TraceStorageName(TraceStorage t);

// The parameters of one drop, in SI units; pad and soil as indices into SweepPlan::pads/soils.
// A drop's stated conditions (drop::DropRow: speed, mass, gravity, zeta, tilt, horizontal speed;
// the atmosphere is the soil's) are its row, passed to the drop as they stand.
struct SweepDropParams : drop::DropRow {
  int64_t index = 0;
  int pad = 0;
  int soil = 0;
  double roll_rad = 0.0, pitch_rad = 0.0;  // lander sweeps
  int pad_soils = 0;  // lander sweeps: index into SweepPlan::pad_soil_sets
  // Lander sweeps: ground slope and its downhill azimuth (from world +x towards +y), body x from
  // the downhill direction, the horizontal velocity's azimuth (world, as downhill_azimuth), the
  // body-axis angular rates at release.
  double slope_rad = 0.0, downhill_azimuth_rad = 0.0, yaw_to_slope_rad = 0.0, horizontal_azimuth_rad = 0.0;
  std::array<double, 3> angular_rate_rad_s{};
  uint32_t given = 0;  // bit p set when parameter p was set by the sweep (else: its default)
  bool Given(SweepParam p) const { return (given >> static_cast<int>(p)) & 1u; }
};

struct SweepDropParams;
// The value of number parameter `p` in a drop's parameters, SI.
double ParamValue(const SweepDropParams& d, SweepParam p);

struct SweepAxis {  // a grid dimension
  SweepParam param;
  std::vector<double> values;  // SI; pad/soil: indices
};

struct SweepRandom {  // a random parameter
  SweepParam param;
  bool choice = false;         // choose among `values` (uniformly, or by `probabilities`), else uniform on [low, high)
  double low = 0.0, high = 0.0;
  std::vector<double> values;  // SI; pad/soil: indices
  std::vector<double> probabilities;  // of `values`, summing to 1; empty: uniform
  // pad_soils only (`per_pad_choice`): `values` are soils (indices into SweepPlan::soils), drawn
  // independently for each pad; the drop's pad_soils is the set for the four draws, which the
  // plan holds from `first_set` on (set index first_set + sum pick_i k^i, k = values.size()).
  bool per_pad = false;
  int first_set = 0;
};

// The soils under a lander's four pads (a `pad_soils` value): indices into SweepPlan::soils,
// pads clockwise from pad 1 (front-left).
struct PadSoilSet {
  std::string label;  // the Table II case ("A", "B", "C") when given by its letter, else ""
  std::array<int, 4> soil{};
};

// The Table II case ("A", "B", "C") four soil names make (LP = fjs1_lp, CP = fjs1_cp), or "".
std::string PaperGroundCase(const std::array<std::string, 4>& soil_names);

struct SweepPlan {
  std::string name;
  std::string source;  // the sweep file
  std::optional<model::ModelFile> model;
  std::vector<io::PadSpec> pads;
  std::vector<rft::SoilParameters> soils;  // with the model applied
  std::vector<std::string> soil_refs;      // as resolved from the file (name or path), per soil
  std::optional<scenario::LanderScenario> lander;    // a lander sweep: the scenario every drop starts from
  std::string lander_digest;               // digest of the scenario, lander, pad (and mesh) files
  std::vector<PadSoilSet> pad_soil_sets;    // the `pad_soils` values
  double pad_patch_half_width_m = 0.08;     // of the patches `pad_soils` puts under the pads
  std::optional<double> fixed[kSweepParamCount];
  std::vector<SweepAxis> grid;
  std::vector<SweepRandom> random;
  int64_t samples = 1;
  uint64_t seed = 0;
  TraceStorage traces = TraceStorage::kDecimated;
  int trace_max_samples = 64;
  // The free drops' model (`simulation: {free_drop_model}`); rig and lander drops keep theirs.
  drop::FreeDropModel free_drop_model = drop::FreeDropModel::kReference;
  pad::RigDropOptions rig;  // rest_duration_s and integrator.max_rhs_evaluations/max_wall_time_s from the file
  // What a plan derived in memory from a loaded one changes (a stability study's re-checks at a
  // tighter tolerance, its joint-range variants: drop_tests/stability/study_followups.h), as text;
  // part of DigestText, so a derived plan's database is never taken for the original's. Empty
  // for a plan as loaded (its digest as before); not written by WriteSweepPlan.
  std::string variant;
  // Uniform draws given per sample in place of the counter draws: sample s's random[k] takes
  // (*given_uniforms)[s][k] in [0, 1) when s is a key (the rest draw as usual). A stability study's
  // rare-event estimators map their standard-normal points to the study's variables this way
  // (drop_tests/stability/study_rare_event.h). Not part of DigestText: a plan that sets it names
  // what chose the draws in `variant`. Not written by WriteSweepPlan.
  std::shared_ptr<const std::map<int64_t, std::vector<double>>> given_uniforms;
  // Per-landing soil parameters (a stability study's soil uncertainty:
  // drop_tests/stability/soil_uncertainty.h): landing i's lander runs with the zeta overrides
  // soil_overrides_at(i) gives, by soil name, on top of the model's. Not part of DigestText: a plan
  // that sets it names what it draws from in `variant`. Not written by WriteSweepPlan.
  std::function<std::map<std::string, model::SoilOverride>(int64_t)> soil_overrides_at;
  // The same draws by output column ("<soil>_zeta_N_cm3", "<soil>_dynamic_lambda"), stored with
  // each landing's record (DropRecord::soil_parameters). Set with soil_overrides_at.
  std::function<std::vector<std::pair<std::string, double>>(int64_t)> soil_parameters_at;

  int64_t size() const;
  SweepDropParams DropAt(int64_t index) const;
  std::string DropId(int64_t index) const;  // "d" + zero-padded index
  // A text that changes whenever anything that shapes a result changes (parameters, pads,
  // soils, model, options); the results database records its hash.
  std::string DigestText() const;
};

// Loads and validates the whole sweep (pads, soils, model, every value) before anything runs.
// `model_override` (from --model) replaces the file's `model:`; giving both is an error.
// The per-drop limits are not part of DigestText: they decide whether a drop finishes, never
// what a finished drop computes, so a restart may change them (and then retries the drops that
// ran out of a lower one). The default evaluation limit is far above what any shipped sweep's
// drop needs (bench/sweep_bench.cpp and tests/drop_tests/sweep_limits_test.cpp measure them).
inline constexpr long kDefaultMaxDropEvaluations = limits::kDefaultMaxRunEvaluations;
inline constexpr double kDefaultMaxDropWallTimeS = 0.0;  // none: wall-clock limits are opt-in
SweepPlan LoadSweepPlan(const std::string& path, const std::string& model_override = "");
// The reference of a sweep file's keys (schema_doc.h; `touchdown schema`, docs/reference.md); the
// parameters under fixed, grid and random are the sweep parameters' table.
std::vector<io::BlockDoc> SweepPlanSchema();
// A sweep file that LoadSweepPlan reads back to the same plan (same DigestText, limits and
// drops): every value in file units, grids as lists, pads, model and lander scenario by absolute
// path, soils as the plan resolved them.
void WriteSweepPlan(const SweepPlan& plan, const std::string& path);
// 64-bit FNV-1a, for digests.
uint64_t Fnv1a64(const std::string& text);
// Counter-based uniform draw in [0, 1) from (seed, sample, stream): splitmix64 mixing.
double CounterUniform(uint64_t seed, uint64_t sample, uint64_t stream);

}  // namespace touchdown::sweep
