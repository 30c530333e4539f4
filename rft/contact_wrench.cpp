#include "rft/contact_wrench.h"

#include <algorithm>
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
constexpr double kSameNormal = 1e-12;

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
  } else {  // below == 2
    const int k = d[0] <= 0.0 ? 0 : (d[1] <= 0.0 ? 1 : 2), i = (k + 1) % 3, j = (k + 2) % 3;
    const double si = d[k] / (d[k] - d[i]), sj = d[k] / (d[k] - d[j]);
    AddTriangle<kAreaMoment>(area, d[0], d[1], d[2], p[0], p[1], p[2], 1.0, s);
    AddTriangle<kAreaMoment>(si * sj * area, d[k], 0.0, 0.0, p[k], p[k] + si * (p[i] - p[k]),
                             p[k] + sj * (p[j] - p[k]), -1.0, s);
  }
  return s;
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
ContactWrench ComputeContactWrench(const SurfaceElements& elements, const PadKinematics& kinematics,
                                   const GroundSurface& ground, const StressLaw3D& law) {
  ContactWrench out;
  const int count = elements.size();
  if (count == 0) return out;
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

  // Weight of the element with outward normal n_W and velocity v_W: 1 when it leads (see the
  // header), 0 when it trails by more than kTrailingBand, a smooth step in between.
  auto lead_weight = [](const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) {
    const double speed2 = v_W.squaredNorm();
    if (!(speed2 > 0.0)) return 0.0;  // at rest: no direction, no RFT stress
    const double c = n_W.dot(v_W) / std::sqrt(speed2);
    if (c >= -kParallelTolerance) return 1.0;
    if (c <= -kTrailingBand) return 0.0;
    const double t = (c + kTrailingBand) / (kTrailingBand - kParallelTolerance);
    return t * t * (3.0 - 2.0 * t);
  };
  auto is_zero = [](const Eigen::Vector3d& a) { return a.x() == 0.0 && a.y() == 0.0 && a.z() == 0.0; };

  // The current run (pure translation): its normal, whether it leads, its stresses, and the
  // sums of depth integral / depth moment / area / area moment (in B) of its submerged parts.
  bool run_open = false, run_leads = false, run_dynamic = false;
  Vec run_n{0.0, 0.0, 0.0};
  Eigen::Vector3d run_sigma = Eigen::Vector3d::Zero(), run_sigma_dyn = Eigen::Vector3d::Zero();
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
    run_depth = run_area = 0.0;
    run_depth_moment = run_area_moment = Vec{0.0, 0.0, 0.0};
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

    const Vec n_B = Load(nb + 3 * e);
    if (!spinning) {
      if (!run_open ||
          std::abs(n_B.x - run_n.x) + std::abs(n_B.y - run_n.y) + std::abs(n_B.z - run_n.z) > kSameNormal) {
        flush();
        run_open = true;
        run_n = n_B;
        const Eigen::Vector3d n_W = rotate(n_B);
        const double weight = lead_weight(n_W, v0);
        run_leads = weight > 0.0;
        if (run_leads) {
          run_sigma = weight * law.StressPerDepth(n_W, v0);
          run_sigma_dyn = weight * law.DynamicStress(n_W, v0);
          run_dynamic = !is_zero(run_sigma_dyn);
        }
      }
      if (run_dynamic && run_leads) {
        const Submerged s = ClipAndIntegrate<true>(areas[e], d, p);
        submerged_area += s.area;
        if (!(s.depth_integral > 0.0)) continue;
        ++leading;
        run_depth += s.depth_integral;
        run_depth_moment = run_depth_moment + s.depth_moment;
        run_area += s.area;
        run_area_moment = run_area_moment + s.area_moment;
      } else {
        const Submerged s = ClipAndIntegrate<false>(areas[e], d, p);
        submerged_area += s.area;
        if (!run_leads || !(s.depth_integral > 0.0)) continue;
        ++leading;
        run_depth += s.depth_integral;
        run_depth_moment = run_depth_moment + s.depth_moment;
      }
      continue;
    }

    // Rotating pad: each element has its own velocity.
    const Submerged s = ClipAndIntegrate<false>(areas[e], d, p);
    submerged_area += s.area;
    if (!(s.depth_integral > 0.0)) continue;
    const Eigen::Vector3d depth_moment_W = rotate(s.depth_moment);
    const Eigen::Vector3d v_W = v0 + w0.cross(depth_moment_W / s.depth_integral);
    const Eigen::Vector3d n_W = rotate(n_B);
    const double weight = lead_weight(n_W, v_W);
    if (!(weight > 0.0)) continue;
    ++leading;
    const Eigen::Vector3d sigma = weight * law.StressPerDepth(n_W, v_W);
    force += s.depth_integral * sigma;
    moment += depth_moment_W.cross(sigma);  // = r_W x (depth_integral sigma)
    const Eigen::Vector3d sigma_dyn = weight * law.DynamicStress(n_W, v_W);
    if (!is_zero(sigma_dyn)) {
      // Not proportional to depth: integrated over the submerged area, acting at its centroid.
      const Submerged sa = ClipAndIntegrate<true>(areas[e], d, p);
      force += sa.area * sigma_dyn;
      moment += rotate(sa.area_moment).cross(sigma_dyn);
    }
  }
  flush();
  out.force_W = force;
  out.moment_W = moment;
  out.submerged_area_m2 = submerged_area;
  out.leading_elements = leading;
  return out;
}

}  // namespace touchdown::rft
