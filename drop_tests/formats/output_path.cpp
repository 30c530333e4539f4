#include "drop_tests/formats/output_path.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <mutex>
#include <fstream>
#include <set>
#include <unistd.h>

#include "drop_tests/formats/output_path_internal.h"
#include "rft/input_error.h"

namespace touchdown::io {

namespace fs = std::filesystem;

namespace output_internal {

constexpr const char* kMarkerTitle = "touchdown output";

[[noreturn]] void Refuse(const std::string& path, const std::string& why) {
  throw InputError(path + ": " + why);
}

std::string Reason(const std::error_code& ec) { return ec.message(); }

// The target as an absolute path without `.`, `..` or a trailing separator (`new/` is `new`).
fs::path Normal(const std::string& path) {
  if (path.empty()) Refuse("''", "empty output path");
  std::error_code ec;
  fs::path p = fs::absolute(fs::path(path), ec);
  if (ec) Refuse(path, Reason(ec));
  p = p.lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  if (p == p.root_path()) Refuse(path, "is the root directory");
  return p;
}

// The same path with every symbolic link of its existing part resolved: what comparisons use.
fs::path Resolved(const fs::path& p) {
  std::error_code ec;
  const fs::path r = fs::weakly_canonical(p, ec);
  return ec ? p : r;
}

// a == b or a lies below b.
bool SameOrInside(const fs::path& a, const fs::path& b) {
  const fs::path rel = a.lexically_relative(b);
  return !rel.empty() && *rel.begin() != "..";
}

void RefuseAroundInputs(const std::string& path, const fs::path& target, const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (input.empty() || !fs::exists(input, ec)) continue;  // a catalogue name, not a path
    const fs::path in = Resolved(fs::absolute(fs::path(input), ec).lexically_normal());
    if (ec) continue;
    if (SameOrInside(target, in))
      Refuse(path, target == in ? "is the command's input '" + input + "'; choose another output path"
                                : "lies inside the command's input '" + input + "'; choose another output path");
    if (SameOrInside(in, target))
      Refuse(path, "contains the command's input '" + input + "'; choose another output path");
  }
}

// The nearest existing ancestor of `p` must be a directory this process can write in.
void RefuseUnwritableParent(const std::string& path, const fs::path& p) {
  fs::path parent = p.parent_path();
  std::error_code ec;
  while (!fs::exists(parent, ec) && parent != parent.root_path()) parent = parent.parent_path();
  if (!fs::is_directory(parent, ec)) Refuse(path, "'" + parent.string() + "' is not a directory");
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    Refuse(path, "cannot write in '" + parent.string() + "': " + std::strerror(errno));
}

std::string TypeName(fs::file_type type) {
  switch (type) {
    case fs::file_type::regular: return "a file";
    case fs::file_type::directory: return "a directory";
    case fs::file_type::symlink: return "a symbolic link";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::block:
    case fs::file_type::character: return "a device";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file or directory";
  }
}

struct Marker {
  bool present = false;
  std::string kind;
  std::set<std::string> files;  // relative generic paths, directories with a trailing '/'
  bool has_manifest = false;
};

Marker ReadMarker(const fs::path& directory) {
  Marker m;
  std::ifstream in(directory / kOutputMarker);
  if (!in) return m;
  std::string line;
  if (!std::getline(in, line) || line != kMarkerTitle) return m;
  m.present = true;
  while (std::getline(in, line)) {
    if (line.rfind("kind: ", 0) == 0) {
      m.kind = line.substr(6);
    } else if (line == "files:") {
      m.has_manifest = true;
      while (std::getline(in, line)) m.files.insert(line);
    }
  }
  return m;
}

// Every entry below `directory`, relative, directories with a trailing '/', the marker left out.
std::set<std::string> Entries(const fs::path& directory) {
  std::set<std::string> entries;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(directory)) {
    std::string rel = e.path().lexically_relative(directory).generic_string();
    if (rel == kOutputMarker) continue;
    if (e.is_directory() && !e.is_symlink()) rel += '/';
    entries.insert(rel);
  }
  return entries;
}

