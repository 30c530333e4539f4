#pragma once
// libFuzzer targets hand the parsers a file: the fuzz input is written to a per-process
// temporary path that the parser then opens, exactly as a user's file would be. A parser may
// accept the input or throw touchdown::InputError; any other exception escapes the target,
// terminates the process and libFuzzer reports it as a crash (as it does sanitizer reports).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace touchdown::fuzz {

// A directory of this process's own, created on first use.
inline std::string FuzzDirectory(const std::string& name) {
  const std::string dir = "/tmp/touchdown_fuzz_" + std::to_string(::getpid()) + "_" + name;
  std::filesystem::create_directories(dir);
  return dir;
}

inline void WriteBytes(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), size);
}

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

inline std::string WriteFuzzInput(const uint8_t* data, size_t size, const std::string& suffix) {
  const std::string path = "/tmp/touchdown_fuzz_" + std::to_string(::getpid()) + suffix;
  WriteBytes(path, data, size);
  return path;
}

}  // namespace touchdown::fuzz
