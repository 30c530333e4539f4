#pragma once
// The rig the pad tests drop: a flat pad of radius kR (m) and mass kMass (kg) on a soil of
// zeta kZeta (N/m^3) under gravity kG (m/s^2).
namespace touchdown::pad::test_rig {
inline constexpr double kR = 0.05, kMass = 1.6, kG = 9.81, kZeta = 2.0e6;
}  // namespace touchdown::pad::test_rig
