#pragma once
// Names that become parts of file names: a pad's or a soil's name in a trace's file name, a
// sweep's in its tables, a drop id in its trace. One check for all of them, made where the name is
// read, so that no name can lead a write out of its output folder.
#include <cstddef>
#include <string>

namespace touchdown::io {

// File names hold a name and a suffix (`_fjs1_lp_v1.00.csv`); 255 bytes is the usual file-name limit.
inline constexpr std::size_t kMaxNameBytes = 200;

// Why `name` cannot be part of a file name, or "" if it can: it must not be empty, "." or "..",
// hold a '/', a '\\' or a control byte, or be longer than kMaxNameBytes. `what` says what the name
// is in the message ("drop id 'a/b' contains '/' (it names files)"); "" for a message that follows
// the field's own name ("name: 'a/b' contains '/' (it names files)").
std::string FileNameProblem(const std::string& what, const std::string& name);

}  // namespace touchdown::io
