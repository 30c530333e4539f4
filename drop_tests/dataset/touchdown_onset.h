#pragma once
// Where a raw drop record touches down, from its force channel (docs/import.md, "Touchdown"):
//
// 1. Trigger: the force's baseline and noise from the samples before it first reaches half its
//    peak (median and rms of the first half of them), a trigger level k sigma above the baseline
//    (k = 5; at least 1 % of the peak, so a noiseless record has a level too; or the mapping's
//    `touchdown.threshold_N`), and the last sample below it before the half-peak crossing: the
//    last sample in the noise band. Scanning back from the rise, a noise spike in the pre-trigger
//    cannot trigger.
// 2. Onset fit: F - baseline = A (t - t0)^k for t > t0, 0 before, or, where the record shows a
//    jump at contact, J + A (t - t0): fitted by least squares (J, A >= 0, k in 0.7-3.5, t0 from up
//    to 10 ms before the last noise-band sample to the first sample above the trigger) to the
//    samples from 10 ms before the trigger to the first sample past 20 % of the peak (at least
//    four samples past the trigger; a curved pad slowed by its own rise bends the power law at
//    30 % and later: its fits to 30 and 50 % put a noiseless cubic rise 2 samples late). The power law is a curved pad's point contact, whose force
//    grows like d^2..3 (3 for a cone, the fastest a convex pad grows) and stays in the noise for
//    milliseconds: the fit carries the rise above the noise back to where it leaves zero. The
//    jump is a flat face's dynamic term, then a force growing with depth at constant area; it is
//    taken where Schwarz's criterion prefers it and J is above 5 noise sigma (measured on
//    gapbench's raw sets, docs/import.md: a power law alone put flat and c4 pads 0.1-0.3 ms early;
//    a jump of noise size pulled curved pads late). t0 is the middle of the interval where the
//    cost, minimised over the other parameters, stays within one residual variance of its least
//    value (step 4): between two samples a jump's place is not in the samples, and the interval
//    then spans them.
// 3. Pre-trigger: the samples before t0 - guard (two samples, or longer for a filtered channel
//    whose phaseless response reaches ahead of a jump). Its mean is the force's zero, its rms about
//    a straight line (drift removed) the noise; steps 1-2 are run once more with them.
// 4. Uncertainty: half a sample (a DAQ stamps a sample at the instant, the start or the middle of
//    what it averaged, which the file does not say) plus, in quadrature, the fit's own spread: the
//    half range of t0 fitted to 10, 20 and 30 % of the peak (how far the form bends), and the
//    half width of the t0 interval where the profile cost stays within one residual variance of
//    its minimum (Delta chi^2 = 1; the variance at least that of a 10-bit step, 1e-3 of the
//    rise, so a noiseless record has an interval too).
#include <string>
#include <vector>

namespace touchdown::dataset {

struct OnsetOptions {
  double threshold_N = 0.0;  // > 0: the trigger level above the baseline; 0: k_sigma x the noise
  double k_sigma = 5.0;
  double guard_s = 0.0;      // excluded from the pre-trigger before t0 (at least two samples)
};

struct TouchdownOnset {
  double t0_s = 0.0;             // the touchdown, in the record's own clock
  double uncertainty_s = 0.0;    // step 4
  size_t pretrigger_end = 0;     // samples [0, pretrigger_end) are the pre-trigger
  double baseline_N = 0.0;       // the pre-trigger's mean force (the zero)
  double noise_N = 0.0;          // the pre-trigger's rms about a straight line
  double threshold_N = 0.0;      // the trigger level used, above the baseline
  double exponent = 0.0;         // k of the fitted rise
  double jump_N = 0.0;           // J of the fitted rise (0 where the record shows none)
  double fit_spread_s = 0.0;     // half range of t0 over the three fit windows
  double fit_halfwidth_s = 0.0;  // the profile's Delta chi^2 = 1 half width
};

// Finds the touchdown in `force_N` sampled at the increasing, uniform times `t_s`. Throws
// InputError naming `source` and the force channel when there is none to find: too few samples,
// a record that starts after touchdown (fewer than 8 pre-trigger samples), a force whose largest
// excursion is negative (its gain's sign), or one that never leaves the noise.
TouchdownOnset DetectTouchdown(const std::vector<double>& t_s, const std::vector<double>& force_N,
                               const OnsetOptions& options, const std::string& source);

}  // namespace touchdown::dataset
