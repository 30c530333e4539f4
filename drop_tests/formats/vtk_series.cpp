#include "drop_tests/formats/vtk_series.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "drop_tests/formats/output_path.h"

namespace touchdown::io {

namespace {
std::string FrameFile(const std::string& part, size_t frame) {
  char number[16];
  std::snprintf(number, sizeof number, "%06zu", frame);
  return part + "_" + number + ".vtp";
}
}  // namespace

VtkSeries::VtkSeries(std::string directory, std::string name) : directory_(std::move(directory)), name_(std::move(name)) {}

int VtkSeries::PartIndex(const std::string& part) {
  const auto it = std::find(parts_.begin(), parts_.end(), part);
  if (it != parts_.end()) return static_cast<int>(it - parts_.begin());
  parts_.push_back(part);
  static_files_.emplace_back();
  last_.emplace_back();
  return static_cast<int>(parts_.size()) - 1;
}

void VtkSeries::AddStaticPart(const std::string& part, const std::vector<VtkPolyData>& pieces) {
  const int index = PartIndex(part);
  static_files_[index] = part + ".vtp";
  WriteFileAtomically(directory_ + "/" + static_files_[index], [&](std::ostream& out) { WriteVtp(pieces, out); });
}

void VtkSeries::AddFrame(double time_s, const std::string& part, const std::vector<VtkPolyData>& pieces) {
  if (!times_.empty() && time_s < times_.back()) throw std::logic_error("VtkSeries: frames out of time order");
  if (times_.empty() || time_s > times_.back()) times_.push_back(time_s);
  const int index = PartIndex(part);
  std::ostringstream text;
  WriteVtp(pieces, text);
  // The part's entry at this time, if any, is the frame this one replaces.
  std::erase_if(frames_, [&](const VtkCollectionEntry& e) { return e.part == index && e.time_s == time_s; });
  Written& last = last_[static_cast<size_t>(index)];
  if (last.file.empty() || last.text != text.str()) {
    // Its own file: the name of this time, which no other time lists.
    last = {FrameFile(part, times_.size() - 1), text.str()};
    WriteFileAtomically(directory_ + "/" + last.file, [&](std::ostream& out) { out << last.text; });
  }
  frames_.push_back({time_s, index, part, last.file});
}

std::string VtkSeries::Finish() const {
  std::vector<VtkCollectionEntry> entries;
  // At each time, the parts in the order they were first added.
  for (size_t t = 0; t < times_.size(); ++t)
    for (size_t p = 0; p < parts_.size(); ++p) {
      if (!static_files_[p].empty()) {
        entries.push_back({times_[t], static_cast<int>(p), parts_[p], static_files_[p]});
        continue;
      }
      for (const VtkCollectionEntry& e : frames_)
        if (e.time_s == times_[t] && e.part == static_cast<int>(p)) entries.push_back(e);
    }
  const std::string path = directory_ + "/" + name_ + ".pvd";
  WriteFileAtomically(path, [&](std::ostream& out) { WritePvd(entries, out); });
  return path;
}

}  // namespace touchdown::io
