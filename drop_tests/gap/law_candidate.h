#pragma once
// "The gap is the law": beside the effect library, diagnose can try another soil law instead of RFT
// (`touchdown diagnose --law-candidate`, docs/bekker_soil.md). The Bekker law (rft/bekker_law.h) is
// fitted per soil on the training drops (`calibrate --law bekker`: n and the modulus k_c/b + k_phi,
// drop_tests/dataset/calibrate_bekker.h), the held-out drops are simulated on the rig with it, and
// their force NRMSE is compared with the RFT base's. Reported only: the decision of diagnose (which
// effect to name) is unchanged.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/dataset/calibrate_bekker.h"
#include "drop_tests/gap/diagnose_fit.h"

namespace touchdown::gap {

struct LawCandidate {
  std::string law = "bekker";
  bool applies = true;
  std::string why_not;
  std::vector<dataset::BekkerFit> fits;  // one per soil, on its training drops
  int held_out_drops = 0, failed = 0;
  double held_out_force_nrmse = 0.0;       // mean over held-out drops
  double base_held_out_force_nrmse = 0.0;  // RFT's, for the comparison
  double gap_reduction = 0.0;              // 1 - law / base (negative: the law fits worse)
};

// Fits and scores the Bekker law; InputErrors of the fit (a mesh pad) make it not apply.
LawCandidate ScoreBekkerLaw(const dataset::Dataset& measured, const FitProblem& problem, double base_force_nrmse);
nlohmann::json LawCandidateJson(const LawCandidate& c);

// A soil without zeta (a Bekker soil) starts RFT's fit from the closed-form zeta of its training
// drops (dataset::CalibrateZeta), as a model file's zeta would; soils with a zeta are left alone.
void StartZetaWhereMissing(const dataset::Dataset& measured, FitProblem& problem);

// diagnose --base bekker: each soil of `problem` becomes the Bekker soil fitted on its training
// drops (dataset::CalibrateBekker, as `calibrate --law bekker`; c = phi = 0, K = 1 m, which the
// vertical rig never uses), with zeta_N_m3 = 1 so that diagnose's per-soil parameter is the scale
// of its moduli; the pads get their Bekker integrals. Returns the fits, one per soil. Throws
// InputError (a mesh pad, a soil without training drops).
std::vector<dataset::BekkerFit> UseBekkerBase(const dataset::Dataset& measured, FitProblem& problem);

}  // namespace touchdown::gap
