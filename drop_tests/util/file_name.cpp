#include "drop_tests/util/file_name.h"

namespace touchdown::io {

std::string FileNameProblem(const std::string& what, const std::string& name) {
  const std::string subject = what.empty() ? "" : what + " ";
  if (name.empty()) return what.empty() ? "must not be empty" : "empty " + what;
  if (name == "." || name == "..") return subject + "'" + name + "' cannot be a file name";
  if (name.size() > kMaxNameBytes)
    return subject + "longer than " + std::to_string(kMaxNameBytes) + " bytes (it names files)";
  for (const char c : name) {
    if (c == '/' || c == '\\')
      return subject + "'" + name + "' contains '" + std::string(1, c) + "' (it names files)";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return subject + "contains a control character (it names files)";
  }
  return "";
}

}  // namespace touchdown::io
