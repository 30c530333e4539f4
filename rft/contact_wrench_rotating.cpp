// ComputeContactWrench for a rotating pad over a plane (contact_internal.h, RotatingWrenchOverPlane).
//
// Why a path of its own: every element of a rotating pad has its own velocity, so the law runs once
// per element; the translation path's grouping by normal does not apply, and the element loop
// itself cost as much as the law. Here each block of elements (SurfaceElements::kBlockSize) goes
// through a branch-free pass that the compiler vectorises: vertex depths, the integrals of a wholly
// submerged triangle, the velocity at its depth-weighted centroid, the leading test and the lead
// weight. The elements that pass (wholly submerged, wholly leading) go to the law in batches
// (StressLaw3D::StressPerDepthBatch); the others - cut by the free surface or by the leading
// boundary - take the same per-element code as the general path (contact_internal.h). The sums are
// the general path's, grouped differently (tests/rft/stress_batch_test.cpp compares the two).
// A block wholly below the surface whose every element trails the motion (BlockTrails: the top of
// a buried pad that sinks, the back of one that slides) adds only its area, without the pass: its
// elements would carry no stress (tests/rft/contact_block_cull_test.cpp, bit for bit).
//
// A law with a dynamic (depth-independent) stress (dynamic RFT's inertial term, on by default in the
// shipped soils) takes the same pass with each leading element's submerged area and area moment kept
// beside its depth integrals, and the law's DynamicStress added over them (kDynamic below).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "rft/contact_internal.h"

