#include "drop_tests/scenario/lander_plots.h"

#include <filesystem>
#include <ostream>
#include <sstream>

#include "drop_tests/io/dataset_csv.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/io/plot_decimation.h"
#include "drop_tests/io/plot_runner.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
using units::kDeg;
}  // namespace

void WriteLanderPlots(const std::string& name, const std::vector<lander::LanderSample>& trace,
                      const std::array<std::string, lander::kNumLegs>& soil_under_pad, const std::string& out_dir) {
  const fs::path dir = out_dir;
  fs::create_directories(dir / "plots" / "data");
  // The plotted columns of trace.csv, decimated (plot_decimation.h): a run at the sample cap has
  // ten million rows. plots/data/trace.csv columns: 1 t, 2 roll, 3 pitch, 4 tilt, 5..8 pad depths.
  constexpr size_t kColumns = 4 + lander::kNumLegs;
  auto value = [&](size_t row, size_t column) {
    const lander::LanderSample& s = trace[row];
    switch (column) {
      case 0: return s.t_s;
      case 1: return s.attitude.roll_rad / kDeg;
      case 2: return s.attitude.pitch_rad / kDeg;
      case 3: return s.attitude.tilt_rad / kDeg;
      default: return s.pad_depth_m[column - 4];
    }
  };
  const std::vector<size_t> rows = io::PlotRowsToKeep(trace.size(), kColumns, value);
  io::WriteFileAtomically((dir / "plots" / "data" / "trace.csv").string(), [&](std::ostream& out) {
    out << "t_s,roll_deg,pitch_deg,tilt_deg";
    for (int i = 1; i <= lander::kNumLegs; ++i) out << ",depth" << i << "_m";
    out << '\n';
    for (const size_t k : rows) {
      for (size_t c = 0; c < kColumns; ++c) out << (c ? "," : "") << io::FormatNumber(value(k, c));
      out << '\n';
    }
  });

  std::ostringstream gp;
  const std::string head = "set terminal pngcairo size 1000,600 font 'sans,10'\nset termoption noenhanced\n"
                           "set grid\nset key top right\nset datafile separator ','\nset xlabel 't [ms] (release at 0)'\n";
  const std::string data = "'plots/data/trace.csv' skip 1 using ($1*1000):";
  gp << head << "set output 'plots/penetration.png'\nset title "
     << io::GnuplotQuote(name + ": penetration of each pad (lowest point below the surface)")
     << "\nset ylabel 'penetration [mm]'\nplot ";
  for (int i = 0; i < lander::kNumLegs; ++i)
    gp << (i ? ", " : "") << data << "($" << 5 + i << "*1000) with lines lw 2 title "
       << io::GnuplotQuote("pad " + std::to_string(i + 1) + " (" + soil_under_pad[i] + ")");
  gp << "\n" << head << "set output 'plots/attitude.png'\nset title "
     << io::GnuplotQuote(name + ": body attitude (roll > 0 right side down, pitch > 0 nose up)")
     << "\nset ylabel 'angle [deg]'\n"
     << "plot " << data << "2 with lines lw 2 title 'roll', " << data << "3 with lines lw 2 title 'pitch', " << data
     << "4 with lines lw 2 dt 2 title 'tilt from vertical'\n";
  io::RenderPlots(dir, {"plots/lander.gp", gp.str(), {"plots/penetration.png", "plots/attitude.png"}});
}

}  // namespace touchdown::scenario
