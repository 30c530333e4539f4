#pragma once
// Internal to rft (not a public header): the contact's constants and the exact triangle clipping
// shared by ComputeContactWrench's general path (contact_wrench.cpp) and its batched path for a
// rotating pad over a plane (contact_wrench_rotating.cpp).
#include <algorithm>
#include <cmath>

#include "rft/contact_wrench.h"
#include "rft/pad_level_terms.h"
#include "rft/surface_elements.h"

namespace touchdown::rft::contact_internal {

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

// The rotation B -> W as nine scalars: in the element loops they stay in registers (Eigen's 3x3
// products there did not).
struct RotationToW {
  double r00, r01, r02, r10, r11, r12, r20, r21, r22;
  explicit RotationToW(const Eigen::Matrix3d& R)
      : r00(R(0, 0)), r01(R(0, 1)), r02(R(0, 2)), r10(R(1, 0)), r11(R(1, 1)), r12(R(1, 2)), r20(R(2, 0)),
        r21(R(2, 1)), r22(R(2, 2)) {}
  [[gnu::always_inline]] inline Eigen::Vector3d operator()(const Vec& a) const {
    return Eigen::Vector3d(r00 * a.x + r01 * a.y + r02 * a.z, r10 * a.x + r11 * a.y + r12 * a.z,
                           r20 * a.x + r21 * a.y + r22 * a.z);
  }
};

// Over a plane, depth is affine in position, so it is computed in B without transforming
// vertices: depth(p_B) = h0 + g . (p_WB + R p_B) = depth0 + g_B . p_B with g = (sx, sy, -1).
struct PlaneDepthInB {
  double depth0 = 0.0, gx = 0.0, gy = 0.0, gz = 0.0;
  static PlaneDepthInB Of(const PlaneGround& plane, const PadKinematics& k) {
    const Eigen::Vector3d g_W(plane.slope_x(), plane.slope_y(), -1.0);
    const Eigen::Vector3d g_B = k.R_WB.transpose() * g_W;
    return {plane.height_at_origin_m() + g_W.dot(k.p_WB), g_B.x(), g_B.y(), g_B.z()};
  }
  [[gnu::always_inline]] inline double At(const Vec& p) const { return depth0 + gx * p.x + gy * p.y + gz * p.z; }
  // Whether block b's box lies wholly above the ground (by more than kCullMargin): its elements
  // contribute nothing.
  [[gnu::always_inline]] inline bool BlockAbove(const SurfaceElements& elements, int b) const {
    const double* lo = elements.block_min_B.data() + 3 * b;
    const double* hi = elements.block_max_B.data() + 3 * b;
    const double deepest = depth0 + (gx > 0.0 ? gx * hi[0] : gx * lo[0]) + (gy > 0.0 ? gy * hi[1] : gy * lo[1]) +
                           (gz > 0.0 ? gz * hi[2] : gz * lo[2]);
    return deepest < -kCullMargin;
  }
  // Whether block b's box lies wholly below the ground (by more than kCullMargin): every vertex of
  // its elements is submerged.
  [[gnu::always_inline]] inline bool BlockBelow(const SurfaceElements& elements, int b) const {
    const double* lo = elements.block_min_B.data() + 3 * b;
    const double* hi = elements.block_max_B.data() + 3 * b;
    const double shallowest = depth0 + (gx > 0.0 ? gx * lo[0] : gx * hi[0]) + (gy > 0.0 ? gy * lo[1] : gy * hi[1]) +
                              (gz > 0.0 ? gz * lo[2] : gz * hi[2]);
    return shallowest > kCullMargin;
  }
};

// The pad's twist in B with its norms, formed once per contact rather than once per block.
struct TwistInB {
  TwistInB(const Eigen::Vector3d& u_B, const Eigen::Vector3d& w_B)
      : u(u_B), w(w_B), u_norm(u_B.norm()), w_norm(w_B.norm()) {}
  Eigen::Vector3d u, w;
  double u_norm, w_norm;
};

// Whether every element of block b trails the pad's motion (twist u + w x r, in B) by more than the
// trailing band, so that none carries stress. With a the block's normal axis, delta its spread, c
// and rho its centre and radius (SurfaceElements), any point r = c + s of it (|s| <= rho) and any
// of its normals n = a + e (|e| <= delta):
//   n.v(r) = n.u + w.(r x n) <= a.u + delta |u| + w.(c x a) + |w| (|c| delta + rho)
//   |v(r)| <= |u + w x c| + |w| rho
// Every element's lead test, n.v(r) + kTrailingBand |v(r')| >= 0 at points r, r' of the element
// (contact_internal.h, LeadingPartOf and PassBlock), then fails. The margin keeps the test on the
// safe side of the elements' own rounding.
inline bool BlockTrails(const SurfaceElements& elements, int b, const TwistInB& t) {
  const Eigen::Vector3d a = elements.block_normal_axis_B.col(b), c = elements.block_centre_B.col(b);
  const double delta = elements.block_normal_spread[b], rho = elements.block_radius_m[b];
  const double lead = a.dot(t.u) + delta * t.u_norm + t.w.dot(c.cross(a)) + t.w_norm * (c.norm() * delta + rho);
  const double speed = (t.u + t.w.cross(c)).norm() + t.w_norm * rho;
  constexpr double kMargin = 1e-9;
  return lead + (kTrailingBand + kMargin) * speed < 0.0;
}

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
// integrals vary continuously as vertices cross the surface. None below: nothing is submerged.
// That case must be handled here rather than left to the callers: the rotating path decides
// which elements touch from depths computed in its vectorised pass and clips with depths
// recomputed per element, and the two may round differently (fused multiply-adds) for a vertex
// within rounding of the surface. Treated as "two below", such a triangle gave a corner fraction
// d_k / (d_k - d_j) between two nearly equal negative depths (1e14 on the hex pad's edge landing
// flat): a force of 1e12 N at t = 0 and CVODE's corrector failing at h = 1e-31.
template <bool kAreaMoment>
[[gnu::always_inline]] inline Submerged ClipAndIntegrate(double area, const double d[3], const Vec p[3]) {
  Submerged s;
  const int below = (d[0] > 0.0) + (d[1] > 0.0) + (d[2] > 0.0);
  if (below == 0) return s;
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
// (Sutherland-Hodgman, at most five corners) and fanned into triangles, each integrated exactly by
// `add(sub_area, d0, d1, d2, p0, p1, p2, s)` (AddTriangle<true> for the linear depth law; the z^p
// depth law integrates its sub-triangles in closed form, contact_wrench.cpp). Used where a rotating
// element's leading boundary (t = 0) crosses it.
struct AddLinearSubTriangle {
  [[gnu::always_inline]] inline void operator()(double sub, double d0, double d1, double d2, Vec p0, Vec p1, Vec p2,
                                                Submerged& s) const {
    AddTriangle<true>(sub, d0, d1, d2, p0, p1, p2, 1.0, s);
  }
};
template <class AddSub = AddLinearSubTriangle>
inline Submerged ClipTwiceAndIntegrate(double area, const double d[3], const Vec p[3], const double t[3],
                                       const AddSub& add = {}) {
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
    add(sub, std::max(a[0].d, 0.0), std::max(a[k].d, 0.0), std::max(a[k + 1].d, 0.0), a[0].p, a[k].p, a[k + 1].p, s);
  }
  return s;
}

// Weight of an element whose outward normal makes c = n.v / |v| with its velocity: 1 when it
// leads (see contact_wrench.h), 0 when it trails by more than kTrailingBand, a smooth step in
// between.
[[gnu::always_inline]] inline double LeadWeight(double c) {
  if (c >= -kParallelTolerance) return 1.0;
  if (c <= -kTrailingBand) return 0.0;
  const double t = (c + kTrailingBand) / (kTrailingBand - kParallelTolerance);
  return t * t * (3.0 - 2.0 * t);
}

// The element ramp's factor (PadKinematics::element_ramp_speed_m_s): speed / ramp below the ramp,
// else 1; 1 when there is no ramp (ramp 0), so the stress is then RFT's to the bit.
[[gnu::always_inline]] inline double RampFactor(double speed, double ramp) {
  return speed < ramp ? speed / ramp : 1.0;
}

// Velocity u + w x c at the centroid c = m / integral of a part whose depth integral and first
// moment are given (all in B).
[[gnu::always_inline]] inline Vec CentroidVelocity(double integral, const Vec& m, const Vec& u, const Vec& w) {
  const Vec c = (1.0 / integral) * m;
  return Vec{u.x + w.y * c.z - w.z * c.y, u.y + w.z * c.x - w.x * c.z, u.z + w.x * c.y - w.y * c.x};
}

// The part of a rotating element that carries stress, from the integrals `s` of its submerged part
// (all in B: vertices p, normal n, the pad's twist u + w x r).
//
// Where the element leads: t(r) = n.v(r) + kTrailingBand |v_c| >= 0, affine in r (v_c: the
// velocity at the submerged part's depth-weighted centroid). When t changes sign over the element
// (a rotating pad's leading boundary crosses it) and `clip_leading`, only the part with t >= 0
// carries stress, taken exactly, with the law at that part's own centroid. The centroid rule alone
// switched the whole element on or off as the boundary passed its centroid: a kink in the force
// per element, and thousands of small steps while a tilted pad rights itself. `add` integrates the
// clipped part's sub-triangles (ClipTwiceAndIntegrate): the z^p depth law clips too, with its own.
struct LeadingPart {
  double weight = 0.0;  // LeadWeight at the part's centroid; 0: no stress
  bool straddles = false;
  Submerged part;       // the leading part's integrals when it straddles, else `s`
  Vec v{0.0, 0.0, 0.0};  // velocity at the part's depth-weighted centroid
};
template <class AddSub = AddLinearSubTriangle>
inline LeadingPart LeadingPartOf(const Submerged& s, double area, const double d[3], const Vec p[3], const Vec& n,
                                 const Vec& u, const Vec& w, bool clip_leading, const AddSub& add = {},
                                 double ramp = 0.0) {
  LeadingPart out;
  out.part = s;
  out.v = CentroidVelocity(s.depth_integral, s.depth_moment, u, w);
  double speed = std::sqrt(out.v.x * out.v.x + out.v.y * out.v.y + out.v.z * out.v.z);
  if (clip_leading) {
    const double a = n.x * u.x + n.y * u.y + n.z * u.z + kTrailingBand * speed;
    const Vec b{n.y * w.z - n.z * w.y, n.z * w.x - n.x * w.z, n.x * w.y - n.y * w.x};  // n.(w x r) = r.(n x w)
    double t[3];
    for (int k = 0; k < 3; ++k) t[k] = a + b.x * p[k].x + b.y * p[k].y + b.z * p[k].z;
    if (t[0] < 0.0 && t[1] < 0.0 && t[2] < 0.0) return out;  // trails beyond the band everywhere
    if (t[0] < 0.0 || t[1] < 0.0 || t[2] < 0.0) {
      out.part = ClipTwiceAndIntegrate(area, d, p, t, add);
      if (!(out.part.depth_integral > 0.0)) return out;
      out.straddles = true;
      out.v = CentroidVelocity(out.part.depth_integral, out.part.depth_moment, u, w);
      speed = std::sqrt(out.v.x * out.v.x + out.v.y * out.v.y + out.v.z * out.v.z);
    }
  }
  if (speed > 0.0)
    out.weight = LeadWeight((n.x * out.v.x + n.y * out.v.y + n.z * out.v.z) / speed) * RampFactor(speed, ramp);
  return out;
}

// Whether the pad's rotation moves any element's velocity by more than kNegligibleSpin |v| (else
// the contact treats it as a translation).
inline bool IsSpinning(const SurfaceElements& elements, const PadKinematics& k) {
  if (k.w_WB_W.isZero(0.0)) return false;
  double r2 = 0.0;
  if (elements.HasBounds()) {
    r2 = elements.max_vertex_radius_m * elements.max_vertex_radius_m;
  } else {
    for (const Eigen::Matrix3Xd* p : {&elements.p0_B, &elements.p1_B, &elements.p2_B})
      r2 = std::max(r2, p->colwise().squaredNorm().maxCoeff());
  }
  return k.w_WB_W.squaredNorm() * r2 > kNegligibleSpin * kNegligibleSpin * k.v_WB_W.squaredNorm();
}

// The stresses of one normal class in translation (the same for every element with that normal):
// the current run's, and cached per class (SurfaceElements::normal_class).
struct ClassStress {
  double nz = 0.0;  // z of the normal in W (footprint)
  bool leads = false, dynamic = false, compaction = false;
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero(), sigma_dyn = Eigen::Vector3d::Zero(),
                  sigma_comp = Eigen::Vector3d::Zero();
};

[[gnu::always_inline]] inline bool IsZero(const Eigen::Vector3d& a) {
  return a.x() == 0.0 && a.y() == 0.0 && a.z() == 0.0;
}

// One step of the translation path: the stresses on elements of normal n_W (in W) moving at v_W,
// weighted by how much they lead (0 at rest: no direction, no RFT stress). `leads` false leaves
// the stresses as they were (the caller skips them).
template <bool kPadTerms>
[[gnu::always_inline]] inline void StressOfNormal(const StressLaw3D& law, const PadLevelTerms& pad_terms,
                                                  bool compaction, double unmobilised, double ramp,
                                                  const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W,
                                                  ClassStress& s) {
  s.nz = n_W.z();
  const double speed2 = v_W.squaredNorm();
  const double speed = std::sqrt(speed2);
  const double weight = speed2 > 0.0 ? LeadWeight(n_W.dot(v_W) / speed) * RampFactor(speed, ramp) : 0.0;
  s.leads = weight > 0.0;
  if (!s.leads) return;
  s.sigma = weight * law.StressPerDepth(n_W, v_W);
  s.sigma_dyn = weight * law.DynamicStress(n_W, v_W);
  if (unmobilised != 0.0) {  // Janosi's shear, not yet fully mobilised (PadKinematics::shear_mobilisation)
    s.sigma -= (weight * unmobilised) * law.MobilisedShearPerDepth(n_W, v_W);
    s.sigma_dyn -= (weight * unmobilised) * law.MobilisedShearStress(n_W, v_W);
  }
  s.dynamic = !IsZero(s.sigma_dyn);
  if (kPadTerms && compaction) {
    s.sigma_comp = weight * pad_terms.CompactionStress(n_W, v_W);
    s.compaction = !IsZero(s.sigma_comp);
  }
}

// The wrench on a rotating pad over a plane for a law without pad-level terms (compaction, added
// mass, a power depth law): ComputeContactWrench's result (to rounding), with the common element -
// wholly submerged, wholly leading - worked in vectorised passes over each block of elements. A law
// with a dynamic stress (StressLaw3D::has_dynamic_stress) has that stress taken over each leading
// element's submerged area, at its centroid, as the general path does. Needs elements with bounds
// (SurfaceElements::HasBounds). Wholly submerged elements that trail the motion at every vertex add
// their area without the per-element code; `skip_trailing` false takes that code for them too (a test
// checks that the two agree bit for bit).
ContactWrench RotatingWrenchOverPlane(const SurfaceElements& elements, const PadKinematics& kinematics,
                                      const PlaneGround& plane, const StressLaw3D& law, bool skip_trailing = true);

}  // namespace touchdown::rft::contact_internal
