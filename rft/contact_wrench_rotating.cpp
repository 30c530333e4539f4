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
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "rft/contact_internal.h"

namespace touchdown::rft::contact_internal {

ContactWrench RotatingWrenchOverPlane(const SurfaceElements& elements, const PadKinematics& kinematics,
                                      const PlaneGround& plane, const StressLaw3D& law) {
  constexpr int kBlock = SurfaceElements::kBlockSize;
  constexpr double kThird = 1.0 / 3.0, kTwelfth = 1.0 / 12.0;
  constexpr double kTiny = std::numeric_limits<double>::min();
  const int count = elements.size();
  const Eigen::Matrix3d& R = kinematics.R_WB;
  // Depth is affine in B: depth(p_B) = depth0 + g_B . p_B, g = (sx, sy, -1) (as the general path).
  const Eigen::Vector3d g_W(plane.slope_x(), plane.slope_y(), -1.0);
  const double depth0 = plane.height_at_origin_m() + g_W.dot(kinematics.p_WB);
  const Eigen::Vector3d g_B = R.transpose() * g_W;
  const double gx = g_B.x(), gy = g_B.y(), gz = g_B.z();
  const Eigen::Vector3d u_B = R.transpose() * kinematics.v_WB_W, w_B = R.transpose() * kinematics.w_WB_W;
  const Vec u{u_B.x(), u_B.y(), u_B.z()}, w{w_B.x(), w_B.y(), w_B.z()};
  const double r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1), r12 = R(1, 2),
               r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
  const double* p0 = elements.p0_B.data();
  const double* p1 = elements.p1_B.data();
  const double* p2 = elements.p2_B.data();
  const double* nb = elements.n_B.data();
  const double* areas = elements.area_m2.data();

  double submerged_area = 0.0;
  int leading = 0;

