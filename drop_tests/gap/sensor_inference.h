#pragma once
// Which sensor recorded the data (docs/model_gap.md, "The sensor is part of the model"): the
// sampling is inferred from the data rather than guessed by the user. The base model (zeta per
// soil, the drops' nuisances) is fitted under each sampling a rig may have - at instants, the mean
// over each period, at instants behind a causal Butterworth anti-alias low-pass of order 2, 4 or 8
// with its cutoff fitted - and the one of lowest BIC is taken; then a load cell's ringing (its
// natural frequency and damping fitted, from the best of a coarse scan of frequencies) is added
// when it lowers the BIC by at least the naming threshold. Every fit is reported with its BIC: the
// evidence for the choice. The sensor's parameters are nuisances: reported apart from the soil's
// effects, and held at their fitted values while the effects are selected.
#include <string>
#include <vector>

#include "drop_tests/dataset/sensor_model.h"
#include "drop_tests/gap/diagnose_fit.h"

namespace touchdown::gap {

struct SensorCandidate {
  std::string name;  // "period_mean", "instantaneous", "lowpass4", "lowpass4+load_cell", ...
  dataset::SensorModel sensor;  // as fitted
  std::vector<ParameterEstimate> estimates;  // its fitted parameters (cutoff; frequency, damping)
  double bic = 0.0;
  int parameters = 0;
  bool chosen = false;
  bool screened = false;  // a screening fit only (ranked below the best of its kind)
};

struct SensorInference {
  bool given = false;  // the user named the sampling (--sensor-sampling): nothing inferred
  std::vector<SensorCandidate> candidates;  // in the order fitted
  dataset::SensorModel chosen;
  std::string evidence;  // one sentence: what was chosen over what, by how much
  FitResult base;        // the base fitted under the chosen sensor
};

// Sets problem.sensor to the inferred sensor (problem.sensor_fit back to kFixed) and returns the
// evidence; min_delta_bic is what the load cell must gain to be kept.
SensorInference InferSensor(FitProblem& problem, double min_delta_bic);

}  // namespace touchdown::gap
