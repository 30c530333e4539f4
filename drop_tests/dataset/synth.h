#pragma once
// `touchdown synth SPEC.yaml --out DATASET_DIR`: measured-like SYNTHETIC drop datasets, for
// rehearsing a campaign and for testing `diagnose` on data whose missing effect is known.
//
// Each drop is simulated (axisymmetric rig drop, optionally with one hidden effect), then
// recorded as a rig would: sampled at `sample_rate_hz` from the recorded t = 0 (each sample the mean
// over its sample period, or with `sensor_sampling: instantaneous` the value at its time), with Gaussian
// load-cell and displacement noise, a linear drift per drop (rate drawn from N(0, sigma)), and
// quantisation to the sensors' resolution. Seeded: the same spec gives the same bytes.
//
// The spec (YAML, SI units suffixed in keys):
//   schema_version: 1
//   type: synth
//   name: air_vs_vacuum
//   seed: 7
//   sample_rate_hz: 1000          # optional
//   rest_duration_s: 0.04         # optional: recorded after the stop
//   sensor_sampling: period_mean  # optional: or instantaneous (pad::SensorSampling)
//   trials: 1                     # optional: repeats of every condition (new noise each)
//   drops:                        # cartesian products, one entry per group
//     - {pads: [flat, curved], soils: [fjs1_lp], atmospheres: [air, vacuum],
//        impact_speeds_m_s: [0.7, 1.0, 1.5], mass_kg: 1.6, gravity_m_s2: 9.81}
//   true_zeta_N_cm3: {fjs1_lp: 3.3}   # optional: the "true" soils (default: the soil files)
//   noise: {force_sigma_N: 1.0, penetration_sigma_mm: 0.02, force_drift_N_s: 2.0,
//           penetration_drift_mm_s: 0.05, force_resolution_N: 0.1, penetration_resolution_mm: 0.005}
//   hidden_effect: {id: gas_cushion, chi: 0.3, c_g_N_s_m3: 5000}   # optional
//
// hidden_effect takes a library id (drop_tests/model/effects.h) with its parameters in file units,
// or `floor_stiffening`, an effect deliberately OUTSIDE the library: a rigid floor under a bed
// of depth H stiffens it once the pad's pressure bulb (depth b below the pad) nears the
// floor, F -> F (1 + exp((d + b - H) / l)); keys bed_depth_mm (150), bulb_depth_mm (100),
// influence_mm (15).
//
// The output says everywhere that it is synthetic: README.md, synthetic.yaml (the resolved
// spec), a `data_origin` column = synthetic in drops.csv, and synthetic_truth.yaml (the hidden
// effect and true zeta; `diagnose` never reads it).
#include <optional>
#include <string>
#include <vector>

#include "drop_tests/dataset/dataset.h"
#include "drop_tests/formats/schema_doc.h"
#include "drop_tests/model/effects.h"
#include "drop_tests/dataset/sensor_sampling.h"
#include "rft/gravity_constants.h"

namespace touchdown::dataset {

struct SynthNoise {
  double force_sigma_N = 1.0;
  double penetration_sigma_m = 2e-5;
  double force_drift_N_s = 2.0;
  double penetration_drift_m_s = 5e-5;
  double force_resolution_N = 0.1;
  double penetration_resolution_m = 5e-6;
};

struct SynthDrop {
  std::string pad, soil;
  rft::Atmosphere atmosphere = rft::Atmosphere::kVacuum;
  double impact_speed_m_s = 0.0;
  std::optional<double> mass_kg;
  double gravity_m_s2 = rft::kEarthGravity_m_s2;
  int trial = 0;
  int group = 0;  // the spec's drops[group] that made it (named in messages)
};

struct FloorStiffening {
  double bed_depth_m = 0.15, bulb_depth_m = 0.10, influence_m = 0.015;
};

struct SynthSpec {
  std::string name, description, source;
  unsigned long long seed = 1;
  double sample_rate_hz = 1000.0;
  double rest_duration_s = 0.04;
  std::vector<SynthDrop> drops;
  std::vector<std::pair<std::string, double>> true_zeta_N_m3;  // soil -> zeta at its reference gravity
  SynthNoise noise;
  std::optional<model::Effect> hidden_effect;      // a library effect
  std::optional<FloorStiffening> floor;     // or the out-of-library one
  // How the recorded samples are taken (sensor_sampling: period_mean, the default, or instantaneous).
  pad::SensorSampling sensor_sampling = pad::SensorSampling::kPeriodMean;
};

// Caps checked at load (the dataset is built in memory before it is written; rft/physical_limits.h,
// kMaxSynth*), the samples counted as drops x (rest_duration_s + kSynthStrokeBoundS) x rate.
inline constexpr double kSynthStrokeBoundS = 0.1;  // an allowance for the stroke (tens of ms at 1 m/s)

SynthSpec LoadSynthSpec(const std::string& path);
// The reference of a synth spec's keys (schema_doc.h; `touchdown schema`, docs/reference.md).
std::vector<io::BlockDoc> SynthSpecSchema();
// Builds the dataset in memory (traces included); drop ids like flat_fjs1_lp_air_v1.00_t0.
Dataset Synthesize(const SynthSpec& spec);
// Writes the dataset (the measured-drop format, docs/guide.md "Datasets") plus README.md, synthetic.yaml and synthetic_truth.yaml,
// all through a staged directory.
void WriteSyntheticDataset(const SynthSpec& spec, const Dataset& dataset, const io::OutputTarget& out);
// `touchdown synth SPEC --out DIR` as one call (the command and touchdown.synth): checks DIR, loads
// the spec, synthesises and writes the dataset; the spec and the number of drops written.
struct SynthRun {
  SynthSpec spec;
  size_t drops = 0;
};
SynthRun SynthesizeToDirectory(const std::string& spec_path, const io::OutputTarget& out);

}  // namespace touchdown::dataset
