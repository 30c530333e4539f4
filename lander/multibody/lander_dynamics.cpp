#include "lander/multibody/lander_dynamics.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "rft/deepest_point.h"
#include "rft/entrained_mass.h"

namespace touchdown::lander {

namespace {
constexpr int kMaxSpeeds = StateLayout::kMaxSpeeds;
using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSpeeds, kMaxSpeeds>;
using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSpeeds, 1>;

Eigen::Quaterniond QuatAt(const Eigen::Ref<const Eigen::VectorXd>& y, int i) {
  return Eigen::Quaterniond(y[i], y[i + 1], y[i + 2], y[i + 3]).normalized();
}

double PadRadius(const Leg& leg) {
  const rft::SurfaceElements& s = leg.pad->surface;
  if (s.HasBounds()) return s.max_vertex_radius_m;  // model data: measured once
  return leg.pad->vertices_B.colwise().norm().maxCoeff();
}

// Linear-velocity Jacobian of the pad CoM (3 x nu) and of the joint centre, and their bias.
void PadJacobians(const StateLayout& L, int i, const PadFrame& pf, const Eigen::Vector3d& w_B,
                  double stroke_rate, Mat* J_C, Mat* J_J, Eigen::Vector3d* bias_C, Eigen::Vector3d* bias_J) {
  J_J->setZero(3, L.nu);
  J_J->block<3, 3>(0, 0).setIdentity();
  J_J->block<3, 3>(0, 3) = -Skew(pf.r_BJ_W);
  if (L.stroke_slot[i] >= 0) J_J->col(L.u_stroke(i)) = -pf.axis_W;
  *J_C = *J_J;
  J_C->block<3, 3>(0, L.u_w_WP_W(i)) = -Skew(pf.c_JC_W);
  *bias_J = w_B.cross(w_B.cross(pf.r_BJ_W)) - 2.0 * stroke_rate * w_B.cross(pf.axis_W);
  *bias_C = *bias_J + pf.w_WP_W.cross(pf.w_WP_W.cross(pf.c_JC_W));
}
}  // namespace

StateLayout::StateLayout(const LanderModel& model, bool shear_states) : has_shear(shear_states) {
  for (int i = 0; i < kNumLegs; ++i) stroke_slot[i] = model.legs[i].absorber ? num_strokes++ : -1;
  nq = kFirstStroke + num_strokes;
  nu = kFirstStrokeRate + num_strokes;
  size = nq + nu + 1 + (has_shear ? kNumLegs : 0);
}

bool HasJanosiShear(const rft::Terrain& terrain) {
  for (const rft::TerrainSoil& soil : terrain.soils)
    if (soil.contact.has_janosi_shear()) return true;
  return false;
}

void FinishModel(LanderModel& model) {
  if (!(model.body_mass_kg > 0.0)) throw std::invalid_argument("lander: body mass must be positive");
  if (!(model.gravity_m_s2 >= 0.0)) throw std::invalid_argument("lander: gravity must be >= 0");
  if (Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(model.body_inertia_B).eigenvalues().minCoeff() <= 0.0)
    throw std::invalid_argument("lander: body inertia must be positive definite");
  for (Leg& leg : model.legs) {
    if (!leg.pad || !(leg.pad->mass_kg > 0.0) || leg.pad->surface.size() == 0)
      throw std::invalid_argument("lander: every leg needs a pad with mass and a surface");
    if ((leg.joint_B - leg.hip_B).norm() <= 0.0) throw std::invalid_argument("lander: leg of zero length");
    if (leg.pad->vertices_B.cols() == 0)
      throw std::invalid_argument("lander: every pad needs its vertices (geom::PadBody::vertices_B)");
  }
}

LanderPose ComputePose(const LanderModel& model, const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y) {
  LanderPose p;
  p.R_WB = QuatAt(y, L.quat_WB()).toRotationMatrix();
  p.p_WB = y.segment<3>(L.p_WB());
  p.v_WB_W = y.segment<3>(L.v_WB_W());
  p.w_WB_W = y.segment<3>(L.w_WB_W());
  for (int i = 0; i < kNumLegs; ++i) {
    const Leg& leg = model.legs[i];
    PadFrame& f = p.pads[i];
    const double s = L.stroke_slot[i] >= 0 ? y[L.stroke(i)] : 0.0;
    const double sdot = L.stroke_slot[i] >= 0 ? y[L.stroke_rate(i)] : 0.0;
    f.axis_W = p.R_WB * leg.axis_B();
    f.r_BJ_W = p.R_WB * leg.joint_B - s * f.axis_W;
    f.p_WJ = p.p_WB + f.r_BJ_W;
    f.v_WJ_W = p.v_WB_W + p.w_WB_W.cross(f.r_BJ_W) - sdot * f.axis_W;
    f.R_WP = QuatAt(y, L.quat_WP(i)).toRotationMatrix();
    f.w_WP_W = y.segment<3>(L.w_WP_W(i));
    f.c_JC_W = f.R_WP * leg.pad->com_B;
    f.shear_displacement_m = L.has_shear ? y[L.shear(i)] : 0.0;
  }
  return p;
}

double PadDepth(const LanderModel& model, const rft::Terrain& terrain, int leg, const PadFrame& pad) {
  const geom::PadBody& body = *model.legs[leg].pad;
  return rft::DeepestVertexDepth(geom::DeepestPointCandidates(body, *terrain.surface), pad.R_WP, pad.p_WJ,
                                 *terrain.surface);
}

rft::ContactWrench FreePadSoilWrench(const LanderModel& model, const rft::SoilContactModel& contact, int leg,
                                     const PadFrame& f, const rft::GroundSurface& surface) {
  const Leg& l = model.legs[leg];
  rft::PadKinematics k{f.R_WP, f.p_WJ, f.v_WJ_W, f.w_WP_W};
  if (contact.has_janosi_shear()) k.shear_mobilisation = contact.ShearMobilisation(f.shear_displacement_m);
  if (model.soil_ramp == SoilRamp::kElement) {
    k.element_ramp_speed_m_s = model.soil_ramp_speed_m_s;
    return rft::ComputeContactWrench(l.pad->surface, k, surface, *contact.law, contact.pad_terms);
  }
  const double speed = f.v_WJ_W.norm() + f.w_WP_W.norm() * PadRadius(l);
  rft::ContactWrench w = rft::ComputeContactWrench(l.pad->surface, k, surface, *contact.law, contact.pad_terms);
  if (speed < model.soil_ramp_speed_m_s) {
    w.force_W *= speed / model.soil_ramp_speed_m_s;
    w.moment_W *= speed / model.soil_ramp_speed_m_s;
  }
  return w;
}

rft::ContactWrench QuasiStaticWrench(const LanderModel& model, const rft::Terrain& terrain, int leg, const PadFrame& pad,
                                     const Eigen::Vector3d& direction_W) {
  rft::PadKinematics k{pad.R_WP, pad.p_WJ, rft::kQuasiStaticProbeSpeed_m_s * direction_W.normalized(),
                       Eigen::Vector3d::Zero()};
  const int soil = terrain.SoilAt(pad.p_WJ.x(), pad.p_WJ.y());
  const rft::SoilContactModel& contact = terrain.soils[soil].contact;
  // The capacity at the pad's own j: a pad that has not slid yet offers no Janosi shear to a load
  // that would make it slide (as the free pad's force after the release would not).
  if (contact.has_janosi_shear()) k.shear_mobilisation = contact.ShearMobilisation(pad.shear_displacement_m);
  return rft::ComputeContactWrench(model.legs[leg].pad->surface, k, *terrain.surface, *contact.law, contact.pad_terms);
}

Eigen::Vector3d HeldPadCapacityForce(const LanderModel& model, const rft::Terrain& terrain, int leg, const PadFrame& pad,
                                     const Eigen::Vector3d& direction_W, HeldPadCapacity* held, long* contacts) {
  const int soil = terrain.SoilAt(pad.p_WJ.x(), pad.p_WJ.y());
  const rft::SoilContactModel& contact = terrain.soils[soil].contact;
  if (!rft::FixedPoseIntegrals::Supports(contact.pad_terms)) {
    ++*contacts;
    return QuasiStaticWrench(model, terrain, leg, pad, direction_W).force_W;
  }
  if (!held->formed || held->soil != soil) {
    ++*contacts;
    rft::FormFixedPoseIntegrals(model.legs[leg].pad->surface, pad.R_WP, pad.p_WJ, *terrain.surface, &held->integrals);
    held->formed = true;
    held->soil = soil;
  }
  // As QuasiStaticWrench probes (its speed, and Janosi's shear at the pad's own j).
  const double mobilisation =
      contact.has_janosi_shear() ? contact.ShearMobilisation(pad.shear_displacement_m) : 1.0;
  return rft::TranslationWrenchAt(held->integrals, rft::kQuasiStaticProbeSpeed_m_s * direction_W.normalized(),
                                  *contact.law, contact.pad_terms, mobilisation)
      .force_W;
}

namespace {
struct Assembly {
  Mat M;
  Vec Q;
  std::array<Mat, kNumLegs> J_J;
  std::array<Eigen::Vector3d, kNumLegs> bias_J;
};

// Mass matrix and generalised forces without constraint forces. Fills e->soil, leg forces and
// the dissipation of free pads, dampers and crushing.
// `mass` false: without M (an evaluation that reuses M's factor).
void Assemble(const LanderModel& model, const StateLayout& L, const rft::Terrain& terrain, const LanderModes& modes,
              const Eigen::Ref<const Eigen::VectorXd>& y, const GivenSoil* given, bool mass, LanderEvaluation* e,
              Assembly* a) {
  const LanderPose& p = e->pose;
  const Eigen::Vector3d g(0, 0, -model.gravity_m_s2);
  a->Q.setZero(L.nu);
  const Eigen::Matrix3d I_B = p.R_WB * model.body_inertia_B * p.R_WB.transpose();
  if (mass) {
    a->M.setZero(L.nu, L.nu);
    a->M.block<3, 3>(0, 0).diagonal().setConstant(model.body_mass_kg);
    a->M.block<3, 3>(3, 3) = I_B;
  }
  a->Q.segment<3>(0) = model.body_mass_kg * g;
  a->Q.segment<3>(3) = -p.w_WB_W.cross(I_B * p.w_WB_W);
  e->dissipation_W = 0.0;
  e->pad_contacts = 0;
  Mat J_C;
  Eigen::Vector3d bias_C;
  for (int i = 0; i < kNumLegs; ++i) {
    const Leg& leg = model.legs[i];
    const PadFrame& f = p.pads[i];
    const double m = leg.pad->mass_kg;
    const bool has_stroke = L.stroke_slot[i] >= 0;
    const double s = has_stroke ? y[L.stroke(i)] : 0.0;
    const double sdot = has_stroke ? y[L.stroke_rate(i)] : 0.0;
    PadJacobians(L, i, f, p.w_WB_W, sdot, &J_C, &a->J_J[i], &bias_C, &a->bias_J[i]);
    const Eigen::Matrix3d I_P = f.R_WP * leg.pad->inertia_com_B * f.R_WP.transpose();
    if (mass) {
      a->M.noalias() += m * J_C.transpose() * J_C;
      a->M.block<3, 3>(L.u_w_WP_W(i), L.u_w_WP_W(i)) += I_P;
    }

    // Soil: RFT on a free pad in contact; a held pad's wrench is a constraint force (later).
    rft::ContactWrench& w = e->soil[i];
    w = rft::ContactWrench{};
    e->shear_rate_m_s[i] = 0.0;
    const rft::ContactWrench* given_wrench = given ? given->wrench[i] : nullptr;
    if (modes.pad[i] == PadMode::kFree && (given_wrench || PadDepth(model, terrain, i, f) > 0.0)) {
      const int soil = terrain.SoilAt(f.p_WJ.x(), f.p_WJ.y());
      const rft::SoilContactModel& contact = terrain.soils[soil].contact;
      if (given_wrench) {
        w = *given_wrench;
      } else {
        w = FreePadSoilWrench(model, contact, i, f, *terrain.surface);
        ++e->pad_contacts;
      }
      e->dissipation_W -= w.force_W.dot(f.v_WJ_W) + w.moment_W.dot(f.w_WP_W);
      // Janosi's j grows with the slip of the contact's reference point, the joint centre
      // (docs/bekker_soil.md says why that point); a held pad does not slip.
      if (L.has_shear && w.submerged_area_m2 > 0.0) e->shear_rate_m_s[i] = std::hypot(f.v_WJ_W.x(), f.v_WJ_W.y());
      // added_mass and added_mass_plug (rft/entrained_mass.h): the entrained grains move with the
      // vertical velocity of the pad's centre of mass, as in the free drop: a mass m_a on the row e_z^T J_C, with the
      // accretion force -max(dm_a/dt, 0) v_z (grains join at rest, leave with the pad) and the
      // kinetic energy lost, |dm_a/dt| v_z^2 / 2.
      if (contact.pad_terms.has_added_mass()) {
        const rft::EntrainedMass ea =
            rft::EntrainedGrains(contact.pad_terms, w.penetration_m, w.penetration_rate_m_s, w.footprint_area_m2,
                                 w.footprint_area_rate_m2_s);
        const double v_z = (f.v_WJ_W + f.w_WP_W.cross(f.c_JC_W)).z();
        const double force_z = -ea.mass_kg * bias_C.z() - std::max(ea.rate_kg_s, 0.0) * v_z;
        for (int r = 0; r < L.nu; ++r) {  // M += m_a J_z^T J_z, Q += J_z^T force_z (no temporaries)
          a->Q[r] += J_C(2, r) * force_z;
          if (mass)
            for (int c = 0; c < L.nu; ++c) a->M(r, c) += ea.mass_kg * J_C(2, r) * J_C(2, c);
        }
        e->dissipation_W += 0.5 * std::abs(ea.rate_kg_s) * v_z * v_z;
      }
    }
    const Eigen::Vector3d F = m * g + w.force_W - m * bias_C;
    a->Q.noalias() += J_C.transpose() * F;
    Eigen::Vector3d tau = w.moment_W - f.c_JC_W.cross(w.force_W) - f.w_WP_W.cross(I_P * f.w_WP_W);

    // Cone limit of the ball joint: a stiff stop beyond the half-angle. The stop is one-sided, as
    // the socket's rim is: it pushes the pad back and never pulls it, so the torque is clamped at
    // zero when the damping of a pad leaving the rim would outweigh the spring. What the stop takes
    // out of the motion beyond the spring's energy, (torque - k over) rate, is dissipated.
    if (leg.cone) {
      const Eigen::Vector3d zB = p.R_WB.col(2), zP = f.R_WP.col(2);
      const Eigen::Vector3d cr = zB.cross(zP);
      const double theta = std::atan2(cr.norm(), zB.dot(zP));
      // kAtStop acts just inside the rim too (lander_hybrid.cpp, StopHysteresis), its damping alone.
      const double over = theta - leg.cone->half_angle_rad;
      const StopMode stop = modes.stop[i];
      const bool acts = stop == StopMode::kAtStop || (stop == StopMode::kByAngle && over > 0.0);
      if (acts && cr.norm() > 0.0) {
        const Eigen::Vector3d n = cr.normalized();
        const double rate = n.dot(f.w_WP_W - p.w_WB_W);
        const double spring = leg.cone->stiffness_N_m_rad * std::max(over, 0.0);
        const double damping = leg.cone->damping_N_m_s_rad * rate;
        const bool pushes = spring + damping > 0.0;
        const double torque = pushes ? spring + damping : 0.0;
        tau -= torque * n;
        a->Q.segment<3>(3) += torque * n;
        e->dissipation_W += pushes ? damping * rate : -spring * rate;
      }
    }
    a->Q.segment<3>(L.u_w_WP_W(i)) += tau;

    // Shock absorber: generalised force on the stroke (compression) coordinate.
    e->leg_force_N[i] = 0.0;
    if (has_stroke) {
      const ShockAbsorber& ab = *leg.absorber;
      double force = 0.0;
      if (ab.kind == ShockAbsorber::Kind::kSpringDamper) {
        force = ab.stiffness_N_m * s + ab.damping_N_s_m * sdot;
        e->dissipation_W += ab.damping_N_s_m * sdot * sdot;
      } else if (modes.stroke[i] == StrokeMode::kFree) {
        force = ab.crush_force_N;
        e->dissipation_W += ab.crush_force_N * sdot;
      }
      e->leg_force_N[i] = force;
      a->Q[L.u_stroke(i)] -= force;
    }
  }
}
}  // namespace

namespace {
// Rows of the constraints of `modes`: six per held pad, one per locked crushable stroke.
int ConstraintRows(const LanderModel& model, const StateLayout& L, const LanderModes& modes) {
  int rows = 0;
  for (int i = 0; i < kNumLegs; ++i) {
    if (modes.pad[i] == PadMode::kHeld) rows += 6;
    if (L.stroke_slot[i] >= 0 && model.legs[i].absorber->kind == ShockAbsorber::Kind::kCrushable &&
        modes.stroke[i] != StrokeMode::kFree)
      rows += 1;
  }
  return rows;
}

// x = A^+ b, the minimum-norm solution from a complete orthogonal decomposition of A: Eigen's
// CompleteOrthogonalDecomposition::solve step by step, with its temporaries in `data`.
void SolveMinimumNorm(LanderData& data, const LanderData::RowVector& b, LanderData::RowVector& x) {
  const Eigen::CompleteOrthogonalDecomposition<LanderData::RowsByRows>& cod = data.cod;
  const Eigen::Index rank = cod.rank(), cols = cod.cols();
  if (rank == 0) {
    x.setZero();
    return;
  }
  LanderData::RowVector& c = data.c;
  c = b;
  c.applyOnTheLeft(cod.matrixQ().setLength(rank).adjoint());
  LanderData::RowVector& z = data.z;
  z.topRows(rank) = cod.matrixT().topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solve(c.topRows(rank));
  if (rank < cols) {  // z = Z^* [z; 0]
    z.bottomRows(cols - rank).setZero();
    for (Eigen::Index k = 0; k < rank; ++k) {
      if (k != rank - 1) z.row(k).swap(z.row(rank - 1));
      z.middleRows(rank - 1, cols - rank + 1)
          .applyHouseholderOnTheLeft(cod.matrixQTZ().row(k).tail(cols - rank).adjoint(), cod.zCoeffs()(k),
                                     &data.householder(0));
      if (k != rank - 1) z.row(k).swap(z.row(rank - 1));
    }
  }
  x.noalias() = cod.colsPermutation() * z;
}
}  // namespace

void EvaluateLander(const LanderModel& model, const StateLayout& L, const rft::Terrain& terrain, const LanderModes& modes,
                    const Eigen::Ref<const Eigen::VectorXd>& y, LanderEvaluation* e) {
  LanderData data;
  EvaluateLander(model, L, terrain, modes, y, e, &data);
}

void EvaluateLander(const LanderModel& model, const StateLayout& L, const rft::Terrain& terrain, const LanderModes& modes,
                    const Eigen::Ref<const Eigen::VectorXd>& y, LanderEvaluation* e, LanderData* data,
                    const GivenSoil* given, PositionTerms positions) {
  e->pose = ComputePose(model, L, y);
  const bool reuse = positions == PositionTerms::kReuse;
  Assembly a;
  Assemble(model, L, terrain, modes, y, given, /*mass=*/!reuse, e, &a);
  // kKeep factors into `data` (for later kReuse evaluations), kForm into a local.
  Eigen::LLT<Mat> formed;
  Eigen::LLT<Mat>& llt = positions == PositionTerms::kForm ? formed : data->mass_llt;
  if (!reuse) llt.compute(a.M);
  Vec u_dot = llt.solve(a.Q);

  // Constraints of held pads and locked crushable strokes.
  const int rows = ConstraintRows(model, L, modes);
  e->constrained = rows > 0;
  if (rows > 0) {
    LanderData& d = *data;
    LanderData::RowsBySpeeds& G = d.G;
    if (!reuse) G.setZero(rows, L.nu);
    d.bias.setZero(rows);
    int r = 0;
    std::array<int, kNumLegs> pad_row{-1, -1, -1, -1}, stroke_row{-1, -1, -1, -1};
    for (int i = 0; i < kNumLegs; ++i) {
      if (modes.pad[i] == PadMode::kHeld) {
        pad_row[i] = r;
        if (!reuse) {
          G.block(r, 0, 3, L.nu) = a.J_J[i];
          G.block<3, 3>(r + 3, L.u_w_WP_W(i)).setIdentity();
        }
        d.bias.segment<3>(r) = a.bias_J[i];
        r += 6;
      }
      if (L.stroke_slot[i] >= 0 && model.legs[i].absorber->kind == ShockAbsorber::Kind::kCrushable &&
          modes.stroke[i] != StrokeMode::kFree) {
        stroke_row[i] = r;
        if (!reuse) G(r, L.u_stroke(i)) = 1.0;
        ++r;
      }
    }
    if (!reuse) {
      d.MinvGt = llt.solve(G.transpose());
      d.A.noalias() = G * d.MinvGt;
    }
    d.u_free = u_dot;
    d.rhs.noalias() = -d.bias - G * d.u_free;
    // Minimum-norm multipliers: four held pads are statically indeterminate.
    if (!reuse) d.cod.compute(d.A);
    d.c.resize(rows);
    d.z.resize(rows);
    d.householder.resize(rows);
    d.lambda.resize(rows);
    SolveMinimumNorm(d, d.rhs, d.lambda);
    d.correction.noalias() = d.MinvGt * d.lambda;
    u_dot += d.correction;
    const LanderData::RowVector& lambda = d.lambda;
    for (int i = 0; i < kNumLegs; ++i) {
      if (pad_row[i] >= 0) {
        e->soil[i].force_W = lambda.segment<3>(pad_row[i]);
        e->soil[i].moment_W = lambda.segment<3>(pad_row[i] + 3);
      }
      // A locked stroke: the generalised constraint force is -(axial compression force).
      if (stroke_row[i] >= 0) e->leg_force_N[i] = -lambda[stroke_row[i]];
    }
  }
  e->u_dot = u_dot;
}

void Derivative(const LanderSystem& system, LanderData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> ydot) {
  EvaluateLander(system.model, system.layout, system.terrain, system.modes, y, &data.evaluation, &data);
  StateDerivative(system.layout, y, data.evaluation, ydot);
}

void StateDerivative(const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y, const LanderEvaluation& e,
                     Eigen::Ref<Eigen::VectorXd> ydot) {
  auto quat_rate = [&](int qi, const Eigen::Vector3d& w) {
    // dq/dt = 1/2 [0, w_W] (x) q for a world-frame angular velocity.
    const Eigen::Quaterniond q(y[qi], y[qi + 1], y[qi + 2], y[qi + 3]);
    const Eigen::Quaterniond wq(0.0, w.x(), w.y(), w.z());
    const Eigen::Quaterniond d = wq * q;
    ydot[qi] = 0.5 * d.w();
    ydot.segment<3>(qi + 1) = 0.5 * d.vec();
  };
  ydot.segment<3>(L.p_WB()) = y.segment<3>(L.v_WB_W());
  quat_rate(L.quat_WB(), y.segment<3>(L.w_WB_W()));
  for (int i = 0; i < kNumLegs; ++i) {
    quat_rate(L.quat_WP(i), y.segment<3>(L.w_WP_W(i)));
    if (L.stroke_slot[i] >= 0) ydot[L.stroke(i)] = y[L.stroke_rate(i)];
  }
  ydot.segment(L.nq, L.nu) = e.u_dot;
  ydot[L.work()] = e.dissipation_W;
  if (L.has_shear)
    for (int i = 0; i < kNumLegs; ++i) ydot[L.shear(i)] = e.shear_rate_m_s[i];
}

double KineticEnergy(const LanderModel& model, const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y) {
  const LanderPose p = ComputePose(model, L, y);
  double T = 0.5 * model.body_mass_kg * p.v_WB_W.squaredNorm() +
             0.5 * p.w_WB_W.dot(p.R_WB * model.body_inertia_B * p.R_WB.transpose() * p.w_WB_W);
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = p.pads[i];
    const Eigen::Vector3d v_C = f.v_WJ_W + f.w_WP_W.cross(f.c_JC_W);
    T += 0.5 * model.legs[i].pad->mass_kg * v_C.squaredNorm() +
         0.5 * f.w_WP_W.dot(f.R_WP * model.legs[i].pad->inertia_com_B * f.R_WP.transpose() * f.w_WP_W);
  }
  return T;
}

