#include "drop_tests/gap/law_candidate.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "drop_tests/dataset/calibrate.h"
#include "drop_tests/dataset/compare.h"
#include "drop_tests/dataset/sensor_model.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/pad/effect_soil_response.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::gap {

namespace {

// The Bekker soil fitted on one soil's training drops. The rig has no shear, so c, phi and K do not
// enter; they are set to c = 0, phi = 0, K = 1 m only so the soil passes the bekker block's checks.
rft::SoilParameters FittedRigSoil(const dataset::BekkerFit& fit, const rft::SoilParameters& soil) {
  rft::SoilParameters out = soil;
  out.rft_law_3d = rft::LawKind::kBekker;
  out.bekker.n = fit.bekker.n;
  out.bekker.k_c_N_m_n1 = fit.bekker.k_c_N_m_n1;
  out.bekker.k_phi_N_m_n2 = fit.bekker.k_phi_N_m_n2;
  out.bekker.cohesion_Pa = 0.0;
  out.bekker.friction_angle_rad = 0.0;
  out.bekker.shear_modulus_K_m = 1.0;
  return out;
}

// The held-out drop's force NRMSE on the measured time grid (1 when the simulation fails).
double HeldOutNrmse(const FitProblem& p, const FitDrop& d, const rft::SoilParameters& soil, bool* failed) {
  drop::DropConditions c;
  c.impact_speed_m_s = d.speed_m_s;
  c.mass_kg = d.mass_kg;
  c.gravity_m_s2 = d.gravity_m_s2;
  c.atmosphere = d.atmosphere;
  drop::DropRunOptions options;
  options.rig = p.rig;
  try {
    const drop::PadDrop sim = drop::RunDrop(drop::ResolveDrop(p.pads[d.pad], soil, c, options));
    const dataset::DatasetTrace recorded =
        dataset::RecordedTrace(sim.result, d.gravity_m_s2, {}, d.trace->t_s, p.sensor, d.sample_period_s);
    return dataset::ForceNrmseTime(*d.trace, recorded).value;
  } catch (const integ::IntegrationFailure&) {
    *failed = true;
    return 1.0;
  } catch (const std::invalid_argument&) {
    *failed = true;
    return 1.0;
  }
}

// The training drops of soil s.
dataset::Dataset TrainingDropsOf(const dataset::Dataset& measured, const FitProblem& p, size_t s) {
  dataset::Dataset training;
  training.directory = measured.directory;
  training.extra_columns = measured.extra_columns;
  for (const FitDrop& d : p.drops)
    if (d.soil == static_cast<int>(s) && d.train) training.drops.push_back(measured.drops[d.dataset_index]);
  return training;
}

}  // namespace

std::vector<dataset::BekkerFit> UseBekkerBase(const dataset::Dataset& measured, FitProblem& p) {
  std::vector<dataset::BekkerFit> fits;
  for (size_t s = 0; s < p.soils.size(); ++s) {
    const dataset::Dataset training = TrainingDropsOf(measured, p, s);
    if (training.drops.empty())
      throw MakeInputError(measured.directory, "soil " + p.soils[s].name, "no training drops for the Bekker base");
    fits.push_back(dataset::CalibrateBekker(training, {}));
    p.soils[s] = FittedRigSoil(fits.back(), p.soils[s]);
    p.soils[s].zeta_N_m3 = 1.0;
  }
  p.bekker_intrusions.clear();
  for (const io::PadSpec& pad : p.pads) p.bekker_intrusions.push_back(drop::MakeBekkerRigIntrusion(pad.profile));
  p.bekker_base = true;
  return fits;
}

void StartZetaWhereMissing(const dataset::Dataset& measured, FitProblem& p) {
  for (size_t s = 0; s < p.soils.size(); ++s) {
    if (p.soils[s].zeta_N_m3 > 0.0) continue;
    dataset::Dataset training;
    training.directory = measured.directory;
    training.extra_columns = measured.extra_columns;
    for (const FitDrop& f : p.drops)
      if (f.soil == static_cast<int>(s) && f.train) training.drops.push_back(measured.drops[f.dataset_index]);
    p.soils[s].zeta_N_m3 = dataset::CalibrateZeta(training, {}).front().zeta_N_m3;
  }
}

LawCandidate ScoreBekkerLaw(const dataset::Dataset& measured, const FitProblem& p, double base_force_nrmse) {
  LawCandidate c;
  c.base_held_out_force_nrmse = base_force_nrmse;
  double sum = 0.0;
  try {
    for (size_t s = 0; s < p.soils.size(); ++s) {
      dataset::Dataset training;
      training.directory = measured.directory;
      training.extra_columns = measured.extra_columns;
      for (const FitDrop& d : p.drops)
        if (d.soil == static_cast<int>(s) && d.train) training.drops.push_back(measured.drops[d.dataset_index]);
      if (training.drops.empty()) continue;
      c.fits.push_back(dataset::CalibrateBekker(training, {}));
      const rft::SoilParameters soil = FittedRigSoil(c.fits.back(), p.soils[s]);
      for (const FitDrop& d : p.drops) {
        if (d.soil != static_cast<int>(s) || d.train) continue;
        bool failed = false;
        sum += HeldOutNrmse(p, d, soil, &failed);
        c.failed += failed ? 1 : 0;
        ++c.held_out_drops;
      }
    }
  } catch (const InputError& e) {
    c.applies = false;
    c.why_not = e.what();
    return c;
  }
  if (c.held_out_drops == 0) {
    c.applies = false;
    c.why_not = "no held-out drops";
    return c;
  }
  c.held_out_force_nrmse = sum / c.held_out_drops;
  c.gap_reduction = base_force_nrmse > 0.0 ? 1.0 - c.held_out_force_nrmse / base_force_nrmse : 0.0;
  return c;
}

nlohmann::json LawCandidateJson(const LawCandidate& c) {
  nlohmann::json j{{"law", c.law}, {"applies", c.applies}};
  if (!c.applies) {
    j["why_not"] = c.why_not;
    return j;
  }
  nlohmann::json fits = nlohmann::json::array();
  for (const dataset::BekkerFit& f : c.fits)
    fits.push_back({{"soils", f.soils},
                    {"n", f.bekker.n},
                    {"k_c_kN_m_n1", f.bekker.k_c_N_m_n1 / units::kKilo},
                    {"k_phi_kN_m_n2", f.bekker.k_phi_N_m_n2 / units::kKilo},
                    {"training_drops", f.drops},
                    {"residual_rms_N", f.residual_rms_N},
                    {"method", f.method}});
  j["fits"] = fits;
  j["held_out_drops"] = c.held_out_drops;
  j["failed"] = c.failed;
  j["held_out_force_nrmse"] = c.held_out_force_nrmse;
  j["base_held_out_force_nrmse"] = c.base_held_out_force_nrmse;
  j["gap_reduction_vs_base"] = c.gap_reduction;
  return j;
}

}  // namespace touchdown::gap
