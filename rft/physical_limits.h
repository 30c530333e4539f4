#pragma once
// The physically meaningful range of every magnitude a user gives, in one place, so the command
// line and the YAML files refuse the same values with the same message. The bounds are generous
// (far beyond any lander) but keep every product the contact sums form finite: a 1e308 m/s
// impact or a 1e30 mm pad would otherwise reach the solver or print NaN.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::limits {

struct Range {
  const char* unit;
  double low, high;
  bool low_open;  // low itself excluded (a positive quantity)
};

inline constexpr Range kSpeed_m_s{"m/s", 0.0, 100.0, false};            // impact speed, |velocity|
inline constexpr Range kAbsSpeed_m_s{"m/s", -100.0, 100.0, false};      // a signed horizontal speed
inline constexpr Range kAngularSpeed_rad_s{"rad/s", 0.0, 1000.0, false};  // |omega|, ~160 rev/s
inline constexpr Range kForceTilt_deg{"deg", -180.0, 180.0, false};     // `force` poses any attitude
// A dropped pad's tilt lies strictly within plus or minus this many degrees: on its side or beyond,
// it would not land on its bottom.
inline constexpr int kDropTiltWithin_deg = 90;
inline constexpr Range kDepth_m{"m", -10.0, 10.0, false};               // below (+) / above (-) the surface
inline constexpr Range kZeta_N_cm3{"N/cm^3", 0.0, 1e4, true};           // RFT scaling factor
// Dynamic RFT's inertial coefficient lambda [-] (rft/dynamic_term.h): order one in every fit
// published (Agarwal et al. 2021: 1.1); 100 is far beyond, and a negative one would pull the pad in.
inline constexpr Range kDynamicLambda{"(dimensionless)", 0.0, 100.0, false};
// simulation.pad_spin_tolerance_factor: 1 is every state's tolerance; beyond 1e3 a pad's spin is
// hardly resolved at all (30 already let a study landing stall, docs/lander_dynamics.md).
inline constexpr Range kPadSpinToleranceFactor{"(dimensionless)", 1.0, 1000.0, false};
inline constexpr Range kPadSize_m{"m", 0.0, 10.0, true};                // pad radius, thickness, mesh extent
inline constexpr Range kPadSize_mm{"mm", 0.0, kPadSize_m.high * units::kMmPerM, true};  // the same, as pad YAML gives it
// Worker threads a run may start (--threads, the Python module's `threads`; 0: every core). Far
// beyond any machine's cores, and checked before a thread starts: a process that cannot start the
// threads it asked for ends in std::terminate, not in an error message.
inline constexpr int kMaxThreads = 4096;
inline constexpr Range kThreads{"threads", 0.0, double(kMaxThreads), false};

