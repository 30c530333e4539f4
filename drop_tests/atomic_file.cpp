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

}  // namespace touchdown::drop
