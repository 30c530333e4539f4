#pragma once
// Placing a pad for a force query or the start of a free drop: a tilt about a horizontal axis
// of W, and the pad lifted or lowered so that its lowest surface point sits at a given depth
// below a level surface z = 0.
#include <array>
#include <Eigen/Core>
#include <string>

#include "footpad_geom/pad_body.h"
#include "rft/enum_names.h"

namespace touchdown::pad {

// The horizontal axis of W a pad is tilted about. Files and the command line say "x" or "y".
enum class TiltAxis { kX, kY };
inline constexpr std::array<EnumName<TiltAxis>, 2> kTiltAxisNames{{{TiltAxis::kX, "x"}, {TiltAxis::kY, "y"}}};
// "x" or "y"; InputError naming `file` and the field tilt_axis otherwise.
TiltAxis ParseTiltAxis(const std::string& text, const std::string& file = "");
const char* TiltAxisName(TiltAxis axis);

// Rotation about W's x or y axis by `tilt_rad`.
Eigen::Matrix3d TiltRotation(TiltAxis axis, double tilt_rad);

// Lowest z of the pad surface in W for orientation R_WB with the reference point at the origin.
double LowestPointOffset(const geom::PadBody& body, const Eigen::Matrix3d& R_WB);

// Position of the reference point that puts the lowest surface point at depth `depth_m` below
// z = 0 (negative depth: above the surface), at horizontal position (x, y) of the reference point.
Eigen::Vector3d PlaceAtDepth(const geom::PadBody& body, const Eigen::Matrix3d& R_WB, double depth_m,
                             double x_m = 0.0, double y_m = 0.0);

// Angle between the pad's z axis and the vertical [rad].
double TiltFromVertical(const Eigen::Matrix3d& R_WB);

}  // namespace touchdown::pad
