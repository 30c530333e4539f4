#pragma once
// Equations of motion of the four-legged lander in reduced (joint) coordinates: the ball
// joints and rigid legs hold by construction, so there is nothing to drift.
//
//   positions  q = [p_WB (3), quat_WB (4), quat_WP_i (4 x 4), s_k (one per absorber leg)]
//   speeds     u = [v_WB_W (3), w_WB_W (3), w_WP_i_W (4 x 3), ds_k/dt]
//   y = [q, u, W]   W: work dissipated so far (soil, dampers, crushing, capture) [J]
//   then, only on a terrain with a Bekker soil with shear (HasJanosiShear), each pad's Janosi
//   shear displacement j_i [m]: y = [q, u, W, j_1..j_4]
//
// Every body b has a centre-of-mass velocity v_b = J_b u and an angular velocity w_b = S_b u
// (S_b a constant selection: angular velocities are world-frame speeds), so
//   M(q) du/dt = sum_b J_b^T (F_b - m_b Jdot_b u) + S_b^T (tau_b - w_b x I_b w_b)
// with M = sum_b m_b J_b^T J_b + S_b^T I_b S_b, solved by Cholesky (Eigen).
//
// A pad held by the soil (rest handling, docs/lander_dynamics.md) adds six constraints: its
// joint centre and its attitude do not move. A crushable absorber that is not crushing adds
// one (its stroke is locked). Constrained accelerations and the constraint forces come from
//   (G M^-1 G^T) lambda = -Gdot u - G M^-1 Q,   M du/dt = Q + G^T lambda
// solved in the minimum-norm sense (four held pads over-constrain the lander; the
// minimum-norm load split is the one reported).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <array>
#include <vector>

#include "lander/multibody/lander_model.h"
#include "rft/soil_map.h"
#include "rft/contact_wrench.h"

namespace touchdown::lander {

// Index layout of the state vector for a model (absorber legs get a stroke coordinate) of the
// four legs (kNumLegs, fixed at compile time: the arrays of LanderModes and LanderRunResult are
// sized by it): positions [p_WB (3), quat_WB (4), quat_WP per leg (4), strokes], speeds
// [v_WB_W (3), w_WB_W (3), w_WP_W per leg (3), stroke rates], then the dissipated work.
struct StateLayout {
  static constexpr int kBodyPositions = 3 + 4, kPadPositions = 4;
  static constexpr int kBodySpeeds = 3 + 3, kPadSpeeds = 3;
  static constexpr int kFirstStroke = kBodyPositions + kPadPositions * kNumLegs;  // in q
  static constexpr int kFirstStrokeRate = kBodySpeeds + kPadSpeeds * kNumLegs;    // in u
  static constexpr int kMaxSpeeds = kFirstStrokeRate + kNumLegs;                  // every leg an absorber