void WriteMarker(const fs::path& directory, OutputKind kind, const std::set<std::string>* files) {
  WriteFileAtomically((directory / kOutputMarker).string(), [&](std::ostream& out) {
    out << kMarkerTitle << "\nkind: " << OutputKindName(kind) << "\n";
    if (files) {
      out << "files:\n";
      for (const std::string& f : *files) out << f << "\n";
    }
  });
}

// touchdown never makes a symbolic link in an output, so one inside an output it fills in place is
// the user's, and writing there would write through it into whatever it points to.
void RefuseLinksInside(const std::string& path, const fs::path& directory) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code ignored;
    if (it->is_symlink(ignored))
      Refuse(path, "holds '" + it->path().lexically_relative(directory).generic_string() +
                       "', a symbolic link touchdown did not make (it writes through no link); remove it or give "
                       "another directory");
  }
}

// The checks shared by whole and in-place outputs; returns the normalised target.
fs::path CheckDirectory(const OutputTarget& target, OutputKind kind, bool whole) {
  const fs::path p = Normal(target.path);
  const std::string& path = target.path;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(p, ec);
  if (ec && status.type() != fs::file_type::not_found) Refuse(path, Reason(ec));
  if (status.type() == fs::file_type::symlink)
    Refuse(path, "is a symbolic link; give the directory it points to");
  const fs::path resolved = Resolved(p);
  const fs::path cwd = Resolved(fs::current_path(ec));
  if (!ec && SameOrInside(cwd, resolved)) Refuse(path, "is the current directory or one of its parents");
  RefuseAroundInputs(path, resolved, target.inputs);
  if (status.type() != fs::file_type::not_found) {
    if (status.type() != fs::file_type::directory)
      Refuse(path, "exists and is " + TypeName(status.type()) + ", not a directory");
    if (::access(p.c_str(), R_OK | W_OK | X_OK) != 0) Refuse(path, std::strerror(errno));
    if (!fs::is_empty(p, ec)) {
      const Marker marker = ReadMarker(p);
      if (!marker.present)
        Refuse(path, "is a directory that is not empty and was not written by touchdown (no " +
                         std::string(kOutputMarker) + "); give a new or empty directory");
      if (marker.kind != OutputKindName(kind))
        Refuse(path, "holds the output of `touchdown " + marker.kind + "`, not of `" + OutputKindName(kind) +
                         "`; give another directory");
      // A link the user put in place of one of its files is theirs too: a whole replacement would delete it.
      RefuseLinksInside(path, p);
      if (whole && marker.has_manifest) {
        for (const std::string& entry : Entries(p))
          if (!marker.files.count(entry))
            Refuse(path, "holds '" + entry + "', which touchdown did not write; move it away or give another directory");
      } else if (whole) {
        Refuse(path, "is an output touchdown fills in place; give another directory");
      }
    }
  }
  RefuseUnwritableParent(path, p);
  return p;
}

bool ProcessAlive(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH; }