double PotentialEnergy(const LanderModel& model, const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y) {
  const LanderPose p = ComputePose(model, L, y);
  const double g = model.gravity_m_s2;
  double V = model.body_mass_kg * g * p.p_WB.z();
  for (int i = 0; i < kNumLegs; ++i) {
    const Leg& leg = model.legs[i];
    const PadFrame& f = p.pads[i];
    V += leg.pad->mass_kg * g * (f.p_WJ + f.c_JC_W).z();
    if (L.stroke_slot[i] >= 0 && leg.absorber->kind == ShockAbsorber::Kind::kSpringDamper)
      V += 0.5 * leg.absorber->stiffness_N_m * y[L.stroke(i)] * y[L.stroke(i)];
    if (leg.cone) {
      const double theta = JointSwingAngle(p.R_WB, f.R_WP);
      const double over = std::max(theta - leg.cone->half_angle_rad, 0.0);
      V += 0.5 * leg.cone->stiffness_N_m_rad * over * over;
    }
  }
  return V;
}

namespace {
// Rows of the constraints of `modes` (ConstraintRows: six per held pad, one per locked crushable
// stroke) at `pose`: the same G as EvaluateLander's.
Eigen::MatrixXd HoldJacobian(const LanderModel& model, const StateLayout& L, const LanderModes& modes,
                             const LanderPose& pose, const Eigen::Ref<const Eigen::VectorXd>& y) {
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(ConstraintRows(model, L, modes), L.nu);
  int r = 0;
  for (int i = 0; i < kNumLegs; ++i) {
    if (modes.pad[i] == PadMode::kHeld) {
      const double sdot = L.stroke_slot[i] >= 0 ? y[L.stroke_rate(i)] : 0.0;
      Mat J_C, J_J;
      Eigen::Vector3d bC, bJ;
      PadJacobians(L, i, pose.pads[i], pose.w_WB_W, sdot, &J_C, &J_J, &bC, &bJ);
      G.block(r, 0, 3, L.nu) = J_J;
      G.block<3, 3>(r + 3, L.u_w_WP_W(i)).setIdentity();
      r += 6;
    }
    if (L.stroke_slot[i] >= 0 && model.legs[i].absorber->kind == ShockAbsorber::Kind::kCrushable &&
        modes.stroke[i] != StrokeMode::kFree)
      G(r++, L.u_stroke(i)) = 1.0;
  }
  return G;
}
}  // namespace

