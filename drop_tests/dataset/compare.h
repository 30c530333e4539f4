#pragma once
// Simulated against measured drops (`touchdown compare`). Each measured drop is paired with a
// simulated one, either simulated here with the drop's own conditions (and a model file), or
// joined from a simulated dataset on the drop conditions. Per drop:
//
//   final_penetration_rel_error = (d_sim - d_meas) / d_meas    (final penetration)
//   peak_force_rel_error        = (F_sim - F_meas) / F_meas    (peak force)
//   force_nrmse_time        = sqrt( mean_i (F_sim(t_i) - F_i)^2 ) / max_i F_i
//       over every measured sample i; F_sim(t) is the simulated trace interpolated linearly
//       in time, 0 before touchdown (t < 0) and its last value after it ends (the pad at rest);
//       a drop simulated here is recorded on the measured times (SimulateMeasuredDrops), so
//       F_sim(t_i) is its recorded sample;
//   force_nrmse_penetration = sqrt( mean_i (F_sim(d_i) - F_i)^2 ) / max_i F_i
//       over the measured loading stroke (samples with d_i > 0 up to the stop, LoadingStrokeIndices
//       as calibrate uses: where the force falls below half its peak in the deeper half; without
//       the stroke's first and last samples, astride the touchdown and the stop), where
//       the simulated stroke covers d_i; F_sim(d) is the simulated force interpolated linearly in
//       penetration along its own stroke. Samples deeper than the simulated stroke are left out
//       and counted (penetration_samples_used of penetration_samples).
//
// Both NRMSEs are normalised by the MEASURED peak force, so they read as a fraction of the
// measured load. Overall: the mean over drops of |rel error| (final_penetration_rel_error,
// peak_force_rel_error), the signed means (..._bias), and the mean NRMSEs (force_nrmse is the
// one against time, force_nrmse_penetration the other), each over the drops where it is defined
// (drops_used in the summary; drops measured at 0 are listed, never silently skipped).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/model/model_file.h"
#include "lander/pad/effect_soil_response.h"

namespace touchdown::dataset {

struct NrmseResult {
  double value = 0.0;  // NaN when no sample could be compared
  size_t samples = 0;  // candidates
  size_t used = 0;     // compared
};

// The metrics above as pure functions of two traces.
NrmseResult ForceNrmseTime(const DatasetTrace& measured, const DatasetTrace& simulated);
NrmseResult ForceNrmsePenetration(const DatasetTrace& measured, const DatasetTrace& simulated);
// Linear interpolation of y(x) on increasing xs, clamped to the end values.
double InterpolateClamped(const std::vector<double>& xs, const std::vector<double>& ys, double x);

struct DropComparison {
  std::string drop_id;          // the measured drop
  std::string simulated_id;     // its simulated partner
  std::string pad, soil;
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;
  double impact_speed_m_s = 0.0;
  double measured_final_penetration_m = 0.0, simulated_final_penetration_m = 0.0;
  double measured_peak_force_N = 0.0, simulated_peak_force_N = 0.0;
  double final_penetration_rel_error = 0.0, peak_force_rel_error = 0.0;
  NrmseResult force_nrmse_time, force_nrmse_penetration;
};

struct Comparison {
  std::vector<DropComparison> drops;
  double final_penetration_rel_error = 0.0;  // mean |.| over drops
  double peak_force_rel_error = 0.0;         // mean |.|
  double final_penetration_bias = 0.0;       // mean signed
  double peak_force_bias = 0.0;
  double force_nrmse = 0.0;                  // mean force_nrmse_time
  double force_nrmse_penetration = 0.0;      // mean over drops where defined
  // A relative error is undefined for a drop whose measured value is 0 (and an NRMSE for a
  // measured peak force of 0): those drops are left out of that mean and listed here, and
  // each mean says over how many drops it was taken.
  std::vector<std::string> zero_final_penetration_drops;  // measured final penetration 0
  std::vector<std::string> zero_peak_force_drops;         // measured peak force 0
  size_t final_penetration_drops_used = 0, peak_force_drops_used = 0;
  size_t force_nrmse_drops_used = 0, force_nrmse_penetration_drops_used = 0;
  std::string simulated_from;                // "model <file>", "catalogue soils" or "dataset <dir>"
};

// Simulates every measured drop with its own pad, soil, atmosphere, speed, mass and gravity
// (DropConditionsFor + ResolveDrop + RunDrop, drop_tests/drop/drop_setup.h), its trace at
// RecordingSimulationRate_Hz, under `model` when given:
// its zeta per soil and its effects (gas_cushion on the drops in air only). A drop with a
// non-zero tilt_deg or horizontal_speed_m_s column is a free 6-DOF drop (tilt about x, travel
// along +x; the effects in their 3D form). Each simulated drop is recorded as the measured one was
// (RecordedTrace, sensor_sampling.h): on the measured sample times, through a sensor that samples
// as `sampling` says (kPeriodMean: the mean over the measured trace's SamplePeriod), with a
// sensor_offset's shifts (time by -dt, penetration by +dz). Its final penetration and peak force
// come from the simulation where the measured drop has those columns, else from its recorded
// trace. Returns a dataset with the same drop ids.
// The rate a drop is simulated at to be recorded on `measured`'s sample times: SimulationRateFor_Hz
// (sensor_model.h) of its fastest sample rate. compare and diagnose simulate at the same rate.
double RecordingSimulationRate_Hz(const Dataset& measured);

Dataset SimulateMeasuredDrops(const Dataset& measured, const std::optional<model::ModelFile>& model,
                              pad::SensorSampling sampling);
// For each measured drop the first simulated drop with the same conditions (pad, soil,
// atmosphere, impact speed, mass, gravity, and tilt_deg/horizontal_speed_m_s where given, 0
// otherwise; numbers equal to a relative 1e-9). Throws InputError naming an unmatched drop.
std::vector<const DatasetDrop*> JoinOnConditions(const Dataset& measured, const Dataset& simulated);

Comparison CompareDrops(const Dataset& measured, const std::vector<const DatasetDrop*>& partners);
nlohmann::json ComparisonJson(const Comparison& c);
// out_dir (replaced when complete): summary.json, per_drop.csv, simulated/ (when simulated here),
// plots/compare.gp, plots/parity (every drop: simulated against measured final penetration and
// peak force) and plots/drops/<drop_id>.png (measured over simulated: force against time and
// against penetration) drawn by RenderPlots (plot_runner.h) from plots/data/, the traces
// decimated for plotting (plot_decimation.h).
void WriteComparison(const Comparison& c, const Dataset& measured, const Dataset& simulated,
                     const std::vector<const DatasetDrop*>& partners, bool write_simulated, const io::OutputTarget& out);

// `touchdown compare` whole, for the command line and the Python module: reads the measured
// dataset, simulates its drops here (with `model_file`, or the catalogue's soils) or joins them to
// the `simulated_dir` dataset on their conditions, compares, and writes the outputs to `out`
// (checked first); drops simulated here are recorded through `sampling` (SimulateMeasuredDrops).
// Returns the comparison.
Comparison RunComparison(const std::string& measured_dir, const std::string& simulated_dir,
                         const std::string& model_file, const io::OutputTarget& out, pad::SensorSampling sampling);

}  // namespace touchdown::dataset
