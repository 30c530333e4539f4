// The effect library against closed forms: the geometric integrals on a cone, rate damping
// as a damped oscillator, added mass against momentum conservation, inertial drag against the
// Katsuragi-Durian closed form, plus each term's limits and the model-file syntax.
#include "drop_tests/model/effects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <yaml-cpp/yaml.h>

#include "drop_tests/model/effects_yaml.h"
#include "drop_tests/model/model_file.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/io/yaml_fields.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/pad/effect_soil_response.h"
#include "rft/input_error.h"

namespace touchdown::model {
namespace {

using pad::EffectSoilResponse;
using pad::RecordedAt;
using pad::RecordedSample;
using rft::EffectTerms;

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.05, kZeta = 2.0e6, kRho = 1540.0, kMass = 1.6, kG = 9.81;
// A flat pad with a negligible side wall (1e-7 m): the force is zeta pi r^2 d to 1e-6.
constexpr double kThin = 1e-7;
const rft::Li2013Law kLaw;

geom::AxisymmetricIntrusion ThinFlat() { return geom::AxisymmetricIntrusion(geom::MakeFlatProfile(kR, kThin), kLaw); }

EffectSoilResponse Response(const geom::AxisymmetricIntrusion& pad, EffectTerms t, bool air = false) {
  return EffectSoilResponse(pad, {kZeta, kRho, air, t});
}

TEST(EffectGeometry, ConeIntegralsFootprintAndPowerLaw) {
  const double theta = 0.6;  // half-angle from the axis
  const geom::AxisymmetricIntrusion cone(geom::MakeConeProfile(kR, 0.08, theta), kLaw);
  const double d = 0.01, a = d * std::tan(theta);
  EXPECT_NEAR(cone.FootprintRadius(d), a, 1e-12);
  EXPECT_NEAR(cone.FootprintRadiusSlope(d), std::tan(theta), 1e-9);
  for (int k = 0; k <= 3; ++k) {
    const double expected = std::pow(std::sin(theta), k) * kPi * a * a / std::sin(theta);
    EXPECT_NEAR(cone.CosinePowerIntegral(d, k), expected, 1e-12 * expected) << "k " << k;
  }
  // p = 1 is the linear law; p = 2 against an independent midpoint quadrature along the slant.
  EXPECT_NEAR(cone.PowerLawVerticalForce(d, kZeta, 1.0, 0.01), cone.VerticalForce(d, kZeta), 1e-9 * cone.VerticalForce(d, kZeta));
  const double alpha = kLaw.Alpha(kPi / 2 - theta, kPi / 2).z, length = a / std::sin(theta);
  double sum = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double s = (i + 0.5) * length / n;  // arc length from the apex
    const double z = d - s * std::cos(theta), x = s * std::sin(theta);
    sum += alpha * 0.01 * std::pow(z / 0.01, 2.0) * 2 * kPi * x * length / n;
  }
  EXPECT_NEAR(cone.PowerLawVerticalForce(d, kZeta, 2.0, 0.01), kZeta * sum, 1e-6 * kZeta * sum);
  // The flat pad: footprint whole at once, I_k = pi r^2 for k >= 1, the wall in I_0 only.
  const geom::AxisymmetricIntrusion flat(geom::MakeFlatProfile(kR, 0.016), kLaw);
  EXPECT_NEAR(flat.FootprintRadius(1e-6), kR, 1e-15);
  EXPECT_EQ(flat.FootprintRadiusSlope(0.005), 0.0);
  EXPECT_NEAR(flat.CosinePowerIntegral(0.005, 2), kPi * kR * kR, 1e-15);
  EXPECT_NEAR(flat.CosinePowerIntegral(0.005, 0), kPi * kR * kR + 2 * kPi * kR * 0.005, 1e-15);
}

TEST(EffectTerms, EachTermHasItsDocumentedLimit) {
  const geom::AxisymmetricIntrusion pad = ThinFlat();
  const double A = kPi * kR * kR, d = 0.01, v = 1.3;
  const double qs = pad.VerticalForce(d, kZeta);
  EffectTerms none;
  EXPECT_EQ(Response(pad, none).Force(d, v), qs);
  EffectTerms drag;
  drag.inertial_lambda = 2.0;
  EXPECT_NEAR(Response(pad, drag).Force(d, v) - qs, 2.0 * kRho * v * v * A, 1e-9);
  EffectTerms damp;
  damp.damping_c_N_s_m3 = 5e3;
  EXPECT_NEAR(Response(pad, damp).Force(d, v) - qs, 5e3 * v * A, 1e-9);
  EffectTerms peak;
  peak.compaction_k_kg_m3 = 2e4;
  peak.compaction_depth_m = 0.003;
  EXPECT_NEAR(Response(pad, peak).Force(1e-9, v), 2e4 * v * v * A, 1e-3);  // the jump at touchdown
  EXPECT_NEAR(Response(pad, peak).Force(0.1, v) / pad.VerticalForce(0.1, kZeta), 1.0, 1e-9);  // gone deep down
  EffectTerms depth;
  depth.depth_exponent = 1.5;
  EXPECT_NEAR(Response(pad, depth).Force(d, v), kZeta * A * 0.01 * std::pow(d / 0.01, 1.5), 1e-5 * qs);
  EffectTerms gas;
  gas.gas_chi = 0.3;
  gas.gas_c_N_s_m3 = 4e3;
  EXPECT_EQ(Response(pad, gas, false).Force(d, v), qs);  // vacuum: no gas
  EXPECT_NEAR(Response(pad, gas, true).Force(d, 0.0), 0.7 * qs, 1e-9 * qs);
  EXPECT_NEAR(Response(pad, gas, true).Force(d, v) - 0.7 * qs, 4e3 * v * A, 1e-9);
  EXPECT_NEAR(Response(pad, gas, true).StaticCapacity(d), 0.7 * qs, 1e-9 * qs);
  // Added mass: continuous from zero with a finite slope, the cone's volume once whole.
  EffectTerms am;
  am.added_mass_ca = 1.5;
  const EffectSoilResponse r = Response(pad, am);
  EXPECT_EQ(r.AddedMass(0.0), 0.0);
  EXPECT_NEAR(r.AddedMass(1e-9), 0.0, 1e-7);  // slope x 1e-9 m
  EXPECT_NEAR(r.AddedMassSlope(1e-9), 1.5 * kRho * kPi / 3 * kR * kR, 1e-9);
  EXPECT_NEAR(r.AddedMass(0.2), 1.5 * kRho * kPi / 3 * kR * kR * kR, 1e-12);
}

// m x'' = m g - k x - b x' (thin flat pad, rate damping): the stop is the first zero of x'.
TEST(EffectRig, RateDampingMatchesTheDampedOscillator) {
  const geom::AxisymmetricIntrusion pad = ThinFlat();
  EffectTerms t;
  t.damping_c_N_s_m3 = 12000.0;
  const double A = kPi * kR * kR, k = kZeta * A, b = t.damping_c_N_s_m3 * A, v0 = 1.2;
  const pad::RigDropResult r = pad::RunRigDrop({kMass, kG, v0}, Response(pad, t));
  const double gamma = b / (2 * kMass), wd = std::sqrt(k / kMass - gamma * gamma), y0 = -kMass * kG / k;
  const double B = (v0 + gamma * y0) / wd;
  auto y = [&](double s) { return std::exp(-gamma * s) * (y0 * std::cos(wd * s) + B * std::sin(wd * s)); };
  auto v = [&](double s) {
    return std::exp(-gamma * s) * ((-gamma * y0 + wd * B) * std::cos(wd * s) + (-gamma * B - wd * y0) * std::sin(wd * s));
  };
  double lo = 1e-9, hi = kPi / wd;
  for (int i = 0; i < 200; ++i) (v(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double t_stop = 0.5 * (lo + hi), d_stop = y(t_stop) - y0;
  EXPECT_NEAR(r.time_to_rest_s, t_stop, 1e-6 * t_stop);
  EXPECT_NEAR(r.final_penetration_m, d_stop, 1e-5 * d_stop);
  for (const pad::DropSample& s : r.trace) {
    if (s.t_s > 0 && s.t_s < t_stop) {
      EXPECT_NEAR(s.penetration_m, y(s.t_s) - y0, 1e-5 * d_stop) << s.t_s;
    }
  }
}

// With no soil force and (almost) no gravity, the pad and its grains conserve momentum:
// (m + m_a(d)) v = m v0, and the kinetic energy lost is the accretion loss.
TEST(EffectRig, AddedMassConservesMomentum) {
  const geom::AxisymmetricIntrusion pad = ThinFlat();
  EffectTerms t;
  t.added_mass_ca = 2.0;
  const EffectSoilResponse with_soil = Response(pad, t);
  struct GrainsOnly final : pad::VerticalSoilResponse {
    const EffectSoilResponse& r;
    explicit GrainsOnly(const EffectSoilResponse& x) : r(x) {}
    double Force(double, double) const override { return 0.0; }
    double AddedMass(double d) const override { return r.AddedMass(d); }
    double AddedMassSlope(double d) const override { return r.AddedMassSlope(d); }
  } grains(with_soil);
  const pad::RigDropInput in{kMass, 1e-12, 1.0};
  integ::IntegratorOptions o;
  integ::CvodeIntegrator integ(4, [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> yd) {
    pad::RigStrokeDerivative(in, grains, y, yd);
  }, o);
  Eigen::VectorXd y0(4);
  y0 << 1e-12, 1.0, 0.0, 0.0;
  integ.Reset(0.0, y0);
  for (double t_out : {0.005, 0.02, 0.04}) {
    integ.AdvanceTo(t_out);
    const Eigen::VectorXd& y = integ.state();
    const double m_a = grains.AddedMass(y[0]);
    EXPECT_NEAR((kMass + m_a) * y[1], kMass * 1.0, 1e-8) << t_out;
    EXPECT_NEAR(0.5 * (kMass + m_a) * y[1] * y[1] + y[3], 0.5 * kMass, 1e-8) << t_out;
    EXPECT_GT(m_a, 0.0);
  }
}

// Katsuragi & Durian (2007): m dv/dt = m g - m v^2 / d1 - k z has v^2 = s(z) in closed form.
TEST(EffectRig, InertialDragMatchesKatsuragiDurian) {
  const geom::AxisymmetricIntrusion pad = ThinFlat();
  EffectTerms t;
  t.inertial_lambda = 2.0;
  const double A = kPi * kR * kR, k = kZeta * A, d1 = kMass / (t.inertial_lambda * kRho * A), v0 = 1.5;
  const double Ac = kG * d1 + k * d1 * d1 / (2 * kMass), Bc = -k * d1 / kMass;
  auto s = [&](double z) { return Ac + Bc * z + (v0 * v0 - Ac) * std::exp(-2 * z / d1); };
  double lo = 1e-6, hi = 0.5;
  for (int i = 0; i < 200; ++i) (s(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const pad::RigDropResult r = pad::RunRigDrop({kMass, kG, v0}, Response(pad, t));
  EXPECT_NEAR(r.final_penetration_m, 0.5 * (lo + hi), 1e-5 * lo);
  for (const pad::DropSample& x : r.trace) {
    if (x.t_s > 0 && x.t_s < r.time_to_rest_s) {
      EXPECT_NEAR(x.velocity_m_s * x.velocity_m_s, s(x.penetration_m), 1e-5);
    }
  }
  // The force jumps at impact to m v0^2 / d1 (inertial drag), it is not zero.
  EXPECT_NEAR(r.trace[1].force_N, kMass * std::pow(r.trace[1].velocity_m_s, 2) / d1 + k * r.trace[1].penetration_m, 1e-3);
}

class EveryEffect : public ::testing::TestWithParam<const char*> {};

// Every term switched on in a catalogue drop: the energy is accounted for, no rebound.
TEST_P(EveryEffect, PadDropKeepsEnergyBookkeeping) {
  const EffectInfo& info = FindEffect(GetParam());
  Effect e{info.id, {}};
  for (const EffectParameterInfo& p : info.parameters) e.values.push_back(p.start != 0.0 ? 3 * p.start : 2 * p.scale);
  drop::DropConditions c;
  c.impact_speed_m_s = 1.2;
  c.atmosphere = rft::Atmosphere::kAir;
  c.effects = MakeEffectTerms({e});
  for (const char* pad_name : {"flat", "curved"}) {
    const drop::PadDrop drop = drop::RunPadDrop(io::LoadPad(pad_name), io::LoadSoil("fjs1_lp"), c);
    const pad::RigDropResult& r = drop.result;
    const double input = r.impact_energy_J + r.gravity_work_J;
    EXPECT_NEAR(r.dissipated_energy_J, input, 1e-6 * input) << pad_name;
    EXPECT_GT(r.final_penetration_m, 0.0);
    for (const pad::DropSample& s : r.trace) {
      EXPECT_GE(s.velocity_m_s, -1e-12);
      EXPECT_TRUE(std::isfinite(s.force_N));
    }
  }
}
INSTANTIATE_TEST_SUITE_P(Library, EveryEffect,
                         ::testing::Values("inertial_drag", "rate_damping", "added_mass", "compaction_peak",
                                           "depth_exponent", "gas_cushion", "sensor_offset"));

TEST(EffectRecord, SensorOffsetShiftsTimeAndZero) {
  const geom::AxisymmetricIntrusion pad = ThinFlat();
  const pad::RigDropResult r = pad::RunRigDrop({kMass, kG, 1.0}, Response(pad, {}));
  EffectTerms t;
  t.sensor_dz_m = 0.001;
  t.sensor_dt_s = 0.002;
  const RecordedSample a = RecordedAt(r, kG, t, 0.003);
  const RecordedSample b = RecordedAt(r, kG, {}, 0.005);
  EXPECT_NEAR(a.penetration_m, b.penetration_m + 0.001, 1e-15);
  EXPECT_EQ(a.force_N, b.force_N);
  // Before the true touchdown: free fall above the surface, no force.
  t.sensor_dt_s = -0.002;
  const RecordedSample early = RecordedAt(r, kG, t, 0.0);
  EXPECT_NEAR(early.penetration_m, 0.001 - 1.0 * 0.002 + 0.5 * kG * 4e-6, 1e-12);
  EXPECT_EQ(early.force_N, 0.0);
}

TEST(EffectFile, ParsesWritesAndRejects) {
  const std::vector<Effect> effects{{"gas_cushion", {0.3, 5000.0}}, {"compaction_peak", {2e4, 0.003}}};
  const YAML::Node node = EffectsToYaml(effects, {{{0.25, 0.35}, {4000.0, 6000.0}}, {}});
  EXPECT_DOUBLE_EQ(node["compaction_peak"]["d_c_mm"].as<double>(), 3.0);
  const std::vector<Effect> back = ParseEffects(io::YamlFields(node, "m.yaml", "effects"));
  ASSERT_EQ(back.size(), 2u);
  for (const Effect& e : back) {
    const auto& orig = e.id == "gas_cushion" ? effects[0] : effects[1];
    for (size_t i = 0; i < e.values.size(); ++i) EXPECT_NEAR(e.values[i], orig.values[i], 1e-12 * std::abs(orig.values[i]));
  }
  auto rejects = [](const std::string& yaml, const std::string& needle) {
    try {
      ParseEffects(io::YamlFields(YAML::Load(yaml), "m.yaml", "effects"));
      ADD_FAILURE() << "accepted " << yaml;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  rejects("{ballistic: {k: 1}}", "effects.ballistic");
  rejects("{gas_cushion: {chi: 1.5, c_g_N_s_m3: 1}}", "effects.gas_cushion.chi");
  rejects("{gas_cushion: {chi: 0.2}}", "effects.gas_cushion.c_g_N_s_m3");
  rejects("{rate_damping: {c_N_s_m3: 10, c_g: 1}}", "c_g");
  // The model file hook: a valid effect loads, a bad one is named.
  const std::string dir = ::testing::TempDir() + "/effects_model";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/good.yaml") << "schema_version: 1\ntype: model\neffects:\n  rate_damping: {c_N_s_m3: 100}\n";
  std::ofstream(dir + "/bad.yaml") << "schema_version: 1\ntype: model\neffects:\n  rate_damping: {c_N_s_m3: -1}\n";
  const ModelFile m = LoadModelFile(dir + "/good.yaml");
  EXPECT_TRUE(m.HasEffects());
  EXPECT_THROW(LoadModelFile(dir + "/bad.yaml"), InputError);
}

}  // namespace
}  // namespace touchdown::model
