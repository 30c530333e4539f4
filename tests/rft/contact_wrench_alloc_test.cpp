// ComputeContactWrench allocates nothing (house style: no allocation in the hot loop). The
// global operator new of this test binary counts allocations while a flag is set.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "rft/contact_wrench.h"
#include "rft/dynamic_term.h"
#include "rft/height_field_ground.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

// The replacements below pair operator new with malloc and operator delete with free; once
// inlined, GCC 12 reports that pairing as a mismatch although it is the standard replacement.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (counting.load()) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace touchdown::rft {
namespace {

TEST(RftContactWrench, DoesNotAllocate) {
  {  // the counter works
    allocations = 0;
    counting = true;
    auto* probe = new std::vector<int>(16);
    counting = false;
    delete probe;
    ASSERT_GE(allocations.load(), 2);
  }
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 3), 64);
  const DynamicTermLaw law(std::make_unique<Li2013TreersLaw>(3e6), 1.0, 1500.0);
  const PlaneGround plane(0.0, 0.02, 0.0);
  class Bumpy final : public GroundSurface {
    double Height(double x, double y) const override { return 0.002 * x * y; }
  } bumpy;
  HeightGrid grid{.x0_m = -0.2, .y0_m = -0.2, .cell_m = 0.04, .nx = 11, .ny = 11, .heights_m = {}};
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) grid.heights_m.push_back(0.001 * ((i * 7 + j * 3) % 5));
  const HeightFieldGround field(grid);
  PadKinematics k;
  k.R_WB = testing::RotX(0.2);
  k.p_WB = Eigen::Vector3d(0, 0, -0.008);
  k.v_WB_W = Eigen::Vector3d(0.3, 0.1, -1.0);
  for (const GroundSurface* ground :
       {static_cast<const GroundSurface*>(&plane), static_cast<const GroundSurface*>(&bumpy),
        static_cast<const GroundSurface*>(&field)})
    for (double spin : {0.0, 2.0}) {
      k.w_WB_W = Eigen::Vector3d(0, 0, spin);
      allocations = 0;
      counting = true;
      const ContactWrench w = ComputeContactWrench(pad, k, *ground, law);
      counting = false;
      EXPECT_EQ(allocations.load(), 0) << "spin " << spin;
      EXPECT_GT(w.force_W.z(), 0.0);
    }
}

}  // namespace
}  // namespace touchdown::rft
