// touchdown: lander footpads hitting granular regolith, by resistive force theory.
// Each subcommand lives in its own file; this one wires them to CLI11 and turns every
// user error into one line on stderr and an exit status: 0 success, 2 bad input or an
// unusable path (InputError, a file system error, out of memory), 3 the solver failed,
// 1 an internal error (a bug).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <new>

#include "apps/command_help.h"
#include "apps/commands.h"
#include "drop_tests/formats/output_path.h"
#include "lander/integ/cvode_integrator.h"
#include "rft/input_error.h"

int main(int argc, char** argv) {
  // Named, so that usage lines read `touchdown drop ...` wherever the executable lives.
  CLI::App app{"touchdown - lander footpad / regolith touchdown simulator (granular RFT)", "touchdown"};
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();  // every option's default shows in --help
  app.set_version_flag("--version", "touchdown " TOUCHDOWN_VERSION);
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
  touchdown::app::AddStabilityCommand(app);
  touchdown::app::AddValidateCommand(app);
  touchdown::app::AddImportCommand(app);
  touchdown::app::AddSchemaCommand(app);
  touchdown::app::AddHelpFooters(app);
  // `touchdown` alone asks what there is: the command list, as --help shows it, and success.
  // Nothing was given that could be wrong (an empty "$VAR" is an argument, and an unknown command).
  if (argc == 1) {
    std::cout << app.help();
    return 0;
  }
  try {
    touchdown::app::RejectNonUtf8Arguments(argc, argv);
    touchdown::app::RejectUnknownCommand(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An option nobody defines is the mistake to name first: CLI11 reports a missing required
    // option before it, so `drop --sped 1` would say only "--speed is required".
    std::cerr << "touchdown: " << touchdown::app::UnknownOptionMessage(app).value_or(e.what()) << "\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 2;
  } catch (const touchdown::InputError& e) {
    std::cerr << "touchdown: " << e.what() << "\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 2;
  } catch (const touchdown::integ::IntegrationFailure& e) {
    std::cerr << "touchdown: integration failed: " << e.what() << "\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 3;
  } catch (const touchdown::SolverFailure& e) {
    std::cerr << "touchdown: " << e.what() << "\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 3;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the OS refused (read-only or full file system, permissions, a loop): the user's
    // to fix, so the path and the OS reason, exit 2.
    std::cerr << "touchdown: " << (e.path1().empty() ? std::string("a path") : e.path1().string()) << ": "
              << e.code().message() << "\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "touchdown: out of memory: the input asks for more than this machine holds (fewer drops, "
                 "samples or trace points)\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 2;
  } catch (const std::exception& e) {
    // Anything else is a bug in touchdown (please report it with the command line).
    std::cerr << "touchdown: internal error: " << e.what() << "\n";
    touchdown::io::RemoveUnusedNewOutputDirectories();
    return 1;
  }
  return 0;
}
