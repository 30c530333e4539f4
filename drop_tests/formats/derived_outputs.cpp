#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/output_path_internal.h"
#include "rft/input_error.h"

// An analysis written into a directory touchdown owns beside what it analyses (diagnose's,
// compare's outputs below a dataset): the derived outputs are staged apart and put in place
// only when whole, each replacing only what touchdown wrote there before (its list kept in
// .touchdown-derived).
namespace touchdown::io {

namespace fs = std::filesystem;
using namespace output_internal;

namespace {

constexpr const char* kDerivedManifest = ".touchdown-derived";

// The derived outputs an earlier run wrote (relative generic paths, directories with a trailing
// '/'); `present` false for a directory written before the list was kept.
std::set<std::string> ReadDerivedManifest(const fs::path& directory, bool& present) {
  std::set<std::string> files;
  std::ifstream in(directory / kDerivedManifest);
  present = static_cast<bool>(in);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) files.insert(line);
  return files;
}

void WriteDerivedManifest(const fs::path& directory, const std::set<std::string>& files) {
  WriteFileAtomically((directory / kDerivedManifest).string(), [&](std::ostream& out) {
    for (const std::string& f : files) out << f << '\n';
  });
}

// The first component of a relative generic path ("plots/data/x.csv" -> "plots").
std::string TopName(const std::string& entry) { return entry.substr(0, entry.find('/')); }

// `name` and everything below it in `directory`, as Entries() lists them; empty when absent.
std::set<std::string> EntriesUnder(const fs::path& directory, const std::string& name) {
  std::set<std::string> entries;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(directory / name, ec);
  if (status.type() == fs::file_type::not_found) return entries;
  if (status.type() != fs::file_type::directory) return {name};
  entries.insert(name + "/");
  for (const std::string& e : Entries(directory / name)) entries.insert(name + "/" + e);
  return entries;
}

// Puts the staged entry `name` in the place of the directory's own (absent or touchdown's).
void MoveIntoPlace(const fs::path& staging, const fs::path& directory, const std::string& name) {
  const fs::path from = staging / name, to = directory / name;
  std::error_code ec;
  if (fs::is_directory(from, ec) && fs::exists(fs::symlink_status(to, ec))) {
    ReplaceDirectory(from, to);
    return;
  }
  if (!fs::is_directory(from, ec)) {
    fs::rename(from, to, ec);  // a file replaces a file in one step
    if (ec) Refuse(to.string(), "cannot move the finished file into place: " + Reason(ec));
  } else if (!RenameNoReplace(from, to)) {
    Refuse(to.string(), "appeared while touchdown was writing it; touchdown does not overwrite it");
  }
}

}  // namespace


void ReplaceDerivedOutputs(const std::string& directory, OutputKind kind, const std::string& complete,
                           const std::function<void(const std::string& staging)>& fill) {
  const fs::path dir = Normal(directory);
  RefuseLinksInside(directory, dir);
  const fs::path staging_name = dir / "derived";
  CleanLeftovers(staging_name);  // a killed run's staging directory
  const fs::path staging = StagingPath(staging_name);
  std::error_code ec;
  if (fs::exists(staging, ec)) RemoveOutput(staging);
  fs::create_directory(staging, ec);
  if (ec) Refuse(directory, "cannot create the staging directory: " + Reason(ec));
  std::set<std::string> fresh;
  try {
    WriteMarker(staging, kind, nullptr);  // so that the next run knows a killed run's staging is touchdown's
    fill(staging.string());
    fresh = Entries(staging);
  } catch (const InputError& e) {
    RemoveOutput(staging);
    throw NamingTheTarget(e, staging, directory);
  } catch (...) {
    RemoveOutput(staging);
    throw;
  }
  try {
    if (!fresh.count(complete)) Refuse(directory, "the analysis wrote no '" + complete + "'");
    bool listed = false;
    const std::set<std::string> earlier = ReadDerivedManifest(dir, listed);
    std::set<std::string> names;  // top-level entries, earlier and new
    for (const std::string& e : fresh) names.insert(TopName(e));
    for (const std::string& e : earlier) names.insert(TopName(e));
    // Everything the new outputs replace must be touchdown's: listed by the earlier run (a directory
    // written before the list was kept holds no link, checked above, and only what it wrote).
    for (const std::string& name : names)
      for (const std::string& e : EntriesUnder(dir, name))
        if (listed && !earlier.count(e))
          Refuse(directory, "holds '" + e + "', which touchdown did not write; move it away so that the analysis can "
                            "be replaced");
    std::set<std::string> both = earlier;
    both.insert(fresh.begin(), fresh.end());
    WriteDerivedManifest(dir, both);  // a kill from here on leaves nothing the next run does not know
    fs::remove(dir / complete, ec);   // first out, last in: present only beside a whole analysis
    for (const std::string& name : names) {
      if (name == complete) continue;
      if (fs::exists(fs::symlink_status(staging / name, ec))) MoveIntoPlace(staging, dir, name);
      else fs::remove_all(dir / name, ec);  // an earlier output this analysis no longer makes
    }
    WriteDerivedManifest(dir, fresh);
    MoveIntoPlace(staging, dir, complete);
  } catch (...) {
    RemoveOutput(staging);
    throw;
  }
  RemoveOutput(staging);
}

}  // namespace touchdown::io
