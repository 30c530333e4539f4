#pragma once
// How a rig's data acquisition turns the pad's continuous force and penetration into samples,
// as one model for every consumer of a recorded simulation (diagnose, compare, synth):
//  - the sampling: at instants, the mean over each sample period (an integrating ADC), or at
//    instants behind a causal analogue Butterworth anti-alias low-pass of a stated order and
//    cutoff (applied to every channel, as an anti-alias filter is);
//  - the load cell's own dynamics: a second-order sensor between the pad's force and the reading,
//    y'' + 2 zeta w y' + w^2 y = w^2 F (w = 2 pi load_cell_hz), lightly damped, which rings after
//    the impact and the stop (force channel only).
// A filter acts on the continuous record (RecordedAt's, the simulated trace linearly interpolated,
// free fall before touchdown) resampled on a fine uniform grid, each second-order section the
// bilinear transform of its analogue prototype pre-warped at its own frequency; the filtered grid
// is then sampled (linearly interpolated, or averaged over the period).
#include <string>
#include <vector>

#include "drop_tests/dataset/dataset.h"
#include "lander/pad/effect_soil_response.h"

namespace touchdown::dataset {

struct SensorModel {
  pad::SensorSampling sampling = pad::SensorSampling::kPeriodMean;
  int lowpass_order = 0;            // the anti-alias filter's order (even, 2 to 8); 0: none
  double lowpass_cutoff_hz = 0.0;   // its -3 dB frequency
  double load_cell_hz = 0.0;        // the load cell's natural frequency; 0: a rigid sensor
  double load_cell_damping = 0.0;   // its damping ratio
  bool HasFilters() const { return lowpass_order > 0 || load_cell_hz > 0.0; }
  bool operator==(const SensorModel&) const = default;
};

// "period_mean", "instantaneous", "lowpass4 at 1,800 Hz", "+ load cell 612 Hz, damping 0.05".
std::string DescribeSensor(const SensorModel& sensor);

// A simulated drop as the rig's sensors record it at the recorded times `t_s` (the sensor_offset
// of `terms` applied; a period mean over sample_period_s, a measured trace's SamplePeriod). Without
// filters this is RecordedSampleOf sample by sample.
DatasetTrace RecordedTrace(const pad::RigDropResult& result, double gravity_m_s2, const rft::EffectTerms& terms,
                           const std::vector<double>& t_s, const SensorModel& sensor, double sample_period_s);

// The fine grid's step for `sensor` at a record's sample period: a fortieth of the period of its
// fastest filter and a tenth of the sample period (the bilinear sections' own error there is below
// 1e-3 of the response).
double FilterGridStep(const SensorModel& sensor, double sample_period_s);
// The rate a drop is simulated at to be recorded at `sample_rate_hz`: twice it, at least 4 kHz, at
// most 20 kHz. A sample (or a filter's fine grid) reads the simulation linearly interpolated between
// its outputs: a 1 kHz simulation under 10 kHz data smeared the impact over ten samples, and under
// 1 kHz data it smeared a plug's impulse (formed within a millimetre) over a sample. synth, compare
// and diagnose simulate at this rate, so that their records agree.
double SimulationRateFor_Hz(double sample_rate_hz);

}  // namespace touchdown::dataset