// Bodies and the world they land in. Each bound is far beyond any lander, and keeps the
// products the dynamics forms (m g, k x, I w^2) finite and the integrator's tolerances meaningful.
// The low ends: a 1 mg dropped mass and 1e-6 m/s^2, below the surface gravity of the smallest bodies
// landed on (comet 67P about 2e-4, asteroid Itokawa about 1e-4 m/s^2). Down at denormal values
// (1e-320) every product with them underflows and the integrator fails instead of the input.
inline constexpr Range kGravity_m_s2{"m/s^2", 1e-6, 1000.0, false};  // ~100 g; the Sun's photosphere is 274
inline constexpr Range kMass_kg{"kg", 1e-6, 1e6, false};             // a 1000 t lander, a pad, a dropped mass
inline constexpr Range kLanderSize_mm{"mm", 0.0, 1e5, false};      // CoG height, leg radii, stroke: 100 m
// A principal moment of inertia: the mass bound times the size bound squared (1e6 kg x (100 m)^2).
inline constexpr Range kInertia_kg_m2{"kg m^2", 0.0, 1e10, true};
inline constexpr Range kDensity_kg_m3{"kg/m^3", 0.0, 1e5, true};  // osmium, the densest element, is 22,590
// Leg absorbers: a steel bar 1 m^2 in section and 0.2 m long is 1e12 N/m; critical damping of that
// spring under the heaviest mass is 2e9 N s/m; the heaviest mass at the highest gravity weighs 1e9 N.
inline constexpr Range kStiffness_N_m{"N/m", 0.0, 1e12, true};
inline constexpr Range kDamping_N_s_m{"N s/m", 0.0, 1e10, false};
inline constexpr Range kForce_N{"N", 0.0, 1e9, true};
// The ball joints' cone limit: the same bounds about a 1 m lever; a joint swings at most 180 deg.
inline constexpr Range kTorsionStiffness_N_m_rad{"N m/rad", 0.0, 1e12, true};
inline constexpr Range kTorsionDamping_N_m_s_rad{"N m s/rad", 0.0, 1e10, false};
inline constexpr Range kConeHalfAngle_deg{"deg", 0.0, 180.0, true};
// Friction angles (a soil's internal one, a Bekker soil's shearing one) lie below this, in
// degrees, excluded: tan(90 deg) is infinite.
inline constexpr int kFrictionAngleBelow_deg = 90;
// A lander's ground slope lies below, and its initial roll and pitch within plus or minus, this many
// degrees (excluded): steeper, the body is released on its side and the landing is no landing.
inline constexpr int kGroundSlopeBelow_deg = 80;
inline constexpr int kInitialRollPitchWithin_deg = 80;
// Headings and azimuths: one turn either way says every direction.
inline constexpr Range kAzimuth_deg{"deg", -360.0, 360.0, false};
// A body's angular rate, per axis: 10 rev/s, a tumbling lander (a single pad's |omega|: kAngularSpeed_rad_s).
inline constexpr Range kAngularRate_deg_s{"deg/s", -3600.0, 3600.0, false};
// A drop height or a terrain's elevation: positions are integrated to a relative tolerance (1e-7 for
// a lander), so at 100 m the error allowed is 10 um; much higher, a pad's millimetres would be lost.
inline constexpr Range kHeight_m{"m", -100.0, 100.0, false};
inline constexpr Range kDropHeight_m{"m", 0.0, kHeight_m.high, false};  // a release height above the ground

// Bekker-Wong soils (rft/bekker_parameters.h), in the soil file's units: about 100 times the
// stiffest soils tabulated (clays and LETE sand: k_phi up to 1e4 kN/m^(n+2), cohesion up to 100 kPa,
// K up to 50 mm).
// The sinkage exponent n: published soils lie about 0.5 to 1.5 (Wong's tables); 5 is far beyond,
// and 0 would make the pressure independent of the depth (a plate held at any sinkage).
inline constexpr Range kBekkerN{"(dimensionless)", 0.0, 5.0, true};
inline constexpr Range kBekkerKc_kN_m_n1{"kN/m^(n+1)", 0.0, 1e6, false};
inline constexpr Range kBekkerKphi_kN_m_n2{"kN/m^(n+2)", 0.0, 1e6, false};
inline constexpr Range kCohesion_kPa{"kPa", 0.0, 1e4, false};
inline constexpr Range kShearModulusK_mm{"mm", 0.0, 1e4, true};

// Random samples of a sweep or study (the file's and --samples): a billion landings is years of CPU.
inline constexpr Range kSamples{"samples", 1.0, 1e9, false};
// The deterministic work limit of one run (drop or landing): right-hand-side evaluations of its
// integrator, the same on any machine under any load; far above what any shipped drop or landing
// needs (bench/sweep_bench.cpp and the sweep limit tests measure them).
inline constexpr long kDefaultMaxRunEvaluations = 2000000;
// The largest such limit a file may set (a sweep's max_drop_evaluations, a landing's max_evaluations).
inline constexpr double kMaxRunEvaluations = 1e15;

