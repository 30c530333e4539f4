#include "rft/contact_wrench.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace touchdown::rft {

namespace {

// A face counts as leading when n.v >= -kParallelTolerance |v|: faces parallel to the motion
// (the side wall of a pad moving straight down) lead by contract, and this keeps them leading
// when their normal, rotated by the pose, picks up a rounding error of order 1e-16.
constexpr double kParallelTolerance = 1e-9;

// Faces turning away from the motion fade out over this band of n.v/|v| (about 1.1 deg) instead
// of switching off at once. A hard switch makes the force jump whenever a face's normal passes
// perpendicular to the motion - the bottom of a pad sliding sideways as its vertical velocity
// changes sign - and the equations then have a sliding mode no integrator can step through. The
// band makes the force Lipschitz in the velocity; faces parallel to the motion still lead fully.
constexpr double kTrailingBand = 0.02;

// Relative speed below which a rotation counts as translation (see `spinning` below). A pad
// dropped straight down picks up an angular velocity of rounding size (1e-11 rad/s measured on
// the lander's pads in case A) from the rounding in its moment; as the pad slows to a few cm/s
// near its stop, 1e-12 |v| would call that a spin and send it down the per-element path (2/3
// of the law evaluations of a case-A landing). A real rotation moves element velocities by far
// more than 1e-9 |v|; below it the stress, Lipschitz in the direction of v, changes by less
// than 1e-9 relative (1e-9 / kTrailingBand for a face in the trailing band).
constexpr double kNegligibleSpin = 1e-9;

// A block of elements is skipped when its box lies at least this far above the ground [m]. The
// box bound is >= every vertex depth computed in the loop (the same affine form, monotone
// rounding), so the margin only guards against a compiler contracting the two differently: a
// skipped block would have contributed nothing, and the sum is bit-identical with or without
// the bounds.
constexpr double kCullMargin = 1e-12;

// Normals closer than this (1-norm) count as equal for reusing the stress of the previous element
// in pure translation: the two triangles of a planar quad get normals that differ by rounding
// only. The laws are continuous in n, so the reuse changes the stress by about this much.
constexpr double kSameNormal = SurfaceElements::kSameNormal;

struct Vec {
  double x, y, z;
};
inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec operator*(double s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec Load(const double* p) { return {p[0], p[1], p[2]}; }

// Exact integrals over the submerged part of one triangle, depth d linear on it (pad frame B):
// depth_integral = int d dA, depth_moment = int d r dA, area = int dA, area_moment = int r dA.
struct Submerged {
  double depth_integral = 0.0;
  Vec depth_moment{0.0, 0.0, 0.0};
  double area = 0.0;
  Vec area_moment{0.0, 0.0, 0.0};
  double area_rate = 0.0;  // d area / d delta when every vertex depth grows by delta
};

// For f linear on a triangle of area A with vertex values f_i: int f dA = A (f0 + f1 + f2) / 3 and
// int f r dA = A / 12 ((f0 + f1 + f2)(p0 + p1 + p2) + f0 p0 + f1 p1 + f2 p2) (from
// int l_i l_j dA = A (1 + delta_ij) / 12 for the barycentric coordinates l_i).
template <bool kAreaMoment>
[[gnu::always_inline]] inline void AddTriangle(double area, double d0, double d1, double d2, Vec p0, Vec p1,
                                               Vec p2, double sign, Submerged& s) {
  const double dsum = d0 + d1 + d2;
  const Vec psum = p0 + p1 + p2;
  constexpr double kThird = 1.0 / 3.0, kTwelfth = 1.0 / 12.0;
  const double signed_area = sign * area;
  s.depth_integral += signed_area * kThird * dsum;
  s.depth_moment = s.depth_moment + (signed_area * kTwelfth) * (dsum * psum + d0 * p0 + d1 * p1 + d2 * p2);
  s.area += signed_area;
  if constexpr (kAreaMoment) s.area_moment = s.area_moment + (signed_area * kThird) * psum;
}

// Clips the triangle by the sign of its vertex depths. One vertex below: the submerged part is
// the corner triangle at it, cut where the depth crosses zero. Two below: the quadrilateral is
// the whole triangle minus the emerged corner triangle at the third vertex (exact, and no
// quadrilateral to split). The corner triangles have depth zero at their cut vertices, so the
// integrals vary continuously as vertices cross the surface.
template <bool kAreaMoment>
[[gnu::always_inline]] inline Submerged ClipAndIntegrate(double area, const double d[3], const Vec p[3]) {
  Submerged s;
  const int below = (d[0] > 0.0) + (d[1] > 0.0) + (d[2] > 0.0);
  if (below == 3) {
    AddTriangle<kAreaMoment>(area, d[0], d[1], d[2], p[0], p[1], p[2], 1.0, s);
  } else if (below == 1) {
    const int i = d[0] > 0.0 ? 0 : (d[1] > 0.0 ? 1 : 2), j = (i + 1) % 3, k = (i + 2) % 3;
    const double tj = d[i] / (d[i] - d[j]), tk = d[i] / (d[i] - d[k]);
    AddTriangle<kAreaMoment>(tj * tk * area, d[i], 0.0, 0.0, p[i], p[i] + tj * (p[j] - p[i]),
                             p[i] + tk * (p[k] - p[i]), 1.0, s);
    s.area_rate = 2.0 * tj * tk * area / d[i];  // area d_i^2 / ((d_i - d_j)(d_i - d_k))
  } else {  // below == 2
    const int k = d[0] <= 0.0 ? 0 : (d[1] <= 0.0 ? 1 : 2), i = (k + 1) % 3, j = (k + 2) % 3;
    const double si = d[k] / (d[k] - d[i]), sj = d[k] / (d[k] - d[j]);
    AddTriangle<kAreaMoment>(area, d[0], d[1], d[2], p[0], p[1], p[2], 1.0, s);
    AddTriangle<kAreaMoment>(si * sj * area, d[k], 0.0, 0.0, p[k], p[k] + si * (p[i] - p[k]),
                             p[k] + sj * (p[j] - p[k]), -1.0, s);
    if (d[k] < 0.0) s.area_rate = -2.0 * si * sj * area / d[k];
  }
  return s;
}

// The integrals of ClipAndIntegrate<true> over the part of a triangle where the depth d > 0 and an
// affine function t >= 0 (vertex values d[k], t[k]): the triangle is clipped by both half-planes
// (Sutherland-Hodgman, at most five corners) and fanned into triangles, each integrated exactly.
// Used where a rotating element's leading boundary (t = 0) crosses it.
inline Submerged ClipTwiceAndIntegrate(double area, const double d[3], const Vec p[3], const double t[3]) {
  struct Corner {
    Vec p;
    double d, t;
  };
  Corner a[5], b[5];
  int na = 3, nb = 0;
  for (int k = 0; k < 3; ++k) a[k] = {p[k], d[k], t[k]};
  auto clip = [](const Corner* in, int n, Corner* out, auto value) {
    int m = 0;
    for (int k = 0; k < n; ++k) {
      const Corner& u = in[k];
      const Corner& w = in[(k + 1) % n];
      const double fu = value(u), fw = value(w);
      if (fu >= 0.0) out[m++] = u;
      if ((fu >= 0.0) != (fw >= 0.0)) {
        const double s = fu / (fu - fw);
        out[m++] = {u.p + s * (w.p - u.p), u.d + s * (w.d - u.d), u.t + s * (w.t - u.t)};
      }
    }
    return m;
  };
  nb = clip(a, na, b, [](const Corner& c) { return c.d; });
  na = clip(b, nb, a, [](const Corner& c) { return c.t; });
  Submerged s;
  if (na < 3) return s;
  // Sub-triangle areas from the cross product, scaled so the fan of the whole triangle sums to
  // `area` (the element's own area, as the other paths use).
  auto twice_area = [](Vec u, Vec v, Vec w) {
    const Vec e1 = v - u, e2 = w - u;
    const double cx = e1.y * e2.z - e1.z * e2.y, cy = e1.z * e2.x - e1.x * e2.z, cz = e1.x * e2.y - e1.y * e2.x;
    return std::sqrt(cx * cx + cy * cy + cz * cz);
  };
  const double whole = twice_area(p[0], p[1], p[2]);
  if (!(whole > 0.0)) return s;
  const double scale = area / whole;
  for (int k = 1; k + 1 < na; ++k) {
    const double sub = scale * twice_area(a[0].p, a[k].p, a[k + 1].p);
    AddTriangle<true>(sub, std::max(a[0].d, 0.0), std::max(a[k].d, 0.0), std::max(a[k + 1].d, 0.0), a[0].p, a[k].p,
                      a[k + 1].p, 1.0, s);
  }
  return s;
}

// d(submerged area)/d(d_k) of a triangle of area `area` for its three vertex depths (0 when all
// are below: the whole triangle). One vertex i below: area f, f = d_i^2 / ((d_i - d_j)(d_i - d_k)),
// df/dd_j = f / (d_i - d_j), df/dd_k = f / (d_i - d_k), df/dd_i = f (2 / d_i - 1/(d_i - d_j) -
// 1/(d_i - d_k)); two below: area (1 - f) at the emerged vertex k, so minus those.
inline void ClippedAreaGradient(double area, const double d[3], double grad[3]) {
  grad[0] = grad[1] = grad[2] = 0.0;
  const int below = (d[0] > 0.0) + (d[1] > 0.0) + (d[2] > 0.0);
  if (below == 3 || below == 0) return;
  const bool corner_below = below == 1;
  const int i = corner_below ? (d[0] > 0.0 ? 0 : (d[1] > 0.0 ? 1 : 2)) : (d[0] <= 0.0 ? 0 : (d[1] <= 0.0 ? 1 : 2));
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  if (d[i] == 0.0) return;  // the emerged corner vanishes: no area changes to first order
  const double a = d[i] - d[j], b = d[i] - d[k];
  const double f = area * d[i] * d[i] / (a * b), sign = corner_below ? 1.0 : -1.0;
  grad[j] = sign * f / a;
  grad[k] = sign * f / b;
  grad[i] = sign * f * (2.0 / d[i] - 1.0 / a - 1.0 / b);
}

// ---- Depth law z_ref (z / z_ref)^p (StressLaw3D::depth_law, p != 1) ----------------------------
//
// The integrals int d^p dA and int d^p r dA over a triangle on which d >= 0 is linear. Cutting it
// at the middle vertex depth along the level line gives two "fans": triangles whose apex P0 has
// depth alpha and whose opposite edge (midpoint M) has the one depth beta. On a fan of area A,
// with s in [0, 1] from the apex to the edge, the level line at s has length ~ s and midpoint
// P0 + s (M - P0), so dA = 2 A s ds and
//   int d^p dA   = 2 A J1,                 J_k = int_0^1 (alpha + s (beta - alpha))^p s^k ds,
//   int d^p r dA = 2 A (J1 P0 + J2 (M - P0)).
// With t = alpha + s D, D = beta - alpha, J1 = D^-2 int_alpha^beta t^p (t - alpha) dt and
// J2 = D^-3 int_alpha^beta t^p (t - alpha)^2 dt, in closed form. The closed forms cancel when D is
// small against alpha (relative error ~ eps (beta / D)^3); there, |D| <= kFanQuadrature min(alpha,
// beta), the integrand is analytic on s in [0, 1] with its branch point t = 0 at least
// 1 / kFanQuadrature fan lengths away, and 8-point Gauss-Legendre is exact to about 1e-19
// (Bernstein ellipse rho ~ 18: error ~ rho^-16). The closed forms are used elsewhere, where their
// cancellation costs at most a factor ~ 3 / 0.2^3 = 375 eps ~ 1e-13 relative.
constexpr double kFanQuadrature = 0.25;

struct FanIntegrals {
  double j1 = 0.0, j2 = 0.0;
};

inline FanIntegrals Fan(double alpha, double beta, double p) {
  FanIntegrals out;
  const double D = beta - alpha;
  if (std::abs(D) <= kFanQuadrature * std::min(alpha, beta)) {
    if (!(alpha > 0.0)) return out;  // alpha = beta = 0: no depth
    // 8-point Gauss-Legendre on [0, 1].
    static constexpr double kX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                     0.9602898564975363};
    static constexpr double kW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                     0.1012285362903763};
    for (int k = 0; k < 4; ++k) {
      for (const double sign : {-1.0, 1.0}) {
        const double s = 0.5 * (1.0 + sign * kX[k]), w = 0.5 * kW[k];
        const double g = std::pow(alpha + s * D, p) * s * w;
        out.j1 += g;
        out.j2 += g * s;
      }
    }
    return out;
  }
  const double p1 = p + 1.0, p2 = p + 2.0, p3 = p + 3.0;
  // t^(p+1) at both ends; antiderivatives of t^p (t - alpha) and t^p (t - alpha)^2.
  auto primitives = [&](double t, double* f1, double* f2) {
    if (!(t > 0.0)) {
      *f1 = *f2 = 0.0;
      return;
    }
    const double tp1 = std::pow(t, p1), tp2 = tp1 * t, tp3 = tp2 * t;
    *f1 = tp2 / p2 - alpha * tp1 / p1;
    *f2 = tp3 / p3 - 2.0 * alpha * tp2 / p2 + alpha * alpha * tp1 / p1;
  };
  double a1, a2, b1, b2;
  primitives(alpha, &a1, &a2);
  primitives(beta, &b1, &b2);
  out.j1 = (b1 - a1) / (D * D);
  out.j2 = (b2 - a2) / (D * D * D);
  return out;
}

