#include "drop_tests/lander_plots.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "drop_tests/output_path.h"
#include "drop_tests/lander_scenario.h"

namespace touchdown::drop {

namespace fs = std::filesystem;

void WriteLanderPlots(const LanderRun& run, const std::string& out_dir) {
  const fs::path dir = out_dir;
  fs::create_directories(dir / "plots");
  // trace.csv columns: 1 t, 5 roll, 6 pitch, 8 tilt, 16..19 pad depths.
  std::ostringstream gp;
  const std::string head = "set terminal pngcairo size 1000,600 font 'sans,10'\nset termoption noenhanced\n"
                           "set grid\nset key top right\nset datafile separator ','\nset xlabel 't [ms] (release at 0)'\n";
  gp << head << "set output 'plots/penetration.png'\nset title '" << run.scenario.name
     << ": penetration of each pad (lowest point below the surface)'\nset ylabel 'penetration [mm]'\nplot ";
  for (int i = 0; i < lander::kNumLegs; ++i)
    gp << (i ? ", " : "") << "'trace.csv' skip 1 using ($1*1000):($" << 16 + i << "*1000) with lines lw 2 title 'pad "
       << i + 1 << " (" << run.soil_under_pad[i] << ")'";
  gp << "\n" << head << "set output 'plots/attitude.png'\nset title '" << run.scenario.name
     << ": body attitude (roll > 0 right side down, pitch > 0 nose up)'\nset ylabel 'angle [deg]'\n"
     << "plot 'trace.csv' skip 1 using ($1*1000):5 with lines lw 2 title 'roll', "
        "'trace.csv' skip 1 using ($1*1000):6 with lines lw 2 title 'pitch', "
        "'trace.csv' skip 1 using ($1*1000):8 with lines lw 2 dt 2 title 'tilt from vertical'\n";
  const fs::path script = dir / "plots" / "lander.gp";
  WriteFileAtomically(script.string(), [&](std::ostream& out) { out << gp.str(); });
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    std::cerr << "warning: gnuplot not found; plot script left in " << script.string() << "\n";
    return;
  }
  const std::string command = "cd '" + dir.string() + "' && gnuplot plots/lander.gp 2>plots/gnuplot.log";
  if (std::system(command.c_str()) != 0)
    throw std::runtime_error("gnuplot failed; see " + (dir / "plots" / "gnuplot.log").string());
  fs::remove(dir / "plots" / "gnuplot.log");
}

}  // namespace touchdown::drop
