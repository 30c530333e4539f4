#pragma once
// Where touchdown writes, and the promise it keeps there: it never deletes or overwrites anything
// it did not write, and an output appears whole or not at all.
//
// Every output directory carries a marker file (kOutputMarker) that names the command kind that
// wrote it and, for outputs written whole, every file in it. A directory target is accepted when it
// does not exist, is empty, or is an earlier output of the same kind whose files are all listed in
// its marker; anything else is refused (InputError, exit 2) with the path and the reason. So are the
// current directory and its ancestors, a symbolic link, and any path equal to, inside or around one
// of the command's inputs.
//
// A whole output is filled in a hidden staging directory beside the target
// (`.NAME.partial-PID.WRITER@HOST`, one per writer, so two threads stage apart) that takes the target's place in one atomic exchange (renameat2
// RENAME_EXCHANGE); only then is the old output removed. A kill at any moment leaves the old output
// or the new one, whole; the staging directories of killed runs are removed by the next run on the
// same machine that writes beside them (another machine sharing the disk cannot tell whether their
// process is gone, so it leaves them).
#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "rft/enum_names.h"

namespace touchdown::io {

inline constexpr const char* kOutputMarker = ".touchdown-output";

// This process's tag, `PID@HOST`; its staging entries are named `PID.WRITER@HOST`.
std::string OutputOwnerTag();

// Which command wrote an output directory: one command never replaces another's output.
// A trade study's tables go into its sweep's output, so they are of the sweep kind.
// `touchdown drop --vtk DIR` writes a ParaView time series (kDropVtk); `touchdown validate` its
// report (kValidation).
enum class OutputKind { kCampaign, kLander, kComparison, kDataset, kDiagnosis, kSweep, kDropVtk, kValidation };
// The names an output's marker file holds (the command that wrote it).
inline constexpr std::array<EnumName<OutputKind>, 8> kOutputKindNames{{{OutputKind::kCampaign, "campaign"},
                                                                       {OutputKind::kLander, "lander"},
                                                                       {OutputKind::kComparison, "compare"},
                                                                       {OutputKind::kDataset, "dataset"},
                                                                       {OutputKind::kDiagnosis, "diagnose"},
                                                                       {OutputKind::kSweep, "sweep"},
                                                                       {OutputKind::kDropVtk, "drop"},
                                                                       {OutputKind::kValidation, "validate"}}};
const char* OutputKindName(OutputKind kind);

// An output path as the user gave it, with the paths the command reads from.
struct OutputTarget {
  OutputTarget(std::string path, std::vector<std::string> inputs = {})  // NOLINT: a plain path converts
      : path(std::move(path)), inputs(std::move(inputs)) {}
  OutputTarget(const char* path) : path(path) {}  // NOLINT
  std::string path;
  std::vector<std::string> inputs;
};

// Refuses (InputError naming the path and why) a directory target the kind may not write to. Commands
// call it before they start work, so that a bad --out costs nothing; the writers call it again.
void CheckOutputDirectory(const OutputTarget& target, OutputKind kind);

// Writes a whole output directory: `fill` writes into the staging directory it is given.
void WriteOutputDirectory(const OutputTarget& target, OutputKind kind,
                          const std::function<void(const std::string& staging)>& fill);

// An output filled in place over several runs (a sweep's database, which a rerun resumes): created
// with its marker, or reopened when it is an earlier output of the same kind and holds no symbolic
// link (touchdown makes none, and would write through it). Nothing is removed.
void OpenOutputDirectory(const OutputTarget& target, OutputKind kind);

// The folders this process created for outputs (OpenOutputDirectory's, and the missing parents
// either writer creates) that still hold nothing but touchdown's marker, removed, deepest first: a
// command that fails (bad input found late, a full disk, no memory) before it wrote any result
// leaves no empty folder behind. `touchdown`'s exit paths call it.
void RemoveUnusedNewOutputDirectories();

// The outputs a command derives from a directory it fills in place (a stability study's or a trade
// study's tables, plots and summary, beside the sweep database), replaced as one whole: `fill`
// writes all of them into a staging directory it is given; then `complete` (the file whose presence
// says the analysis is whole, e.g. summary.json) is removed, the other entries take the places of
// the earlier ones, and `complete` comes last. A failure or a kill before that leaves the earlier
// analysis untouched; one during it leaves no `complete`. Refuses (InputError) a directory holding
// a symbolic link or, among the outputs it replaces, anything the earlier run did not write (their
// list is kept in the directory as `.touchdown-derived`).
void ReplaceDerivedOutputs(const std::string& directory, OutputKind kind, const std::string& complete,
                           const std::function<void(const std::string& staging)>& fill);

// A single output file (a trace, a model file). An existing file is replaced only when its first line
// is `mark`, or one of `marks` (a line touchdown writes first in such files: a comment, or a CSV header
// only touchdown writes), so a file of the user's is never lost. The file's directory must exist:
// touchdown creates no directory for a single file (an output directory, by contrast, is touchdown's
// and is created with its missing parents).
void CheckOutputFile(const OutputTarget& target, const std::string& mark = "");
void CheckOutputFile(const OutputTarget& target, const std::vector<std::string>& marks);
void WriteOutputFile(const OutputTarget& target, const std::function<void(std::ostream&)>& write,
                     const std::string& mark = "");
void WriteOutputFile(const OutputTarget& target, const std::function<void(std::ostream&)>& write,
                     const std::vector<std::string>& marks);

// A file inside a directory touchdown owns (a staging directory, a sweep output): written beside the
// path and renamed over it, so no reader ever sees it half written. Write errors name the path and
// the operating system's reason (InputError: a full or read-only file system is an unusable path).
void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace touchdown::io