  // Leading elements waiting for their stresses.
  StressBatch batch;
  alignas(64) double batch_weight[StressBatch::kCapacity], batch_depth[StressBatch::kCapacity];
  alignas(64) double batch_mx[StressBatch::kCapacity], batch_my[StressBatch::kCapacity],
      batch_mz[StressBatch::kCapacity];
  // sum of m_B sigma_W^T, entry (j, k) = S[3 j + k]; plain scalars (Eigen's 3x3 outer product
  // here cost a third of this function).
  double S[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double fx = 0.0, fy = 0.0, fz = 0.0;
  auto drain = [&]() {
    law.StressPerDepthBatch(batch);
    for (int i = 0; i < batch.count; ++i) {
      const double sx = batch_weight[i] * batch.sx[i], sy = batch_weight[i] * batch.sy[i],
                   sz = batch_weight[i] * batch.sz[i];
      fx += batch_depth[i] * sx;
      fy += batch_depth[i] * sy;
      fz += batch_depth[i] * sz;
      S[0] += batch_mx[i] * sx, S[1] += batch_mx[i] * sy, S[2] += batch_mx[i] * sz;
      S[3] += batch_my[i] * sx, S[4] += batch_my[i] * sy, S[5] += batch_my[i] * sz;
      S[6] += batch_mz[i] * sx, S[7] += batch_mz[i] * sy, S[8] += batch_mz[i] * sz;
    }
    batch.count = 0;
  };
  auto append = [&](const Vec& n, const Vec& v, double weight, double depth_integral, const Vec& m) {
    if (batch.count == StressBatch::kCapacity) drain();
    const int i = batch.count++;
    batch.nx[i] = r00 * n.x + r01 * n.y + r02 * n.z;
    batch.ny[i] = r10 * n.x + r11 * n.y + r12 * n.z;
    batch.nz[i] = r20 * n.x + r21 * n.y + r22 * n.z;
    batch.vx[i] = r00 * v.x + r01 * v.y + r02 * v.z;
    batch.vy[i] = r10 * v.x + r11 * v.y + r12 * v.z;
    batch.vz[i] = r20 * v.x + r21 * v.y + r22 * v.z;
    batch_weight[i] = weight;
    batch_depth[i] = depth_integral;
    batch_mx[i] = m.x;
    batch_my[i] = m.y;
    batch_mz[i] = m.z;
    ++leading;
  };

  // Per block: the branch-free pass's results (`whole` > 0: wholly submerged and wholly leading,
  // with weight > 0; `touches` > 0: some vertex below the surface).
  alignas(64) double whole[kBlock], touches[kBlock], weight[kBlock], depth[kBlock];
  alignas(64) double mx[kBlock], my[kBlock], mz[kBlock], vx[kBlock], vy[kBlock], vz[kBlock];
  for (int block = 0; block < elements.block_count(); ++block) {
    const double* lo = elements.block_min_B.data() + 3 * block;
    const double* hi = elements.block_max_B.data() + 3 * block;
    const double deepest = depth0 + (gx > 0.0 ? gx * hi[0] : gx * lo[0]) + (gy > 0.0 ? gy * hi[1] : gy * lo[1]) +
                           (gz > 0.0 ? gz * hi[2] : gz * lo[2]);
    if (deepest < -kCullMargin) continue;  // wholly above the ground
    const int first = block * kBlock, n = std::min(kBlock, count - first);
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
      const double lead_weight = x * x * (3.0 - 2.0 * x);
      const double inv = 1.0 / std::max(D, kTiny);
      const double speed = V * inv, v_x = Vx * inv, v_y = Vy * inv, v_z = Vz * inv;
      whole[i] = static_cast<double>(std::min(std::min(d0, d1), d2) > 0.0) *
                 static_cast<double>(std::min(std::min(t0, t1), t2) >= 0.0) * static_cast<double>(speed > 0.0);
      touches[i] = static_cast<double>(std::max(std::max(d0, d1), d2) > 0.0);
      weight[i] = lead_weight;
      depth[i] = D;
      mx[i] = Mx, my[i] = My, mz[i] = Mz;
      vx[i] = v_x, vy[i] = v_y, vz[i] = v_z;
    }
    for (int i = 0; i < n; ++i) {
      if (touches[i] == 0.0) continue;
      const int e = first + i;
      const Vec nrm = Load(nb + 3 * e);
      if (whole[i] != 0.0) {
        submerged_area += areas[e];
        if (weight[i] > 0.0) append(nrm, Vec{vx[i], vy[i], vz[i]}, weight[i], depth[i], Vec{mx[i], my[i], mz[i]});
        continue;
      }
      // Cut by the surface or by the leading boundary: the general path's code.
      const Vec p[3] = {Load(p0 + 3 * e), Load(p1 + 3 * e), Load(p2 + 3 * e)};
      double d[3];
      for (int k = 0; k < 3; ++k) d[k] = depth0 + gx * p[k].x + gy * p[k].y + gz * p[k].z;
      const Submerged s = ClipAndIntegrate<false>(areas[e], d, p);
      submerged_area += s.area;
      if (!(s.depth_integral > 0.0)) continue;
      const LeadingPart lead = LeadingPartOf(s, areas[e], d, p, nrm, u, w, /*clip_leading=*/true);
      if (lead.weight > 0.0) append(nrm, lead.v, lead.weight, lead.part.depth_integral, lead.part.depth_moment);
    }
  }
  if (batch.count > 0) drain();

  ContactWrench out;
  out.force_W = Eigen::Vector3d(fx, fy, fz);
  // sum (R m_B) x sigma = eps_ijk (R S)_jk with S = sum m_B sigma^T.
  const Eigen::Matrix3d P = R * Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(S);
  out.moment_W = Eigen::Vector3d(P(1, 2) - P(2, 1), P(2, 0) - P(0, 2), P(0, 1) - P(1, 0));
  out.submerged_area_m2 = submerged_area;
  out.leading_elements = leading;
  return out;
}

}  // namespace touchdown::rft::contact_internal