// Adds a fan (apex P0 at depth alpha, opposite edge P1 P2 at depth beta, area A).
inline void AddFan(double area, double alpha, double beta, Vec p0, Vec p1, Vec p2, double p, double& integral,
                   Vec& moment) {
  if (!(area > 0.0)) return;
  const FanIntegrals j = Fan(alpha, beta, p);
  const Vec m = 0.5 * (p1 + p2);
  integral += 2.0 * area * j.j1;
  moment = moment + (2.0 * area) * (j.j1 * p0 + j.j2 * (m - p0));
}

// A triangle with vertex depths d_i >= 0: split along the level line of the middle depth.
inline void AddPowerTriangle(double area, double d0, double d1, double d2, Vec p0, Vec p1, Vec p2, double p,
                             double& integral, Vec& moment) {
  double d[3] = {d0, d1, d2};
  Vec q[3] = {p0, p1, p2};
  // Sort by depth: d[0] <= d[1] <= d[2].
  if (d[1] < d[0]) std::swap(d[0], d[1]), std::swap(q[0], q[1]);
  if (d[2] < d[1]) std::swap(d[1], d[2]), std::swap(q[1], q[2]);
  if (d[1] < d[0]) std::swap(d[0], d[1]), std::swap(q[0], q[1]);
  const double span = d[2] - d[0];
  if (!(span > 0.0)) {  // uniform depth: a fan of equal depths
    AddFan(area, d[0], d[0], q[0], q[1], q[2], p, integral, moment);
    return;
  }
  const double t = (d[1] - d[0]) / span;  // the level line runs from q[1] to c on edge q[0] q[2]
  const Vec c = q[0] + t * (q[2] - q[0]);
  AddFan(t * area, d[0], d[1], q[0], q[1], c, p, integral, moment);
  AddFan((1.0 - t) * area, d[2], d[1], q[2], q[1], c, p, integral, moment);
}

