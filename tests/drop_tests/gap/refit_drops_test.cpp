// Each training drop's nuisances fitted again alone after a full fit (FitProblem::
// refit_drop_nuisances): through a ringing load cell the misfit in a drop's touchdown time has a
// valley at each period of the ring, and a drop whose record starts milliseconds after its
// touchdown (a trigger that fired late), its joint descent started the other side of its nominal
// time, stays in one of them; fitted again from a fresh scan it lands in its own, and the fit's cost
// falls.
// The ring is applied here by the test's own integrator (RK4 on the sampled force), not touchdown's.
#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/dataset/synth.h"
#include "drop_tests/gap/diagnose_fit.h"

namespace touchdown::gap {
namespace {

constexpr double kLateTrigger_s = 3e-3;
constexpr size_t kLateDrop = 5;
constexpr double kCell_hz = 800.0, kCellDamping = 0.05;
constexpr double kFine_hz = 50000.0;  // synthesised at, before the load cell
constexpr int kDecimation = 10;       // recorded at 5 kHz

// y'' + 2 c w y' + w^2 y = w^2 F(t), from rest, F linear between the fine samples (RK4 per step).
std::vector<double> ThroughLoadCell(const std::vector<double>& force_N) {
  const double w = 2 * M_PI * kCell_hz, h = 1.0 / kFine_hz;
  std::vector<double> out(force_N.size(), 0.0);
  double y = 0.0, v = 0.0;
  for (size_t i = 0; i + 1 < force_N.size(); ++i) {
    const auto f = [&](double tau) { return force_N[i] + (force_N[i + 1] - force_N[i]) * tau / h; };
    const auto acc = [&](double tau, double yy, double vv) { return w * w * (f(tau) - yy) - 2 * kCellDamping * w * vv; };
    const double k1y = v, k1v = acc(0, y, v);
    const double k2y = v + h / 2 * k1v, k2v = acc(h / 2, y + h / 2 * k1y, v + h / 2 * k1v);
    const double k3y = v + h / 2 * k2v, k3v = acc(h / 2, y + h / 2 * k2y, v + h / 2 * k2v);
    const double k4y = v + h * k3v, k4v = acc(h, y + h * k3y, v + h * k3v);
    y += h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    out[i + 1] = y;
  }
  return out;
}

// Two trials of four conditions (flat and curved pads, two speeds), sampled at instants through an
// 800 Hz load cell at 5 kHz; drop kLateDrop's record starts kLateTrigger_s after its touchdown.
dataset::Dataset Drops() {
  dataset::SynthSpec s;
  s.name = "refit_drops";
  s.source = "refit_drops.yaml";
  s.seed = 5;
  s.rest_duration_s = 0.008;
  s.sample_rate_hz = kFine_hz;
  s.sensor_sampling = pad::SensorSampling::kInstantaneous;
  for (const char* pad : {"flat", "curved"})
    for (double v : {0.8, 1.4})
      for (int trial = 0; trial < 2; ++trial)
        s.drops.push_back({pad, "fjs1_lp", rft::Atmosphere::kVacuum, v, std::nullopt, 9.81, trial});
  s.noise = dataset::SynthNoise{0.05, 1e-6, 0.0, 0.0, 0.01, 1e-7};
  dataset::Dataset ds = dataset::Synthesize(s);
  ds.directory = "in-memory";
  for (dataset::DatasetDrop& d : ds.drops) {
    const std::vector<double> rung = ThroughLoadCell(d.trace.force_N);
    dataset::DatasetTrace recorded;
    for (size_t i = 0; i < d.trace.size(); i += kDecimation) {
      recorded.t_s.push_back(d.trace.t_s[i]);
      recorded.penetration_m.push_back(d.trace.penetration_m[i]);
      recorded.force_N.push_back(rung[i]);
    }
    d.trace = recorded;
  }
  for (double& t : ds.drops[kLateDrop].trace.t_s) t -= kLateTrigger_s;
  return ds;
}

FitResult Fit(bool refit) {
  const dataset::Dataset ds = Drops();
  FitProblem p = MakeFitProblem(ds, std::vector<bool>(ds.drops.size(), false), 2);
  p.sensor = dataset::SensorModel{pad::SensorSampling::kInstantaneous};
  p.sensor.load_cell_hz = kCell_hz;
  p.sensor.load_cell_damping = kCellDamping;
  p.drop_nuisances = true;
  p.spreads = NuisanceSpreads{0.03, 0.01, 2e-3};
  p.refit_drop_nuisances = refit;
  FitResult start;  // the catalogue's zeta, every drop but one at its nominal time: no scan before the descent
  for (const rft::SoilParameters& s : p.soils) start.zeta_N_m3.push_back(s.zeta_N_m3);
  start.nuisances.assign(p.drops.size(), DropNuisance{});
  start.nuisances[kLateDrop].time_s = -kLateTrigger_s;  // the descent starts as far the other side
  return FitCandidate(p, {}, &start);
}

TEST(RefitDrops, ADropWhoseTriggerFiredLateIsFoundAgain) {
  const FitResult joint = Fit(false), refitted = Fit(true);
  // Without the refit the late drop's descent stays in another valley, more than two samples off
  // (the premise; 0.87 ms when written).
  EXPECT_GT(std::abs(joint.nuisances[kLateDrop].time_s - kLateTrigger_s), 5e-4) << joint.nuisances[kLateDrop].time_s;
  // With it, in the late trigger's own valley of the ring (within half its period, 0.625 ms),
  // nearer than the joint descent, and the cost lower. Where in that valley the descent ends depends
  // on the build's rounding (0.007 ms off with GCC, 0.40 ms with the sanitized clang build).
  const double refit_off = std::abs(refitted.nuisances[kLateDrop].time_s - kLateTrigger_s);
  EXPECT_LT(refit_off, 0.5 / kCell_hz);
  EXPECT_LT(refit_off, std::abs(joint.nuisances[kLateDrop].time_s - kLateTrigger_s));
  EXPECT_LT(refitted.cost, joint.cost);
  // The other drops' times stay near their touchdowns (no trigger delay hidden in them).
  for (size_t i = 0; i < refitted.nuisances.size(); ++i)
    if (i != kLateDrop) {
      EXPECT_NEAR(refitted.nuisances[i].time_s, 0.0, 1e-4) << i;
    }
}

}  // namespace
}  // namespace touchdown::gap
