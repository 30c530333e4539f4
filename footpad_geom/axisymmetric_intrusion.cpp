#include "footpad_geom/axisymmetric_intrusion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace touchdown::geom {

namespace {
constexpr double kPi = std::numbers::pi;

// cos^k for k = 0..3, without pow.
double CosineWeight(double c, int k) { return k == 0 ? 1.0 : k == 1 ? c : k == 2 ? c * c : c * c * c; }

// Fraction T in [0, 1] of a piece (u0 -> u0 + du, du >= 0) that lies below depth d.
double SubmergedFraction(double u0, double du, double depth_m) {
  if (depth_m <= u0) return 0.0;
  if (du <= 0.0 || depth_m >= u0 + du) return 1.0;
  return (depth_m - u0) / du;
}
}  // namespace

AxisymmetricIntrusion::AxisymmetricIntrusion(const AxisymmetricProfile& profile,
                                             const rft::StressLaw2D& law)
    : radius_m_(profile.radius_m()), thickness_m_(profile.thickness_m()) {
  for (size_t i = 1; i < profile.points.size(); ++i) {
    const ProfilePoint& a = profile.points[i - 1];
    const ProfilePoint& b = profile.points[i];
    Piece p{a.x_m, a.u_m, b.x_m - a.x_m, b.u_m - a.u_m, 0.0, 0.0, 0.0};
    p.length = std::hypot(p.dx, p.du);
    p.cos_beta = p.dx / p.length;
    // Attack angle of the piece; for straight-down motion the law is even in beta.
    p.alpha_z = law.Alpha(std::atan2(p.du, p.dx), kPi / 2).z;
    pieces_.push_back(p);
  }
  // A wholly submerged piece contributes alpha 2 pi L [(d - u0)(x0 + dx/2) - du x0/2 - du dx/3].
  slope_sum_.assign(1, 0.0);
  offset_sum_.assign(1, 0.0);
  for (const Piece& p : pieces_) {
    const double w = p.alpha_z * 2 * kPi * p.length, mean_x = p.x0 + p.dx / 2;
    slope_sum_.push_back(slope_sum_.back() + w * mean_x);
    offset_sum_.push_back(offset_sum_.back() + w * (-p.u0 * mean_x - p.du * p.x0 / 2 - p.du * p.dx / 3));
    top_u_.push_back(p.u0 + p.du);
  }
  for (int k = 0; k < 4; ++k) {
    cos_sum_[k].assign(1, 0.0);
    for (const Piece& p : pieces_)
      cos_sum_[k].push_back(cos_sum_[k].back() + std::pow(p.cos_beta, k) * kPi * p.length * (2 * p.x0 + p.dx));
    SmoothJoints(profile, k);
  }
}

void AxisymmetricIntrusion::SmoothJoints(const AxisymmetricProfile& profile, int k) {
  // dI_k/dT at either end of a piece, T its submerged fraction: the ring's weighted circumference
  // times the piece length.
  auto slope = [&](const Piece& p, double t) {
    return CosineWeight(p.cos_beta, k) * 2 * kPi * p.length * (p.x0 + p.dx * t);
  };
  auto smooth = [&](size_t j) {  // profile point j joins pieces j - 1 and j without a corner
    return j > 0 && j < pieces_.size() && profile.points[j].smooth && pieces_[j - 1].du > 0.0 && pieces_[j].du > 0.0;
  };
  std::vector<Blend>& blend = blend_[k];
  blend.assign(pieces_.size(), Blend{});
  for (size_t j = 1; j < pieces_.size(); ++j) {
    if (!smooth(j)) continue;
    const Piece& below = pieces_[j - 1];
    const Piece& above = pieces_[j];
    // The curve's dI_k/dd at the joint: the mean of its two chords' (their angles bracket the curve's).
    const double joint = 0.5 * (slope(below, 1.0) / below.du + slope(above, 0.0) / above.du);
    blend[j - 1].hi = joint * below.du - slope(below, 1.0);
    blend[j].lo = joint * above.du - slope(above, 0.0);
    blend[j - 1].active = blend[j].active = true;
  }
  // The cubic's mean excess over the chord's quadratic on a piece is (lo - hi) / 12; it varies
  // slowly from piece to piece, so a bias linear across each piece between the joints' means of
  // it takes it away without a kink of the first order.
  auto excess = [&](size_t j) { return (blend[j].lo - blend[j].hi) / 12; };
  for (size_t j = 1; j < pieces_.size(); ++j) {
    if (!smooth(j)) continue;
    const double bias = 0.5 * (excess(j - 1) + excess(j));
    blend[j - 1].bias_hi = bias;
    blend[j].bias_lo = bias;
  }
}