  // shear_states: each pad carries Janosi's shear displacement j after W (HasJanosiShear).
  explicit StateLayout(const LanderModel& model, bool shear_states = false);
  bool has_shear = false;
  int stroke_slot[kNumLegs];  // index among strokes, -1 for a rigid leg
  int num_strokes = 0;
  int nq = 0, nu = 0, size = 0;
  int p_WB() const { return 0; }
  int quat_WB() const { return 3; }
  int quat_WP(int leg) const { return kBodyPositions + kPadPositions * leg; }
  int stroke(int leg) const { return kFirstStroke + stroke_slot[leg]; }
  int v_WB_W() const { return nq; }
  int w_WB_W() const { return nq + 3; }
  int w_WP_W(int leg) const { return nq + u_w_WP_W(leg); }
  int stroke_rate(int leg) const { return nq + u_stroke(leg); }
  int work() const { return nq + nu; }
  int shear(int leg) const { return nq + nu + 1 + leg; }  // only with has_shear
  // Column of a generalised speed in u (not in y).
  int u_w_WP_W(int leg) const { return kBodySpeeds + kPadSpeeds * leg; }
  int u_stroke(int leg) const { return kFirstStrokeRate + stroke_slot[leg]; }
};

enum class PadMode { kFree, kHeld };

// The cross-product matrix: Skew(a) b = a x b.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}
enum class StrokeMode { kFree, kLocked, kBottomed };  // crushable absorbers only

// Whether a ball joint's stop (ConeLimit) acts. kByAngle: wherever the pad is beyond the cone. The
// hybrid run switches kClear / kAtStop at root functions instead (LanderRunOptions::
// joint_stops_as_modes), so that the stop's damping, which acts the instant the pad reaches the rim,
// never switches on inside a solver step: kAtStop from the rim on, until the pad is back a little
// inside it (lander_hybrid.cpp, StopHysteresis); there the stop has no spring, only its damping.
enum class StopMode { kByAngle, kClear, kAtStop };

// Discrete state of the hybrid system, changed only at events.
struct LanderModes {
  std::array<PadMode, kNumLegs> pad{PadMode::kFree, PadMode::kFree, PadMode::kFree, PadMode::kFree};
  std::array<StopMode, kNumLegs> stop{StopMode::kByAngle, StopMode::kByAngle, StopMode::kByAngle,
                                      StopMode::kByAngle};
  std::array<StrokeMode, kNumLegs> stroke{StrokeMode::kLocked, StrokeMode::kLocked, StrokeMode::kLocked,
                                          StrokeMode::kLocked};
};

struct PadFrame {
  Eigen::Matrix3d R_WP;
  Eigen::Vector3d p_WJ, v_WJ_W, w_WP_W;  // joint centre, its velocity, pad angular velocity
  Eigen::Vector3d r_BJ_W;                // body CoM to joint centre
  Eigen::Vector3d axis_W;                // leg axis (hip to foot)
  Eigen::Vector3d c_JC_W;                // joint centre to pad CoM
  double shear_displacement_m = 0.0;     // Janosi's j (StateLayout::has_shear), else 0
};

struct LanderPose {
  Eigen::Matrix3d R_WB;
  Eigen::Vector3d p_WB, v_WB_W, w_WB_W;
  std::array<PadFrame, kNumLegs> pads;
};

// Everything one evaluation of the equations of motion produces.
struct LanderEvaluation {
  LanderPose pose;
  Eigen::VectorXd u_dot;                              // du/dt
  std::array<rft::ContactWrench, kNumLegs> soil;      // soil on pad, moment about the joint centre
  std::array<double, kNumLegs> leg_force_N{};         // axial absorber force, compression positive
  double dissipation_W = 0.0;                         // dW/dt
  std::array<double, kNumLegs> shear_rate_m_s{};      // dj/dt (StateLayout::has_shear)
  bool constrained = false;                           // any held pad or locked stroke
  int pad_contacts = 0;                               // soil contacts evaluated (not given)
};

// Scratch of EvaluateLander (house style: Pinocchio's Data next to the fixed Model): the
// constraint solve's matrices at their largest size (every pad held, every stroke locked), stored
// inline, so a right-hand side allocates nothing, whatever the modes.
struct LanderData {
  static constexpr int kMaxRows = 6 * kNumLegs + kNumLegs;  // six per held pad, one per locked stroke
  static constexpr int kMaxSpeeds = StateLayout::kMaxSpeeds;
  using RowsBySpeeds = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxSpeeds>;
  using SpeedsByRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSpeeds, kMaxRows>;
  using RowsByRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxRows>;
  using RowVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1>;
  using SpeedVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSpeeds, 1>;

