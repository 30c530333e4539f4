#pragma once
// A four-legged lander drop from a scenario YAML (`touchdown lander SCENARIO.yaml --out DIR`), all
// of it, for code that loads, runs and reports a landing; each part has its own header:
//   lander_scenario_types.h  the scenario, its setup and a run's result (types)
//   lander_scenario_file.h   the lander and scenario files and the resolved copy (load, write)
//   lander_setup.h           the setup built from a scenario (model, terrain, initial state); the run
//   lander_outputs.h         summary.json, trace.csv, events.csv, plots/ and vtk/
// Schema: docs/lander_dynamics.md.
#include "drop_tests/scenario/lander_outputs.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/scenario/lander_scenario_types.h"
#include "drop_tests/scenario/lander_setup.h"
