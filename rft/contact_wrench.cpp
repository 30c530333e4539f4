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
// 1 / kFanQuadrature fan lengths away, and its binomial series in x = D / alpha (|x| <= 1/4)
// converges geometrically: summed to 1e-17 (Fan). The closed forms are used elsewhere, where their
// cancellation costs at most a factor ~ 3 / 0.2^3 = 375 eps ~ 1e-13 relative.
constexpr double kFanQuadrature = 0.25;
constexpr int kFanSeriesTerms = 64;  // a bound; the series stops far earlier (see Fan)

struct FanIntegrals {
  double j1 = 0.0, j2 = 0.0;
};

inline FanIntegrals Fan(double alpha, double beta, double p) {
  FanIntegrals out;
  const double D = beta - alpha;
  if (std::abs(D) <= kFanQuadrature * std::min(alpha, beta)) {
    if (!(alpha > 0.0)) return out;  // alpha = beta = 0: no depth
    // The binomial series of (alpha + s D)^p = alpha^p (1 + s x)^p, x = D / alpha, |x| <= 1/4:
    //   J1 = alpha^p sum_k C(p, k) x^k / (k + 2),   J2 = alpha^p sum_k C(p, k) x^k / (k + 3).
    // Its terms fall at least as |x|^k k^(-p-1) |C| (|C(p, k)| <= 10 for p <= 5), so it stops below
    // 1e-17 of the sum within ~30 terms; one pow where an 8-point Gauss-Legendre rule takes 8 (and
    // there the pows are half the cost of a lander on a Bekker soil with n != 1).
    const double x = D / alpha;
    double c = 1.0, xk = 1.0, s1 = 0.5, s2 = 1.0 / 3.0;
    for (int k = 0; k < kFanSeriesTerms; ++k) {
      c *= (p - k) / (k + 1.0);
      xk *= x;
      const double term = c * xk;
      s1 += term / (k + 3.0);
      s2 += term / (k + 4.0);
      if (std::abs(term) < 1e-17 * s1) break;
    }
    const double ap = std::pow(alpha, p);
    out.j1 = ap * s1;
    out.j2 = ap * s2;
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

// A sub-triangle of a rotating element's leading part (ClipTwiceAndIntegrate) under the z^p depth
// law: its area terms as the linear law's, its depth integrals int d^p dA, int d^p r dA in closed
// form (AddPowerTriangle; its vertex depths are >= 0), scaled by z_ref^(1 - p).
struct AddPowerSubTriangle {
  double exponent, scale;
  [[gnu::always_inline]] inline void operator()(double sub, double d0, double d1, double d2, Vec p0, Vec p1, Vec p2,
                                                Submerged& s) const {
    Submerged linear;
    AddTriangle<true>(sub, d0, d1, d2, p0, p1, p2, 1.0, linear);
    s.area += linear.area;
    s.area_moment = s.area_moment + linear.area_moment;
    double integral = 0.0;
    Vec moment{0.0, 0.0, 0.0};
    AddPowerTriangle(sub, d0, d1, d2, p0, p1, p2, exponent, integral, moment);
    s.depth_integral += scale * integral;
    s.depth_moment = s.depth_moment + scale * moment;
  }
};

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

// A leading element of a rotating pad waiting for its stress: its weight and depth / area
// integrals (moments in B).
struct RotatingElement {
  double weight, depth_integral, area;
  Vec depth_moment, area_moment;
};
using RotatingBatch = std::array<RotatingElement, StressBatch::kCapacity>;

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
// Rotating pads: each element has its own velocity; leading elements are buffered and their
// stresses evaluated in batches of StressBatch::kCapacity.
//
// Pad-level terms (rft/pad_level_terms.h): kPower selects the depth law's exact z^p
// integration (p = 1 keeps the linear path, compiled separately, so the linear law runs exactly
// as without it); kPadTerms compiles in the penetration, compaction and footprint bookkeeping
// (off without them: the plain contact pays nothing for it); `compaction` sums the compaction
// stress's area integrals apart and scales them by exp(-z_pad / d_c) at the end; `footprint` sums
// the projected downward-facing area and its rate.
//
// Every member function is always inlined into ContactWrenchImpl: the sums then compile to the
// same operations as one loop body (GCC fuses multiply-adds across inlined calls, so a call
// boundary would move results by rounding).
template <bool kPower, bool kPadTerms>
class WrenchSum {
 public:
  [[gnu::always_inline]] WrenchSum(const SurfaceElements& elements, const PadKinematics& kinematics,
                                   const GroundSurface& ground, const StressLaw3D& law,
                                   const PadLevelTerms& pad_terms, bool compaction, bool footprint,
                                   StressBatch& batch, RotatingBatch& rotating)
      : elements_(elements),
        kinematics_(kinematics),
        ground_(ground),
        law_(law),
        pad_terms_(pad_terms),
        compaction_(compaction),
        footprint_(footprint),
        batch_(batch),
        rotating_(rotating),
        plane_(dynamic_cast<const PlaneGround*>(&ground)),
        rotate_(kinematics.R_WB),
        exponent_(pad_terms.depth.exponent),
        depth_scale_(kPower ? std::pow(pad_terms.depth.reference_m, 1.0 - exponent_) : 1.0),
        spinning_(IsSpinning(elements, kinematics)),
        cull_(elements.HasBounds() && plane_ != nullptr),
        classes_(elements.HasBounds() && !spinning_ && elements.class_normal_B.cols() > 0),
        dynamic_terms_(law.has_dynamic_stress()),
        area_terms_(dynamic_terms_ || (kPadTerms && compaction)),
        unmobilised_(law.has_mobilised_shear() ? 1.0 - kinematics.shear_mobilisation : 0.0),
        ramp_(kinematics.element_ramp_speed_m_s) {
    if (plane_ != nullptr) depth_ = PlaneDepthInB::Of(*plane_, kinematics);
    const Eigen::Matrix3d& R = kinematics.R_WB;
    const Eigen::Vector3d u0_B = R.transpose() * kinematics.v_WB_W, w0_B = R.transpose() * kinematics.w_WB_W;
    u0b_ = {u0_B.x(), u0_B.y(), u0_B.z()};
    w0b_ = {w0_B.x(), w0_B.y(), w0_B.z()};
    // Rate of every depth under the translation alone: g . v0 (g = (sx, sy, -1) over a plane; the
    // vertical rate on any other ground).
    g_W_ = plane_ != nullptr ? Eigen::Vector3d(plane_->slope_x(), plane_->slope_y(), -1.0)
                             : Eigen::Vector3d(0.0, 0.0, -1.0);
    depth_rate0_ = g_W_.dot(kinematics.v_WB_W);
    if (classes_) class_done_.fill(false);
  }

  // Over a plane, a block whose box is wholly above the ground is skipped (see kCullMargin).
  [[gnu::always_inline]] bool BlockAboveGround(int b) const { return cull_ && depth_.BlockAbove(elements_, b); }

  // Element e's vertices (in B) and their depths; false when none is submerged.
  [[gnu::always_inline]] bool Submerges(int e, Vec p[3], double d[3]) const {
    const double* p0 = elements_.p0_B.data();
    const double* p1 = elements_.p1_B.data();
    const double* p2 = elements_.p2_B.data();
    p[0] = Load(p0 + 3 * e), p[1] = Load(p1 + 3 * e), p[2] = Load(p2 + 3 * e);
    if (plane_ != nullptr) {
      for (int k = 0; k < 3; ++k) d[k] = depth_.At(p[k]);
    } else {
      for (int k = 0; k < 3; ++k) d[k] = ground_.Depth(kinematics_.p_WB + rotate_(p[k]));
    }
    return !(d[0] <= 0.0 && d[1] <= 0.0 && d[2] <= 0.0);
  }

  [[gnu::always_inline]] void Add(int e, const double d[3], const Vec p[3]) {
    if constexpr (kPadTerms) {
      for (int k = 0; k < 3; ++k)
        if (d[k] > penetration_) penetration_ = d[k], deepest_B_ = p[k];
    }
    const Vec n_B = Load(elements_.n_B.data() + 3 * e);
    if (spinning_)
      AddRotating(e, d, p, n_B);
    else
      AddTranslating(e, d, p, n_B);
  }

  [[gnu::always_inline]] ContactWrench Finish() {
    if (batch_.count > 0) DrainRotating();
    // Moments of the rotating elements: sum (R m_B) x sigma = eps_ijk (R S)_jk, S = sum m_B sigma^T.
    {
      const Eigen::Matrix3d P = kinematics_.R_WB * depth_moment_stress_;
      moment_ += Eigen::Vector3d(P(1, 2) - P(2, 1), P(2, 0) - P(0, 2), P(0, 1) - P(1, 0));
    }
    FlushRun();
    if (kPadTerms && compaction_) {
      const double decay = std::exp(-penetration_ / pad_terms_.compaction_depth_m);
      force_ += decay * compaction_force_;
      moment_ += decay * compaction_moment_;
    }
    ContactWrench out;
    out.force_W = force_;
    out.moment_W = moment_;
    out.submerged_area_m2 = submerged_area_;
    out.leading_elements = leading_;
    out.penetration_m = penetration_;
    if (footprint_) {
      out.footprint_area_m2 = footprint_area_;
      out.footprint_area_rate_m2_s = footprint_rate_;
      out.penetration_rate_m_s =
          penetration_ > 0.0 ? depth_rate0_ + g_W_.dot(kinematics_.w_WB_W.cross(rotate_(deepest_B_))) : 0.0;
    }
    return out;
  }

 private:
  // Translation: the element joins the current run of equal normals or opens a new one.
  [[gnu::always_inline]] void AddTranslating(int e, const double d[3], const Vec p[3], const Vec& n_B) {
    if (!run_open_ || std::abs(n_B.x - run_n_.x) + std::abs(n_B.y - run_n_.y) + std::abs(n_B.z - run_n_.z) > kSameNormal)
      OpenRun(e, n_B);
    const double area = elements_.area_m2[e];
    const bool footprint_face = kPadTerms && footprint_ && run_.nz < 0.0;
    if ((run_.dynamic || run_.compaction) && run_.leads) {
      const Submerged s = Clip<kPower, true>(area, d, p, exponent_, depth_scale_);
      submerged_area_ += s.area;
      if (footprint_face)
        footprint_area_ -= run_.nz * s.area, footprint_rate_ -= run_.nz * s.area_rate * depth_rate0_;
      if (!(s.depth_integral > 0.0)) return;
      ++leading_;
      run_depth_ += s.depth_integral;
      run_depth_moment_ = run_depth_moment_ + s.depth_moment;
      run_area_ += s.area;
      run_area_moment_ = run_area_moment_ + s.area_moment;
      return;
    }
    if (!run_.leads && !footprint_face) {
      submerged_area_ += SubmergedArea(area, d);  // a trailing face: its area is all it adds
      return;
    }
    const Submerged s = Clip<kPower, false>(area, d, p, exponent_, depth_scale_);
    submerged_area_ += s.area;
    if (footprint_face)
      footprint_area_ -= run_.nz * s.area, footprint_rate_ -= run_.nz * s.area_rate * depth_rate0_;
    if (!run_.leads || !(s.depth_integral > 0.0)) return;
    ++leading_;
    run_depth_ += s.depth_integral;
    run_depth_moment_ = run_depth_moment_ + s.depth_moment;
  }

  // A new run of normal n_B: its stresses from the class cache or the law.
  [[gnu::always_inline]] void OpenRun(int e, const Vec& n_B) {
    FlushRun();
    run_open_ = true;
    run_n_ = n_B;
    const int cls = classes_ ? elements_.normal_class[e] : -1;
    if (cls >= 0 && class_done_[cls]) {  // this normal's stresses are known from an earlier run
      run_ = class_stress_[cls];
      return;
    }
    const Eigen::Vector3d n_W = cls >= 0 ? rotate_(Load(elements_.class_normal_B.data() + 3 * cls)) : rotate_(n_B);
    StressOfNormal<kPadTerms>(law_, pad_terms_, compaction_, unmobilised_, ramp_, n_W, kinematics_.v_WB_W, run_);
    if (cls >= 0) {
      class_done_[cls] = true;
      class_stress_[cls] = run_;
    }
  }

  // The current run's stresses times its summed integrals, added to the wrench.
  [[gnu::always_inline]] void FlushRun() {
    if (!run_open_ || !run_.leads) return;
    force_ += run_depth_ * run_.sigma;
    moment_ += rotate_(run_depth_moment_).cross(run_.sigma);
    if (run_.dynamic) {
      force_ += run_area_ * run_.sigma_dyn;
      moment_ += rotate_(run_area_moment_).cross(run_.sigma_dyn);
    }
    if (run_.compaction) {
      compaction_force_ += run_area_ * run_.sigma_comp;
      compaction_moment_ += rotate_(run_area_moment_).cross(run_.sigma_comp);
    }
    run_depth_ = run_area_ = 0.0;
    run_depth_moment_ = run_area_moment_ = Vec{0.0, 0.0, 0.0};
  }

  // Rotation: worked in B up to the law; a leading element joins the batch.
  [[gnu::always_inline]] void AddRotating(int e, const double d[3], const Vec p[3], const Vec& n_B) {
    const double area = elements_.area_m2[e];
    const Submerged s = Clip<kPower, false>(area, d, p, exponent_, depth_scale_);
    submerged_area_ += s.area;
    if (kPadTerms && footprint_) AddRotatingFootprint(area, d, p, n_B, s);
    if (!(s.depth_integral > 0.0)) return;
    // The leading part, clipped at the leading boundary (exactly, under either depth law).
    LeadingPart lead;
    if constexpr (kPower)
      lead = LeadingPartOf(s, area, d, p, n_B, u0b_, w0b_, true, AddPowerSubTriangle{exponent_, depth_scale_}, ramp_);
    else
      lead = LeadingPartOf(s, area, d, p, n_B, u0b_, w0b_, true, AddLinearSubTriangle{}, ramp_);
    if (!(lead.weight > 0.0)) return;
    ++leading_;
    int& pending = batch_.count;
    RotatingElement& r = rotating_[pending];
    const Eigen::Vector3d n_W = rotate_(n_B), v_W = rotate_(lead.v);
    batch_.nx[pending] = n_W.x();
    batch_.ny[pending] = n_W.y();
    batch_.nz[pending] = n_W.z();
    batch_.vx[pending] = v_W.x();
    batch_.vy[pending] = v_W.y();
    batch_.vz[pending] = v_W.z();
    r.weight = lead.weight;
    r.depth_integral = lead.part.depth_integral;
    r.depth_moment = lead.part.depth_moment;
    if (area_terms_) {
      // Not proportional to depth: integrated over the submerged area, acting at its centroid.
      const Submerged sa = lead.straddles ? lead.part : ClipAndIntegrate<true>(area, d, p);
      r.area = sa.area;
      r.area_moment = sa.area_moment;
    }
    if (++pending == StressBatch::kCapacity) DrainRotating();
  }

  // d/dt (-n_z a) of a downward-facing element with n rotating (dn/dt = w x n) and each vertex
  // depth at its own rate.
  [[gnu::always_inline]] void AddRotatingFootprint(double area, const double d[3], const Vec p[3], const Vec& n_B,
                                                   const Submerged& s) {
    const Eigen::Vector3d n_W = rotate_(n_B);
    if (!(n_W.z() < 0.0)) return;
    const Eigen::Vector3d& w0 = kinematics_.w_WB_W;
    double grad[3];
    ClippedAreaGradient(area, d, grad);
    double area_dot = 0.0;
    for (int k = 0; k < 3; ++k)
      if (grad[k] != 0.0) area_dot += grad[k] * (depth_rate0_ + g_W_.dot(w0.cross(rotate_(p[k]))));
    footprint_area_ -= n_W.z() * s.area;
    footprint_rate_ -= n_W.z() * area_dot + w0.cross(n_W).z() * s.area;
  }

  // The batch's stresses from the law, times each element's integrals, added to the wrench.
  [[gnu::always_inline]] void DrainRotating() {
    law_.StressPerDepthBatch(batch_);
    for (int i = 0; i < batch_.count; ++i) {
      const RotatingElement& r = rotating_[i];
      Eigen::Vector3d sigma = r.weight * Eigen::Vector3d(batch_.sx[i], batch_.sy[i], batch_.sz[i]);
      if (unmobilised_ != 0.0) {  // Janosi's shear, not yet fully mobilised
        const Eigen::Vector3d n_W(batch_.nx[i], batch_.ny[i], batch_.nz[i]),
            v_W(batch_.vx[i], batch_.vy[i], batch_.vz[i]);
        sigma -= (r.weight * unmobilised_) * law_.MobilisedShearPerDepth(n_W, v_W);
      }
      force_ += r.depth_integral * sigma;
      depth_moment_stress_ +=
          Eigen::Vector3d(r.depth_moment.x, r.depth_moment.y, r.depth_moment.z) * sigma.transpose();
      if (!area_terms_) continue;
      const Eigen::Vector3d n_W(batch_.nx[i], batch_.ny[i], batch_.nz[i]), v_W(batch_.vx[i], batch_.vy[i], batch_.vz[i]);
      const Eigen::Vector3d r_W = rotate_(r.area_moment);
      if (dynamic_terms_) {
        Eigen::Vector3d sigma_dyn = r.weight * law_.DynamicStress(n_W, v_W);
        if (unmobilised_ != 0.0) sigma_dyn -= (r.weight * unmobilised_) * law_.MobilisedShearStress(n_W, v_W);
        force_ += r.area * sigma_dyn;
        moment_ += r_W.cross(sigma_dyn);
      }
      if (kPadTerms && compaction_) {
        const Eigen::Vector3d sigma_comp = r.weight * pad_terms_.CompactionStress(n_W, v_W);
        compaction_force_ += r.area * sigma_comp;
        compaction_moment_ += r_W.cross(sigma_comp);
      }
    }
    batch_.count = 0;
  }

  const SurfaceElements& elements_;
  const PadKinematics& kinematics_;
  const GroundSurface& ground_;
  const StressLaw3D& law_;
  const PadLevelTerms& pad_terms_;
  const bool compaction_, footprint_;
  StressBatch& batch_;
  RotatingBatch& rotating_;
  const PlaneGround* const plane_;
  const RotationToW rotate_;  // scalars rather than Eigen 3x3 products: kept in registers
  const double exponent_, depth_scale_;
  // Spin so slow that w x r changes no element's velocity by more than kNegligibleSpin |v| counts
  // as translation (the run path, several times cheaper): a level pad dropped straight down picks
  // up an angular velocity of order 1e-16 rad/s from rounding in its moment, and the stress,
  // Lipschitz in the velocity with constant ~ 1 / kTrailingBand, then moves by < 1e-10.
  const bool spinning_, cull_, classes_, dynamic_terms_, area_terms_;
  // 1 - m for a law with Janosi's shear at mobilisation m (PadKinematics::shear_mobilisation): the
  // part of its shear to take off again; exactly 0 for every other law (nothing changes for them).
  const double unmobilised_;
  const double ramp_;  // PadKinematics::element_ramp_speed_m_s
  PlaneDepthInB depth_;
  Vec u0b_, w0b_;  // v and w in B (the leading boundary)
  Eigen::Vector3d g_W_;
  double depth_rate0_ = 0.0;

  Eigen::Vector3d force_ = Eigen::Vector3d::Zero(), moment_ = Eigen::Vector3d::Zero();
  double submerged_area_ = 0.0;
  int leading_ = 0;
  // Compaction transient (area integrals, scaled at the end), penetration and footprint.
  Eigen::Vector3d compaction_force_ = Eigen::Vector3d::Zero(), compaction_moment_ = Eigen::Vector3d::Zero();
  double penetration_ = 0.0, footprint_area_ = 0.0, footprint_rate_ = 0.0;
  Vec deepest_B_{0.0, 0.0, 0.0};  // the deepest submerged vertex (penetration rate)

  // The current run (translation): its normal and stresses, and the sums of depth integral /
  // depth moment / area / area moment (in B) of its submerged parts.
  bool run_open_ = false;
  Vec run_n_{0.0, 0.0, 0.0};
  ClassStress run_;
  double run_depth_ = 0.0, run_area_ = 0.0;
  Vec run_depth_moment_{0.0, 0.0, 0.0}, run_area_moment_{0.0, 0.0, 0.0};
  std::array<bool, SurfaceElements::kMaxNormalClasses> class_done_;
  std::array<ClassStress, SurfaceElements::kMaxNormalClasses> class_stress_;

  // Rotation: sum of m_B sigma_W^T over the batches drained (the moment, formed once in Finish).
  Eigen::Matrix3d depth_moment_stress_ = Eigen::Matrix3d::Zero();
};

template <bool kPower, bool kPadTerms>
ContactWrench ContactWrenchImpl(const SurfaceElements& elements, const PadKinematics& kinematics,
                                const GroundSurface& ground, const StressLaw3D& law, const PadLevelTerms& pad_terms,
                                bool compaction, bool footprint) {
  if (elements.size() == 0) return {};
  StressBatch batch;
  RotatingBatch rotating;
  WrenchSum<kPower, kPadTerms> sum(elements, kinematics, ground, law, pad_terms, compaction, footprint, batch,
                                   rotating);
  const int count = elements.size();
  for (int e = 0; e < count; ++e) {
    if (e % SurfaceElements::kBlockSize == 0 && sum.BlockAboveGround(e / SurfaceElements::kBlockSize)) {
      e += SurfaceElements::kBlockSize - 1;
      continue;
    }
    Vec p[3];
    double d[3];
    if (sum.Submerges(e, p, d)) sum.Add(e, d, p);
  }
  return sum.Finish();
}
}  // namespace

ContactWrench ComputeContactWrench(const SurfaceElements& elements, const PadKinematics& kinematics,
                                   const GroundSurface& ground, const StressLaw3D& law,
                                   const PadLevelTerms& pad_terms) {
  // A surface that is a plane without being a PlaneGround (a flat height field) is summed as that
  // plane: the exact path, bit for bit the level ground's.
  if (const PlaneGround* plane = ground.ExactPlane(); plane != nullptr && plane != &ground)
    return ComputeContactWrench(elements, kinematics, *plane, law, pad_terms);
  const bool compaction = pad_terms.has_compaction();
  const bool footprint = pad_terms.has_added_mass();
  const bool power = pad_terms.has_power_depth();
  if (!compaction && !footprint && !power && elements.size() > 0 && elements.HasBounds() &&
      !(law.has_mobilised_shear() && kinematics.shear_mobilisation != 1.0) && IsSpinning(elements, kinematics)) {
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
