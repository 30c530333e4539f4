// Force evaluation throughput of ComputeContactWrench (target: <= 20 ns per element on one core)
// on 20,000-triangle pads of 100 mm diameter and 16 mm thickness, revolved with 200 sectors,
// 42 bottom rings, 8 wall rows and a top fan: the flat pad (its bottom triangles share one
// normal) and the paper's curved pad (every triangle has its own normal, so the stress law runs
// once per element). Partially submerged and moving obliquely; ns per element = time per
// evaluation / 20,000 (all elements, as the issue counts).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "rft/agarwal2023.h"
#include "rft/contact_wrench.h"
#include "rft/dynamic_term.h"
#include "rft/gravity_constants.h"
#include "rft/li2013_3d.h"
#include "rft/soil.h"
#include "rft/units.h"

namespace {

using namespace touchdown::rft;

SurfaceElements MakeFinePad(bool curved) {
  const int sectors = 200, rings = 42, wall_rows = 8;
  const double r = 0.05, h = 0.016;
  const double a1 = 31.9, a0 = 0.015 / std::expm1(a1 * r);  // curved: rim 1 mm below the top
  std::vector<std::pair<double, double>> profile;
  for (int i = 0; i <= rings; ++i) {
    const double x = r * i / rings;
    profile.push_back({x, curved ? a0 * std::expm1(a1 * x) : 0.0});
  }
  const double rim = profile.back().second;
  for (int i = 1; i <= wall_rows; ++i) profile.push_back({r, rim + (h - rim) * i / wall_rows});
  std::vector<std::array<Eigen::Vector3d, 3>> tri;
  auto at = [&](double x, double u, int j) {
    const double th = 2.0 * std::numbers::pi * j / sectors;
    return Eigen::Vector3d(x * std::cos(th), x * std::sin(th), u);
  };
  auto add = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    if ((b - a).cross(c - a).norm() > 0.0) tri.push_back({a, b, c});
  };
  for (size_t k = 0; k + 1 < profile.size(); ++k)
    for (int j = 0; j < sectors; ++j) {
      const auto [x0, u0] = profile[k];
      const auto [x1, u1] = profile[k + 1];
      add(at(x0, u0, j), at(x1, u1, j + 1), at(x1, u1, j));
      add(at(x0, u0, j), at(x0, u0, j + 1), at(x1, u1, j + 1));
    }
  for (int j = 0; j < sectors; ++j) add(Eigen::Vector3d(0, 0, h), at(r, h, j), at(r, h, j + 1));
  SurfaceElements s;
  s.Resize(static_cast<int>(tri.size()));
  for (int i = 0; i < s.size(); ++i) {
    const Eigen::Vector3d c = (tri[i][1] - tri[i][0]).cross(tri[i][2] - tri[i][0]);
    s.p0_B.col(i) = tri[i][0];
    s.p1_B.col(i) = tri[i][1];
    s.p2_B.col(i) = tri[i][2];
    s.n_B.col(i) = c.normalized();
    s.area_m2(i) = 0.5 * c.norm();
  }
  s.UpdateBounds();  // as footpad_geom's MakeSurfaceElements does for every pad
  return s;
}

// tilt: about x [rad]; depth: of the level pad's lowest point [m]; spin: angular velocity about
// the pad axis [rad/s].
void Run(benchmark::State& state, const StressLaw3D& law, bool curved, double tilt_rad, double depth_m,
         double spin_rad_s) {
  static const SurfaceElements flat = MakeFinePad(false), curved_pad = MakeFinePad(true);
  const SurfaceElements& pad = curved ? curved_pad : flat;
  PadKinematics k;
  k.R_WB = Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -depth_m);
  k.v_WB_W = Eigen::Vector3d(0.5, 0.2, -1.0);
  k.w_WB_W = k.R_WB * Eigen::Vector3d(0.0, 0.0, spin_rad_s);
  const PlaneGround ground;
  ContactWrench w;
  for (auto _ : state) {
    w = ComputeContactWrench(pad, k, ground, law);
    benchmark::DoNotOptimize(w);
  }
  state.SetItemsProcessed(state.iterations() * pad.size());
  state.counters["elements"] = pad.size();
  state.counters["leading"] = w.leading_elements;
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * pad.size(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

const Li2013TreersLaw kLi(3.48e6);
const Agarwal2023Law kAgarwal(AgarwalScalingXi(1540.0, kEarthGravity_m_s2, std::tan(touchdown::units::DegToRad(37.0))), 0.4);
constexpr double kTilt = touchdown::units::DegToRad(10.0);
// Li 2013 with dynamic RFT's inertial term (lambda 1.1, rho 1540 kg/m^3), as fjs1_lp and fjs1_cp
// carry it by default: area terms per element, the general path even when the pad spins.
const DynamicTermLaw kLiDynamic(std::make_unique<Li2013TreersLaw>(3.48e6), 1.1, 1540.0);

// Flat pad, tilted 10 deg, lowest point 5 mm deep: about a third of the bottom is in the soil.
void BM_Flat_Li2013_Tilted(benchmark::State& s) { Run(s, kLi, false, kTilt, 0.005, 0.0); }
void BM_Flat_Agarwal2023_Tilted(benchmark::State& s) { Run(s, kAgarwal, false, kTilt, 0.005, 0.0); }
void BM_Flat_Li2013_TiltedSpinning(benchmark::State& s) { Run(s, kLi, false, kTilt, 0.005, 3.0); }
// Flat pad level, 6 mm deep: the whole bottom and part of the wall in the soil.
void BM_Flat_Dynamic_Tilted(benchmark::State& s) { Run(s, kLiDynamic, false, kTilt, 0.005, 0.0); }
void BM_Flat_Dynamic_TiltedSpinning(benchmark::State& s) { Run(s, kLiDynamic, false, kTilt, 0.005, 3.0); }
void BM_Curved_Dynamic_Level(benchmark::State& s) { Run(s, kLiDynamic, true, 0.0, 0.006, 0.0); }
void BM_Flat_Li2013_LevelDeep(benchmark::State& s) { Run(s, kLi, false, 0.0, 0.006, 0.0); }
// Curved pad level, 6 mm deep (its bottom rises 15 mm to the rim): one law call per element.
void BM_Curved_Li2013_Level(benchmark::State& s) { Run(s, kLi, true, 0.0, 0.006, 0.0); }
void BM_Curved_Agarwal2023_Level(benchmark::State& s) { Run(s, kAgarwal, true, 0.0, 0.006, 0.0); }

BENCHMARK(BM_Flat_Li2013_Tilted)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Flat_Agarwal2023_Tilted)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Flat_Li2013_TiltedSpinning)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Flat_Dynamic_Tilted)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Flat_Dynamic_TiltedSpinning)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Curved_Dynamic_Level)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Flat_Li2013_LevelDeep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Curved_Li2013_Level)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Curved_Agarwal2023_Level)->Unit(benchmark::kMicrosecond);

}  // namespace
