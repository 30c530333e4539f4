#pragma once
// Every file touchdown reads as input (pad, soil and scenario YAML, dataset CSV, meshes) is
// opened here, so a path that is not a readable regular file is refused with one line saying
// what it is instead: "file not found", "is a directory, not a file", "is a FIFO (named pipe),
// not a regular file", "symbolic link loop", "permission denied", or the OS's own reason.
// A FIFO is never opened for reading (that would block until a writer appears).
#include <string>
#include <string_view>

#include "rft/input_error.h"

namespace touchdown {

// An input file the OS would not open: the InputError "<path>: <reason>" with the OS's error
// number, so a caller that tells such errors apart (the Python module: FileNotFoundError,
// PermissionError) need not parse the message.
class InputFileError : public InputError {
 public:
  InputFileError(const std::string& message, int os_error) : InputError(message), os_error_(os_error) {}
  int os_error() const { return os_error_; }

 private:
  int os_error_;
};

// Throws InputError "<path>: <reason>" unless `path` is a regular file this process can read.
// `what` names the file in the "not found" message ("file", "mesh file", "trace file").
void RequireReadableFile(const std::string& path, const std::string& what = "file");

// The whole file, checked as above; a read error is reported with the OS reason.
std::string ReadInputFile(const std::string& path, const std::string& what = "file");

// True if `text` is well-formed UTF-8 (no overlong forms, surrogates or code points above
// U+10FFFF). Names and ids end up in JSON and in file names, which need valid UTF-8.
bool IsValidUtf8(std::string_view text);

}  // namespace touchdown
