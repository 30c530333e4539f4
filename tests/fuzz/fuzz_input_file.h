#pragma once
// libFuzzer targets hand the parsers a file: the fuzz input is written to a per-process
// temporary path that the parser then opens, exactly as a user's file would be.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <unistd.h>

namespace touchdown::fuzz {

inline std::string WriteFuzzInput(const uint8_t* data, size_t size, const std::string& suffix) {
  const std::string path = "/tmp/touchdown_fuzz_" + std::to_string(::getpid()) + suffix;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), size);
  return path;
}

}  // namespace touchdown::fuzz
