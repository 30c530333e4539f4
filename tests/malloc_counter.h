#pragma once
// Counts calls to malloc, so Eigen's heap buffers count as well as operator new: for the tests
// that a right-hand side allocates nothing (house style).
//
// This header DEFINES malloc: include it from exactly one translation unit per test executable.
// AddressSanitizer replaces malloc itself; there kCountsMalloc is false and the count is left to
// the plain build.
#include <Eigen/Core>
#include <atomic>
#include <cstdlib>

// AddressSanitizer: GCC defines __SANITIZE_ADDRESS__, clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define TOUCHDOWN_TESTS_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TOUCHDOWN_TESTS_UNDER_ASAN 1
#endif
#endif

namespace touchdown::testing_alloc {
inline std::atomic<bool> counting{false};
inline std::atomic<long> allocations{0};
}  // namespace touchdown::testing_alloc

#if !defined(TOUCHDOWN_TESTS_UNDER_ASAN)
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) {
  if (touchdown::testing_alloc::counting.load()) ++touchdown::testing_alloc::allocations;
  return __libc_malloc(size);
}
#endif

namespace touchdown::testing_alloc {

#if !defined(TOUCHDOWN_TESTS_UNDER_ASAN)
inline constexpr bool kCountsMalloc = true;
#else
inline constexpr bool kCountsMalloc = false;
#endif

// The number of mallocs while `fn` runs.
template <class Fn>
long CountAllocations(Fn&& fn) {
  allocations = 0;
  counting = true;
  fn();
  counting = false;
  return allocations.load();
}

// The mallocs of one Eigen vector's buffer: at least one, unless Eigen takes its buffers from
// somewhere the count does not see.
inline long AllocationsOfAnEigenBuffer() {
  Eigen::VectorXd probe;
  const long n = CountAllocations([&] { probe.resize(64); });
  probe.setZero();
  return n;
}

}  // namespace touchdown::testing_alloc
