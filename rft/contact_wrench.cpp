#include "rft/contact_wrench.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "rft/contact_internal.h"

namespace touchdown::rft {

using namespace contact_internal;

namespace {

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

// ---- Depth law z_ref (z / z_ref)^p (PadLevelTerms::depth, p != 1) ----------------------------
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
  if (below == 0) return 0.0;
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
  if (below == 0) return s;
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

namespace {

// The stresses of one normal class in translation (the same for every element with that normal),
// cached per class by ContactWrenchImpl.
struct ClassStress {
  double nz;
  bool leads, dynamic, compaction;
  Eigen::Vector3d sigma, sigma_dyn, sigma_comp;
};

[[gnu::always_inline]] inline bool IsZero(const Eigen::Vector3d& a) {
  return a.x() == 0.0 && a.y() == 0.0 && a.z() == 0.0;
}

// One step of the translation path: the stresses on elements of normal n_W (in W) moving at v_W,
// weighted by how much they lead (0 at rest: no direction, no RFT stress). `leads` false leaves
// the stresses as they were (the caller skips them).
template <bool kPadTerms>
[[gnu::always_inline]] inline void StressOfNormal(const StressLaw3D& law, const PadLevelTerms& pad_terms,
                                                  bool compaction, const Eigen::Vector3d& n_W,
                                                  const Eigen::Vector3d& v_W, double& nz, bool& leads, bool& dynamic,
                                                  bool& has_compaction, Eigen::Vector3d& sigma,
                                                  Eigen::Vector3d& sigma_dyn, Eigen::Vector3d& sigma_comp) {
  nz = n_W.z();
  const double speed2 = v_W.squaredNorm();
  const double weight = speed2 > 0.0 ? LeadWeight(n_W.dot(v_W) / std::sqrt(speed2)) : 0.0;
  leads = weight > 0.0;
  if (!leads) return;
  sigma = weight * law.StressPerDepth(n_W, v_W);
  sigma_dyn = weight * law.DynamicStress(n_W, v_W);
  dynamic = !IsZero(sigma_dyn);
  if (kPadTerms && compaction) {
    sigma_comp = weight * pad_terms.CompactionStress(n_W, v_W);
    has_compaction = !IsZero(sigma_comp);
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
// Pad-level terms (rft/pad_level_terms.h): kPower selects the depth law's exact z^p
// integration (p = 1 keeps the linear path, compiled separately, so the linear law runs exactly
// as without it); kPadTerms compiles in the penetration, compaction and footprint bookkeeping
// (off without them: the plain contact pays nothing for it); `compaction` sums the compaction
// stress's area integrals apart and scales them by exp(-z_pad / d_c) at the end; `footprint` sums the projected downward-facing area and its rate.
namespace {
template <bool kPower, bool kPadTerms>
ContactWrench ContactWrenchImpl(const SurfaceElements& elements, const PadKinematics& kinematics,
                                const GroundSurface& ground, const StressLaw3D& law, const PadLevelTerms& pad_terms,
                                bool compaction, bool footprint) {
  ContactWrench out;
  const int count = elements.size();
  if (count == 0) return out;
  const DepthLaw depth_law = pad_terms.depth;
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
  const bool spinning = IsSpinning(elements, kinematics);
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
        const Eigen::Vector3d sigma_comp = r.weight * pad_terms.CompactionStress(n_W, v_W);
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
          StressOfNormal<kPadTerms>(law, pad_terms, compaction, n_W, v0, run_nz, run_leads, run_dynamic,
                                    run_compaction, run_sigma, run_sigma_dyn, run_sigma_comp);
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
    const LeadingPart lead = LeadingPartOf(s, areas[e], d, p, n_B, u0b, w0b, /*clip_leading=*/!kPower);
    const double weight = lead.weight;
    if (!(weight > 0.0)) continue;
    const double depth_integral = lead.part.depth_integral;
    const Vec depth_moment = lead.part.depth_moment, v_B = lead.v;
    const bool straddles = lead.straddles;
    const Submerged& leading_part = lead.part;
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
    const double decay = std::exp(-penetration / pad_terms.compaction_depth_m);
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
                                   const GroundSurface& ground, const StressLaw3D& law,
                                   const PadLevelTerms& pad_terms) {
  const bool compaction = pad_terms.has_compaction();
  const bool footprint = pad_terms.has_added_mass();
  const bool power = pad_terms.has_power_depth();
  if (!compaction && !footprint && !power && elements.size() > 0 && elements.HasBounds() &&
      !law.has_dynamic_stress() && IsSpinning(elements, kinematics)) {
    if (const auto* plane = dynamic_cast<const PlaneGround*>(&ground))
      return RotatingWrenchOverPlane(elements, kinematics, *plane, law);
  }
  if (compaction || footprint) {
    return power ? ContactWrenchImpl<true, true>(elements, kinematics, ground, law, pad_terms, compaction, footprint)
                 : ContactWrenchImpl<false, true>(elements, kinematics, ground, law, pad_terms, compaction, footprint);
  }
  return power ? ContactWrenchImpl<true, false>(elements, kinematics, ground, law, pad_terms, false, false)
               : ContactWrenchImpl<false, false>(elements, kinematics, ground, law, pad_terms, false, false);
}

}  // namespace touchdown::rft
