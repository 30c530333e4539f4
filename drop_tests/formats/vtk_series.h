#pragma once
// A time series for ParaView written into a directory touchdown owns (a staging directory of
// output_path.h): each frame's parts as PART_NNNNNN.vtp, parts that never change once as PART.vtp,
// and NAME.pvd listing every part at every time (ParaView opens NAME.pvd as one multiblock data set
// per time, a block per part).
#include <string>
#include <vector>

#include "drop_tests/formats/vtk_writer.h"

namespace touchdown::io {

class VtkSeries {
 public:
  VtkSeries(std::string directory, std::string name);

  // A part that does not move (the soil's surface): written once, listed at every time.
  void AddStaticPart(const std::string& part, const std::vector<VtkPolyData>& pieces);
  // A part at `time_s` (non-decreasing). A second frame at the same time as the last (a sample at
  // an event) replaces it. A frame the same byte for byte as the part's previous one (a crater that
  // did not change) is not written again: the collection lists the previous file at this time.
  void AddFrame(double time_s, const std::string& part, const std::vector<VtkPolyData>& pieces);
  // Writes NAME.pvd. Returns its path.
  std::string Finish() const;

 private:
  int PartIndex(const std::string& part);
  std::string directory_, name_;
  std::vector<std::string> parts_;
  std::vector<std::string> static_files_;  // by part, "" for moving parts
  struct Written {
    std::string file, text;
  };
  std::vector<Written> last_;  // by part: the file of its latest frame and what it holds
  std::vector<double> times_;
  std::vector<VtkCollectionEntry> frames_;
};

}  // namespace touchdown::io
