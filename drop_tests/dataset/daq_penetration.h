#pragma once
// The penetration of a raw drop record, referenced to its detected touchdown t0 (docs/import.md,
// "Penetration"): positive down, 0 at t0, negative before it (the pad above the surface).
//
// From displacement: the channel's value at t0 is taken from a quadratic least-squares fit to the
// pre-trigger's last 20 ms (the pad's free fall, smooth), evaluated at t0: it carries a fraction of
// one sample's noise where the sample nearest t0 would carry all of it. penetration = displacement
// - that value. The fit's slope at t0 is the speed the displacement measured at touchdown.
//
// From acceleration (positive down, the pad's own dv/dt): v(t) = v0 + int_t0^t (a - b) dt with v0
// the drop's impact speed and b the accelerometer's bias, the mean of a over the final rest (where
// the pad is still, so its true acceleration is 0); penetration = int_t0^t v dt, both by the
// trapezoid rule, with v = 0 from the stop on: the stop is where v first reaches 0 after t0, or,
// when it does not (v0 a little high), where the rest begins. The rest is found on the
// acceleration itself: from the first sample after its largest excursion (the deceleration's
// peak) from which it stays within max(5 noise, 2 % of that excursion) of its final level (the
// median of the record's last fifth); the bias is averaged from a fifth of the way into it to the
// end. Why these choices (measured on gapbench's acceleration sets against a linear velocity
// correction fitted over the rest and a bias from the free-fall pre-trigger) is in docs/import.md.
#include <string>
#include <vector>

namespace touchdown::dataset {

struct DisplacementPenetration {
  std::vector<double> penetration_m;
  double at_touchdown_m = 0.0;  // the channel's value at t0 (the surface, in the sensor's frame)
  double speed_m_s = 0.0;       // its rate at t0
};

// `t_s` increasing; the pre-trigger is [0, pretrigger_end). Throws InputError naming `source` and
// the displacement channel when it moves up through the drop (its gain's sign).
DisplacementPenetration PenetrationFromDisplacement(const std::vector<double>& t_s, const std::vector<double>& displacement_m,
                                                    double t0_s, size_t pretrigger_end, const std::string& source);

struct AccelerationPenetration {
  std::vector<double> penetration_m;
  double bias_m_s2 = 0.0;                     // b, removed
  double stop_s = 0.0;                        // where the pad stops, from t0
  double rest_velocity_m_s = 0.0;             // v0 + int (a - b) where the rest begins: 0 when v0 and a agree
  double pretrigger_acceleration_m_s2 = 0.0;  // the pre-trigger's mean a - b: g for a free fall
};

// The first sample of `x`'s final rest, as above (`noise`: its noise sigma); throws InputError
// naming `source` and `channel` when the record ends before 13 samples of rest.
size_t RestStart(const std::vector<double>& x, double noise, const std::string& source, const std::string& channel);

// Throws InputError naming `source` and the acceleration channel when the rest is too short to
// find the bias on.
AccelerationPenetration PenetrationFromAcceleration(const std::vector<double>& t_s, const std::vector<double>& acceleration_m_s2,
                                                    double t0_s, double impact_speed_m_s, size_t pretrigger_end,
                                                    const std::string& source);

}  // namespace touchdown::dataset
