#include "lander/pad/free_drop.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "lander/integ/hybrid_run.h"
#include "lander/pad/pad_pose.h"
#include "rft/contact_wrench.h"
#include "rft/deepest_point.h"
#include "rft/entrained_mass.h"
#include "rft/units.h"

namespace touchdown::pad {

namespace {
// State layout: centre of mass p_WC, attitude quaternion q_WB (w, x, y, z), velocity v_WC,
// body-frame angular velocity w_B, work done against the soil.
enum : int { kP = 0, kQ = 3, kV = 7, kW = 10, kWork = 13, kSize = 14 };

struct Pose {
  Eigen::Matrix3d R_WB;
  Eigen::Vector3d p_WC, p_WB, v_WC, w_B, w_W, v_WB;
};

Pose PoseOf(const geom::PadBody& body, const Eigen::Ref<const Eigen::VectorXd>& y) {
  Pose s;
  const Eigen::Quaterniond q(y[kQ], y[kQ + 1], y[kQ + 2], y[kQ + 3]);
  s.R_WB = q.normalized().toRotationMatrix();
  s.p_WC = y.segment<3>(kP);
  s.v_WC = y.segment<3>(kV);
  s.w_B = y.segment<3>(kW);
  s.w_W = s.R_WB * s.w_B;
  s.p_WB = s.p_WC - s.R_WB * body.com_B;
  s.v_WB = s.v_WC + s.w_W.cross(s.p_WB - s.p_WC);
  return s;
}

double Depth(const geom::PadBody& body, const rft::GroundSurface& ground, const Pose& s) {
  return rft::DeepestVertexDepth(geom::DeepestPointCandidates(body, ground), s.R_WB, s.p_WB, ground);
}

// Radius of the pad about its centre of mass: spin times it is a speed.
double BodyRadius(const geom::PadBody& body) {
  return body.vertices_B.cols() > 0 ? (body.vertices_B.colwise() - body.com_B).colwise().norm().maxCoeff() : 0.0;
}

// The absolute tolerance of each state: rtol times the drop's own scale for that state (unless the
// caller gave component_atol). Why: a state that stays near zero - the rotation about an axis the
// drop is symmetric about, a level pad's spin - was resolved to a scalar atol of 1e-11 in its own
// unit; the mesh's small asymmetries drive it, and the 5-degree tilted drop spent 5,964 steps
// resolving 1e-4 rad/s of wobble to 1e-11 rad/s (12 times fewer steps with these scales, the
// depth and tilt unchanged to 1e-6; tests/lander/pad/free_drop_test.cpp).
//   length L: the pad's radius about its centre of mass; speed V: the largest of the impact speed,
//   the horizontal speed, spin times L and sqrt(g L); angle: 1 rad; angular speed V / L;
//   energy: m V^2 / 2 + m g L.
integ::IntegratorOptions WithScaledTolerances(integ::IntegratorOptions options, const geom::PadBody& body,
                                              const FreeDropInput& in, double radius) {
  if (!options.component_atol.empty()) return options;
  const double L = radius > 0.0 ? radius : 1.0;
  const double V = std::max({in.impact_speed_m_s, std::abs(in.horizontal_speed_m_s), in.omega_W.norm() * L,
                             std::sqrt(in.gravity_m_s2 * L)});
  const double E = 0.5 * body.mass_kg * V * V + body.mass_kg * in.gravity_m_s2 * L;
  const double r = options.rtol;
  options.component_atol.assign(kSize, 0.0);
  for (int i = 0; i < 3; ++i) {
    options.component_atol[kP + i] = r * L;
    options.component_atol[kV + i] = r * V;
    options.component_atol[kW + i] = r * V / L;
  }
  for (int i = 0; i < 4; ++i) options.component_atol[kQ + i] = r;
  options.component_atol[kWork] = r * E;
  return options;
}
}  // namespace

FreeDropResult RunFreeDrop(const geom::PadBody& body, const rft::SoilContactModel& soil, const rft::GroundSurface& ground,
                           const FreeDropInput& in, const FreeDropOptions& options) {
  if (!(body.mass_kg > 0.0) || body.surface.size() == 0 || body.vertices_B.cols() == 0) throw std::invalid_argument("RunFreeDrop: empty pad body");
  if (!(in.gravity_m_s2 > 0.0) || !(in.impact_speed_m_s >= 0.0) || !std::isfinite(in.horizontal_speed_m_s) ||
      !std::isfinite(in.tilt_rad) || !in.omega_W.allFinite())
    throw std::invalid_argument("RunFreeDrop: invalid input");
  const double m = body.mass_kg, g = in.gravity_m_s2;
  const Eigen::Matrix3d I = body.inertia_com_B, I_inv = I.inverse();
  const double radius = BodyRadius(body);

  auto wrench_at = [&](const Pose& s) {
    rft::PadKinematics k{s.R_WB, s.p_WB, s.v_WB, s.w_W};
    return rft::ComputeContactWrench(body.surface, k, ground, *soil.law, soil.pad_terms);
  };
  // added_mass (rft/entrained_mass.h): the entrained cone moves with the centre of mass's vertical
  // velocity v_z. Grains join at rest (dm_a/dt > 0) or leave with the pad's velocity (< 0), so
  // m a_z + m_a a_z = F_z - m g - max(dm_a/dt, 0) v_z (the grains' weight rests on the bed); the
  // kinetic energy lost, |dm_a/dt| v_z^2 / 2 (accretion, or carried off by shed grains), counts as
  // dissipated with the soil's work. Horizontal motion and rotation keep the pad's own inertia:
  // the cone is defined by the vertical stroke.
  const double added_density = soil.pad_terms.added_mass_density_kg_m3;
  struct Vertical {
    double a_z = 0.0;         // vertical acceleration of the centre of mass
    double accretion_W = 0.0;  // accretion loss rate
    double force_z = 0.0;     // vertical force on the pad from below: soil and entrained grains, m (a_z + g)
  };
  auto vertical = [&](const Pose& s, const rft::ContactWrench& w) {
    Vertical out;
    if (added_density > 0.0) {
      const rft::EntrainedMass e = rft::EntrainedCone(added_density, w.penetration_m, w.penetration_rate_m_s,
                                                      w.footprint_area_m2, w.footprint_area_rate_m2_s);
      const double v_z = s.v_WC.z();
      const double accretion = -std::max(e.rate_kg_s, 0.0) * v_z;  // upward while sinking
      out.a_z = (w.force_W.z() - m * g + accretion) / (m + e.mass_kg);
      out.accretion_W = 0.5 * std::abs(e.rate_kg_s) * v_z * v_z;
      out.force_z = m * (out.a_z + g);
      if (e.mass_kg == 0.0 && accretion == 0.0) out.force_z = w.force_W.z();
    } else {
      out.a_z = w.force_W.z() / m - g;
      out.force_z = w.force_W.z();
    }
    return out;
  };
  auto rhs = [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) {
    const Pose s = PoseOf(body, y);
    const bool moving = s.v_WB.squaredNorm() + s.w_W.squaredNorm() * radius * radius > 0.0;
    const rft::ContactWrench w = moving ? wrench_at(s) : rft::ContactWrench{};
    const Eigen::Vector3d M_C = w.moment_W + (s.p_WB - s.p_WC).cross(w.force_W);
    ydot.segment<3>(kP) = s.v_WC;
    const Eigen::Vector4d q = y.segment<4>(kQ);
    const Eigen::Vector3d& wb = s.w_B;
    ydot.segment<4>(kQ) << -0.5 * (q[1] * wb.x() + q[2] * wb.y() + q[3] * wb.z()),
        0.5 * (q[0] * wb.x() + q[2] * wb.z() - q[3] * wb.y()), 0.5 * (q[0] * wb.y() + q[3] * wb.x() - q[1] * wb.z()),
        0.5 * (q[0] * wb.z() + q[1] * wb.y() - q[2] * wb.x());
    ydot.segment<3>(kV) = w.force_W / m - Eigen::Vector3d(0.0, 0.0, g);
    ydot.segment<3>(kW) = I_inv * (s.R_WB.transpose() * M_C - wb.cross(I * wb));
    ydot[kWork] = -(w.force_W.dot(s.v_WB) + w.moment_W.dot(s.w_W));
    if (added_density > 0.0) {
      const Vertical vz = vertical(s, w);
      ydot[kV + 2] = vz.a_z;
      ydot[kWork] += vz.accretion_W;
    }
  };
  const double rest_speed = options.rest_speed_m_s;
  integ::RootSpec roots;
  roots.count = 2;  // [0] touchdown (depth rises through 0), [1] rest (speed falls below threshold)
  roots.directions = {+1, -1};
  // Touchdown is looked for during the approach only: the stroke starts on the surface (depth 0 at
  // t = 0, which CVODE would report as a root at its start), and a pad that bounces off the soil
  // flies on in the same stroke.
  bool approaching = true;
  roots.function = [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> gv) {
    const Pose s = PoseOf(body, y);
    gv[0] = approaching ? Depth(body, ground, s) : -1.0;
    gv[1] = s.v_WC.squaredNorm() + s.w_W.squaredNorm() * radius * radius - rest_speed * rest_speed;
  };
  integ::CvodeIntegrator integrator(kSize, rhs, WithScaledTolerances(options.integrator, body, in, radius), roots);
  integ::HybridRun run(integrator);

  // Release: tilted, lowest point `clearance` above the surface, speed chosen to reach the
  // requested vertical impact speed at touchdown.
  const double v_td = in.impact_speed_m_s;
  const double clearance = std::min(options.approach_clearance_m, v_td * v_td / (4.0 * g));
  const Eigen::Matrix3d R0 = TiltRotation(in.tilt_axis, in.tilt_rad);
  const Eigen::Quaterniond q0(R0);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(kSize);
  y.segment<3>(kP) = PlaceAtDepth(body, R0, -clearance) + R0 * body.com_B;
  y.segment<4>(kQ) << q0.w(), q0.x(), q0.y(), q0.z();
  y.segment<3>(kV) << in.horizontal_speed_m_s, 0.0, -std::sqrt(std::max(v_td * v_td - 2.0 * g * clearance, 0.0));
  y.segment<3>(kW) = R0.transpose() * in.omega_W;
  if (clearance > 0.0) {
    run.Start(0.0, y);
    y = run.AdvanceToRoot(10.0 * std::sqrt(2.0 * clearance / g) + 1.0, 0,
                          "touchdown was not reached during the approach");
    // Touchdown defines t = 0, with the lowest point on the surface, as in the rig drop: the root is
    // located only to rounding, and a depth of +1e-18 m already submerges a flat bottom whole (a
    // depth-independent term such as compaction_peak then acted on its full area in the sample at
    // t = 0). A shift of that size, up to the last representable step.
    y[kP + 2] += Depth(body, ground, PoseOf(body, y));
    for (int i = 0; i < 8 && Depth(body, ground, PoseOf(body, y)) > 0.0; ++i)
      y[kP + 2] = std::nextafter(y[kP + 2], std::numeric_limits<double>::infinity());
  }
  y[kWork] = 0.0;
  approaching = false;
  run.Start(0.0, y);

  FreeDropResult result;
  const Pose s0 = PoseOf(body, y);
  const double z_C0 = s0.p_WC.z();
  const Eigen::Vector2d xy_C0 = s0.p_WC.head<2>();
  result.impact_energy_J = 0.5 * m * s0.v_WC.squaredNorm() + 0.5 * s0.w_B.dot(I * s0.w_B);
  result.touchdown_tilt_deg = units::RadToDeg(TiltFromVertical(s0.R_WB));
  auto record = [&](double t, const Eigen::VectorXd& state) {
    const Pose s = PoseOf(body, state);
    const bool moving = s.v_WB.squaredNorm() + s.w_W.squaredNorm() * radius * radius > 0.0;
    // At rest the soil carries the weight: report the static reaction, as the rig drop does.
    Eigen::Vector3d f(0.0, 0.0, m * g);
    if (moving) {
      const rft::ContactWrench w = wrench_at(s);
      f = w.force_W;
      if (added_density > 0.0) f.z() = vertical(s, w).force_z;
    }
    result.trace.push_back({t, std::max(Depth(body, ground, s), 0.0), -s.v_WC.z(), f.z(), f.x(),
                            s.p_WC.x() - xy_C0.x(), units::RadToDeg(TiltFromVertical(s.R_WB))});
    result.peak_force_N = std::max(result.peak_force_N, f.z());
    if (moving) result.max_deceleration_m_s2 = std::max(result.max_deceleration_m_s2, f.z() / m - g);
  };
  record(0.0, y);

  // Stroke: sample at the output rate until the rest event with enough static capacity.
  integ::HybridPhase stroke;
  stroke.sample_rate_hz = options.sample_rate_hz;
  stroke.end_s = options.max_duration_s;
  stroke.end = integ::RunEnd::kFailPastEnd;
  stroke.failure = "the pad did not come to rest within " + std::to_string(options.max_duration_s) + " s";
  integ::HybridCallbacks calls;
  calls.sample = record;
  calls.event = [&](double t, const std::vector<int>& found, Eigen::VectorXd& s) {
    if (found[1] == 0) return integ::EventAction::kContinue;  // not the rest event
    // Slow enough: rest if pushing straight down meets at least the weight. The probe moves at
    // 1 um/s: quasi-static RFT depends on the direction only, and speed-dependent terms (dynamic
    // term, damping effects) must not count as static capacity.
    Pose probe = PoseOf(body, s);
    rft::PadKinematics down{probe.R_WB, probe.p_WB, Eigen::Vector3d(0.0, 0.0, -1e-6), Eigen::Vector3d::Zero()};
    const double capacity = rft::ComputeContactWrench(body.surface, down, ground, *soil.law, soil.pad_terms).force_W.z();
    if (capacity < m * g) return integ::EventAction::kContinue;
    result.final_kinetic_energy_J = 0.5 * m * probe.v_WC.squaredNorm() + 0.5 * probe.w_B.dot(I * probe.w_B);
    s.segment<3>(kV).setZero();
    s.segment<3>(kW).setZero();
    record(t, s);
    return integ::EventAction::kStop;
  };
  const integ::HybridOutcome rest = run.Run(stroke, calls);
  const double t_rest = rest.t;
  y = rest.y;
  const Pose end = PoseOf(body, y);
  result.time_to_rest_s = t_rest;
  result.final_penetration_m = std::max(Depth(body, ground, end), 0.0);
  result.dissipated_energy_J = y[kWork];
  result.gravity_work_J = m * g * (z_C0 - end.p_WC.z());
  result.final_tilt_deg = units::RadToDeg(TiltFromVertical(end.R_WB));
  result.horizontal_travel_m = (end.p_WC.head<2>() - xy_C0).norm();
  result.solver = run.summary().solver;
  return result;
}

}  // namespace touchdown::pad