double ProjectOntoConstraints(const LanderModel& model, const StateLayout& L, const LanderModes& modes,
                              Eigen::Ref<Eigen::VectorXd> y) {
  const LanderPose pose = ComputePose(model, L, y);
  // Only the mass matrix and the constraint Jacobian are needed: assemble with free modes
  // and no terrain contact by evaluating the Jacobians directly.
  Mat M = Mat::Zero(L.nu, L.nu);
  M.block<3, 3>(0, 0).diagonal().setConstant(model.body_mass_kg);
  M.block<3, 3>(3, 3) = pose.R_WB * model.body_inertia_B * pose.R_WB.transpose();
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = pose.pads[i];
    const double sdot = L.stroke_slot[i] >= 0 ? y[L.stroke_rate(i)] : 0.0;
    Mat J_C, J_J;
    Eigen::Vector3d bC, bJ;
    PadJacobians(L, i, f, pose.w_WB_W, sdot, &J_C, &J_J, &bC, &bJ);
    M.noalias() += model.legs[i].pad->mass_kg * J_C.transpose() * J_C;
    M.block<3, 3>(L.u_w_WP_W(i), L.u_w_WP_W(i)) += f.R_WP * model.legs[i].pad->inertia_com_B * f.R_WP.transpose();
  }
  const Eigen::MatrixXd G = HoldJacobian(model, L, modes, pose, y);
  if (G.rows() == 0) return 0.0;
  const double T0 = KineticEnergy(model, L, y);
  // u+ = u - M^-1 G^T (G M^-1 G^T)^+ G u: the M-orthogonal projection onto G u = 0.
  const Eigen::LLT<Mat> llt(M);
  const Eigen::VectorXd u = y.segment(L.nq, L.nu);
  const Eigen::MatrixXd MinvGt = llt.solve(G.transpose());
  const Eigen::VectorXd mu = (G * MinvGt).completeOrthogonalDecomposition().solve(G * u);
  y.segment(L.nq, L.nu) = u - MinvGt * mu;
  return T0 - KineticEnergy(model, L, y);
}