// This machine's name as it appears in OutputOwnerTag (characters outside [A-Za-z0-9._-] as '_').
const std::string& HostName() {
  static const std::string name = [] {
    char buffer[256] = {};
    if (::gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0') return std::string("localhost");
    std::string host(buffer);
    for (char& c : host)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
    return host;
  }();
  return name;
}

// `.NAME.partial-PID.WRITER@HOST` or `.NAME.old-PID.WRITER@HOST` beside `p` (or, as earlier versions
// named them, without `.WRITER` or `@HOST`): the pid, or -1 when `entry` is not one of those or another machine's. Only the
// machine that made a leftover can tell whether its process is gone: on a disk that a cluster's
// nodes share, a pid says nothing about another node's processes.
long LeftoverPid(const std::string& entry, const std::string& name, const std::string& suffix) {
  const std::string prefix = "." + name + suffix;
  if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return -1;
  const std::string tag = entry.substr(prefix.size());
  const size_t at = tag.find('@');
  const std::string digits = tag.substr(0, std::min(at, tag.find('.')));  // PID, or PID.WRITER
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  if (at != std::string::npos && tag.substr(at + 1) != HostName()) return -1;
  return std::stol(digits);
}

// Removes an output of touchdown's, its marker last, so that a kill part way leaves a directory the
// next run still recognises as touchdown's and finishes removing.
void RemoveOutput(const fs::path& directory) {
  std::error_code ec;
  std::vector<fs::path> entries;  // listed first: a directory read while it is emptied may skip entries
  for (const fs::directory_entry& e : fs::directory_iterator(directory, ec))
    if (e.path().filename() != kOutputMarker) entries.push_back(e.path());
  for (const fs::path& entry : entries) fs::remove_all(entry, ec);
  for (const fs::directory_entry& e : fs::directory_iterator(directory, ec))
    if (e.path().filename() != kOutputMarker) return;  // not all removed: the marker stays for the next run
  fs::remove(directory / kOutputMarker, ec);
  fs::remove(directory, ec);
}

// A staging directory killed before its marker was whole: empty, or holding nothing but the marker
// being written. Its name and its dead owner say it is touchdown's.
bool JustCreated(const fs::path& directory) {
  std::error_code ec;
  const std::string marker = kOutputMarker;
  for (const fs::directory_entry& e : fs::directory_iterator(directory, ec)) {
    const std::string name = e.path().filename().string();
    if (name != marker && name.rfind("." + marker + ".partial-", 0) != 0) return false;
  }
  return !ec;
}

// What killed runs left beside `p`: their staging directories and files go; an old output that a
// run without RENAME_EXCHANGE had moved aside, and not replaced, comes back.
void CleanLeftovers(const fs::path& p) {
  const fs::path parent = p.parent_path();
  const std::string name = p.filename().string();
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) return;
  for (const fs::directory_entry& e : fs::directory_iterator(parent, ec)) {
    const std::string entry = e.path().filename().string();
    for (const char* suffix : {".partial-", ".old-"}) {
      const long pid = LeftoverPid(entry, name, suffix);
      if (pid < 0 || pid == ::getpid() || ProcessAlive(pid)) continue;
      std::error_code ignored;
      const bool directory = e.is_directory(ignored) && !e.is_symlink(ignored);
      if (directory && !ReadMarker(e.path()).present && !JustCreated(e.path())) continue;  // not ours to remove
      if (std::string(suffix) == ".old-" && !fs::exists(p, ignored)) {
        fs::rename(e.path(), p, ignored);
        continue;
      }
      if (directory) RemoveOutput(e.path());
      else fs::remove(e.path(), ignored);
    }
  }
}

// `.NAME<suffix>PID.WRITER@HOST` beside `p`: hidden, named so the next run knows whose it was, and
// one of its own for every writer (two threads of one process writing one output each stage apart,
// as two processes do).
fs::path Sibling(const fs::path& p, const char* suffix) {
  static std::atomic<unsigned long> writers{0};
  std::string name = ".";
  name += p.filename().string();
  name += suffix;
  name += std::to_string(::getpid()) + "." + std::to_string(++writers) + "@" + HostName();
  return p.parent_path() / name;
}

fs::path StagingPath(const fs::path& p) { return Sibling(p, ".partial-"); }

// Moves `from` to the new path `to`, failing (rather than replacing) when `to` appeared meanwhile.
bool RenameNoReplace(const fs::path& from, const fs::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno == EEXIST) return false;
  if (errno == EINVAL || errno == ENOSYS) {  // a file system without renameat2 flags
    if (fs::exists(to)) return false;
    std::error_code ec;
    fs::rename(from, to, ec);
    if (!ec) return true;
    errno = ec.value();
  }
  throw InputError(to.string() + ": cannot move the finished output into place: " + std::strerror(errno));
}

// Puts the staging directory in the place of the existing target, then removes the old output.
void ReplaceDirectory(const fs::path& staging, const fs::path& target) {
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    RemoveOutput(staging);  // now the old output
    return;
  }
  if (errno != EINVAL && errno != ENOSYS)
    throw InputError(target.string() + ": cannot replace the earlier output: " + std::strerror(errno));
  // Without an atomic exchange: the old output steps aside under a name the next run restores.
  const fs::path old = Sibling(target, ".old-");
  std::error_code ec;
  fs::rename(target, old, ec);
  if (ec) throw InputError(target.string() + ": cannot replace the earlier output: " + Reason(ec));
  fs::rename(staging, target, ec);
  if (ec) {
    fs::rename(old, target, ec);
    throw InputError(target.string() + ": cannot replace the earlier output: " + Reason(ec));
  }
  RemoveOutput(old);
}

