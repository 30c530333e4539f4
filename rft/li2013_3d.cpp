#include "rft/li2013_3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rft/units.h"

namespace touchdown::rft {

namespace {

// Treers, Cao & Stuart (RA-L 2021) fits of the speed-fraction weights, full precision as in
// their public release (embodied-dexterity-group/granular_rft_3D, rft_3D_body.m):
//   f1(s)  = a1 (tanh(a2 s - a3) + tanh(a3)) / a4
//   f23(s) = b1 (atanh(b2 s - b3) + atanh(b3)) / b4
// With these constants f1(1) and f23(1) equal 1 to 4e-16; with the four-digit constants of
// physics.md f23(1) = 0.99973 (a value of 1.0012 has also been quoted; we could not reproduce
// it from either set of constants). We divide by the value at s = 1 so that the weights are
// exactly 1 for pure in-plane (or pure lateral) motion whatever the rounding: the 2D law is
// what Li measured (s23 = 1), and the issue requires the vertical intrusion of an axisymmetric
// pad to reduce to the 2D profile integral. The prefactors a1/a4 and b1/b4 cancel in the
// normalised form.
constexpr double kA2 = 3.62263982880971, kA3 = 1.60910808139526;
constexpr double kB2 = 1.61146827229181, kB3 = 0.973746396532650;

// Facets whose normal is within this angle of vertical (|n_h| < sin 1 deg) blend towards
// e2 = horizontal direction of the velocity. Why: as n_h -> 0 the decomposition's limit depends
// on the azimuth n_h comes from (a near-flat plate dragged across its tilt gets only the
// lateral term, dragged along it gets Li's lift and drag), so no rule at n_h = 0 alone is
// continuous. The treatment of a flat plate in its plane of motion is Li's own 2D experiment,
// so it is the limit we blend to; the smooth blend keeps the force continuous in the pad's
// tilt (Treers' release switches abruptly at |n_z| = 1 - 1e-3, and returns NaN at n_h = 0).
const double kHorizontalBand = std::sin(units::kDeg);

// The weights' values at s = 1 (and tanh(a3)), computed once at load time.
const double kTanhA3 = std::tanh(kA3);
const double kF1AtOne = std::tanh(kA2 - kA3) + kTanhA3;
const double kF23AtOne = std::atanh(kB2 - kB3) + std::atanh(kB3);

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace

// Both weights in closed forms with one elementary function each (they are evaluated per element
// in the force loop): tanh x = expm1(2x) / (expm1(2x) + 2), and atanh a + atanh b =
// atanh((a + b) / (1 + a b)) with atanh y = log1p(2y / (1 - y)) / 2.
double TreersLateralWeight(double s1) {
  if (s1 <= 0.0) return 0.0;
  if (s1 >= 1.0) return 1.0;
  const double e = std::expm1(2.0 * (kA2 * s1 - kA3));
  return (e / (e + 2.0) + kTanhA3) / kF1AtOne;
}

double TreersInPlaneWeight(double s23) {
  if (s23 <= 0.0) return 0.0;
  if (s23 >= 1.0) return 1.0;
  // a = b2 s - b3, b = b3: (a + b) / (1 + a b) = b2 s / (1 - b3^2 + b2 b3 s).
  const double y = kB2 * s23 / (1.0 - kB3 * kB3 + kB2 * kB3 * s23);
  return 0.5 * std::log1p(2.0 * y / (1.0 - y)) / kF23AtOne;
}

namespace {
// Derivatives of the closed forms: d/ds tanh(a2 s - a3) = a2 (1 - tanh^2), d/ds atanh(b2 s - b3) =
// b2 / (1 - (b2 s - b3)^2).
double LateralWeightSlope(double s) {
  const double t = std::tanh(kA2 * s - kA3);
  return kA2 * (1.0 - t * t) / kF1AtOne;
}
double InPlaneWeightSlope(double s) {
  const double a = kB2 * s - kB3;
  return kB2 / (1.0 - a * a) / kF23AtOne;
}

// Cubic Hermite interpolation of f on [0, 1] from values and slopes at kNodes + 1 equally spaced
// nodes. The error bound h^4 max(fourth derivative) / 384 gives 1e-11 for f1 and 3e-8 for f23
// (near s = 0, where its atanh argument approaches -0.974); the tests check both.
class HermiteTable {
 public:
  static constexpr int kNodes = 1024;
  HermiteTable(double (*f)(double), double (*slope)(double)) {
    double value[kNodes + 1], step_slope[kNodes + 1];
    for (int i = 0; i <= kNodes; ++i) {
      const double s = static_cast<double>(i) / kNodes;
      value[i] = f(s);
      step_slope[i] = slope(s) / kNodes;  // per unit of the local coordinate t in [0, 1]
    }
    // Each interval's cubic in power form, c0 + t (c1 + t (c2 + t c3)): four adjacent numbers to
    // load and three multiply-adds, from the Hermite basis
    // (2t^3 - 3t^2 + 1) v0 + (t^3 - 2t^2 + t) m0 + (3t^2 - 2t^3) v1 + (t^3 - t^2) m1.
    for (int i = 0; i < kNodes; ++i) {
      const double v0 = value[i], m0 = step_slope[i], v1 = value[i + 1], m1 = step_slope[i + 1];
      cubic_[i] = {v0, m0, -3.0 * v0 - 2.0 * m0 + 3.0 * v1 - m1, 2.0 * v0 + m0 - 2.0 * v1 + m1};
    }
  }
  // Branch-free (selects only, for the law's batch loop). s <= 0 gives f(0) = 0 (c0 of the first
  // interval, exactly); s >= 1 gives exactly 1, the weights' normalised value at s = 1.
  double Clamped(double s) const {
    const double x = std::min(std::max(s, 0.0), 1.0) * kNodes;
    const int i = std::min(static_cast<int>(x), kNodes - 1);
    const double t = x - i;
    const Cubic& c = cubic_[i];
    const double value = c.c0 + t * (c.c1 + t * (c.c2 + t * c.c3));
    return s >= 1.0 ? 1.0 : value;
  }
  double operator()(double s) const {
    if (s <= 0.0) return 0.0;
    if (s >= 1.0) return 1.0;
    return Clamped(s);
  }