bool HoldsFixTheStance(const LanderModel& model, const StateLayout& L, const LanderModes& modes,
                       const Eigen::Ref<const Eigen::VectorXd>& y) {
  const Eigen::MatrixXd G = HoldJacobian(model, L, modes, ComputePose(model, L, y), y);
  if (G.rows() == 0) return false;
  // The speeds the holds allow (the null space of G) must not move the body or any stroke; a free
  // pad's spin about its (then fixed) joint is all that may be left.
  Eigen::FullPivLU<Eigen::MatrixXd> lu(G);
  lu.setThreshold(1e-10);
  const Eigen::MatrixXd allowed = lu.kernel();
  if (lu.dimensionOfKernel() == 0) return true;
  double stance = allowed.topRows(StateLayout::kBodySpeeds).cwiseAbs().maxCoeff();
  for (int i = 0; i < kNumLegs; ++i)
    if (L.stroke_slot[i] >= 0) stance = std::max(stance, allowed.row(L.u_stroke(i)).cwiseAbs().maxCoeff());
  return stance < 1e-9;
}

void NormalizeQuaternions(const StateLayout& L, Eigen::Ref<Eigen::VectorXd> y) {
  y.segment<4>(L.quat_WB()).normalize();
  for (int i = 0; i < kNumLegs; ++i) y.segment<4>(L.quat_WP(i)).normalize();
}