// The submerged area alone, as ClipAndIntegrate computes it (same operations, same bits): what a
// trailing element contributes (submerged_area_m2) without its depth integrals.
[[gnu::always_inline]] inline double SubmergedArea(double area, const double d[3]) {
  const int below = (d[0] > 0.0) + (d[1] > 0.0) + (d[2] > 0.0);
  if (below == 3) return area;
  if (below == 1) {
    const int i = d[0] > 0.0 ? 0 : (d[1] > 0.0 ? 1 : 2), j = (i + 1) % 3, k = (i + 2) % 3;
    const double tj = d[i] / (d[i] - d[j]), tk = d[i] / (d[i] - d[k]);
    return tj * tk * area;
  }
  const int k = d[0] <= 0.0 ? 0 : (d[1] <= 0.0 ? 1 : 2), i = (k + 1) % 3, j = (k + 2) % 3;
  const double si = d[k] / (d[k] - d[i]), sj = d[k] / (d[k] - d[j]);
  return area + -1.0 * (si * sj * area);
}

// int d^p dA and int d^p r dA over the submerged part of a triangle (clipped as in
// ClipAndIntegrate), scaled by z_ref^(1 - p); the area terms as ClipAndIntegrate's.
template <bool kAreaMoment>
[[gnu::always_inline]] inline Submerged ClipAndIntegratePower(double area, const double d[3], const Vec p[3],
                                                              double exponent, double scale) {
  Submerged s = ClipAndIntegrate<kAreaMoment>(area, d, p);
  double integral = 0.0;
  Vec moment{0.0, 0.0, 0.0};
  const int below = (d[0] > 0.0) + (d[1] > 0.0) + (d[2] > 0.0);
  if (below == 3) {
    AddPowerTriangle(area, d[0], d[1], d[2], p[0], p[1], p[2], exponent, integral, moment);
  } else if (below == 1) {
    const int i = d[0] > 0.0 ? 0 : (d[1] > 0.0 ? 1 : 2), j = (i + 1) % 3, k = (i + 2) % 3;
    const double tj = d[i] / (d[i] - d[j]), tk = d[i] / (d[i] - d[k]);
    AddFan(tj * tk * area, d[i], 0.0, p[i], p[i] + tj * (p[j] - p[i]), p[i] + tk * (p[k] - p[i]), exponent,
           integral, moment);
  } else {  // below == 2: the quadrilateral p_i p_j q_j q_i as two triangles with depths >= 0
    const int k = d[0] <= 0.0 ? 0 : (d[1] <= 0.0 ? 1 : 2), i = (k + 1) % 3, j = (k + 2) % 3;
    const double si = d[k] / (d[k] - d[i]), sj = d[k] / (d[k] - d[j]);
    const Vec qi = p[k] + si * (p[i] - p[k]), qj = p[k] + sj * (p[j] - p[k]);
    AddPowerTriangle((1.0 - sj) * area, d[i], d[j], 0.0, p[i], p[j], qj, exponent, integral, moment);
    AddFan(sj * (1.0 - si) * area, d[i], 0.0, p[i], qj, qi, exponent, integral, moment);
  }
  s.depth_integral = scale * integral;
  s.depth_moment = scale * moment;
  return s;
}

