#pragma once
// The output writers' shared steps (output_path.cpp), for the writers of one output kind kept in
// their own file (derived_outputs.cpp). Private to drop_tests/formats: no other module includes it.
#include <filesystem>
#include <set>
#include <string>

#include "drop_tests/formats/output_path.h"
#include "rft/input_error.h"

namespace touchdown::io::output_internal {

// Throws InputError "PATH: WHY".
[[noreturn]] void Refuse(const std::string& path, const std::string& why);
std::string Reason(const std::error_code& ec);
// The target as an absolute path without `.`, `..` or a trailing separator (`new/` is `new`).
std::filesystem::path Normal(const std::string& path);
// Every entry below `directory`, relative, directories with a trailing '/', the marker left out.
std::set<std::string> Entries(const std::filesystem::path& directory);
// The output marker of `kind` (with the list of `files` when given).
void WriteMarker(const std::filesystem::path& directory, OutputKind kind, const std::set<std::string>* files);
// Refuses a directory holding a symbolic link (touchdown makes none, so it is the user's).
void RefuseLinksInside(const std::string& path, const std::filesystem::path& directory);
// Removes an output of touchdown's, its marker last.
void RemoveOutput(const std::filesystem::path& directory);
// Removes or restores what killed runs left beside `p`.
void CleanLeftovers(const std::filesystem::path& p);
// `.NAME.partial-PID.WRITER@HOST` beside `p`: where this writer stages it.
std::filesystem::path StagingPath(const std::filesystem::path& p);
// Moves `from` to the new path `to`; false (nothing moved) when `to` exists.
bool RenameNoReplace(const std::filesystem::path& from, const std::filesystem::path& to);
// Puts the staging directory in the place of the existing target, then removes the old output.
void ReplaceDirectory(const std::filesystem::path& staging, const std::filesystem::path& target);
// The error with the staging directory named as the user's path.
InputError NamingTheTarget(const InputError& e, const std::filesystem::path& staging, const std::string& shown_path);

}  // namespace touchdown::io::output_internal
