#pragma once
// The resultant soil force and moment on a rigid pad: the sum, over surface elements below the
// free surface that lead the motion, of a 3D stress law times depth times area.
//
// Contract (for every caller: pad geometry, free pad, lander, drop simulations):
//  - Elements are in the pad frame B, whose origin is the reference point; the pose gives
//    R_WB and p_WB (the reference point in W); the twist gives v_WB_W (velocity of the
//    reference point) and w_WB_W (angular velocity), both in W, z up.
//  - Each triangle is transformed by the pose and clipped exactly against the ground by its
//    vertex depths; depth is integrated exactly over the submerged polygon (depth is linear on
//    a triangle), so a triangle crossing the surface contributes continuously.
//  - An element leads when n . v >= 0 with v = v_WB + w x r at the depth-weighted centroid of
//    its submerged part (faces parallel to the motion count, as the side wall does in the
//    paper's axisymmetric integral; see contact_wrench.cpp for why that point). A face that
//    turns away from the motion fades out smoothly over n.v/|v| in [-0.02, 0] rather than at
//    once, so the force is Lipschitz in the velocity (see kTrailingBand). On a rotating pad n.v
//    varies over an element (affinely); where the leading boundary crosses it, only the part that
//    leads is integrated (clipped exactly, as at the free surface), with the velocity at that
//    part's own depth-weighted centroid, so the force varies continuously as the boundary moves.
//  - The law's DynamicStress (if any) is integrated over the submerged area, not over depth.
//  - The pad-level terms (rft/pad_level_terms.h), each only when it acts: the depth law
//    (PadLevelTerms::depth): for p != 1 the stress per depth is weighted by z_ref (z / z_ref)^p
//    instead of z, integrated exactly over each clipped triangle (closed form, see
//    contact_wrench.cpp); p = 1 takes the linear path. The compaction stress
//    (PadLevelTerms::CompactionStress) is integrated over the submerged area like DynamicStress,
//    and its force and moment are scaled by exp(-z_pad / d_c), z_pad the pad's penetration (the
//    deepest submerged vertex depth, = rft/deepest_point.h when in contact).
//  - A pad at rest (v = 0 at an element) gets no RFT stress there: the law needs a direction.
//    With PadKinematics::element_ramp_speed_m_s > 0, an element slower than it gets its stress
//    scaled by its speed over the ramp's (the lead weight times the ramp factor).
//  - Moments are about the reference point (the origin of B), expressed in W.
//  - No allocation inside the element loop.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "rft/ground.h"
#include "rft/pad_level_terms.h"
#include "rft/stress_law_3d.h"
#include "rft/surface_elements.h"

