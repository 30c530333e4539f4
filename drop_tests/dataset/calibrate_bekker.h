#pragma once
// Fitting a Bekker soil (rft/bekker_law.h) to measured drops (`touchdown calibrate --law bekker`):
// k_c, k_phi and n instead of zeta, by least squares of force against penetration over the loading
// strokes (LoadingStrokeIndices, calibrate.h), as calibrate fits zeta.
//
// On the loading stroke of an axisymmetric pad of radius b, straight down,
//   F(d) = (k_c / b + k_phi) I_n(d),  I_n(d) = the footprint integral of z^n (the rig's Bekker
//   profile integral, drop::MakeBekkerRigIntrusion, with unit modulus),
// no gravity scaling. For a fixed n the fit is linear in (k_c, k_phi): regressors I_n / b and I_n.
// n is found by golden-section search of the residual sum of squares over [0.2, 2] (each n solving
// its linear problem in closed form). k_c and k_phi can be told apart only by pads of different b
// (Bekker's two plates); with one pad size k_c = 0 and k_phi carries the whole modulus (the fit's
// method says so). Neither may be negative: when the unconstrained solution has one below 0, the
// better of the two one-parameter fits is kept. Mesh pads are refused (no profile integral).
#include <string>
#include <vector>

#include "drop_tests/dataset/calibrate.h"
#include "rft/bekker_parameters.h"

namespace touchdown::dataset {

struct BekkerCalibrationOptions {
  std::optional<rft::Atmosphere> atmosphere;  // only the drops in it; none: all drops
  std::string soil;                           // only the drops on it (catalogue name or path); "": all
  std::string pad;                            // only the drops of it; "": all
};

struct BekkerFit {
  std::vector<std::string> soils;  // the soils of the fitted drops (one fit for all of them)
  rft::BekkerParameters bekker;    // n, k_c, k_phi fitted; c, phi, K as the first soil has them
  int drops = 0;
  long samples = 0;
  int pad_sizes = 0;  // distinct b among the drops' pads
  double residual_rms_N = 0.0;
  std::string method;
};

// Throws InputError (naming the dataset and the drop) on a mesh pad, or when no drops are left.
BekkerFit CalibrateBekker(const Dataset& measured, const BekkerCalibrationOptions& options);

// The soil calibrate writes: the first fitted soil as a Bekker soil named `name`, with the fit's
// n, k_c and k_phi, and its shear parameters kept from that soil's bekker block (0 when it has none:
// the file then fails to load until they are given, which the description says).
rft::SoilParameters CalibratedBekkerSoil(const BekkerFit& fit, const Dataset& measured, const std::string& name);

}  // namespace touchdown::dataset
