// FormFixedPoseIntegrals and TranslationWrenchAt (contact_wrench.h): a pad that keeps still, its
// integrals formed once at a pose and probed in any direction of translation.
//
// Why a path of its own: a held lander pad's sideways capacity is probed in the direction of its load
// at every root-function call, and the load turns from step to step while the pad does not move. The
// translation path of ComputeContactWrench (contact_wrench.cpp, WrenchSum) clips every submerged
// element and sums the clipped integrals per run of equal normals, then applies the law once per
// run; only the last part depends on the direction. Here the first part is done once and kept per
// run, with the same culling, depths, runs and clips (ClipAndIntegrate, as the path's Clip without a
// power depth law), so the force comes out as the path's, bit for bit over a plane.
#include <algorithm>
#include <array>
#include <cmath>

#include "rft/contact_internal.h"
#include "rft/contact_wrench.h"

namespace touchdown::rft {

using namespace contact_internal;

void FormFixedPoseIntegrals(const SurfaceElements& elements, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB,
                            const GroundSurface& ground, FixedPoseIntegrals* out) {
  out->R_WB = R_WB;
  out->runs.clear();
  out->runs.reserve(static_cast<size_t>(elements.size()));  // at most a run per element: no reallocation below
  // As WrenchSum forms a translation's runs (a twist with w = 0 never spins): the same culling, the
  // same depths, the same runs of consecutive submerged elements with equal normals, the same clips
  // (so the force comes out bit for bit).
  PadKinematics k;
  k.R_WB = R_WB;
  k.p_WB = p_WB;
  const auto* plane = ground.ExactPlane();
  const bool cull = elements.HasBounds() && plane != nullptr;
  out->classes = elements.HasBounds() && elements.class_normal_B.cols() > 0;
  PlaneDepthInB depth;
  if (plane != nullptr) depth = PlaneDepthInB::Of(*plane, k);
  const RotationToW rotate(R_WB);
  const double* p0 = elements.p0_B.data();
  const double* p1 = elements.p1_B.data();
  const double* p2 = elements.p2_B.data();
  FixedPoseIntegrals::Run* run = nullptr;  // the open run (`runs` never reallocates: reserved above)
  Vec run_n{0.0, 0.0, 0.0};
  Vec depth_moment{0.0, 0.0, 0.0}, depth_moment_with_area{0.0, 0.0, 0.0}, area_moment{0.0, 0.0, 0.0};
  auto close = [&] {
    if (run == nullptr) return;
    run->depth_moment = Eigen::Vector3d(depth_moment.x, depth_moment.y, depth_moment.z);
    run->depth_moment_with_area =
        Eigen::Vector3d(depth_moment_with_area.x, depth_moment_with_area.y, depth_moment_with_area.z);
    run->area_moment = Eigen::Vector3d(area_moment.x, area_moment.y, area_moment.z);
  };
  const int count = elements.size();
  for (int e = 0; e < count; ++e) {
    if (e % SurfaceElements::kBlockSize == 0 && cull && depth.BlockAbove(elements, e / SurfaceElements::kBlockSize)) {
      e += SurfaceElements::kBlockSize - 1;
      continue;
    }
    const Vec p[3] = {Load(p0 + 3 * e), Load(p1 + 3 * e), Load(p2 + 3 * e)};
    double d[3];
    for (int j = 0; j < 3; ++j) d[j] = plane != nullptr ? depth.At(p[j]) : ground.Depth(p_WB + rotate(p[j]));
    if (d[0] <= 0.0 && d[1] <= 0.0 && d[2] <= 0.0) continue;
    const Vec n_B = Load(elements.n_B.data() + 3 * e);
    if (run == nullptr ||
        std::abs(n_B.x - run_n.x) + std::abs(n_B.y - run_n.y) + std::abs(n_B.z - run_n.z) > kSameNormal) {
      close();
      out->runs.emplace_back();
      run = &out->runs.back();
      run_n = n_B;
      run->normal_class = out->classes ? elements.normal_class[e] : -1;
      // The normal the law sees (WrenchSum::OpenRun): its class's, else the run's first element's.
      run->n_B = run->normal_class >= 0 ? Eigen::Vector3d(elements.class_normal_B.col(run->normal_class))
                                        : Eigen::Vector3d(n_B.x, n_B.y, n_B.z);
      depth_moment = depth_moment_with_area = area_moment = Vec{0.0, 0.0, 0.0};
    }
    const double area = elements.area_m2[e];
    const Submerged plain = ClipAndIntegrate<false>(area, d, p);
    if (plain.depth_integral > 0.0) {
      run->depth += plain.depth_integral;
      depth_moment = depth_moment + plain.depth_moment;
    }
    const Submerged with_area = ClipAndIntegrate<true>(area, d, p);
    if (with_area.depth_integral > 0.0) {
      run->depth_with_area += with_area.depth_integral;
      depth_moment_with_area = depth_moment_with_area + with_area.depth_moment;
      run->area += with_area.area;
      area_moment = area_moment + with_area.area_moment;
    }
  }
  close();
}

ContactWrench TranslationWrenchAt(const FixedPoseIntegrals& integrals, const Eigen::Vector3d& v_W,
                                  const StressLaw3D& law, const PadLevelTerms& pad_terms, double shear_mobilisation,
                                  double element_ramp_speed_m_s) {
  const RotationToW rotate(integrals.R_WB);
  const double unmobilised = law.has_mobilised_shear() ? 1.0 - shear_mobilisation : 0.0;
  std::array<bool, SurfaceElements::kMaxNormalClasses> done;
  std::array<ClassStress, SurfaceElements::kMaxNormalClasses> cached;
  done.fill(false);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (const FixedPoseIntegrals::Run& run : integrals.runs) {
    // The run's stresses, as WrenchSum::OpenRun forms them.
    const int cls = run.normal_class;
    ClassStress st;
    if (cls >= 0 && done[cls]) {
      st = cached[cls];
    } else {
      StressOfNormal<false>(law, pad_terms, false, unmobilised, element_ramp_speed_m_s,
                            rotate(Vec{run.n_B.x(), run.n_B.y(), run.n_B.z()}), v_W, st);
      if (cls >= 0) done[cls] = true, cached[cls] = st;
    }
    // ... and added as WrenchSum::FlushRun adds them.
    if (!st.leads) continue;
    if (st.dynamic) {
      force += run.depth_with_area * st.sigma;
      moment += rotate(Vec{run.depth_moment_with_area.x(), run.depth_moment_with_area.y(), run.depth_moment_with_area.z()})
                    .cross(st.sigma);
      force += run.area * st.sigma_dyn;
      moment += rotate(Vec{run.area_moment.x(), run.area_moment.y(), run.area_moment.z()}).cross(st.sigma_dyn);
    } else {
      force += run.depth * st.sigma;
      moment += rotate(Vec{run.depth_moment.x(), run.depth_moment.y(), run.depth_moment.z()}).cross(st.sigma);
    }
  }
  ContactWrench out;
  out.force_W = force;
  out.moment_W = moment;
  return out;
}

}  // namespace touchdown::rft