template <bool kPower, bool kAreaMoment>
[[gnu::always_inline]] inline Submerged Clip(double area, const double d[3], const Vec p[3], double exponent,
                                             double scale) {
  if constexpr (kPower) {
    return ClipAndIntegratePower<kAreaMoment>(area, d, p, exponent, scale);
  } else {
    return ClipAndIntegrate<kAreaMoment>(area, d, p);
  }
}

}  // namespace

// Where the stress law is evaluated. Each submerged element gets one stress per unit depth,
// evaluated with the velocity at the depth-weighted centroid r_c = int d r dA / int d dA of its
// submerged part. Why this point: (1) v = v_WB + w x r is affine in r, so v(r_c) is exactly the
// depth-weighted mean velocity over the submerged part (the weight the stress carries); (2) a
// stress uniform over the element then gives the moment r_c x F exactly, i.e. the moment
// int d r dA x sigma is exact; (3) r_c stays inside the triangle and moves continuously while
// the triangle crosses the surface, and the force (int d dA) sigma goes to zero continuously.
// Integrating the law itself exactly over the element is not possible in closed form (it is
// nonlinear in the direction of v); the error of the one-point rule is second order in the
// element size times the angular rate, and vanishes for pure translation.
//
// Speed: in pure translation v is the same everywhere, so the stress depends on the normal
// alone. Consecutive elements with equal normals (to kSameNormal: a flat bottom, a planar facet
// split into many triangles) form a run: the law is called once per run and only the run's depth
// integral and first moment are summed (the result is the same sum, grouped differently).
//
// Pad-level terms of the law (stress_law_3d.h): kPower selects the depth law's exact z^p
// integration (p = 1 keeps the linear path, compiled separately, so the linear law runs exactly
// as without it); kPadTerms compiles in the penetration, compaction and footprint bookkeeping
// (off for laws without them: the plain contact pays nothing for it); `compaction` sums the CompactionStress area integrals apart and scales them by
// exp(-z_pad / d_c) at the end; `footprint` sums the projected downward-facing area and its rate.
namespace {
template <bool kPower, bool kPadTerms>
ContactWrench ContactWrenchImpl(const SurfaceElements& elements, const PadKinematics& kinematics,
                                const GroundSurface& ground, const StressLaw3D& law, bool compaction,
                                bool footprint) {
  ContactWrench out;
  const int count = elements.size();
  if (count == 0) return out;
  const DepthLaw depth_law = law.depth_law();
  const double exponent = depth_law.exponent;
  const double depth_scale = kPower ? std::pow(depth_law.reference_m, 1.0 - exponent) : 1.0;

  const Eigen::Matrix3d& R = kinematics.R_WB;
  const Eigen::Vector3d& p_WB = kinematics.p_WB;

  // Over a plane, depth is affine in position, so it is computed in B without transforming
  // vertices: depth(p_B) = h0 + g . (p_WB + R p_B) = depth0 + g_B . p_B with g = (sx, sy, -1).
  const auto* plane = dynamic_cast<const PlaneGround*>(&ground);
  double depth0 = 0.0;
  Eigen::Vector3d g_B = Eigen::Vector3d::Zero();
  if (plane != nullptr) {
    const Eigen::Vector3d g_W(plane->slope_x(), plane->slope_y(), -1.0);
    depth0 = plane->height_at_origin_m() + g_W.dot(p_WB);
    g_B = R.transpose() * g_W;
  }

  const double* p0 = elements.p0_B.data();
  const double* p1 = elements.p1_B.data();
  const double* p2 = elements.p2_B.data();
  const double* nb = elements.n_B.data();
  const double* areas = elements.area_m2.data();
  // Scalars rather than Eigen 3x3 products in the loop: it keeps everything in registers.
  const double r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1), r12 = R(1, 2),
               r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
  auto rotate = [&](const Vec& a) {
    return Eigen::Vector3d(r00 * a.x + r01 * a.y + r02 * a.z, r10 * a.x + r11 * a.y + r12 * a.z,
                           r20 * a.x + r21 * a.y + r22 * a.z);
  };
  const double gx = g_B.x(), gy = g_B.y(), gz = g_B.z();
  const Eigen::Vector3d& v0 = kinematics.v_WB_W;
  const Eigen::Vector3d& w0 = kinematics.w_WB_W;
  const Eigen::Vector3d u0_B = R.transpose() * v0, w0_B = R.transpose() * w0;  // for the leading boundary
  // Spin so slow that w x r changes no element's velocity by more than kNegligibleSpin |v| counts
  // as translation (the run path, several times cheaper): a level pad dropped straight down picks
  // up an angular velocity of order 1e-16 rad/s from rounding in its moment, and the stress,
  // Lipschitz in the velocity with constant ~ 1 / kTrailingBand, then moves by < 1e-10.
  const bool bounded = elements.HasBounds();
  bool spinning = !w0.isZero(0.0);
  if (spinning) {
    double r2 = 0.0;
    if (bounded) {
      r2 = elements.max_vertex_radius_m * elements.max_vertex_radius_m;
    } else {
      for (const Eigen::Matrix3Xd* p : {&elements.p0_B, &elements.p1_B, &elements.p2_B})
        r2 = std::max(r2, p->colwise().squaredNorm().maxCoeff());
    }
    spinning = w0.squaredNorm() * r2 > kNegligibleSpin * kNegligibleSpin * v0.squaredNorm();
  }
  // Over a plane, a block whose box is wholly above the ground is skipped (see kCullMargin).
  const bool cull = bounded && plane != nullptr;
  auto block_above_ground = [&](int b) {
    const double* lo = elements.block_min_B.data() + 3 * b;
    const double* hi = elements.block_max_B.data() + 3 * b;
    const double deepest = depth0 + (gx > 0.0 ? gx * hi[0] : gx * lo[0]) + (gy > 0.0 ? gy * hi[1] : gy * lo[1]) +
                           (gz > 0.0 ? gz * hi[2] : gz * lo[2]);
    return deepest < -kCullMargin;
  };

  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double submerged_area = 0.0;
  int leading = 0;

