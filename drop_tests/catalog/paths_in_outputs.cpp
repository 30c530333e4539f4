#include "drop_tests/catalog/paths_in_outputs.h"

#include <filesystem>

#include "drop_tests/catalog/catalog.h"

namespace touchdown::io {

namespace fs = std::filesystem;

namespace {
// Absolute, lexically normal, without a trailing separator ("out/" and "out" are one directory).
fs::path Normal(const fs::path& p) {
  fs::path n = fs::absolute(p.empty() ? fs::path(".") : p).lexically_normal();  // "": the working directory
  if (!n.has_filename() && n.has_parent_path() && n != n.root_path()) n = n.parent_path();
  return n;
}

// `path` relative to `base` when it lies inside it, else empty.
fs::path Inside(const fs::path& path, const fs::path& base) {
  const fs::path rel = path.lexically_relative(base);
  if (rel.empty() || *rel.begin() == "..") return {};
  return rel;
}
}  // namespace

std::string PathForOutput(const std::string& path, const std::string& output_dir) {
  if (path.empty()) return path;
  const fs::path file = Normal(path);
  if (const fs::path in_data = Inside(file, Normal(DataDirectory())); !in_data.empty())
    return kDataDirReference + in_data.generic_string();
  const fs::path rel = file.lexically_relative(Normal(output_dir));
  return rel.empty() ? path : rel.generic_string();
}

std::string PathFromOutput(const std::string& written, const std::string& output_dir) {
  if (written.empty()) return written;
  const std::string data = kDataDirReference;
  if (written.rfind(data, 0) == 0) return (fs::path(DataDirectory()) / written.substr(data.size())).string();
  if (fs::path(written).is_absolute()) return written;
  return (fs::path(output_dir) / written).lexically_normal().string();
}

}  // namespace touchdown::io
