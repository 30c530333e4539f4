// calibrate --law bekker (drop_tests/dataset/calibrate_bekker.h) recovers a known Bekker soil from
// noise-free SYNTHETIC rig drops simulated on it: n, k_phi and, with two pad sizes, k_c.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "drop_tests/dataset/calibrate_bekker.h"
#include "drop_tests/dataset/synth.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/catalog/catalog.h"
#include "rft/bekker_law.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::dataset {
namespace {

// The soil the synthetic drops run on (the dataset names toyoura_bekker; only its name is read).
rft::SoilParameters TrueBekkerSoil() {
  rft::SoilParameters s = io::LoadSoil("toyoura_bekker");
  s.bekker.n = 0.8;
  s.bekker.k_c_N_m_n1 = 40e3;
  s.bekker.k_phi_N_m_n2 = 1.5e6;
  return s;
}

Dataset BekkerDataset(const std::vector<std::string>& pads) {
  Dataset ds;
  ds.directory = ".";
  int k = 0;
  for (const std::string& pad : pads)
    for (double v : {0.7, 1.0, 1.5}) {
      drop::DropConditions c;
      c.impact_speed_m_s = v;
      const drop::PadDrop sim = drop::RunDrop(drop::ResolveDrop(io::LoadPad(pad), TrueBekkerSoil(), c));
      DatasetDrop d;
      d.drop_id = "bekker_" + std::to_string(k++);
      d.pad = pad;
      d.soil = "toyoura_bekker";
      d.impact_speed_m_s = v;
      d.pad_mass_kg = sim.mass_kg;
      d.gravity_m_s2 = 9.81;
      for (const pad::DropSample& s : sim.result.trace) {
        d.trace.t_s.push_back(s.t_s);
        d.trace.penetration_m.push_back(s.penetration_m);
        d.trace.force_N.push_back(s.force_N);
      }
      ds.drops.push_back(std::move(d));
    }
  return ds;
}

struct CalibrateBekkerTest : testing_scratch::ScratchDirTest {};

TEST_F(CalibrateBekkerTest, OnePadSizeRecoversNAndTheModulus) {
  const BekkerFit fit = CalibrateBekker(BekkerDataset({"flat"}), {});
  const rft::SoilParameters truth = TrueBekkerSoil();
  EXPECT_EQ(fit.pad_sizes, 1);
  EXPECT_EQ(fit.drops, 3);
  EXPECT_NEAR(fit.bekker.n, truth.bekker.n, 1e-6);
  EXPECT_EQ(fit.bekker.k_c_N_m_n1, 0.0);
  const double modulus = rft::BekkerModulus(truth.bekker, 0.05);
  EXPECT_NEAR(fit.bekker.k_phi_N_m_n2, modulus, 1e-5 * modulus);
  EXPECT_LT(fit.residual_rms_N, 1e-4);  // of forces of ~200 N: n is found to ~1e-8
}

TEST_F(CalibrateBekkerTest, TwoPadSizesTellKcFromKphi) {
  // A 30 mm flat pad beside the 50 mm one: Bekker's two plates.
  std::ofstream(Path("small.yaml")) << "schema_version: 1\nname: small_flat\nmass_kg: 1.0\n"
                                       "profile: {shape: flat, radius_mm: 30, thickness_mm: 16}\n";
  const BekkerFit fit = CalibrateBekker(BekkerDataset({"flat", Path("small.yaml")}), {});
  const rft::SoilParameters truth = TrueBekkerSoil();
  EXPECT_EQ(fit.pad_sizes, 2);
  EXPECT_NEAR(fit.bekker.n, truth.bekker.n, 1e-6);
  EXPECT_NEAR(fit.bekker.k_c_N_m_n1, truth.bekker.k_c_N_m_n1, 1e-4 * truth.bekker.k_c_N_m_n1);
  EXPECT_NEAR(fit.bekker.k_phi_N_m_n2, truth.bekker.k_phi_N_m_n2, 1e-5 * truth.bekker.k_phi_N_m_n2);
  const rft::SoilParameters soil = CalibratedBekkerSoil(fit, BekkerDataset({"flat"}), "fitted");
  EXPECT_EQ(soil.rft_law_3d, rft::LawKind::kBekker);
  EXPECT_EQ(soil.bekker.shear_modulus_K_m, truth.bekker.shear_modulus_K_m);  // kept, not fitted
}

TEST_F(CalibrateBekkerTest, MeshPadsAndEmptySelectionsAreRefused) {
  Dataset ds = BekkerDataset({"flat"});
  BekkerCalibrationOptions only_other;
  only_other.soil = "fjs1_lp";
  EXPECT_THROW(CalibrateBekker(ds, only_other), InputError);
  ds.drops[0].pad = "hex";
  EXPECT_THROW(CalibrateBekker(ds, {}), InputError);
}

}  // namespace
}  // namespace touchdown::dataset

namespace touchdown::dataset {
namespace {

TEST(CalibrateBekkerSynth, SynthRunsBekkerSoilsOnTheirLawAndCalibrateFindsThem) {
  // A synthetic dataset on the lunar Bekker soil (noise as synth's defaults): its drops run on the
  // bekker law, and calibrate --law bekker finds n = 1 and the flat pad's modulus k_c / b + k_phi.
  SynthSpec spec;
  spec.name = "bekker_unit";
  spec.source = "bekker_unit.yaml";
  spec.seed = 11;
  spec.rest_duration_s = 0.01;
  for (double v : {0.7, 1.0, 1.5})
    spec.drops.push_back({"flat", "lunar_nominal_bekker", rft::Atmosphere::kVacuum, v, std::nullopt, 1.62, 0});
  Dataset ds = Synthesize(spec);
  ds.directory = ".";
  const BekkerFit fit = CalibrateBekker(ds, {});
  const double modulus = rft::BekkerModulus(io::LoadSoil("lunar_nominal_bekker").bekker, 0.05);
  EXPECT_NEAR(fit.bekker.n, 1.0, 0.02);
  EXPECT_NEAR(fit.bekker.k_phi_N_m_n2, modulus, 0.05 * modulus);
}

}  // namespace
}  // namespace touchdown::dataset