Attitude BodyAttitude(const Eigen::Matrix3d& R) {
  // R = Rz(yaw) Ry(theta) Rx(phi) in the z-up, y-left body frame; the aerospace pitch (nose
  // up positive, y to the right) is -theta, and the roll about x is the same in both frames.
  Attitude a;
  a.roll_rad = std::atan2(R(2, 1), R(2, 2));
  a.pitch_rad = std::asin(std::clamp(R(2, 0), -1.0, 1.0));  // -theta = asin(R20)
  a.yaw_rad = std::atan2(R(1, 0), R(0, 0));
  a.tilt_rad = std::acos(std::clamp(R(2, 2), -1.0, 1.0));
  return a;
}

double JointSwingAngle(const Eigen::Matrix3d& R_WB, const Eigen::Matrix3d& R_WP) {
  const Eigen::Vector3d zB = R_WB.col(2), zP = R_WP.col(2);
  return std::atan2(zB.cross(zP).norm(), zB.dot(zP));
}

Eigen::Vector3d LanderCentreOfMass(const LanderModel& model, const LanderPose& pose) {
  Eigen::Vector3d moment = model.body_mass_kg * pose.p_WB;
  for (int i = 0; i < kNumLegs; ++i)
    moment += model.legs[i].pad->mass_kg * (pose.pads[i].p_WJ + pose.pads[i].c_JC_W);
  return moment / model.TotalMass();
}

