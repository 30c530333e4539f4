#pragma once
// A rig drop with a known answer for the importer's tests: a pad of mass m falls freely, touches
// a bed at a known instant and is braked by F = k d^p + c v^2 (a quasi-static power of depth plus
// a dynamic term, which jumps to c v0^2 at contact on a flat face), then rests. Integrated by RK4
// on a fine step and sampled at a DAQ's rate with a chosen sample phase, so the touchdown falls
// between samples; noise is seeded. The load cell reads the soil force (0 in free fall, m g at
// rest), the displacement is the depth (negative above the bed), the accelerometer dv/dt.
#include <cmath>
#include <random>
#include <vector>

namespace touchdown::dataset::testing_drop {

struct DropShape {
  double mass_kg = 1.6, gravity_m_s2 = 9.81, speed_m_s = 1.0;
  double stiffness = 3e4, exponent = 1.0;  // k d^p [N]: a flat pad of 50 mm radius on loose FJS-1
  double dynamic = 13.0;                   // c v^2 [N], c in kg/m (lambda rho pi r^2)
  double pretrigger_s = 0.03, rest_s = 0.05;
  double rate_hz = 5000.0, phase = 0.37;   // the first sample at phase / rate after the record's start
  double touchdown_in_file_s = 12.5;       // the record's clock at touchdown
  double force_noise_N = 0.0, displacement_noise_m = 0.0, acceleration_noise_m_s2 = 0.0;
  double acceleration_bias_m_s2 = 0.0;
  unsigned seed = 1;
};

struct DropRecord {
  std::vector<double> t_s, force_N, depth_m, acceleration_m_s2;
  double final_depth_m = 0.0, stop_s = 0.0;  // the truth: depth at rest, stop time after touchdown
};

inline double SoilForce(const DropShape& s, double d, double v) {
  if (d < 0) return 0.0;
  const double quasi_static = s.stiffness * std::pow(d, s.exponent);
  return v > 0 ? quasi_static + s.dynamic * v * v : std::min(quasi_static, s.mass_kg * s.gravity_m_s2);
}

inline DropRecord MakeDrop(const DropShape& s) {
  // The trajectory from touchdown (d = 0, v = v0) on a 1 us step until the pad stops.
  const double h = 1e-6;
  std::vector<double> depth{0.0}, velocity{s.speed_m_s};
  auto accel = [&](double d, double v) { return s.gravity_m_s2 - SoilForce(s, d, v) / s.mass_kg; };
  while (velocity.back() > 0) {
    const double d = depth.back(), v = velocity.back();
    const double k1v = accel(d, v), k1d = v;
    const double k2v = accel(d + 0.5 * h * k1d, v + 0.5 * h * k1v), k2d = v + 0.5 * h * k1v;
    const double k3v = accel(d + 0.5 * h * k2d, v + 0.5 * h * k2v), k3d = v + 0.5 * h * k2v;
    const double k4v = accel(d + h * k3d, v + h * k3v), k4d = v + h * k3v;
    depth.push_back(d + h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d));
    velocity.push_back(v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v));
  }
  DropRecord r;
  r.stop_s = h * double(depth.size() - 1);
  r.final_depth_m = depth.back();
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double start = -s.pretrigger_s, end = r.stop_s + s.rest_s;
  for (long k = 0;; ++k) {
    const double tau = start + (k + s.phase) / s.rate_hz;  // time since touchdown
    if (tau > end) break;
    double d, v;
    if (tau < 0) {
      v = s.speed_m_s + s.gravity_m_s2 * tau;
      d = s.speed_m_s * tau + 0.5 * s.gravity_m_s2 * tau * tau;
    } else if (tau < r.stop_s) {
      const double x = tau / h;
      const size_t i = static_cast<size_t>(x);
      const double f = x - double(i);
      d = depth[i] + f * (depth[i + 1] - depth[i]);
      v = velocity[i] + f * (velocity[i + 1] - velocity[i]);
    } else {
      d = r.final_depth_m, v = 0.0;
    }
    const double force = tau < 0 ? 0.0 : tau < r.stop_s ? SoilForce(s, d, v) : s.mass_kg * s.gravity_m_s2;
    r.t_s.push_back(s.touchdown_in_file_s + tau);
    r.force_N.push_back(force + s.force_noise_N * normal(rng));
    r.depth_m.push_back(d + s.displacement_noise_m * normal(rng));
    r.acceleration_m_s2.push_back(s.gravity_m_s2 - force / s.mass_kg + s.acceleration_bias_m_s2 +
                                  s.acceleration_noise_m_s2 * normal(rng));
  }
  return r;
}

}  // namespace touchdown::dataset::testing_drop