namespace touchdown::rft {

// The speed of a probe that measures the soil's quasi-static capacity (a pad pushed on at rest):
// small enough that a speed-dependent (dynamic) term is negligible, large enough to stay far from
// underflow. RFT itself depends on the direction of motion only.
inline constexpr double kQuasiStaticProbeSpeed_m_s = 1e-6;

struct PadKinematics {
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_WB = Eigen::Vector3d::Zero();    // reference point [m]
  Eigen::Vector3d v_WB_W = Eigen::Vector3d::Zero();  // velocity of the reference point [m/s]
  Eigen::Vector3d w_WB_W = Eigen::Vector3d::Zero();  // angular velocity [rad/s]
  // How far a law's Janosi shear is mobilised, 1 - exp(-j / K) in [0, 1] for the pad's shear
  // displacement j (StressLaw3D::has_mobilised_shear; ignored by every other law): 1 takes the
  // shear fully mobilised.
  double shear_mobilisation = 1.0;
  // The element ramp: an element whose own velocity (at its depth-weighted centroid) is slower than
  // this has its stress scaled by speed / element_ramp_speed_m_s, so the stress is continuous, and
  // Lipschitz, through v = 0 at every element, whatever the pad's spin (the lander's soil ramp,
  // lander/multibody/lander_model.h). 0 (the default): no ramp, RFT's direction-only stress.
  double element_ramp_speed_m_s = 0.0;
};

struct ContactWrench {
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero();   // soil on pad [N]
  Eigen::Vector3d moment_W = Eigen::Vector3d::Zero();  // about the reference point [N m]
  double submerged_area_m2 = 0.0;                      // all elements below the surface
  int leading_elements = 0;                            // submerged and leading
  // Only with compaction or added mass (PadLevelTerms), else 0: the deepest vertex depth of the
  // submerged elements (0: none) [m].
  double penetration_m = 0.0;
  // Only with added mass (PadLevelTerms::has_added_mass), else 0
  // (rft/entrained_mass.h): the footprint, i.e. the horizontal projection of the submerged
  // downward-facing surface (n_z < 0) [m^2], and its time derivative under the pad's motion
  // [m^2/s] (vertex depth rates and the rotation of the normals; exact over a plane, the vertical
  // rate on any other ground); the rate of the penetration (the deepest vertex) [m/s].
  double footprint_area_m2 = 0.0;
  double footprint_area_rate_m2_s = 0.0;
  double penetration_rate_m_s = 0.0;
};

ContactWrench ComputeContactWrench(const SurfaceElements& elements, const PadKinematics& kinematics,
                                   const GroundSurface& ground, const StressLaw3D& law,
                                   const PadLevelTerms& pad_terms = {});

// A pad that keeps still (a held lander pad, whose capacity is probed in every direction of load):
// the integrals of its submerged elements at one pose, summed in the runs of equal normals that the
// translation path of ComputeContactWrench forms. TranslationWrenchAt then gives the wrench of a
// translation at that pose in any direction for the cost of the law on each run, with no clipping:
// its force is ComputeContactWrench's for the same pose and twist, bit for bit over a plane, and its
// moment to rounding (the compiler contracts the cross products, and off a plane the depths, into
// multiply-adds differently; tests/rft/fixed_pose_integrals_test.cpp); its other fields stay zero. Only for contacts without
// pad-level terms (FixedPoseIntegrals::Supports).
struct FixedPoseIntegrals {
  struct Run {
    int normal_class = -1;  // SurfaceElements::normal_class of its elements, or -1
    Eigen::Vector3d n_B = Eigen::Vector3d::Zero();  // its first element's normal
    // Over its elements with a positive depth integral, as the translation path sums them: without
    // and with the area terms a dynamic stress needs (the path clips either way, by the stress).
    double depth = 0.0, depth_with_area = 0.0, area = 0.0;
    Eigen::Vector3d depth_moment = Eigen::Vector3d::Zero(), depth_moment_with_area = Eigen::Vector3d::Zero(),
                    area_moment = Eigen::Vector3d::Zero();
  };
  static bool Supports(const PadLevelTerms& pad_terms) {
    return !pad_terms.has_compaction() && !pad_terms.has_added_mass() && !pad_terms.has_power_depth();
  }
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  std::vector<Run> runs;  // in element order
  bool classes = false;   // the elements' normal classes are used (as the translation path does)
};

// The integrals of `elements` at the pose (R_WB, p_WB) over `ground`, into `out` (its storage is
// reused: no allocation once it has held as many runs).
void FormFixedPoseIntegrals(const SurfaceElements& elements, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB,
                            const GroundSurface& ground, FixedPoseIntegrals* out);

// The wrench on the pad of `integrals` translating at v_W (w = 0), as ComputeContactWrench gives it
// at their pose with `shear_mobilisation` and `element_ramp_speed_m_s` (PadKinematics). Requires
// FixedPoseIntegrals::Supports(pad_terms).
ContactWrench TranslationWrenchAt(const FixedPoseIntegrals& integrals, const Eigen::Vector3d& v_W,
                                  const StressLaw3D& law, const PadLevelTerms& pad_terms,
                                  double shear_mobilisation = 1.0, double element_ramp_speed_m_s = 0.0);

}  // namespace touchdown::rft
