#include "drop_tests/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace touchdown::drop {

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temporary);
    write(out);
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary);
      throw std::runtime_error("error writing " + temporary);
    }
  }
  std::filesystem::rename(temporary, path);
}

void WriteStagedDirectory(const std::string& directory, const std::function<void(const std::string& staging)>& fill) {
  namespace fs = std::filesystem;
  const fs::path target = fs::absolute(directory);
  const fs::path staging = target.string() + ".partial-" + std::to_string(::getpid());
  fs::remove_all(staging);
  fs::create_directories(staging);
  try {
    fill(staging.string());
    fs::remove_all(target);
    fs::rename(staging, target);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(staging, ec);
    throw;
  }
}

}  // namespace touchdown::drop