// The error with the staging directory, which the user never asked for, named as their path.
InputError NamingTheTarget(const InputError& e, const fs::path& staging, const std::string& shown_path) {
  std::string message = e.what();
  const std::string staged = staging.string();
  for (size_t at = message.find(staged); at != std::string::npos; at = message.find(staged, at))
    message.replace(at, staged.size(), shown_path);
  return InputError(message);
}

// Writes `file` from scratch; on any failure removes it and throws, naming `shown_path`.
void WriteNewFile(const fs::path& file, const std::function<void(std::ostream&)>& write,
                  const std::string& shown_path) {
  auto fail = [&](const std::string& what, int error) {
    std::error_code ec;
    fs::remove(file, ec);
    Refuse(shown_path, what + ": " + std::strerror(error));
  };
  errno = 0;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) fail("cannot write", errno ? errno : EIO);
  try {
    write(out);
  } catch (...) {
    out.close();
    std::error_code ec;
    fs::remove(file, ec);
    throw;
  }
  out.flush();
  if (!out) fail("error writing", errno ? errno : EIO);
  out.close();
  if (out.fail()) fail("error writing", errno ? errno : EIO);
}

// A single file's directory must exist: a typo in it (`--trace /nonexistent/x.csv`) is reported
// instead of leaving a directory tree behind, as `cp` or a compiler's `-o` would.
void RefuseMissingDirectory(const std::string& path, const fs::path& p) {
  std::error_code ec;
  const fs::path parent = p.parent_path();
  if (!fs::exists(parent, ec))
    Refuse(path, "directory '" + parent.string() + "' does not exist; create it first (a single output file "
                 "goes into an existing directory)");
}

}  // namespace output_internal

using namespace output_internal;

const char* OutputKindName(OutputKind kind) { return NameIn(kOutputKindNames, kind); }

namespace {
std::mutex new_directories_mutex;
std::vector<fs::path> new_directories;  // in the order created, each after its parent

// create_directories(p), noting each folder it makes.
void CreateNoted(const fs::path& p, std::error_code& ec) {
  std::vector<fs::path> missing;
  for (fs::path q = p; !q.empty() && !fs::exists(fs::symlink_status(q, ec)); q = q.parent_path()) {
    missing.push_back(q);
    if (q == q.parent_path()) break;
  }
  fs::create_directories(p, ec);
  if (ec) return;
  const std::lock_guard<std::mutex> lock(new_directories_mutex);
  new_directories.insert(new_directories.end(), missing.rbegin(), missing.rend());
}
}  // namespace

void CheckOutputDirectory(const OutputTarget& target, OutputKind kind) { CheckDirectory(target, kind, true); }

void WriteOutputDirectory(const OutputTarget& target, OutputKind kind,
                          const std::function<void(const std::string& staging)>& fill) {
  const fs::path p = CheckDirectory(target, kind, true);
  CleanLeftovers(p);
  std::error_code ec;
  CreateNoted(p.parent_path(), ec);
  if (ec) Refuse(target.path, "cannot create '" + p.parent_path().string() + "': " + Reason(ec));
  const fs::path staging = StagingPath(p);
  if (fs::exists(staging, ec)) {  // left by an earlier process with this pid
    if (!ReadMarker(staging).present && !JustCreated(staging))
      Refuse(target.path, "'" + staging.string() + "' is in the way and was not written by touchdown");
    RemoveOutput(staging);
  }
  fs::create_directory(staging, ec);
  if (ec) Refuse(target.path, "cannot create the staging directory: " + Reason(ec));
  try {
    WriteMarker(staging, kind, nullptr);
    fill(staging.string());
    const std::set<std::string> files = Entries(staging);
    WriteMarker(staging, kind, &files);
    CheckDirectory(target, kind, true);  // nothing of the user's appeared there meanwhile
    if (!RenameNoReplace(staging, p)) {
      CheckDirectory(target, kind, true);
      ReplaceDirectory(staging, p);
    }
  } catch (const InputError& e) {
    RemoveOutput(staging);
    throw NamingTheTarget(e, staging, target.path);
  } catch (...) {
    RemoveOutput(staging);
    throw;
  }
}