double InsideEdgeDistance(const LanderPose& pose, int edge, const Eigen::Vector3d& point_W) {
  const Eigen::Vector2d a = pose.pads[edge].p_WJ.head<2>(), b = pose.pads[(edge + 1) % kNumLegs].p_WJ.head<2>();
  const Eigen::Vector2d e = b - a, r = point_W.head<2>() - a;
  // Clockwise polygon seen from above: the inside is on the right of each edge.
  return -(e.x() * r.y() - e.y() * r.x()) / e.norm();
}

namespace {
// The support edge with the least InsideEdgeDistance of the centre of mass, and that distance.
std::pair<int, double> LeastInsideEdge(const LanderModel& model, const LanderPose& p) {
  const Eigen::Vector3d com = LanderCentreOfMass(model, p);
  std::pair<int, double> least{0, std::numeric_limits<double>::infinity()};
  for (int i = 0; i < kNumLegs; ++i) {
    const double inside = InsideEdgeDistance(p, i, com);
    if (inside < least.second) least = {i, inside};
  }
  return least;
}
}  // namespace

double StabilityMargin(const LanderModel& model, const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y) {
  return LeastInsideEdge(model, ComputePose(model, L, y)).second;
}

CriticalEdge CriticalSupportEdge(const LanderModel& model, const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y) {
  const LanderPose p = ComputePose(model, L, y);
  CriticalEdge edge;
  std::tie(edge.from_leg, edge.margin_m) = LeastInsideEdge(model, p);
  const Eigen::Vector2d e = p.pads[(edge.from_leg + 1) % kNumLegs].p_WJ.head<2>() - p.pads[edge.from_leg].p_WJ.head<2>();
  // Clockwise seen from above, the inside is on the right of e: outward is its left normal (-e_y, e_x).
  edge.outward_azimuth_rad = std::atan2(e.x(), -e.y());
  return edge;
}

}  // namespace touchdown::lander
