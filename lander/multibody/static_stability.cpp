#include "lander/multibody/static_stability.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "rft/units.h"

namespace touchdown::lander {

SlopeGeometry SlopeOf(const rft::PlaneGround& plane, const Eigen::Vector3d& downhill_if_level_W) {
  const Eigen::Vector3d gradient(plane.slope_x(), plane.slope_y(), 0.0);
  const double rise = gradient.norm();
  if (rise == 0.0) return {0.0, downhill_if_level_W.normalized()};
  return {std::atan(rise), -gradient / rise};
}

Eigen::VectorXd RotateLanderState(const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y,
                                  const Eigen::Matrix3d& R_W, const Eigen::Vector3d& pivot_W) {
  Eigen::VectorXd out = y;
  const Eigen::Quaterniond turn(R_W);
  auto rotate_quat = [&](int i) {
    const Eigen::Quaterniond q = turn * Eigen::Quaterniond(y[i], y[i + 1], y[i + 2], y[i + 3]);
    out.segment<4>(i) << q.w(), q.x(), q.y(), q.z();
  };
  out.segment<3>(L.p_WB()) = pivot_W + R_W * (y.segment<3>(L.p_WB()) - pivot_W);
  rotate_quat(L.quat_WB());
  out.segment<3>(L.v_WB_W()) = R_W * y.segment<3>(L.v_WB_W());
  out.segment<3>(L.w_WB_W()) = R_W * y.segment<3>(L.w_WB_W());
  for (int i = 0; i < kNumLegs; ++i) {
    rotate_quat(L.quat_WP(i));
    out.segment<3>(L.w_WP_W(i)) = R_W * y.segment<3>(L.w_WP_W(i));
  }
  return out;
}

namespace {

// Moment of inertia about the axis k through a, and angular momentum along k, of one rigid body
// (mass m, CoM c moving at v, inertia I_W about its CoM in world axes, angular velocity w).
void AddAboutAxis(double m, const Eigen::Vector3d& c, const Eigen::Vector3d& v, const Eigen::Matrix3d& I_W,
                  const Eigen::Vector3d& w, const Eigen::Vector3d& a, const Eigen::Vector3d& k, EdgeTipping* edge) {
  const Eigen::Vector3d r = c - a;
  const Eigen::Vector3d r_perp = r - r.dot(k) * k;
  edge->inertia_kg_m2 += m * r_perp.squaredNorm() + k.dot(I_W * k);
  edge->angular_momentum_N_m_s += k.dot(m * r.cross(v) + I_W * w);
}

EdgeTipping TippingAboutEdge(const LanderModel& model, const LanderPose& pose, const Eigen::Vector3d& com,
                             int from_leg) {
  EdgeTipping edge;
  edge.from_leg = from_leg;
  edge.to_leg = (from_leg + 1) % kNumLegs;
  const Eigen::Vector3d a = pose.pads[edge.from_leg].p_WJ;
  const Eigen::Vector3d e = (pose.pads[edge.to_leg].p_WJ - a).normalized();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // Clockwise polygon seen from above: the inside is on the right of each edge, e x z.
  const Eigen::Vector3d inward = e.cross(up).normalized();
  const Eigen::Vector3d normal_up = inward.cross(e);  // perpendicular to the edge, upward (z = |e x z|)
  const Eigen::Vector3d r = com - a;
  edge.inside_m = InsideEdgeDistance(pose, from_leg, com);  // r . inward, as StabilityMargin has it
  edge.height_m = r.dot(normal_up);
  edge.tip_angle_rad = std::atan2(edge.inside_m, edge.height_m);
  const double radius = std::hypot(edge.inside_m, edge.height_m);
  const double rise = edge.inside_m > 0.0 ? (radius - edge.height_m) * normal_up.z() : 0.0;
  edge.barrier_J = model.TotalMass() * model.gravity_m_s2 * rise;
  edge.tip_axis_W = -e;  // (-e) x normal_up = -inward: carries the CoM outward
  const Eigen::Matrix3d I_B = pose.R_WB * model.body_inertia_B * pose.R_WB.transpose();
  AddAboutAxis(model.body_mass_kg, pose.p_WB, pose.v_WB_W, I_B, pose.w_WB_W, a, edge.tip_axis_W, &edge);
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = pose.pads[i];
    const geom::PadBody& pad = *model.legs[i].pad;
    const Eigen::Matrix3d I_P = f.R_WP * pad.inertia_com_B * f.R_WP.transpose();
    AddAboutAxis(pad.mass_kg, f.p_WJ + f.c_JC_W, f.v_WJ_W + f.w_WP_W.cross(f.c_JC_W), I_P, f.w_WP_W, a,
                 edge.tip_axis_W, &edge);
  }
  return edge;
}

}  // namespace

