#pragma once
// The free surface of the granular bed, z up. Depth below the surface is measured vertically:
// depth(p) = Height(p.x, p.y) - p.z, the lithostatic depth RFT scales with. For a plane (level or
// uniformly sloped) the depth is linear in position, so clipping a triangle against the surface
// by its vertex depths is exact. A height field (rft/height_field_ground.h) uses the same
// interface; clipping by vertex depths is then a linear approximation within each triangle.
#include <Eigen/Core>

namespace touchdown::rft {

class PlaneGround;

class GroundSurface {
 public:
  virtual ~GroundSurface() = default;
  virtual double Height(double x_m, double y_m) const = 0;
  // The plane this surface is everywhere, or nullptr. The contact sums take a plane's exact,
  // faster path through it (depths linear in the pad frame, blocks above the plane culled), so
  // any surface that is a plane answers here, not only PlaneGround.
  virtual const PlaneGround* ExactPlane() const { return nullptr; }
  double Depth(const Eigen::Vector3d& p_W) const { return Height(p_W.x(), p_W.y()) - p_W.z(); }
};

// z = height_at_origin + slope_x * x + slope_y * y. Level ground when both slopes are 0.
class PlaneGround final : public GroundSurface {
 public:
  explicit PlaneGround(double height_at_origin_m = 0.0, double slope_x = 0.0, double slope_y = 0.0)
      : h0_(height_at_origin_m), sx_(slope_x), sy_(slope_y) {}
  double Height(double x_m, double y_m) const override { return h0_ + sx_ * x_m + sy_ * y_m; }
  const PlaneGround* ExactPlane() const override { return this; }
  // The plane's coefficients (ComputeContactWrench uses them to get depths in the pad frame).
  double height_at_origin_m() const { return h0_; }
  double slope_x() const { return sx_; }
  double slope_y() const { return sy_; }

 private:
  double h0_, sx_, sy_;
};

}  // namespace touchdown::rft
