#pragma once
// A dropped pad's peak vertical force and largest deceleration, read from the solution between
// samples (integ::DenseSegment), not from the samples alone: on a stiff soil the pad stops within
// one sample period, its force rising and falling between two samples (a 1 m/s flat drop at zeta
// 1000 N/cm^3 stops in 0.7 ms, and its samples held only the weight before).
#include <Eigen/Core>

#include "lander/integ/cvode_integrator.h"

namespace touchdown::pad {

class VerticalPeaks {
 public:
  // The force from below on the pad is m (g + a), a its vertical acceleration, positive up: the
  // time derivative of the state's component `velocity`, times `up` (+1 where the state holds the
  // upward speed, -1 the downward one). That is the rig's load-cell force and the free pad's
  // vertical force with or without entrained grains. `state_size`: the state vector's.
  VerticalPeaks(int state_size, int velocity, double up, double mass_kg, double gravity_m_s2)
      : velocity_(velocity), up_(up), m_(mass_kg), g_(gravity_m_s2), rate_(state_size) {}

  // The segment's end and three points inside it (the polynomial is smooth within a step).
  void Observe(const integ::DenseSegment& segment);
  // What a sample or an event saw directly.
  void Take(double force_N, double deceleration_m_s2);

  double peak_force_N() const { return peak_force_N_; }
  double max_deceleration_m_s2() const { return max_deceleration_m_s2_; }

 private:
  int velocity_;
  double up_, m_, g_;
  double peak_force_N_ = 0.0, max_deceleration_m_s2_ = 0.0;
  Eigen::VectorXd rate_;  // the state's derivative at a point
};

}  // namespace touchdown::pad