std::array<EdgeTipping, kNumLegs> EdgeTippings(const LanderModel& model, const StateLayout& layout,
                                               const Eigen::Ref<const Eigen::VectorXd>& y) {
  const LanderPose pose = ComputePose(model, layout, y);
  const Eigen::Vector3d com = LanderCentreOfMass(model, pose);
  std::array<EdgeTipping, kNumLegs> edges;
  for (int i = 0; i < kNumLegs; ++i) edges[i] = TippingAboutEdge(model, pose, com, i);
  return edges;
}

namespace {

// The state on a slope steepened by `extra_rad` (about the horizontal contour line).
Eigen::VectorXd Steepened(const StateLayout& layout, const Eigen::Ref<const Eigen::VectorXd>& y,
                          const SlopeGeometry& slope, double extra_rad) {
  const Eigen::Vector3d contour = Eigen::Vector3d::UnitZ().cross(slope.downhill_W).normalized();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(extra_rad, contour).toRotationMatrix();  // tips downhill down
  return RotateLanderState(layout, y, R, y.segment<3>(layout.p_WB()));
}

// The edge the CoM is nearest to leaving through (smallest inside distance).
int NearestEdge(const std::array<EdgeTipping, kNumLegs>& edges) {
  int nearest = 0;
  for (int i = 1; i < kNumLegs; ++i)
    if (edges[i].inside_m < edges[nearest].inside_m) nearest = i;
  return nearest;
}

}  // namespace

StaticTipOver StaticTipOverOnSlope(const LanderModel& model, const StateLayout& layout,
                                   const Eigen::Ref<const Eigen::VectorXd>& y_rest, const SlopeGeometry& slope) {
  StaticTipOver out;
  out.margin_m = StabilityMargin(model, layout, y_rest);
  auto margin_at = [&](double extra) { return StabilityMargin(model, layout, Steepened(layout, y_rest, slope, extra)); };
  if (out.margin_m <= 0.0) {
    out.critical_slope_rad = slope.angle_rad;
    out.edge_from_leg = NearestEdge(EdgeTippings(model, layout, y_rest));
    return out;
  }
  // Bracket the crossing by steps of 5 deg below vertical ground, then TOMS 748 to rounding.
  constexpr double kStep = 5.0 * units::kDeg;
  const double limit = 0.5 * std::numbers::pi - slope.angle_rad;
  double lo = 0.0, hi = std::min(kStep, limit);
  while (margin_at(hi) > 0.0) {
    if (hi >= limit) throw std::invalid_argument("static tip-over: the lander stands on any slope up to vertical");
    lo = hi;
    hi = std::min(hi + kStep, limit);
  }
  std::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve(margin_at, lo, hi, margin_at(lo), margin_at(hi),
                                                      boost::math::tools::eps_tolerance<double>(50), iterations);
  out.extra_tilt_rad = 0.5 * (root.first + root.second);
  out.critical_slope_rad = slope.angle_rad + out.extra_tilt_rad;
  out.edge_from_leg = NearestEdge(EdgeTippings(model, layout, Steepened(layout, y_rest, slope, out.extra_tilt_rad)));
  return out;
}

EnergyTipOver EnergyTipOverAtEdge(const LanderModel& model, const StateLayout& layout,
                                  const Eigen::Ref<const Eigen::VectorXd>& standing,
                                  const Eigen::Ref<const Eigen::VectorXd>& touchdown, int edge_from_leg) {
  EnergyTipOver out;
  out.barrier_J = EdgeTippings(model, layout, standing)[edge_from_leg].barrier_J;
  out.kinetic_J = KineticEnergy(model, layout, touchdown);
  out.released_potential_J = PotentialEnergy(model, layout, touchdown) - PotentialEnergy(model, layout, standing);
  out.edge_kinetic_J = EdgeTippings(model, layout, touchdown)[edge_from_leg].EdgeKineticEnergy();
  return out;
}

}  // namespace touchdown::lander
