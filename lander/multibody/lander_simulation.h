#pragma once
// A lander drop as a hybrid system integrated by CVODE: continuous motion between events,
// discrete mode changes at events found by root-finding (never by step-size luck).
//
// Events (CVODE root functions):
//   touchdown      a pad's lowest vertex reaches the free surface (recorded);
//   capture        a free, submerged pad's joint centre stops sinking (its vertical velocity
//                  rises through 0) while its horizontal speed is below capture_speed: the
//                  soil holds the pad (PadMode::kHeld) and its speed is projected to zero;
//   release        a held pad's soil reaction leaves the quasi-static capacity of its bed:
//                  lift-off (vertical reaction falls through 0), sinking (it exceeds the RFT
//                  force for straight-down motion at that pose) or sliding (the horizontal
//                  reaction exceeds the RFT force for motion in its direction);
//   crushing       a crushable absorber's compression force reaches its crush force; it locks
//                  again when its stroke rate falls to 0 or it bottoms out;
//   tip-over       the centre of mass, seen from above, leaves the polygon of the four joint
//                  centres (the lander has passed its static stability limit): the run ends;
//   rest           every pad held: the lander is static and stays so (loads no longer change),
//                  so the run ends without integrating the remaining time.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "lander/integ/cvode_integrator.h"
#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_run.h"

namespace touchdown::lander {

// Height of the body CoM at which the lowest pad vertex is `clearance_m` above the ground, for
// the attitudes and horizontal position in `state` (exact for any height field: a vertical shift).
double BodyHeightForClearance(const LanderModel& model, const rft::Terrain& terrain, const LanderInitialState& state,
                              double clearance_m);

LanderRunResult SimulateLander(const LanderSetup& setup);

}  // namespace touchdown::lander