  RowsBySpeeds G;       // constraint Jacobian
  SpeedsByRows MinvGt;  // M^-1 G^T
  RowsByRows A;         // G M^-1 G^T
  RowVector bias, rhs, lambda;       // Gdot u, the multipliers' right-hand side, the multipliers
  SpeedVector u_free, correction;    // du/dt without constraints, M^-1 G^T lambda
  RowVector c, z, householder;       // the minimum-norm solve's temporaries
  Eigen::CompleteOrthogonalDecomposition<RowsByRows> cod;
  // The mass matrix's Cholesky factor. With G, MinvGt, A and cod above it is all of an evaluation
  // that depends on the positions q alone: an evaluation with PositionTerms::kReuse takes them from
  // the last one with kKeep (same q, same modes) instead of forming them again.
  using MassMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSpeeds, kMaxSpeeds>;
  Eigen::LLT<MassMatrix> mass_llt;
  // The last Derivative's evaluation (forces, accelerations, the pads' wrenches): what the
  // right-hand side found at its state, for the Jacobian formed there and for records.
  LanderEvaluation evaluation;
};

// What an evaluation does with LanderData's position terms (above). A Jacobian's speed columns move
// u only: they reuse the factorisations of the evaluation at their base point, bit for bit what
// forming them again would give.
enum class PositionTerms { kForm, kKeep, kReuse };

// Soil wrenches an evaluation takes as given instead of computing them: a Jacobian column that
// moves one pad leaves the other pads' contact unchanged (their contact depends on their own
// state and the body's only), and the contact is nearly all of a right-hand side's cost.
struct GivenSoil {
  std::array<const rft::ContactWrench*, kNumLegs> wrench{};  // nullptr: compute (free pads only)
};

// Whether a soil of the terrain has Janosi's shear (rft::SoilContactModel::has_janosi_shear): the
// pads then carry their shear displacement j as a state (StateLayout's shear_states). j grows with
// the horizontal slip of the pad's joint centre while the pad is free in the soil; it is reset at
// the pad's next touchdown (j does not grow in the air, so that is the reset at lift-off).
bool HasJanosiShear(const rft::Terrain& terrain);

// The state layout a landing of `model` on `terrain` runs with (the shear states when a soil has
// them): the one the hybrid run integrates, for anything that reads its states afterwards.
inline StateLayout RunStateLayout(const LanderModel& model, const rft::Terrain& terrain) {
  return StateLayout(model, HasJanosiShear(terrain));
}

// Pose and velocities of all bodies from y.
LanderPose ComputePose(const LanderModel& model, const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y);

// Depth of each pad's lowest vertex below the free surface [m] (negative: above).
double PadDepth(const LanderModel& model, const rft::Terrain& terrain, int leg, const PadFrame& pad);

// The equations of motion (pure function of model, terrain, modes and state).
// `positions`: kKeep leaves the position terms in `data`; kReuse takes them from there (the caller
// guarantees the same q and modes as the kKeep evaluation, and no soil with added mass, whose mass
// moves with the contact).
void EvaluateLander(const LanderModel& model, const StateLayout& layout, const rft::Terrain& terrain,
                    const LanderModes& modes, const Eigen::Ref<const Eigen::VectorXd>& y, LanderEvaluation* out,
                    LanderData* data, const GivenSoil* given = nullptr, PositionTerms positions = PositionTerms::kForm);
// The same with scratch of its own (allocates: for samples and events, not right-hand sides).
void EvaluateLander(const LanderModel& model, const StateLayout& layout, const rft::Terrain& terrain,
                    const LanderModes& modes, const Eigen::Ref<const Eigen::VectorXd>& y, LanderEvaluation* out);
// dy/dt from an evaluation (quaternion kinematics, du/dt, dW/dt).
void StateDerivative(const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y,
                     const LanderEvaluation& e, Eigen::Ref<Eigen::VectorXd> ydot);

// The lander's Model for its right-hand side: the fixed model, its state layout and terrain, and
// the hybrid modes of the continuous phase (fixed between events). References: each must outlive it.
struct LanderSystem {
  const LanderModel& model;
  const StateLayout& layout;
  const rft::Terrain& terrain;
  const LanderModes& modes;
};
// The lander's right-hand side: dy/dt at y, its evaluation left in data.evaluation (the three
// right-hand sides, rig, free pad and lander, take this one shape, as Pinocchio's algorithms do).
// Nothing allocates once data.evaluation.u_dot has the layout's nu entries.
void Derivative(const LanderSystem& system, LanderData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> ydot);

// Kinetic energy, and potential energy (gravity, absorber springs, cone stops) [J].
double KineticEnergy(const LanderModel& model, const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y);
double PotentialEnergy(const LanderModel& model, const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y);

// RFT soil wrench on a free pad in contact with `contact` (moment about the joint centre), with
// the low-speed ramp (LanderModel::soil_ramp_speed_m_s).
rft::ContactWrench FreePadSoilWrench(const LanderModel& model, const rft::SoilContactModel& contact, int leg,
                                     const PadFrame& pad, const rft::GroundSurface& surface);

// Soil wrench on a pad at rest that starts to move along `direction` (the quasi-static
// capacity in that direction).
rft::ContactWrench QuasiStaticWrench(const LanderModel& model, const rft::Terrain& terrain, int leg, const PadFrame& pad,
                                     const Eigen::Vector3d& direction_W);

// A held pad's soil integrals at the pose it is held in (rft::FixedPoseIntegrals): formed at its
// first probe after an event, they give its quasi-static capacity in every direction of load until
// the next event without clipping its elements again (the root functions' slide check: most of
// their contacts). Per-run scratch of the hybrid run, not model data.
struct HeldPadCapacity {
  rft::FixedPoseIntegrals integrals;
  bool formed = false;  // false: form at the next probe (after an event)
  int soil = -1;        // the terrain's soil under the pad when formed
};

// QuasiStaticWrench's force for a held pad, from `held` (formed here from `pad`'s pose when it is not
// yet): bit for bit the same force at the pose it was formed in (over a plane). A soil with pad-level
// terms (rft::FixedPoseIntegrals::Supports false) takes QuasiStaticWrench itself. `contacts` counts
// the contacts evaluated (1 when it forms or falls back, else 0).
Eigen::Vector3d HeldPadCapacityForce(const LanderModel& model, const rft::Terrain& terrain, int leg, const PadFrame& pad,
                                     const Eigen::Vector3d& direction_W, HeldPadCapacity* held, long* contacts);

// Projects the speeds onto the constraints of `modes` with the least kinetic-energy change (a
// perfectly plastic capture). Returns the kinetic energy removed [J].
double ProjectOntoConstraints(const LanderModel& model, const StateLayout& layout, const LanderModes& modes,
                              Eigen::Ref<Eigen::VectorXd> y);

// True if the holds of `modes` leave the body and every stroke no freedom to move (three held pads
// on rigid legs, for example): a pad left free can then only turn about its fixed ball joint.
bool HoldsFixTheStance(const LanderModel& model, const StateLayout& layout, const LanderModes& modes,
                       const Eigen::Ref<const Eigen::VectorXd>& y);

// Renormalises every quaternion in y (done at each event; the drift is integration error,
// not a joint violation).
void NormalizeQuaternions(const StateLayout& layout, Eigen::Ref<Eigen::VectorXd> y);

// Body attitude angles, aerospace convention in the body frame of this model: roll > 0 right
// side (pads 2, 3) down; pitch > 0 nose (pads 1, 2) up; tilt = angle of z_B from vertical.
struct Attitude {
  double roll_rad = 0.0, pitch_rad = 0.0, yaw_rad = 0.0, tilt_rad = 0.0;
};
Attitude BodyAttitude(const Eigen::Matrix3d& R_WB);

// The ball joint's swing: the angle of the pad's axis (z_P) from the body's z axis [rad], the angle
// a ConeLimit bounds.
double JointSwingAngle(const Eigen::Matrix3d& R_WB, const Eigen::Matrix3d& R_WP);

// Centre of mass of the whole lander (body and pads), world frame [m]; the point StabilityMargin
// tests.
Eigen::Vector3d LanderCentreOfMass(const LanderModel& model, const LanderPose& pose);

// Signed horizontal distance of point_W inside the support polygon's edge `edge` (from joint centre
// `edge` to the next one clockwise seen from above; positive inside) [m].
double InsideEdgeDistance(const LanderPose& pose, int edge, const Eigen::Vector3d& point_W);

// Signed horizontal distance of the lander's centre of mass inside the polygon of the joint
// centres (positive inside) [m]: the least InsideEdgeDistance of LanderCentreOfMass.
double StabilityMargin(const LanderModel& model, const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y);

// The support polygon's edge the centre of mass is nearest to crossing (the least InsideEdgeDistance,
// the one StabilityMargin reports): at a tip-over, the edge the lander goes over.
struct CriticalEdge {
  int from_leg = 0;                // from this joint centre to the next one clockwise (0-based)
  double margin_m = 0.0;           // InsideEdgeDistance of the centre of mass
  double outward_azimuth_rad = 0.0;  // azimuth of the edge's outward horizontal normal (from world +x towards +y)
};
CriticalEdge CriticalSupportEdge(const LanderModel& model, const StateLayout& layout,
                                 const Eigen::Ref<const Eigen::VectorXd>& y);

}  // namespace touchdown::lander