  // Weight of an element whose outward normal makes c = n.v / |v| with its velocity: 1 when it
  // leads (see the header), 0 when it trails by more than kTrailingBand, a smooth step in between.
  auto lead_weight_of = [](double c) {
    if (c >= -kParallelTolerance) return 1.0;
    if (c <= -kTrailingBand) return 0.0;
    const double t = (c + kTrailingBand) / (kTrailingBand - kParallelTolerance);
    return t * t * (3.0 - 2.0 * t);
  };
  auto lead_weight = [&](const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) {
    const double speed2 = v_W.squaredNorm();
    if (!(speed2 > 0.0)) return 0.0;  // at rest: no direction, no RFT stress
    return lead_weight_of(n_W.dot(v_W) / std::sqrt(speed2));
  };
  auto is_zero = [](const Eigen::Vector3d& a) { return a.x() == 0.0 && a.y() == 0.0 && a.z() == 0.0; };

  // The current run (pure translation): its normal, whether it leads, its stresses, and the
  // sums of depth integral / depth moment / area / area moment (in B) of its submerged parts.
  bool run_open = false, run_leads = false, run_dynamic = false, run_compaction = false;
  Vec run_n{0.0, 0.0, 0.0};
  double run_nz = 0.0;  // z of the run's normal in W (footprint)
  Eigen::Vector3d run_sigma = Eigen::Vector3d::Zero(), run_sigma_dyn = Eigen::Vector3d::Zero(),
                  run_sigma_comp = Eigen::Vector3d::Zero();
  // Compaction transient (area integrals, scaled at the end), penetration and footprint.
  Eigen::Vector3d compaction_force = Eigen::Vector3d::Zero(), compaction_moment = Eigen::Vector3d::Zero();
  double penetration = 0.0, footprint_area = 0.0, footprint_rate = 0.0;
  Vec deepest_B{0.0, 0.0, 0.0};  // the deepest submerged vertex (penetration rate)
  // Rate of every depth under the translation alone: g . v0 (g = (sx, sy, -1) over a plane; the
  // vertical rate on any other ground).
  const Eigen::Vector3d g_W = plane != nullptr ? Eigen::Vector3d(plane->slope_x(), plane->slope_y(), -1.0)
                                               : Eigen::Vector3d(0.0, 0.0, -1.0);
  const double depth_rate0 = g_W.dot(kinematics.v_WB_W);
  double run_depth = 0.0, run_area = 0.0;
  Vec run_depth_moment{0.0, 0.0, 0.0}, run_area_moment{0.0, 0.0, 0.0};
  auto flush = [&]() {
    if (!run_open || !run_leads) return;
    force += run_depth * run_sigma;
    moment += rotate(run_depth_moment).cross(run_sigma);
    if (run_dynamic) {
      force += run_area * run_sigma_dyn;
      moment += rotate(run_area_moment).cross(run_sigma_dyn);
    }
    if (run_compaction) {
      compaction_force += run_area * run_sigma_comp;
      compaction_moment += rotate(run_area_moment).cross(run_sigma_comp);
    }
    run_depth = run_area = 0.0;
    run_depth_moment = run_area_moment = Vec{0.0, 0.0, 0.0};
  };

