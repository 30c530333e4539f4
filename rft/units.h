#pragma once
// Unit conversions at the IO boundary. Inside, everything is SI and radians; files and the
// command line use degrees and N/cm^3 (the paper's unit of the RFT scaling factor zeta), marked
// by a suffix on the name (tilt_deg, zeta_N_cm3).
#include <numbers>

namespace touchdown::units {

// Radians per degree: angle_rad = angle_deg * kDeg, angle_deg = angle_rad / kDeg.
inline constexpr double kDeg = std::numbers::pi / 180.0;
// The same conversions for one value, rounded as every `* kDeg` and `/ kDeg` is, so that an angle
// converted here and the same angle converted with kDeg elsewhere agree bit for bit.
constexpr double DegToRad(double angle_deg) { return angle_deg * kDeg; }
constexpr double RadToDeg(double angle_rad) { return angle_rad / kDeg; }
// Metres per millimetre: length_m = length_mm * kMm (pad and lander files give millimetres).
inline constexpr double kMm = 1e-3;
// Seconds per millisecond: time_s = time_ms * kMs.
inline constexpr double kMs = 1e-3;

// Display and file units the other way (value_unit = value_SI * k..., value_SI = value_unit /
// k...): constants, not literals, so that a reader sees which unit a number is shown in, and the
// products stay the bit-for-bit same as the literal's.
inline constexpr double kMmPerM = 1e3;     // millimetres per metre
inline constexpr double kMsPerS = 1e3;     // milliseconds per second
inline constexpr double kGPerKg = 1e3;     // grams per kilogram
inline constexpr double kKilo = 1e3;       // N per kN, Pa per kPa, Hz per kHz: value_kilo = value / kKilo
inline constexpr double kN_cm2_per_Pa = 1e-4;  // a pressure in N/cm^2 (Surveyor's bearing strengths)
inline constexpr double kN_cm3_per_N_m3 = 1e-6;  // zeta in N/cm^3 for a message (ZetaToN_cm3 divides)

// N/m^3 per N/cm^3.
inline constexpr double kN_m3_per_N_cm3 = 1e6;
// zeta as stored (N/m^3) from its file unit (N/cm^3), and back.
constexpr double ZetaFromN_cm3(double zeta_N_cm3) { return zeta_N_cm3 * kN_m3_per_N_cm3; }
constexpr double ZetaToN_cm3(double zeta_N_m3) { return zeta_N_m3 / kN_m3_per_N_cm3; }

}  // namespace touchdown::units