// Resolution and size caps, checked at load so that a hand-written 1e9 is refused instead of
// exhausting memory or running for days; each is far above what a shipped file asks for.
// A revolved pad has about 0.5 N^2 triangles for N angular segments (~8k at the default 128, ~500k
// at 1024); 10000 profile pieces resolve any curve a pad drawing can specify, and keep the profile
// simplification (quadratic in the points) quick.
inline constexpr int kMaxAngularSegments = 1024;
// The fewest angular segments a revolved pad (and each of its inner rings) has: a hexagon.
inline constexpr int kMinAngularSegments = 6;
inline constexpr int kMaxProfileSegments = 10000;
// A remeshed pad: about 90 MB of pad body and seconds per contact evaluation.
inline constexpr double kMaxRemeshTriangles = 500000.0;
// A sweep's rig drops: the rest recorded after each stop (a minute).
inline constexpr double kMaxRigRestDuration_s = 60.0;
// A sweep: the values of one `{from, to, count}` grid axis, and the drops of a whole plan.
inline constexpr int kMaxGridCount = 100000;
inline constexpr std::int64_t kMaxSweepDrops = std::int64_t{1} << 40;
// A lander run keeps its trace in memory until it is written (lander::LanderSample, 816 bytes a
// sample with the bodies' and pads' poses, plus the plots' copy): 1e6 samples keep a run under
// about 1 GB.
inline constexpr double kMaxLanderDuration_s = 600.0;
inline constexpr double kMaxLanderSampleRate_Hz = 1e6;
inline constexpr double kMaxLanderTraceSamples = 1e6;
// synth builds its dataset in memory before it writes it: at most 1 MHz, a minute of rest after
// each stop, 1,000 trials, 100,000 drops and 2e7 samples in all (about 0.5 GB of traces).
inline constexpr double kMaxSynthSampleRate_Hz = 1e6;
inline constexpr double kMaxSynthRestDuration_s = 60.0;
inline constexpr int kMaxSynthTrials = 1000;
inline constexpr std::size_t kMaxSynthDrops = 100000;
inline constexpr double kMaxSynthSamples = 2e7;
// A stability study: map bins per axis, and the landings a list (worst cases, ...) may name.
inline constexpr int kMaxStudyMapBins = 200;
inline constexpr int kMaxStudyListed = 100000;
// Input files (drop_tests/formats/yaml_fields.cpp): a count read into an int; a YAML tree's depth and
// node count. yaml-cpp keeps an alias as a second reference to its anchor's node, so a walk visits
// an aliased subtree once per reference: an alias inside its own anchor (`a: &a [*a]`) makes the
// tree infinitely deep, and aliases of aliases multiply ("billion laughs": nine levels of ten
// references are 10^9 nodes). Every touchdown file is a few hundred nodes and a few levels deep;
// these bounds are far above that and are reached in milliseconds.
inline constexpr double kMaxWholeNumber = 1e9;
inline constexpr int kMaxYamlDepth = 64;
inline constexpr long kMaxYamlNodes = 1'000'000;
// A fit's confidence level (calibrate --confidence, touchdown.calibrate's `confidence`).
inline constexpr double kMinConfidence = 0.5, kMaxConfidence = 0.9999;

inline bool Within(const Range& r, double v) {
  return std::isfinite(v) && (r.low_open ? v > r.low : v >= r.low) && v <= r.high;
}

// "must be between 0 and 100 m/s, got 1e+308"
inline std::string Describe(const Range& r, double v) {
  char text[160];
  std::snprintf(text, sizeof text, "must be %s %g and %g %s, got %.6g", r.low_open ? "above" : "between", r.low,
                r.high, r.unit, v);
  std::string s = text;
  if (r.low_open) s.replace(s.find(" and "), 5, " and at most ");
  return s;
}

// Throws InputError(file, field, Describe(...)) unless v is in r.
inline void Require(const Range& r, double v, const std::string& file, const std::string& field) {
  if (!Within(r, v)) throw MakeInputError(file, field, Describe(r, v));
}

}  // namespace touchdown::limits
