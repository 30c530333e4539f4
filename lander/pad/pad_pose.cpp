#include "lander/pad/pad_pose.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "rft/input_error.h"

namespace touchdown::pad {

TiltAxis ParseTiltAxis(const std::string& text, const std::string& file) {
  return ParseName(kTiltAxisNames, text, file, "tilt_axis");
}

const char* TiltAxisName(TiltAxis axis) { return NameIn(kTiltAxisNames, axis); }

Eigen::Matrix3d TiltRotation(TiltAxis axis, double tilt_rad) {
  const Eigen::Vector3d unit = axis == TiltAxis::kX ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return Eigen::AngleAxisd(tilt_rad, unit).toRotationMatrix();
}

double LowestPointOffset(const geom::PadBody& body, const Eigen::Matrix3d& R_WB) {
  const rft::SurfaceElements& s = body.surface;
  double lowest = INFINITY;
  for (const Eigen::Matrix3Xd* vertices : {&s.p0_B, &s.p1_B, &s.p2_B})
    lowest = std::min(lowest, (R_WB.row(2) * *vertices).minCoeff());
  return lowest;
}

Eigen::Vector3d PlaceAtDepth(const geom::PadBody& body, const Eigen::Matrix3d& R_WB, double depth_m, double x_m,
                             double y_m) {
  return {x_m, y_m, -depth_m - LowestPointOffset(body, R_WB)};
}

double TiltFromVertical(const Eigen::Matrix3d& R_WB) { return std::acos(std::clamp(R_WB(2, 2), -1.0, 1.0)); }

}  // namespace touchdown::pad
