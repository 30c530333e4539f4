#pragma once
// The free pad's equations of motion (Model: fixed for a drop; nothing allocates per call): one
// rigid body with 6 degrees of freedom under gravity and the 3D RFT soil wrench, Newton-Euler
// about the centre of mass, with the pad-level added mass of the soil contact model.
//
// State y (FreePadStateLayout): centre of mass p_WC, attitude quaternion q_WB (w, x, y, z), velocity
// v_WC_W, angular velocity w_WB_B in the pad's own frame, and the work done against the soil
// (dissipated energy); on a terrain with a Bekker soil with shear, Janosi's shear displacement j
// after them. The lander integrates world-frame angular velocities (lander::StateLayout); the free
// pad keeps the body frame, where its inertia is constant: in the world frame its spinning and
// curved drops took 20 % to almost three times the solver steps (docs/architecture.md, "State
// vectors and frames").
#include <Eigen/Core>

#include "footpad_geom/pad_body.h"
#include "rft/contact_wrench.h"
#include "rft/ground.h"
#include "rft/soil_contact_model.h"
#include "rft/soil_map.h"

namespace touchdown::pad {

// Index layout of the free pad's state vector, in the lander's idiom (lander::StateLayout): an
// accessor per quantity, named with its frames. Janosi's shear displacement j [m] follows the 14
// states only when a soil of the pad's terrain has a shear that mobilises with it
// (rft::SoilContactModel::has_janosi_shear); every other drop keeps the 14 states.
struct FreePadStateLayout {
  static constexpr int kMaxSize = 15;
  explicit constexpr FreePadStateLayout(bool shear_state) : has_shear(shear_state), size(shear_state ? 15 : 14) {}
  bool has_shear;
  int size;
  static constexpr int p_WC() { return 0; }
  static constexpr int quat_WB() { return 3; }
  static constexpr int v_WC_W() { return 7; }
  static constexpr int w_WB_B() { return 10; }
  static constexpr int work() { return 13; }
  static constexpr int shear() { return 14; }  // only with has_shear
};

// Kinematics of the pad at one state.
struct FreePadPose {
  Eigen::Matrix3d R_WB;
  Eigen::Vector3d p_WC, p_WB, v_WC, w_B, w_W, v_WB;
  double shear_displacement_m = 0.0;  // Janosi's j (0 without the state)
};

// The vertical motion of the centre of mass with the entrained grains of added_mass.
struct FreePadVertical {
  double a_z = 0.0;          // vertical acceleration of the centre of mass
  double accretion_W = 0.0;  // accretion loss rate
  double force_z = 0.0;      // vertical force on the pad from below: soil and entrained grains, m (a_z + g)
};

// What one evaluation of the free pad's right-hand side found at its state (the free pad's Data;
// its Model is FreePadDynamics).
struct FreePadData {
  FreePadPose pose;
  rft::ContactWrench soil;  // the soil's wrench on the pad (zero at rest or in the air)
};

class FreePadDynamics {
 public:
  // References are kept: `body` and `terrain` must outlive this object.
  FreePadDynamics(const geom::PadBody& body, const rft::Terrain& terrain, double gravity_m_s2);

  FreePadPose PoseOf(const Eigen::Ref<const Eigen::VectorXd>& y) const;
  // Depth of the lowest point below the surface (negative above it).
  double Depth(const FreePadPose& s) const;
  // Whether the pad moves at all (translation or spin): the soil wrench needs a direction.
  bool Moving(const FreePadPose& s) const;
  // The soil under the pad: the terrain's soil at the pad frame's origin (x, y), as a lander's pad
  // takes the soil at its ball joint. A pad crossing a patch's edge meets the other soil at once.
  const rft::SoilContactModel& SoilUnder(const FreePadPose& s) const;
  // The soil wrench and the vertical motion at pose s on `soil` (SoilUnder(s), looked up once).
  rft::ContactWrench Wrench(const FreePadPose& s, const rft::SoilContactModel& soil) const;
  FreePadVertical Vertical(const FreePadPose& s, const rft::ContactWrench& w, const rft::SoilContactModel& soil) const;
  // d(ydot)/dy at y, ydot = Derivative(*this, data, y, ydot), into J (size() x size()), formed from the structure:
  // the kinematic rows (p, q) exactly; the soil's columns by forward differences of Derivative
  // along the pose's and twist's own coordinates: over a plane the wrench depends on
  // the position only through the depth (one difference, not three); the attitude through the
  // normalised quaternion (three rotations, not four quaternion components); the work done never
  // feeds back (no column). JacobianContacts() differences, where CVODE's own Jacobian takes one per
  // state (14). `scale`: each state's typical size, sizing its difference (as CVODE's 1 / ewt).
  // Nothing allocates.
  void Jacobian(const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::Ref<const Eigen::VectorXd>& ydot,
                const Eigen::Ref<const Eigen::VectorXd>& scale, Eigen::Ref<Eigen::MatrixXd> J) const;
  int JacobianContacts() const;
  // The soil's quasi-static capacity for further straight-down motion at pose s: the vertical force
  // on a probe moving down at rft::kQuasiStaticProbeSpeed_m_s (speed-dependent terms must not count
  // as static capacity).
  double RestCapacity(const FreePadPose& s) const;
  // Kinetic energy (translation and rotation) at pose s.
  double KineticEnergy(const FreePadPose& s) const;

  const geom::PadBody& body() const { return body_; }
  // Whether the state carries Janosi's j (FreePadStateLayout::shear), and the state's size. j grows with
  // the horizontal slip speed of the pad's reference point while the pad is in the soil (a rotating
  // pad's slip reduced to that one point: docs/bekker_soil.md argues it) and is reset at lift-off.
  bool has_shear_state() const { return shear_state_; }
  int size() const { return layout().size; }
  FreePadStateLayout layout() const { return FreePadStateLayout(shear_state_); }
  double mass_kg() const { return m_; }
  double gravity_m_s2() const { return g_; }
  // Radius about the centre of mass: spin times it is a speed.
  double radius_m() const { return radius_; }

 private:
  // The right-hand side (below) reads the pad's mass, inertia and soil lookup held here.
  friend void Derivative(const FreePadDynamics& model, FreePadData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                         Eigen::Ref<Eigen::VectorXd> ydot);

  const geom::PadBody& body_;
  const rft::Terrain& terrain_;
  const rft::GroundSurface& ground_;
  double m_, g_;
  Eigen::Matrix3d I_, I_inv_;
  double radius_;
  bool shear_state_ = false;
  // Over a plane the wrench on one soil depends on the position through the depth alone, depth =
  // h0 + g_W . p (g_W = (slope_x, slope_y, -1)); the soil under the pad is piecewise constant in
  // (x, y), so its changes have no derivative for the Jacobian to carry (a difference across a
  // patch edge would be a spike). The drop on a patch then takes the uniform bed's Newton steps.
  bool depth_only_ = false;
  Eigen::Vector3d g_W_ = Eigen::Vector3d(0.0, 0.0, -1.0);
};

// The free pad's right-hand side: dy/dt at y (the three right-hand sides, rig, free pad and
// lander, take this one shape, as Pinocchio's algorithms do). Nothing allocates.
void Derivative(const FreePadDynamics& model, FreePadData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> ydot);

}  // namespace touchdown::pad