void RemoveUnusedNewOutputDirectories() {
  const std::lock_guard<std::mutex> lock(new_directories_mutex);
  for (auto it = new_directories.rbegin(); it != new_directories.rend(); ++it) {
    std::error_code ec;
    bool unused = true;
    for (const fs::directory_entry& e : fs::directory_iterator(*it, ec))
      unused &= e.path().filename() == kOutputMarker && e.is_regular_file(ec) && !e.is_symlink(ec);
    if (ec || !unused) continue;
    fs::remove(*it / kOutputMarker, ec);
    fs::remove(*it, ec);  // only if empty now
  }
  new_directories.clear();
}

void OpenOutputDirectory(const OutputTarget& target, OutputKind kind) {
  const fs::path p = CheckDirectory(target, kind, false);
  std::error_code ec;
  CreateNoted(p, ec);
  if (ec) Refuse(target.path, "cannot create: " + Reason(ec));
  if (!ReadMarker(p).present) WriteMarker(p, kind, nullptr);
  for (const fs::directory_entry& e : fs::directory_iterator(p, ec))
    CleanLeftovers(e.path());
}

std::string OutputOwnerTag() { return std::to_string(::getpid()) + "@" + HostName(); }

void CheckOutputFile(const OutputTarget& target, const std::string& mark) {
  CheckOutputFile(target, mark.empty() ? std::vector<std::string>{} : std::vector<std::string>{mark});
}

void CheckOutputFile(const OutputTarget& target, const std::vector<std::string>& marks) {
  const std::string& path = target.path;
  if (!path.empty() && (path.back() == '/')) Refuse(path, "names a directory; give a file name");
  const fs::path p = Normal(path);
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(p, ec);
  if (ec && status.type() != fs::file_type::not_found) Refuse(path, Reason(ec));
  RefuseAroundInputs(path, Resolved(p), target.inputs);
  if (status.type() == fs::file_type::regular) {
    std::ifstream in(p);
    std::string first;
    const bool marked = in && std::getline(in, first) && std::find(marks.begin(), marks.end(), first) != marks.end();
    if (!marked)
      Refuse(path, "exists and was not written by touchdown; touchdown does not overwrite it (give a new file name)");
  } else if (status.type() != fs::file_type::not_found) {
    Refuse(path, "exists and is " + TypeName(status.type()) + "; give a new file name");
  }
  RefuseMissingDirectory(path, p);
  RefuseUnwritableParent(path, p);
}

void WriteOutputFile(const OutputTarget& target, const std::function<void(std::ostream&)>& write,
                     const std::string& mark) {
  WriteOutputFile(target, write, mark.empty() ? std::vector<std::string>{} : std::vector<std::string>{mark});
}

void WriteOutputFile(const OutputTarget& target, const std::function<void(std::ostream&)>& write,
                     const std::vector<std::string>& marks) {
  CheckOutputFile(target, marks);
  const fs::path p = Normal(target.path);
  CleanLeftovers(p);
  std::error_code ec;
  const bool existed = fs::exists(p, ec);
  const fs::path staging = StagingPath(p);
  WriteNewFile(staging, write, target.path);
  try {
    if (existed) {
      CheckOutputFile(target, marks);
      fs::rename(staging, p, ec);
      if (ec) Refuse(target.path, Reason(ec));
    } else if (!RenameNoReplace(staging, p)) {
      Refuse(target.path, "appeared while touchdown was writing it; touchdown does not overwrite it");
    }
  } catch (...) {
    fs::remove(staging, ec);
    throw;
  }
}

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const fs::path p(path);
  if (!p.has_filename()) Refuse(path, "names a directory; give a file name");
  const fs::path temporary = StagingPath(p);
  WriteNewFile(temporary, write, path);
  std::error_code ec;
  fs::rename(temporary, p, ec);
  if (ec) {
    fs::remove(temporary, ec);
    Refuse(path, "cannot move the finished file into place: " + Reason(ec));
  }
}

}  // namespace touchdown::io
