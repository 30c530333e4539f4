// touchdown: lander footpads hitting granular regolith, by resistive force theory.
// Each subcommand lives in its own file; this one wires them to CLI11 and turns every
// user error into one line on stderr and exit status 2.
#include <CLI/CLI.hpp>
#include <iostream>

#include "apps/commands.h"
#include "lander/cvode_integrator.h"
#include "rft/input_error.h"

int main(int argc, char** argv) {
  CLI::App app{"touchdown - lander footpad / regolith touchdown simulator (granular RFT)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "touchdown 0.1.0");
  touchdown::app::AddDropCommand(app);
  touchdown::app::AddCampaignCommand(app);
  touchdown::app::AddForceCommand(app);
  touchdown::app::AddSweepCommand(app);
  touchdown::app::AddExportCommand(app);
  touchdown::app::AddMergeCommand(app);
  touchdown::app::AddCompareCommand(app);
  touchdown::app::AddCalibrateCommand(app);
  touchdown::app::AddTradeCommand(app);
  touchdown::app::AddLanderCommand(app);
  touchdown::app::AddSynthCommand(app);
  touchdown::app::AddDiagnoseCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "touchdown: " << e.what() << "\n";
    return 2;
  } catch (const touchdown::InputError& e) {
    std::cerr << "touchdown: " << e.what() << "\n";
    return 2;
  } catch (const touchdown::integ::IntegrationFailure& e) {
    std::cerr << "touchdown: integration failed: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "touchdown: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