  // Stresses per normal class in translation (SurfaceElements::normal_class), on the stack.
  struct ClassStress {
    double nz;
    bool leads, dynamic, compaction;
    Eigen::Vector3d sigma, sigma_dyn, sigma_comp;
  };
  const bool classes = bounded && !spinning && elements.class_normal_B.cols() > 0;
  std::array<bool, SurfaceElements::kMaxNormalClasses> class_done;
  std::array<ClassStress, SurfaceElements::kMaxNormalClasses> class_stress;
  if (classes) class_done.fill(false);

  // Rotating pads: a batch of leading elements waiting for their stresses (on the stack).
  struct RotatingElement {
    double weight, depth_integral, area;
    Vec depth_moment, area_moment;  // in B
  };
  constexpr int kRotatingBatch = StressBatch::kCapacity;
  std::array<RotatingElement, kRotatingBatch> rotating;
  StressBatch batch;
  int& pending = batch.count;
  const Vec u0b{u0_B.x(), u0_B.y(), u0_B.z()}, w0b{w0_B.x(), w0_B.y(), w0_B.z()};
  const bool dynamic_terms = law.has_dynamic_stress(), area_terms = dynamic_terms || (kPadTerms && compaction);
  Eigen::Matrix3d depth_moment_stress = Eigen::Matrix3d::Zero();  // sum of m_B sigma_W^T
  auto drain_rotating = [&]() {
    law.StressPerDepthBatch(batch);
    for (int i = 0; i < pending; ++i) {
      const RotatingElement& r = rotating[i];
      const Eigen::Vector3d sigma = r.weight * Eigen::Vector3d(batch.sx[i], batch.sy[i], batch.sz[i]);
      force += r.depth_integral * sigma;
      depth_moment_stress += Eigen::Vector3d(r.depth_moment.x, r.depth_moment.y, r.depth_moment.z) * sigma.transpose();
      if (!area_terms) continue;
      const Eigen::Vector3d n_W(batch.nx[i], batch.ny[i], batch.nz[i]), v_W(batch.vx[i], batch.vy[i], batch.vz[i]);
      const Eigen::Vector3d r_W = rotate(r.area_moment);
      if (dynamic_terms) {
        const Eigen::Vector3d sigma_dyn = r.weight * law.DynamicStress(n_W, v_W);
        force += r.area * sigma_dyn;
        moment += r_W.cross(sigma_dyn);
      }
      if (kPadTerms && compaction) {
        const Eigen::Vector3d sigma_comp = r.weight * law.CompactionStress(n_W, v_W);
        compaction_force += r.area * sigma_comp;
        compaction_moment += r_W.cross(sigma_comp);
      }
    }
    pending = 0;
  };

