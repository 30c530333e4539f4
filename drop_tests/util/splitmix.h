#pragma once
// The splitmix64 finaliser (Steele, Lea & Flood 2014): a bijective mix of 64 bits, for seeds and
// counter-based random streams that must be the same on every machine (the sweep's draws, the
// soil-patch fields' per-landing seeds).
#include <cstdint>

namespace touchdown::io {

constexpr uint64_t SplitMix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace touchdown::io