double AxisymmetricIntrusion::VerticalForce(double depth_m, double zeta_N_m3) const {
  if (!(depth_m > 0.0)) return 0.0;
  // Pieces [0, k) lie wholly below the surface; piece k (if any) is cut by it; none after.
  const size_t k = std::upper_bound(top_u_.begin(), top_u_.end(), depth_m) - top_u_.begin();
  double sum = slope_sum_[k] * depth_m + offset_sum_[k];
  if (k < pieces_.size()) {
    const Piece& p = pieces_[k];
    const double T = SubmergedFraction(p.u0, p.du, depth_m);
    // integral_0^T (a + b t)(c + e t) dt with depth a + b t and radius c + e t
    const double a = depth_m - p.u0, b = -p.du, c = p.x0, e = p.dx;
    sum += p.alpha_z * 2 * kPi * p.length * (a * c * T + (a * e + b * c) * T * T / 2 + b * e * T * T * T / 3);
  }
  return zeta_N_m3 * sum;
}

double AxisymmetricIntrusion::SubmergedArea(double depth_m) const {
  double area = 0.0;
  for (const Piece& p : pieces_) {
    const double T = SubmergedFraction(p.u0, p.du, depth_m);
    if (T == 0.0) break;
    area += 2 * kPi * p.length * (p.x0 * T + p.dx * T * T / 2);
  }
  return area;
}

double AxisymmetricIntrusion::CosinePowerIntegral(double depth_m, int k) const {
  if (!(depth_m > 0.0)) return 0.0;
  const size_t n = std::upper_bound(top_u_.begin(), top_u_.end(), depth_m) - top_u_.begin();
  if (k < 0 || k > 3) {  // rare: a direct sum over the polyline
    double sum = 0.0;
    for (const Piece& p : pieces_) {
      const double T = SubmergedFraction(p.u0, p.du, depth_m);
      if (T == 0.0) break;
      sum += std::pow(p.cos_beta, k) * 2 * kPi * p.length * (p.x0 * T + p.dx * T * T / 2);
    }
    return sum;
  }
  double sum = cos_sum_[k][n];
  if (n < pieces_.size()) {
    const Piece& p = pieces_[n];
    const double T = SubmergedFraction(p.u0, p.du, depth_m);
    sum += CosineWeight(p.cos_beta, k) * 2 * kPi * p.length * (p.x0 * T + p.dx * T * T / 2);
    // Next to a smooth joint: the Hermite cubic through the same end values with the joints'
    // slopes, the chord's quadratic plus T (1 - T) [(1 - T) lo - T hi], less the bias.
    const Blend& b = blend_[k][n];
    if (b.active) sum += T * (1 - T) * ((1 - T) * b.lo - T * b.hi) - ((1 - T) * b.bias_lo + T * b.bias_hi);
  }
  return sum;
}

double AxisymmetricIntrusion::FootprintRadius(double depth_m) const {
  if (!(depth_m > 0.0)) return 0.0;
  const size_t k = std::upper_bound(top_u_.begin(), top_u_.end(), depth_m) - top_u_.begin();
  if (k >= pieces_.size()) return radius_m_;
  const Piece& p = pieces_[k];
  return p.x0 + p.dx * SubmergedFraction(p.u0, p.du, depth_m);
}

double AxisymmetricIntrusion::FootprintRadiusSlope(double depth_m) const {
  if (!(depth_m > 0.0)) return 0.0;
  const size_t k = std::upper_bound(top_u_.begin(), top_u_.end(), depth_m) - top_u_.begin();
  if (k >= pieces_.size()) return 0.0;
  const Piece& p = pieces_[k];
  return p.du > 0.0 ? p.dx / p.du : 0.0;
}

double AxisymmetricIntrusion::PowerLawVerticalForce(double depth_m, double zeta_N_m3, double exponent,
                                                    double z_ref_m) const {
  if (!(depth_m > 0.0)) return 0.0;
  const double p1 = exponent + 1, p2 = exponent + 2;
  double sum = 0.0;
  for (const Piece& p : pieces_) {
    const double T = SubmergedFraction(p.u0, p.du, depth_m);
    if (T == 0.0) break;
    const double w = p.alpha_z * 2 * kPi * p.length;
    const double z0 = depth_m - p.u0;  // depth of the piece's lower end (> 0)
    if (p.du == 0.0) {
      // Horizontal piece: constant depth, radius linear in t.
      sum += w * std::pow(z0, exponent) * (p.x0 * T + p.dx * T * T / 2);
      continue;
    }
    // Along the piece z = z0 - du t, x = x0 + dx t; with t = (z0 - z) / du:
    // integral_0^T z^p x dt = (1/du) integral_{z1}^{z0} z^p (x0 + dx (z0 - z) / du) dz.
    const double z1 = z0 - p.du * T;
    const double A = p.x0 + p.dx * z0 / p.du, B = -p.dx / p.du;
    auto primitive = [&](double z) {
      if (z <= 0.0) return 0.0;
      const double zp1 = std::pow(z, p1);
      return A * zp1 / p1 + B * zp1 * z / p2;
    };
    sum += w * (primitive(z0) - primitive(z1)) / p.du;
  }
  return zeta_N_m3 * std::pow(z_ref_m, 1.0 - exponent) * sum;
}

}  // namespace touchdown::geom
