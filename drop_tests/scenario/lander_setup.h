#pragma once
// A lander scenario turned into what the multibody code runs, a lander::LanderSetup: the model
// (body, legs, pads), the terrain with its soils' 3D laws, the initial state and the run options;
// and the run itself.
#include <map>
#include <vector>
#include <string>

#include "drop_tests/scenario/lander_scenario_types.h"
#include "lander/multibody/lander_model.h"
#include "rft/soil.h"

namespace touchdown::scenario {

// Soils by the reference a scenario's ground names them with (a name in data/soils or a path), as
// their files give them (no model applied): loaded once for many landings (a sweep's).
using LanderSoilCatalog = std::map<std::string, rft::SoilParameters>;
// Loads every soil `scenario`'s ground names (default soil, patches, soil field) and `more`.
LanderSoilCatalog LoadLanderSoils(const LanderScenario& scenario, const std::vector<std::string>& more = {});

// The first pad's touchdown speed [m/s]: as given, or from the drop height, release speed and gravity.
double TouchdownSpeed(const LanderScenario& scenario);
// The lander alone (body, legs, pads, gravity, soil ramp): no soil is read.
lander::LanderModel BuildLanderModel(const LanderScenario& scenario);
// The landing's one resolution step (drop::ResolveDrop's counterpart): the model, the terrain with
// its soils' contact models, the initial state and the run options (the scenario's simulation block).
// Soils come from `soils` when given (a reference it lacks, and every soil without it, loaded from
// data/soils by name).
lander::LanderSetup ResolveLander(const LanderScenario& scenario, const LanderSoilCatalog* soils = nullptr);
LanderRun RunLanderScenario(const LanderScenario& scenario);
// As above, on the setup ResolveLander built for this scenario (built once, used for checks
// before the run and by the run).
LanderRun RunLanderScenario(const LanderScenario& scenario, lander::LanderSetup setup);

}  // namespace touchdown::scenario