  for (int e = 0; e < count; ++e) {
    if (cull && e % SurfaceElements::kBlockSize == 0 && block_above_ground(e / SurfaceElements::kBlockSize)) {
      e += SurfaceElements::kBlockSize - 1;
      continue;
    }
    const Vec p[3] = {Load(p0 + 3 * e), Load(p1 + 3 * e), Load(p2 + 3 * e)};
    double d[3];
    if (plane != nullptr) {
      for (int k = 0; k < 3; ++k) d[k] = depth0 + gx * p[k].x + gy * p[k].y + gz * p[k].z;
    } else {
      for (int k = 0; k < 3; ++k) d[k] = ground.Depth(p_WB + rotate(p[k]));
    }
    if (d[0] <= 0.0 && d[1] <= 0.0 && d[2] <= 0.0) continue;
    if constexpr (kPadTerms) {
      for (int k = 0; k < 3; ++k)
        if (d[k] > penetration) penetration = d[k], deepest_B = p[k];
    }

    const Vec n_B = Load(nb + 3 * e);
    if (!spinning) {
      if (!run_open ||
          std::abs(n_B.x - run_n.x) + std::abs(n_B.y - run_n.y) + std::abs(n_B.z - run_n.z) > kSameNormal) {
        flush();
        run_open = true;
        run_n = n_B;
        const int cls = classes ? elements.normal_class[e] : -1;
        if (cls >= 0 && class_done[cls]) {  // this normal's stresses are known from an earlier run
          const ClassStress& c = class_stress[cls];
          run_nz = c.nz;
          run_leads = c.leads;
          run_sigma = c.sigma;
          run_sigma_dyn = c.sigma_dyn;
          run_dynamic = c.dynamic;
          run_sigma_comp = c.sigma_comp;
          run_compaction = c.compaction;
        } else {
          const Eigen::Vector3d n_W = cls >= 0 ? rotate(Load(elements.class_normal_B.data() + 3 * cls)) : rotate(n_B);
          run_nz = n_W.z();
          const double weight = lead_weight(n_W, v0);
          run_leads = weight > 0.0;
          if (run_leads) {
            run_sigma = weight * law.StressPerDepth(n_W, v0);
            run_sigma_dyn = weight * law.DynamicStress(n_W, v0);
            run_dynamic = !is_zero(run_sigma_dyn);
            if (kPadTerms && compaction) {
              run_sigma_comp = weight * law.CompactionStress(n_W, v0);
              run_compaction = !is_zero(run_sigma_comp);
            }
          }
          if (cls >= 0) {
            class_done[cls] = true;
            class_stress[cls] = {run_nz, run_leads, run_dynamic, run_compaction, run_sigma, run_sigma_dyn, run_sigma_comp};
          }
        }
      }
      if ((run_dynamic || run_compaction) && run_leads) {
        const Submerged s = Clip<kPower, true>(areas[e], d, p, exponent, depth_scale);
        submerged_area += s.area;
        if (kPadTerms && footprint && run_nz < 0.0)
          footprint_area -= run_nz * s.area, footprint_rate -= run_nz * s.area_rate * depth_rate0;
        if (!(s.depth_integral > 0.0)) continue;
        ++leading;
        run_depth += s.depth_integral;
        run_depth_moment = run_depth_moment + s.depth_moment;
        run_area += s.area;
        run_area_moment = run_area_moment + s.area_moment;
      } else {
        if (!run_leads && !(kPadTerms && footprint && run_nz < 0.0)) {
          submerged_area += SubmergedArea(areas[e], d);  // a trailing face: its area is all it adds
          continue;
        }
        const Submerged s = Clip<kPower, false>(areas[e], d, p, exponent, depth_scale);
        submerged_area += s.area;
        if (kPadTerms && footprint && run_nz < 0.0)
          footprint_area -= run_nz * s.area, footprint_rate -= run_nz * s.area_rate * depth_rate0;
        if (!run_leads || !(s.depth_integral > 0.0)) continue;
        ++leading;
        run_depth += s.depth_integral;
        run_depth_moment = run_depth_moment + s.depth_moment;
      }
      continue;
    }

    // Rotating pad: each element has its own velocity. Worked in B up to the law; the leading
    // elements are buffered and their stresses evaluated in batches (drain_rotating).
    const Submerged s = Clip<kPower, false>(areas[e], d, p, exponent, depth_scale);
    submerged_area += s.area;
    if (kPadTerms && footprint) {
      const Eigen::Vector3d n_W = rotate(n_B);
      if (n_W.z() < 0.0) {
        // d/dt (-n_z a) with n rotating (dn/dt = w x n) and each vertex depth at its own rate.
        double grad[3];
        ClippedAreaGradient(areas[e], d, grad);
        double area_dot = 0.0;
        for (int k = 0; k < 3; ++k)
          if (grad[k] != 0.0) area_dot += grad[k] * (depth_rate0 + g_W.dot(w0.cross(rotate(p[k]))));
        footprint_area -= n_W.z() * s.area;
        footprint_rate -= n_W.z() * area_dot + w0.cross(n_W).z() * s.area;
      }
    }
    if (!(s.depth_integral > 0.0)) continue;
    double depth_integral = s.depth_integral;
    Vec depth_moment = s.depth_moment;
    // Velocity at the depth-weighted centroid c: u0 + w0 x c, in B.
    auto centroid_velocity = [&](double integral, const Vec& m) {
      const Vec c = (1.0 / integral) * m;
      return Vec{u0b.x + w0b.y * c.z - w0b.z * c.y, u0b.y + w0b.z * c.x - w0b.x * c.z,
                 u0b.z + w0b.x * c.y - w0b.y * c.x};
    };
    Vec v_B = centroid_velocity(depth_integral, depth_moment);
    double speed = std::sqrt(v_B.x * v_B.x + v_B.y * v_B.y + v_B.z * v_B.z);
    // Where the element leads: t(r) = n.v(r) + kTrailingBand |v_c| >= 0, affine in r (v_c: the
    // velocity at the submerged part's depth-weighted centroid). When t changes sign over the
    // element (a rotating pad's leading boundary crosses it), only the part with t >= 0 carries
    // stress, taken exactly, with the law at that part's own centroid. The centroid rule alone
    // switched the whole element on or off as the boundary passed its centroid: a kink in the
    // force per element, and thousands of small steps while a tilted pad rights itself.
    bool straddles = false;
    Submerged leading_part;
    if constexpr (!kPower) {
      const double a = n_B.x * u0b.x + n_B.y * u0b.y + n_B.z * u0b.z + kTrailingBand * speed;
      const Vec b{n_B.y * w0b.z - n_B.z * w0b.y, n_B.z * w0b.x - n_B.x * w0b.z,
                  n_B.x * w0b.y - n_B.y * w0b.x};  // n x w: n.(w x r) = r.(n x w)
      double t[3];
      for (int k = 0; k < 3; ++k) t[k] = a + b.x * p[k].x + b.y * p[k].y + b.z * p[k].z;
      if (t[0] < 0.0 && t[1] < 0.0 && t[2] < 0.0) continue;  // trails beyond the band everywhere
      if (t[0] < 0.0 || t[1] < 0.0 || t[2] < 0.0) {
        leading_part = ClipTwiceAndIntegrate(areas[e], d, p, t);
        if (!(leading_part.depth_integral > 0.0)) continue;
        straddles = true;
        depth_integral = leading_part.depth_integral;
        depth_moment = leading_part.depth_moment;
        v_B = centroid_velocity(depth_integral, depth_moment);
        speed = std::sqrt(v_B.x * v_B.x + v_B.y * v_B.y + v_B.z * v_B.z);
      }
    }
    const double weight = speed > 0.0 ? lead_weight_of((n_B.x * v_B.x + n_B.y * v_B.y + n_B.z * v_B.z) / speed) : 0.0;
    if (!(weight > 0.0)) continue;
    ++leading;
    RotatingElement& r = rotating[pending];
    const Eigen::Vector3d n_W = rotate(n_B), v_W = rotate(v_B);
    batch.nx[pending] = n_W.x();
    batch.ny[pending] = n_W.y();
    batch.nz[pending] = n_W.z();
    batch.vx[pending] = v_W.x();
    batch.vy[pending] = v_W.y();
    batch.vz[pending] = v_W.z();
    r.weight = weight;
    r.depth_integral = depth_integral;
    r.depth_moment = depth_moment;
    if (area_terms) {
      // Not proportional to depth: integrated over the submerged area, acting at its centroid.
      const Submerged sa = straddles ? leading_part : ClipAndIntegrate<true>(areas[e], d, p);
      r.area = sa.area;
      r.area_moment = sa.area_moment;
    }
    if (++pending == kRotatingBatch) drain_rotating();
  }
  if (pending > 0) drain_rotating();
  // Moments of the rotating elements: sum (R m_B) x sigma = eps_ijk (R S)_jk, S = sum m_B sigma^T.
  {
    const Eigen::Matrix3d P = R * depth_moment_stress;
    moment += Eigen::Vector3d(P(1, 2) - P(2, 1), P(2, 0) - P(0, 2), P(0, 1) - P(1, 0));
  }
  flush();
  if (kPadTerms && compaction) {
    const double decay = std::exp(-penetration / law.compaction_decay_depth_m());
    force += decay * compaction_force;
    moment += decay * compaction_moment;
  }
  out.force_W = force;
  out.moment_W = moment;
  out.submerged_area_m2 = submerged_area;
  out.leading_elements = leading;
  out.penetration_m = penetration;
  if (footprint) {
    out.footprint_area_m2 = footprint_area;
    out.footprint_area_rate_m2_s = footprint_rate;
    out.penetration_rate_m_s = penetration > 0.0 ? depth_rate0 + g_W.dot(w0.cross(rotate(deepest_B))) : 0.0;
  }
  return out;
}
}  // namespace

ContactWrench ComputeContactWrench(const SurfaceElements& elements, const PadKinematics& kinematics,
                                   const GroundSurface& ground, const StressLaw3D& law) {
  const bool compaction = law.has_compaction();
  const bool footprint = law.added_mass_density_kg_m3() > 0.0;
  const bool power = law.depth_law().exponent != 1.0;
  if (compaction || footprint) {
    return power ? ContactWrenchImpl<true, true>(elements, kinematics, ground, law, compaction, footprint)
                 : ContactWrenchImpl<false, true>(elements, kinematics, ground, law, compaction, footprint);
  }
  return power ? ContactWrenchImpl<true, false>(elements, kinematics, ground, law, false, false)
               : ContactWrenchImpl<false, false>(elements, kinematics, ground, law, false, false);
}

}  // namespace touchdown::rft