namespace touchdown::rft::contact_internal {

namespace {

constexpr int kBlock = SurfaceElements::kBlockSize;

// What the branch-free pass finds for each element of one block: `whole` > 0: wholly submerged and
// wholly leading, with weight > 0; `trails` > 0: wholly submerged and trailing beyond the band at
// every vertex (no stress, only its area; see kTrailMargin); `touches` > 0: some vertex below the
// surface; the lead weight, the depth integral D and depth moment M (in B) of the whole triangle,
// and the velocity at its depth-weighted centroid (in B).
struct BlockPass {
  alignas(64) double whole[kBlock], trails[kBlock], touches[kBlock], weight[kBlock], depth[kBlock];
  alignas(64) double mx[kBlock], my[kBlock], mz[kBlock], vx[kBlock], vy[kBlock], vz[kBlock];
};

// How far below zero the pass's leading test must be at every vertex of a wholly submerged element
// for it to count as trailing without the per-element code, relative to the size of the test's terms
// (|D n.u| + |D v| + |D (n x w)| r_max). The per-element code (LeadingPartOf) forms
// the same test divided by D in another order; the two differ by a few roundings of those terms, far
// below this margin, so an element the pass calls trailing is one the per-element code would find
// trailing at every vertex too, and every vertex deeper than kCullMargin is one it finds submerged:
// it adds the element's area and nothing else (tests/rft/contact_block_cull_test.cpp).
// Such elements (the back of a sliding pad, the top of a buried one) were a third of the elements a
// lunar-study landing sends through the pass.
constexpr double kTrailMargin = 1e-9;

// The branch-free pass over the n elements of a block from `first` (vectorised): vertex depths,
// the integrals of the whole triangle, the velocity at its depth-weighted centroid, the leading
// test and the lead weight. `r_max`: the largest |p_B| of any vertex.
[[gnu::always_inline]] inline void PassBlock(const SurfaceElements& elements, int first, int n,
                                             const PlaneDepthInB& plane, const Vec& u, const Vec& w,
                                             double ramp, double r_max, BlockPass& out) {
  constexpr double kThird = 1.0 / 3.0, kTwelfth = 1.0 / 12.0;
  constexpr double kTiny = std::numeric_limits<double>::min();
  const double depth0 = plane.depth0, gx = plane.gx, gy = plane.gy, gz = plane.gz;
  const double* p0 = elements.p0_B.data();
  const double* p1 = elements.p1_B.data();
  const double* p2 = elements.p2_B.data();
  const double* nb = elements.n_B.data();
  const double* areas = elements.area_m2.data();
  for (int i = 0; i < n; ++i) {
    const int e = first + i;
    const double ax = p0[3 * e], ay = p0[3 * e + 1], az = p0[3 * e + 2];
    const double bx = p1[3 * e], by = p1[3 * e + 1], bz = p1[3 * e + 2];
    const double cx = p2[3 * e], cy = p2[3 * e + 1], cz = p2[3 * e + 2];
    const double d0 = depth0 + gx * ax + gy * ay + gz * az;
    const double d1 = depth0 + gx * bx + gy * by + gz * bz;
    const double d2 = depth0 + gx * cx + gy * cy + gz * cz;
    // Integrals of the whole triangle (AddTriangle's expressions).
    const double area = areas[e], dsum = d0 + d1 + d2, a12 = area * kTwelfth;
    const double D = area * kThird * dsum;
    const double Mx = a12 * (dsum * (ax + bx + cx) + d0 * ax + d1 * bx + d2 * cx);
    const double My = a12 * (dsum * (ay + by + cy) + d0 * ay + d1 * by + d2 * cy);
    const double Mz = a12 * (dsum * (az + bz + cz) + d0 * az + d1 * bz + d2 * cz);
    // Velocity at the depth-weighted centroid M / D (CentroidVelocity), kept as V = D v = D u +
    // w x M: the leading test and the lead weight depend on the direction of v only (D > 0 for
    // the elements this pass serves), so they need no division by D.
    const double Vx = D * u.x + w.y * Mz - w.z * My, Vy = D * u.y + w.z * Mx - w.x * Mz,
                 Vz = D * u.z + w.x * My - w.y * Mx;
    const double V = std::sqrt(Vx * Vx + Vy * Vy + Vz * Vz);
    // Leading test at the vertices, times D (LeadingPartOf), and the lead weight (LeadWeight).
    const double nx = nb[3 * e], ny = nb[3 * e + 1], nz = nb[3 * e + 2];
    const double lead0 = D * (nx * u.x + ny * u.y + nz * u.z) + kTrailingBand * V;
    const double tx = D * (ny * w.z - nz * w.y), ty = D * (nz * w.x - nx * w.z), tz = D * (nx * w.y - ny * w.x);
    const double t0 = lead0 + tx * ax + ty * ay + tz * az;
    const double t1 = lead0 + tx * bx + ty * by + tz * bz;
    const double t2 = lead0 + tx * cx + ty * cy + tz * cz;
    const double nV = nx * Vx + ny * Vy + nz * Vz;
    const double x = std::min(
        std::max((nV + kTrailingBand * V) / std::max((kTrailingBand - kParallelTolerance) * V, kTiny), 0.0), 1.0);
    const double inv = 1.0 / std::max(D, kTiny);
    const double speed = V * inv, v_x = Vx * inv, v_y = Vy * inv, v_z = Vz * inv;
    const double lead_weight = x * x * (3.0 - 2.0 * x) * RampFactor(speed, ramp);
    const double submerged = static_cast<double>(std::min(std::min(d0, d1), d2) > 0.0);
    out.whole[i] = submerged * static_cast<double>(std::min(std::min(t0, t1), t2) >= 0.0) *
                   static_cast<double>(speed > 0.0);
    // (Bounded by D |n.u| + V + ..., no product of lead0's own again: a second use of one would
    // change how the compiler fuses lead0's multiply-adds, and with it the last bits of every wrench.)
    const double test_size = D * std::abs(nx * u.x + ny * u.y + nz * u.z) + V +
                             (std::abs(tx) + std::abs(ty) + std::abs(tz)) * r_max;
    out.trails[i] = static_cast<double>(std::min(std::min(d0, d1), d2) > kCullMargin) *
                    static_cast<double>(std::max(std::max(t0, t1), t2) < -kTrailMargin * test_size);
    out.touches[i] = static_cast<double>(std::max(std::max(d0, d1), d2) > 0.0);
    out.weight[i] = lead_weight;
    out.depth[i] = D;
    out.mx[i] = Mx, out.my[i] = My, out.mz[i] = Mz;
    out.vx[i] = v_x, out.vy[i] = v_y, out.vz[i] = v_z;
  }
}

// Leading elements waiting for their stresses (beside the StressBatch of their normals and
// velocities in W): lead weight, depth integral, depth moment (in B).
// With a law's dynamic (depth-independent) stress, also each element's leading submerged area and
// its first moment (in B), over which that stress acts.
struct PendingLeading {
  alignas(64) double weight[StressBatch::kCapacity], depth[StressBatch::kCapacity];
  alignas(64) double mx[StressBatch::kCapacity], my[StressBatch::kCapacity], mz[StressBatch::kCapacity];
  alignas(64) double area[StressBatch::kCapacity];
  alignas(64) double ax[StressBatch::kCapacity], ay[StressBatch::kCapacity], az[StressBatch::kCapacity];
};

// What the drained elements add up to: the force and S = sum m_B sigma_W^T, entry (j, k) =
// S[3 j + k] (plain scalars: Eigen's 3x3 outer product here cost a third of this function).
struct LeadingSums {
  double S[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double fx = 0.0, fy = 0.0, fz = 0.0;
  int leading = 0;
};

// The law's dynamic stress on the waiting elements (StressLaw3D::DynamicStress at the normal and
// velocity the quasi-static stress takes), times their areas, into the sums: the force, and S, since
// the moment of a stress acting at the area's centroid is (R a_B) x sigma with a_B its area moment.
inline void DrainDynamic(const StressLaw3D& law, const StressBatch& batch, const PendingLeading& pending,
                         LeadingSums& sums) {
  for (int i = 0; i < batch.count; ++i) {
    const Eigen::Vector3d sigma =
        pending.weight[i] * law.DynamicStress(Eigen::Vector3d(batch.nx[i], batch.ny[i], batch.nz[i]),
                                              Eigen::Vector3d(batch.vx[i], batch.vy[i], batch.vz[i]));
    const double a = pending.area[i];
    sums.fx += a * sigma.x(), sums.fy += a * sigma.y(), sums.fz += a * sigma.z();
    sums.S[0] += pending.ax[i] * sigma.x(), sums.S[1] += pending.ax[i] * sigma.y(), sums.S[2] += pending.ax[i] * sigma.z();
    sums.S[3] += pending.ay[i] * sigma.x(), sums.S[4] += pending.ay[i] * sigma.y(), sums.S[5] += pending.ay[i] * sigma.z();
    sums.S[6] += pending.az[i] * sigma.x(), sums.S[7] += pending.az[i] * sigma.y(), sums.S[8] += pending.az[i] * sigma.z();
  }
}

// The law on the waiting elements in one batch; their stresses times their integrals into the sums.
template <bool kDynamic>
[[gnu::always_inline]] inline void Drain(const StressLaw3D& law, StressBatch& batch, const PendingLeading& pending,
                                         LeadingSums& sums) {
  law.StressPerDepthBatch(batch);
  if constexpr (kDynamic) DrainDynamic(law, batch, pending, sums);
  for (int i = 0; i < batch.count; ++i) {
    const double sx = pending.weight[i] * batch.sx[i], sy = pending.weight[i] * batch.sy[i],
                 sz = pending.weight[i] * batch.sz[i];
    sums.fx += pending.depth[i] * sx;
    sums.fy += pending.depth[i] * sy;
    sums.fz += pending.depth[i] * sz;
    sums.S[0] += pending.mx[i] * sx, sums.S[1] += pending.mx[i] * sy, sums.S[2] += pending.mx[i] * sz;
    sums.S[3] += pending.my[i] * sx, sums.S[4] += pending.my[i] * sy, sums.S[5] += pending.my[i] * sz;
    sums.S[6] += pending.mz[i] * sx, sums.S[7] += pending.mz[i] * sy, sums.S[8] += pending.mz[i] * sz;
  }
  batch.count = 0;
}

// Queues one leading element (normal n, velocity v at its centroid, both in B) for the law,
// draining the batch first when it is full.
// `area`, `area_moment`: the element's leading submerged area and its moment (kept with a dynamic
// stress only).
template <bool kDynamic>
[[gnu::always_inline]] inline void Append(const StressLaw3D& law, const RotationToW& rotate, const Vec& n,
                                          const Vec& v, double weight, double depth_integral, const Vec& m,
                                          double area, const Vec& area_moment, StressBatch& batch,
                                          PendingLeading& pending, LeadingSums& sums) {
  if (batch.count == StressBatch::kCapacity) Drain<kDynamic>(law, batch, pending, sums);
  const int i = batch.count++;
  const Eigen::Vector3d n_W = rotate(n), v_W = rotate(v);
  batch.nx[i] = n_W.x();
  batch.ny[i] = n_W.y();
  batch.nz[i] = n_W.z();
  batch.vx[i] = v_W.x();
  batch.vy[i] = v_W.y();
  batch.vz[i] = v_W.z();
  pending.weight[i] = weight;
  pending.depth[i] = depth_integral;
  pending.mx[i] = m.x;
  pending.my[i] = m.y;
  pending.mz[i] = m.z;
  if constexpr (kDynamic) {
    pending.area[i] = area;
    pending.ax[i] = area_moment.x;
    pending.ay[i] = area_moment.y;
    pending.az[i] = area_moment.z;
  }
  ++sums.leading;
}

}  // namespace

// kDynamic: the law has a dynamic stress. kSkipTrailing: wholly trailing submerged elements add their
// area without the per-element code (the pass's `trails`); false only to test that this changes no bit.
namespace {
template <bool kDynamic, bool kSkipTrailing>
ContactWrench RotatingWrench(const SurfaceElements& elements, const PadKinematics& kinematics,
                             const PlaneGround& plane, const StressLaw3D& law) {
  const int count = elements.size();
  const Eigen::Matrix3d& R = kinematics.R_WB;
  const PlaneDepthInB depth = PlaneDepthInB::Of(plane, kinematics);  // as the general path
  const Eigen::Vector3d u_B = R.transpose() * kinematics.v_WB_W, w_B = R.transpose() * kinematics.w_WB_W;
  const Vec u{u_B.x(), u_B.y(), u_B.z()}, w{w_B.x(), w_B.y(), w_B.z()};
  const TwistInB twist(u_B, w_B);
  const RotationToW rotate(R);
  const double ramp = kinematics.element_ramp_speed_m_s;
  const double r_max = elements.max_vertex_radius_m;
  const double* p0 = elements.p0_B.data();
  const double* p1 = elements.p1_B.data();
  const double* p2 = elements.p2_B.data();
  const double* nb = elements.n_B.data();
  const double* areas = elements.area_m2.data();

  constexpr double kThird = 1.0 / 3.0;
  double submerged_area = 0.0;
  StressBatch batch;
  PendingLeading pending;
  LeadingSums sums;
  BlockPass pass;
  for (int block = 0; block < elements.block_count(); ++block) {
    if (depth.BlockAbove(elements, block)) continue;  // wholly above the ground
    const int first = block * kBlock, n = std::min(kBlock, count - first);
    if (depth.BlockBelow(elements, block) && BlockTrails(elements, block, twist)) {
      // Wholly submerged and wholly trailing: only the submerged area, as the pass would add it.
      for (int e = first; e < first + n; ++e) submerged_area += areas[e];
      continue;
    }
    PassBlock(elements, first, n, depth, u, w, ramp, r_max, pass);
    for (int i = 0; i < n; ++i) {
      if (pass.touches[i] == 0.0) continue;
      const int e = first + i;
      if (kSkipTrailing && pass.trails[i] != 0.0) {  // wholly submerged, trailing everywhere: its area only
        submerged_area += areas[e];
        continue;
      }
      const Vec nrm = Load(nb + 3 * e);
      if (pass.whole[i] != 0.0) {
        submerged_area += areas[e];
        if (pass.weight[i] > 0.0) {
          // The whole triangle's area moment, as AddTriangle<true> forms it (kept with a dynamic stress).
          Vec psum{0.0, 0.0, 0.0};
          if constexpr (kDynamic) psum = Load(p0 + 3 * e) + Load(p1 + 3 * e) + Load(p2 + 3 * e);
          Append<kDynamic>(law, rotate, nrm, Vec{pass.vx[i], pass.vy[i], pass.vz[i]}, pass.weight[i], pass.depth[i],
                 Vec{pass.mx[i], pass.my[i], pass.mz[i]}, areas[e], (areas[e] * kThird) * psum, batch, pending,
                 sums);
        }
        continue;
      }
      // Cut by the surface or by the leading boundary: the general path's code.
      const Vec p[3] = {Load(p0 + 3 * e), Load(p1 + 3 * e), Load(p2 + 3 * e)};
      double d[3];
      for (int k = 0; k < 3; ++k) d[k] = depth.At(p[k]);
      const Submerged s = ClipAndIntegrate<kDynamic>(areas[e], d, p);
      submerged_area += s.area;
      if (!(s.depth_integral > 0.0)) continue;
      const LeadingPart lead = LeadingPartOf(s, areas[e], d, p, nrm, u, w, /*clip_leading=*/true, AddLinearSubTriangle{}, ramp);
      if (lead.weight > 0.0)
        Append<kDynamic>(law, rotate, nrm, lead.v, lead.weight, lead.part.depth_integral, lead.part.depth_moment,
               lead.part.area, lead.part.area_moment, batch, pending, sums);
    }
  }
  if (batch.count > 0) Drain<kDynamic>(law, batch, pending, sums);

  ContactWrench out;
  out.force_W = Eigen::Vector3d(sums.fx, sums.fy, sums.fz);
  // sum (R m_B) x sigma = eps_ijk (R S)_jk with S = sum m_B sigma^T.
  const Eigen::Matrix3d P = R * Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(sums.S);
  out.moment_W = Eigen::Vector3d(P(1, 2) - P(2, 1), P(2, 0) - P(0, 2), P(0, 1) - P(1, 0));
  out.submerged_area_m2 = submerged_area;
  out.leading_elements = sums.leading;
  return out;
}

}  // namespace

ContactWrench RotatingWrenchOverPlane(const SurfaceElements& elements, const PadKinematics& kinematics,
                                      const PlaneGround& plane, const StressLaw3D& law, bool skip_trailing) {
  if (!skip_trailing)
    return law.has_dynamic_stress() ? RotatingWrench<true, false>(elements, kinematics, plane, law)
                                    : RotatingWrench<false, false>(elements, kinematics, plane, law);
  return law.has_dynamic_stress() ? RotatingWrench<true, true>(elements, kinematics, plane, law)
                                  : RotatingWrench<false, true>(elements, kinematics, plane, law);
}

}  // namespace touchdown::rft::contact_internal
