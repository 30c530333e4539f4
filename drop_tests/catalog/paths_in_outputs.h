#pragma once
// How outputs name the files they came from (resolved scenarios, model files, a sweep database's
// meta table) without carrying this machine's absolute paths: a file of the bundled data
// directory is written as "$TOUCHDOWN_DATA_DIR/<path inside it>" (the catalog the name came
// from, wherever it lives), any other file relative to the output's directory (as paths inside a
// touchdown YAML file are relative to that file).
#include <string>

namespace touchdown::io {

inline constexpr const char* kDataDirReference = "$TOUCHDOWN_DATA_DIR/";

// `path` as `output_dir` (the directory the output finally lives in; both may be relative to the
// working directory) should name it.
std::string PathForOutput(const std::string& path, const std::string& output_dir);
// The inverse: a path written by PathForOutput into `output_dir`, as the working directory reaches it.
std::string PathFromOutput(const std::string& written, const std::string& output_dir);

}  // namespace touchdown::io