 private:
  struct Cubic {
    double c0, c1, c2, c3;
  };
  Cubic cubic_[kNodes];
};

// Built at load time, after the constants above (same translation unit, in order): no guard to
// test in the force loop.
const HermiteTable kLateralTable(&TreersLateralWeight, &LateralWeightSlope);
const HermiteTable kInPlaneTable(&TreersInPlaneWeight, &InPlaneWeightSlope);
const HermiteTable& LateralTable() { return kLateralTable; }
const HermiteTable& InPlaneTable() { return kInPlaneTable; }

[[gnu::always_inline]] inline Alpha2 AlphaFromSinCos(const Li2013Coefficients& c, double sb, double cb, double sg,
                                                     double cg);
}  // namespace

double TreersLateralWeightTabulated(double s1) { return LateralTable()(s1); }
double TreersInPlaneWeightTabulated(double s23) { return InPlaneTable()(s23); }

Alpha2 Li2013AlphaFromSinCos(const Li2013Coefficients& c, double sb, double cb, double sg, double cg) {
  return AlphaFromSinCos(c, sb, cb, sg, cg);
}

namespace {
Alpha2 AlphaFromSinCos(const Li2013Coefficients& c, double sb, double cb, double sg, double cg) {
  // Mirror rule for a velocity with a backward horizontal part (|gamma| > pi/2):
  // alpha(beta, gamma) = (alpha_z, -alpha_x)(-beta, pi - gamma).
  double mirror = 1.0;
  if (cg < 0.0) {
    sb = -sb;
    cg = -cg;
    mirror = -1.0;
  }
  const double s2b = 2.0 * sb * cb, c2b = cb * cb - sb * sb;
  const double sin_2b_plus_g = s2b * cg + c2b * sg, sin_m2b_plus_g = c2b * sg - s2b * cg;
  const double cos_2b_plus_g = c2b * cg - s2b * sg, cos_m2b_plus_g = c2b * cg + s2b * sg;
  Alpha2 a;
  a.z = c.A00 + c.A10 * c2b + c.B11 * sin_2b_plus_g + c.B01 * sg + c.Bm11 * sin_m2b_plus_g;
  a.x = mirror * (c.C11 * cos_2b_plus_g + c.C01 * cg + c.Cm11 * cos_m2b_plus_g + c.D10 * s2b);
  return a;
}
}  // namespace

Li2013TreersLaw::Li2013TreersLaw(double zeta_N_m3, Li2013Coefficients coefficients, double alpha_y)
    : zeta_(zeta_N_m3), c_(coefficients), alpha_y_(alpha_y) {}

[[gnu::always_inline]] inline Eigen::Vector3d Li2013TreersLaw::Decomposed(double sb, double cb, const Eigen::Vector3d& v, double e2x,
                                            double e2y) const {
  // e2 = (e2x, e2y, 0), e1 = e2 x z = (e2y, -e2x, 0). Written for the force loop of a rotating pad,
  // which calls it once per element: two square roots and one division, the weights' tables inline.
  const double u1 = v.x() * e2y - v.y() * e2x;
  const double u2 = v.x() * e2x + v.y() * e2y;
  const double vz = v.z();
  const double r23_sq = u2 * u2 + vz * vz;
  double stress_e2 = 0.0, stress_z = 0.0, s1 = 1.0;
  if (r23_sq > 0.0) {
    // With r23 = |v23| and speed = |v|: s23 = r23 / speed, s1 = |u1| / speed, and gamma, the
    // direction of v23 from e2 (positive moving down), has sin = -vz / r23, cos = u2 / r23.
    const double r23 = std::sqrt(r23_sq), speed = std::sqrt(r23_sq + u1 * u1);
    const double inv = 1.0 / (r23 * speed);
    const double s23 = std::min(1.0, r23_sq * inv);
    s1 = std::min(1.0, std::abs(u1) * r23 * inv);
    const Alpha2 a = AlphaFromSinCos(c_, sb, cb, -vz * speed * inv, u2 * speed * inv);
    const double w = InPlaneTable()(s23);
    stress_e2 = -w * a.x;  // alpha_x > 0 resists motion along +e2
    stress_z = w * a.z;    // alpha_z > 0 pushes up
  }
  const double stress_e1 = u1 == 0.0 ? 0.0 : -LateralTable()(s1) * alpha_y_ * (u1 > 0.0 ? 1.0 : -1.0);
  return zeta_ *
         Eigen::Vector3d(stress_e2 * e2x + stress_e1 * e2y, stress_e2 * e2y - stress_e1 * e2x, stress_z);
}

Eigen::Vector3d Li2013TreersLaw::StressPerDepth(const Eigen::Vector3d& n, const Eigen::Vector3d& v) const {
  const double speed_sq = v.squaredNorm();
  if (!(speed_sq > 0.0)) return Eigen::Vector3d::Zero();
  const double nh = std::sqrt(n.x() * n.x() + n.y() * n.y());
  // beta is the angle of n in the e2-z plane plus pi/2, so sin(beta) = n.e2, cos(beta) = -n_z (a
  // bottom face, n = -z, has beta = 0). With e2 along n's horizontal part, n.e2 = nh and n lies in
  // the plane (n is a unit vector).
  if (nh >= kHorizontalBand) return Decomposed(nh, -n.z(), v, n.x() / nh, n.y() / nh);

  // Near-horizontal facet: e2 along the horizontal part of the velocity; for a vertical
  // velocity any horizontal e2 gives the same stress up to the facet's tilt, so take n's (or x).
  // n then has an e1 part, so it is projected onto the e2-z plane.
  const double uh = std::sqrt(v.x() * v.x() + v.y() * v.y());
  double ex = 1.0, ey = 0.0;
  if (uh > 1e-12 * std::sqrt(speed_sq)) {
    ex = v.x() / uh;
    ey = v.y() / uh;
  } else if (nh > 0.0) {
    ex = n.x() / nh;
    ey = n.y() / nh;
  }
  const double sb = n.x() * ex + n.y() * ey, cb = -n.z(), norm = std::sqrt(sb * sb + cb * cb);
  const Eigen::Vector3d in_motion_plane = Decomposed(sb / norm, cb / norm, v, ex, ey);
  if (nh == 0.0) return in_motion_plane;
  const double w = Smoothstep(nh / kHorizontalBand);
  return w * Decomposed(nh, -n.z(), v, n.x() / nh, n.y() / nh) + (1.0 - w) * in_motion_plane;
}

namespace {
// One element's decomposition for a given unit e2 and unit (sin, cos) of beta, without branches
// (so that loops over a batch vectorise): Li's alphas (mirror rule included), the speed fractions
// and the sign of the lateral motion. r23_sq <= 0 (no motion in the e2-z plane) is not covered.
struct Lane {
  double s23, s1, alpha_x, alpha_z, lateral_sign, r23_sq;
};
[[gnu::always_inline]] inline Lane DecomposeLane(const Li2013Coefficients& c, double sb, double cb, double ex,
                                                 double ey, double vx, double vy, double vz) {
  Lane l;
  const double u1 = vx * ey - vy * ex, u2 = vx * ex + vy * ey;
  l.r23_sq = u2 * u2 + vz * vz;
  const double r23 = std::sqrt(l.r23_sq), speed = std::sqrt(l.r23_sq + u1 * u1);
  const double inv = 1.0 / std::max(r23 * speed, std::numeric_limits<double>::min());
  l.s23 = std::min(1.0, l.r23_sq * inv);
  l.s1 = std::min(1.0, std::abs(u1) * r23 * inv);
  const double sg = -vz * speed * inv, cg_raw = u2 * speed * inv;
  const double mirror = std::copysign(1.0, cg_raw);  // the mirror rule of Li2013AlphaFromSinCos
  const double sbm = mirror * sb, cg = mirror * cg_raw;
  const double s2b = 2.0 * sbm * cb, c2b = cb * cb - sbm * sbm;
  const double sin_2b_plus_g = s2b * cg + c2b * sg, sin_m2b_plus_g = c2b * sg - s2b * cg;
  const double cos_2b_plus_g = c2b * cg - s2b * sg, cos_m2b_plus_g = c2b * cg + s2b * sg;
  l.alpha_z = c.A00 + c.A10 * c2b + c.B11 * sin_2b_plus_g + c.B01 * sg + c.Bm11 * sin_m2b_plus_g;
  l.alpha_x = mirror * (c.C11 * cos_2b_plus_g + c.C01 * cg + c.Cm11 * cos_m2b_plus_g + c.D10 * s2b);
  l.lateral_sign = static_cast<double>(u1 > 0.0) - static_cast<double>(u1 < 0.0);
  return l;
}
}  // namespace

namespace {
// The batch's passes (Li2013TreersLaw::StressPerDepthBatch), each a loop the compiler vectorises.
constexpr int kBatchCap = StressBatch::kCapacity;
struct Lanes {
  alignas(64) double e2x[kBatchCap], e2y[kBatchCap], s23[kBatchCap], s1[kBatchCap], alpha_x[kBatchCap],
      alpha_z[kBatchCap], sign[kBatchCap], nh[kBatchCap];
};

// A: e2 along the normal's horizontal part. Returns the number of near-horizontal facets.
double DecomposeAlongNormals(const Li2013Coefficients& c, const StressBatch& b, Lanes& a,
                             double* blend, double* general) {
  const int count = b.count;
  double near_count = 0.0;
  for (int i = 0; i < count; ++i) {
    const double nx = b.nx[i], ny = b.ny[i], nz = b.nz[i];
    const double nh = std::sqrt(nx * nx + ny * ny);
    const double inv_nh = 1.0 / std::max(nh, std::numeric_limits<double>::min());
    const double ex = nx * inv_nh, ey = ny * inv_nh;
    const Lane l = DecomposeLane(c, nh, -nz, ex, ey, b.vx[i], b.vy[i], b.vz[i]);
    a.nh[i] = nh;
    a.e2x[i] = ex;
    a.e2y[i] = ey;
    a.s23[i] = l.s23;
    a.s1[i] = l.s1;
    a.alpha_x[i] = l.alpha_x;
    a.alpha_z[i] = l.alpha_z;
    a.sign[i] = l.lateral_sign;
    const double x = std::min(nh / kHorizontalBand, 1.0);
    blend[i] = x * x * (3.0 - 2.0 * x);
    general[i] = static_cast<double>(l.r23_sq <= 0.0);
    near_count += static_cast<double>(nh < kHorizontalBand);
  }
  return near_count;
}

// B: e2 along the velocity's horizontal part (the near-horizontal facets' blend partner).
void DecomposeAlongVelocities(const Li2013Coefficients& c, const StressBatch& b, const Lanes& a, Lanes& bl,
                              double* general) {
  const int count = b.count;
  for (int i = 0; i < count; ++i) {
    const double nx = b.nx[i], ny = b.ny[i], nz = b.nz[i], vx = b.vx[i], vy = b.vy[i], vz = b.vz[i];
    // e2: the velocity's horizontal direction; for a (nearly) vertical velocity the normal's (pass
    // A's e2), or x. uh > 1e-12 |v| is tested squared.
    const double uh_sq = vx * vx + vy * vy, uh = std::sqrt(uh_sq);
    const bool from_v = uh_sq > 1e-24 * (uh_sq + vz * vz), from_n = a.nh[i] > 0.0;
    const double inv_uh = 1.0 / std::max(uh, std::numeric_limits<double>::min());
    const double ex = from_v ? vx * inv_uh : (from_n ? a.e2x[i] : 1.0);
    const double ey = from_v ? vy * inv_uh : (from_n ? a.e2y[i] : 0.0);
    const double nh = a.nh[i];
    // n projected onto the e2-z plane.
    const double sb = nx * ex + ny * ey, cb = -nz, inv_norm = 1.0 / std::sqrt(sb * sb + cb * cb);
    const Lane l = DecomposeLane(c, sb * inv_norm, cb * inv_norm, ex, ey, vx, vy, vz);
    bl.e2x[i] = ex;
    bl.e2y[i] = ey;
    bl.s23[i] = l.s23;
    bl.s1[i] = l.s1;
    bl.alpha_x[i] = l.alpha_x;
    bl.alpha_z[i] = l.alpha_z;
    bl.sign[i] = l.lateral_sign;
    // A near-horizontal facet needs B, and A too unless it is exactly horizontal (weight 0).
    const double near = static_cast<double>(nh < kHorizontalBand);
    general[i] = general[i] * static_cast<double>(nh > 0.0) + near * static_cast<double>(l.r23_sq <= 0.0);
  }
}
}  // namespace

void Li2013TreersLaw::StressPerDepthBatch(StressBatch& b) const {
  const int count = b.count;
  // StressPerDepth in passes over the batch. A: e2 along the normal's horizontal part (every facet
  // more than 1 degree from horizontal has only this). B: e2 along the velocity's horizontal part,
  // the near-horizontal facets' blend partner, computed only when the batch has such facets.
  // `general` marks the elements neither covers (no motion in the e2-z plane, rest): they take
  // StressPerDepth itself.
  Lanes a, bl;
  alignas(64) double blend[kBatchCap];    // weight of A: 1 above the band, smoothstep within it
  alignas(64) double general[kBatchCap];  // > 0: take StressPerDepth (a double: vectorises with the rest)
  if (DecomposeAlongNormals(c_, b, a, blend, general) > 0.0) DecomposeAlongVelocities(c_, b, a, bl, general);
  // The weights from their tables, and the stress.
  const HermiteTable& in_plane = InPlaneTable();
  const HermiteTable& lateral = LateralTable();
  auto stress = [&](const Lanes& l, int i, double out[3]) {
    const double w23 = in_plane.Clamped(l.s23[i]), w1 = lateral.Clamped(l.s1[i]);
    const double stress_e2 = -w23 * l.alpha_x[i], stress_z = w23 * l.alpha_z[i];
    const double stress_e1 = -w1 * alpha_y_ * l.sign[i];
    out[0] = zeta_ * (stress_e2 * l.e2x[i] + stress_e1 * l.e2y[i]);
    out[1] = zeta_ * (stress_e2 * l.e2y[i] - stress_e1 * l.e2x[i]);
    out[2] = zeta_ * stress_z;
  };
  for (int i = 0; i < count; ++i) {
    double s[3];
    stress(a, i, s);
    if (blend[i] < 1.0) {  // near-horizontal: blend with B (StressPerDepth's order of operations)
      double t[3];
      stress(bl, i, t);
      if (blend[i] == 0.0) {
        s[0] = t[0], s[1] = t[1], s[2] = t[2];
      } else {
        for (int k = 0; k < 3; ++k) s[k] = blend[i] * s[k] + (1.0 - blend[i]) * t[k];
      }
    }
    b.sx[i] = s[0];
    b.sy[i] = s[1];
    b.sz[i] = s[2];
  }
  for (int i = 0; i < count; ++i) {
    if (general[i] == 0.0) continue;
    const Eigen::Vector3d s =
        StressPerDepth(Eigen::Vector3d(b.nx[i], b.ny[i], b.nz[i]), Eigen::Vector3d(b.vx[i], b.vy[i], b.vz[i]));
    b.sx[i] = s.x();
    b.sy[i] = s.y();
    b.sz[i] = s.z();
  }
}

}  // namespace touchdown::rft
