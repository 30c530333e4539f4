// The pad-level terms in the 3D contact (rft/pad_level_terms.h): the depth law
// z_ref (z / z_ref)^p integrated exactly over clipped triangles (against polynomial closed forms,
// a brute-force fine quadrature, continuity through the surface and across the closed-form /
// quadrature switch, p = 1 bit-identical to the linear law), the compaction transient
// (k_c v^2 A exp(-z_pad / d_c) on a plate) and the footprint the entrained mass is built on.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "rft/contact_wrench.h"
#include "rft/deepest_point.h"
#include "rft/entrained_mass.h"
#include "rft/input_error.h"
#include "rft/li2013_3d.h"
#include "rft/pad_level_terms.h"
#include "rft/stress_law_3d_factory.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kZref = 0.01;

// A law with one constant stress per depth on every element, so the contact's force is
// sigma int w(d) dA and its moment (int w(d) r dA) x sigma exactly, whatever the velocity.
class ConstantLaw final : public StressLaw3D {
 public:
  explicit ConstantLaw(Eigen::Vector3d sigma) : sigma_(std::move(sigma)) {}
  std::string_view name() const override { return "constant"; }
  LawKind kind() const override { return LawKind::kLi2013; }  // an RFT stand-in: pad-level terms apply
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d&, const Eigen::Vector3d&) const override { return sigma_; }

 private:
  Eigen::Vector3d sigma_;
};

const Eigen::Vector3d kSigma(0.1e6, -0.2e6, 1.0e6);

// One triangle with vertex depths d (ground z = 0, depth = -z), facing down so that it leads a
// downward motion.
SurfaceElements Triangle(const Eigen::Vector3d& d, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  Eigen::Vector3d p[3];
  for (int k = 0; k < 3; ++k) p[k] = Eigen::Vector3d(x[k], y[k], -d[k]);
  if ((p[1] - p[0]).cross(p[2] - p[0]).z() > 0.0) std::swap(p[1], p[2]);
  testing::MeshBuilder m;
  m.Add(p[0], p[1], p[2]);
  return m.Build();
}

struct Moments {
  double integral = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};

// Brute force: the triangle cut into n^2 similar triangles, each integrated with the 3-point
// edge-midpoint rule (exact for quadratics) of z_ref^(1-p) max(d, 0)^p and of that times r.
Moments BruteForce(const SurfaceElements& s, double p, int n) {
  const Eigen::Vector3d a = s.p0_B.col(0), b = s.p1_B.col(0), c = s.p2_B.col(0);
  const double cell = s.area_m2(0) / (double(n) * n), scale = std::pow(kZref, 1.0 - p);
  Moments out;
  auto at = [&](double i, double j) { return a + (i / n) * (b - a) + (j / n) * (c - a); };
  auto add = [&](const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, const Eigen::Vector3d& q2) {
    for (const Eigen::Vector3d& q : {Eigen::Vector3d(0.5 * (q0 + q1)), Eigen::Vector3d(0.5 * (q1 + q2)),
                                     Eigen::Vector3d(0.5 * (q2 + q0))}) {
      const double w = scale * std::pow(std::max(-q.z(), 0.0), p) * cell / 3.0;
      out.integral += w;
      out.moment += w * q;
    }
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      add(at(i, j), at(i + 1, j), at(i, j + 1));
      if (i + j + 1 < n) add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return out;
}

PadLevelTerms DepthTerms(double p) {
  PadLevelTerms t;
  t.depth = {p, kZref};
  return t;
}

PadLevelTerms CompactionTerms(double k_c, double d_c) {
  PadLevelTerms t;
  t.compaction_k_kg_m3 = k_c;
  t.compaction_depth_m = d_c;
  return t;
}

ContactWrench Wrench(const SurfaceElements& s, double p, const Eigen::Vector3d& w = Eigen::Vector3d::Zero()) {
  const ConstantLaw law(kSigma);
  PadKinematics k;
  k.v_WB_W = Eigen::Vector3d(0.0, 0.0, -1.0);
  k.w_WB_W = w;
  return ComputeContactWrench(s, k, PlaneGround(), law, DepthTerms(p));
}

// int d^2 r dA over a submerged triangle from int l0^a l1^b l2^c dA = 2 A a! b! c! / (a+b+c+2)!.
TEST(RftDepthExponent, SquareLawMatchesThePolynomialClosedForm) {
  const SurfaceElements s = Triangle({0.004, 0.013, 0.021}, {0.0, 0.03, -0.01}, {0.0, 0.005, 0.025});
  const double A = s.area_m2(0);
  const Eigen::Vector3d d(0.004, 0.013, 0.021);
  Eigen::Vector3d q[3] = {s.p0_B.col(0), s.p1_B.col(0), s.p2_B.col(0)};
  double dv[3];
  for (int k = 0; k < 3; ++k) dv[k] = -q[k].z();
  auto fact = [](int n) { return n <= 1 ? 1.0 : (n == 2 ? 2.0 : (n == 3 ? 6.0 : 24.0)); };
  double integral = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int e2[3] = {0, 0, 0};
      ++e2[i], ++e2[j];
      integral += dv[i] * dv[j] * 2 * A * fact(e2[0]) * fact(e2[1]) * fact(e2[2]) / fact(4);
      for (int k = 0; k < 3; ++k) {
        int e3[3] = {e2[0], e2[1], e2[2]};
        ++e3[k];
        moment += dv[i] * dv[j] * 2 * A * fact(e3[0]) * fact(e3[1]) * fact(e3[2]) / 120.0 * q[k];
      }
    }
  integral /= kZref, moment /= kZref;  // z_ref^(1 - p), p = 2
  const ContactWrench w = Wrench(s, 2.0);
  EXPECT_NEAR(w.force_W.z(), integral * kSigma.z(), 1e-12 * integral * kSigma.z());
  EXPECT_TRUE(w.force_W.isApprox(integral * kSigma, 1e-12));
  EXPECT_TRUE(w.moment_W.isApprox(moment.cross(kSigma), 1e-12)) << w.moment_W.transpose() << " vs "
                                                                  << moment.cross(kSigma).transpose();
  (void)d;
}

// Against an independent reference: int z_ref^(1-p) max(d, 0)^p (1, r) dA over the triangle
// below (vertex depths as given, ground z = 0), computed with 25-digit adaptive quadrature in
// mpmath (the parametric double integral, split at the cut line; nothing shared with the contact).
TEST(RftDepthExponent, ClippedTrianglesMatchAnIndependentReference) {
  struct Ref {
    double p;
    Eigen::Vector3d depths;
    double integral;
    Eigen::Vector3d moment;
  };
  const Ref refs[] = {
      {0.2, {0.008, -0.004, -0.011}, 1.0943013017414182e-6, {5.3995130020135765e-9, 4.7395725239896949e-9, -3.2829039052242545e-9}},
      {0.2, {0.008, 0.003, -0.006}, 2.525000939231154e-6, {2.3268684377143973e-8, 1.7000068294399668e-8, -8.6127453399607792e-9}},
      {0.2, {0.004, 0.013, 0.021}, 5.2581184612219737e-6, {3.4682605282477775e-8, 5.4089255826685788e-8, -6.7668871639335847e-8}},
      {2.7, {0.008, -0.004, -0.011}, 9.5096871161069964e-8, {2.634262359032409e-10, 2.3122969595951146e-10, -4.938363835732756e-10}},
      {2.7, {0.008, 0.003, -0.006}, 2.6338249852786082e-7, {1.8569949704024321e-9, 1.0182263801682819e-9, -1.3811835856588538e-9}},
      {2.7, {0.004, 0.013, 0.021}, 1.1194914173361676e-5, {5.4224284386164932e-8, 1.5020204661328243e-7, -1.6692044142098739e-7}},
  };
  const Eigen::Vector3d x(0.0, 0.03, -0.01), y(0.0, 0.005, 0.025);
  for (const Ref& r : refs) {
    const SurfaceElements s = Triangle(r.depths, x, y);
    for (const Eigen::Vector3d& w : {Eigen::Vector3d::Zero().eval(), Eigen::Vector3d(3.0, -2.0, 1.0)}) {
      const ContactWrench c = Wrench(s, r.p, w);  // translating (run path) and rotating
      EXPECT_NEAR(c.force_W.z() / kSigma.z(), r.integral, 1e-13 * r.integral) << r.p << " " << r.depths.transpose();
      EXPECT_TRUE(c.force_W.isApprox(r.integral * kSigma, 1e-13));
      EXPECT_TRUE(c.moment_W.isApprox(r.moment.cross(kSigma), 1e-12))
          << r.p << " " << r.depths.transpose() << ": " << c.moment_W.transpose() << " vs "
          << r.moment.cross(kSigma).transpose();
    }
  }
}

// Over the admissible exponents and every branch (one, two, three vertices below; nearly level,
// the fans just inside and just outside the closed-form / quadrature switch), against a brute-force
// quadrature (the triangle cut into 512^2 cells, 3-point rule on max(d, 0)^p): it converges only as
// h^(1+p) near the cut line, so the tolerance is 5e-5 relative; the reference test above is exact.
TEST(RftDepthExponent, ClippedTrianglesMatchABruteForceQuadrature) {
  const Eigen::Vector3d x(0.0, 0.03, -0.01), y(0.0, 0.005, 0.025);
  const Eigen::Vector3d cases[] = {
      {0.008, -0.004, -0.011},        // one below
      {0.008, 0.003, -0.006},         // two below
      {0.004, 0.013, 0.021},          // all below
      {0.010, 0.0100001, 0.0099998},  // nearly level (quadrature branch)
      {0.010, 0.0124, 0.0126},        // fans just inside the switch (|D| <= 0.25 min)
      {0.010, 0.0126, 0.0131},        // and just outside
  };
  double worst = 0.0;
  for (const double p : {0.2, 0.55, 1.4, 2.7}) {
    for (const Eigen::Vector3d& d : cases) {
      const SurfaceElements s = Triangle(d, x, y);
      const ContactWrench w = Wrench(s, p);
      const Moments fine = BruteForce(s, p, 512);
      const double err = std::abs(w.force_W.z() / kSigma.z() / fine.integral - 1);
      const double err_m = (w.moment_W - fine.moment.cross(kSigma)).norm() / (fine.moment.cross(kSigma)).norm();
      worst = std::max({worst, err, err_m});
      EXPECT_LT(err, 5e-5) << "p " << p << " depths " << d.transpose();
      EXPECT_LT(err_m, 5e-5) << "p " << p << " depths " << d.transpose();
    }
  }
  std::printf("[ depth law ] largest relative difference from the brute force: %.2e\n", worst);
}

// Uniform depth: int = A z_ref^(1-p) d^p, the moment at the centroid; nearly uniform depths tend
// to it (no cancellation in the closed forms).
TEST(RftDepthExponent, NearlyLevelTrianglesTendToTheLevelValue) {
  const Eigen::Vector3d x(0.0, 0.03, -0.01), y(0.0, 0.005, 0.025);
  for (const double p : {0.3, 1.7}) {
    const SurfaceElements level = Triangle({0.01, 0.01, 0.01}, x, y);
    const double exact = level.area_m2(0) * std::pow(kZref, 1 - p) * std::pow(0.01, p);
    EXPECT_NEAR(Wrench(level, p).force_W.z(), exact * kSigma.z(), 1e-13 * exact * kSigma.z());
    for (const double eps : {1e-3, 1e-6, 1e-9, 1e-12}) {
      const SurfaceElements s = Triangle({0.01, 0.01 * (1 + eps), 0.01 * (1 + 2 * eps)}, x, y);
      const double got = Wrench(s, p).force_W.z() / kSigma.z();
      // The mean depth is 0.01 (1 + eps): the integral is A z_ref^(1-p) (0.01 (1 + eps))^p to O(eps^2)
      // (the depth's variance over the triangle is (0.01 eps)^2 / 6; A is this tilted triangle's).
      const double first_order = s.area_m2(0) * std::pow(kZref, 1 - p) * std::pow(0.01 * (1 + eps), p);
      EXPECT_NEAR(got, first_order, (p * std::abs(p - 1) * eps * eps + 1e-14) * exact) << p << " " << eps;
    }
  }
}

// A triangle sliding down through the surface: the force is continuous as each vertex crosses.
TEST(RftDepthExponent, ContinuousAsATriangleCrossesTheSurface) {
  const Eigen::Vector3d x(0.0, 0.03, -0.01), y(0.0, 0.005, 0.025), shape(0.0, 0.006, 0.015);
  for (const double p : {0.25, 1.6}) {
    for (const double crossing : {0.0, 0.006, 0.015}) {  // the offset at which a vertex meets the surface
      double f[2];
      int i = 0;
      for (const double h : {-1e-12, 1e-12}) {
        const Eigen::Vector3d d = Eigen::Vector3d::Constant(h - crossing) + shape;
        f[i++] = Wrench(Triangle(d, x, y), p).force_W.z();
      }
      const double scale = Wrench(Triangle(shape, x, y), p).force_W.z();
      EXPECT_LT(std::abs(f[1] - f[0]), 1e-8 * scale) << "p " << p << " crossing " << crossing;
    }
  }
}

// p = 1 takes the linear path: bit-identical to no pad-level terms, rotating or not.
TEST(RftDepthExponent, ExponentOneIsTheLinearLawBitForBit) {
  const SurfaceElements pad = testing::MakeRevolvedPad({{0.0, 0.0}, {0.04, 0.0}, {0.05, 0.008}, {0.05, 0.016}}, 48);
  const Li2013TreersLaw base(2.0e6);
  const PadLevelTerms same = DepthTerms(1.0);
  for (const Eigen::Vector3d& w : {Eigen::Vector3d::Zero().eval(), Eigen::Vector3d(0.5, -1.0, 0.2)}) {
    PadKinematics k;
    k.R_WB = testing::RotX(0.2) * testing::RotY(-0.1);
    k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.012);
    k.v_WB_W = Eigen::Vector3d(0.3, 0.1, -1.1);
    k.w_WB_W = w;
    const ContactWrench a = ComputeContactWrench(pad, k, PlaneGround(), base);
    const ContactWrench b = ComputeContactWrench(pad, k, PlaneGround(), base, same);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(a.force_W[i], b.force_W[i]);
      EXPECT_EQ(a.moment_W[i], b.moment_W[i]);
    }
  }
}

// A rotating pad's leading boundary clips its elements under the z^p depth law as under the linear
// one (contact_internal.h LeadingPartOf): with p a hair from 1 the power path (its own closed forms,
// its own clip) lands on the linear path's wrench to the size of the hair. Without the clip the
// elements the boundary crosses were taken whole or not at all.
TEST(RftDepthExponent, RotatingPadIsClippedAtItsLeadingBoundaryAsTheLinearLaw) {
  const SurfaceElements pad = testing::MakeRevolvedPad({{0.0, 0.0}, {0.04, 0.0}, {0.05, 0.008}, {0.05, 0.016}}, 48);
  const Li2013TreersLaw base(2.0e6);
  for (const double hair : {1e-9, -1e-9}) {
    PadKinematics k;
    k.R_WB = testing::RotX(0.2) * testing::RotY(-0.1);
    k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.012);
    k.v_WB_W = Eigen::Vector3d(0.3, 0.1, -0.2);
    k.w_WB_W = Eigen::Vector3d(4.0, -6.0, 1.0);  // the leading boundary crosses the pad
    PadLevelTerms power = DepthTerms(1.0 + hair);
    power.depth.reference_m = 1.0;  // z_ref^(1 - p) = 1: only the exponent differs
    const ContactWrench linear = ComputeContactWrench(pad, k, PlaneGround(), base);
    const ContactWrench clipped = ComputeContactWrench(pad, k, PlaneGround(), base, power);
    EXPECT_EQ(clipped.leading_elements, linear.leading_elements);
    // |ln z| <= 4 over these depths: the hair moves the wrench by < 1e-8 of it.
    EXPECT_LT((clipped.force_W - linear.force_W).norm(), 1e-8 * linear.force_W.norm()) << hair;
    EXPECT_LT((clipped.moment_W - linear.moment_W).norm(), 1e-8 * linear.moment_W.norm()) << hair;
  }
}

// A level flat disc pushed straight down: zeta z_ref^(1-p) A d^p on the bottom, plus the side
// wall alpha_z(pi/2, pi/2) zeta z_ref^(1-p) P d^(p+1) / (p+1) - the rig's closed form.
TEST(RftDepthExponent, LevelFlatPadIsTheRigsPowerLaw) {
  const double r = 0.05, zeta = 2.0e6, d = 0.008;
  const int sectors = 256;
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(r, 0.016), sectors);
  const double area = 0.5 * sectors * r * r * std::sin(2 * std::numbers::pi / sectors), perimeter = 2 * sectors * r * std::sin(std::numbers::pi / sectors);
  for (const double p : {0.6, 1.5}) {
    const Li2013TreersLaw law(zeta);
    PadKinematics k;
    k.p_WB = Eigen::Vector3d(0.0, 0.0, -d);
    k.v_WB_W = Eigen::Vector3d(0.0, 0.0, -1.0);
    const double s = std::pow(kZref, 1 - p);
    const Eigen::Vector3d n_wall(1.0, 0.0, 0.0);
    const double wall = law.StressPerDepth(n_wall, k.v_WB_W).z();  // alpha_z(pi/2, pi/2) zeta (Treers weights)
    const double bottom = law.StressPerDepth(Eigen::Vector3d(0.0, 0.0, -1.0), k.v_WB_W).z();  // zeta
    EXPECT_NEAR(bottom, zeta, 1e-9 * zeta);
    const double expected = bottom * s * area * std::pow(d, p) + wall * s * perimeter * std::pow(d, p + 1) / (p + 1);
    EXPECT_NEAR(ComputeContactWrench(pad, k, PlaneGround(), law, DepthTerms(p)).force_W.z(), expected,
                1e-10 * expected)
        << p;
  }
}

// compaction_peak on a horizontal plate moving down: k_c v^2 A exp(-z_pad / d_c) more upward force,
// z_pad the deepest vertex; tilted, the decay follows rft/deepest_point.h.
TEST(RftCompactionPeak, PlateGetsKcV2AExpOfThePadDepth) {
  constexpr double L = 0.04, kc = 3.0e4, dc = 0.003, zeta = 2.0e6;
  const SurfaceElements plate = testing::MakeBox(Eigen::Vector3d(-L / 2, -L / 2, 0.0), Eigen::Vector3d(L / 2, L / 2, 1e-3), 2);
  const Li2013TreersLaw law(zeta);
  const PadLevelTerms terms = CompactionTerms(kc, dc);
  const Eigen::Vector3d down(0, 0, -1), n = Eigen::Vector3d(0.2, 0.1, -0.9).normalized(), v(0.3, 0.0, -1.5);
  EXPECT_TRUE(terms.CompactionStress(n, v).isApprox(-kc * n.dot(v) * n.dot(v) * n, 1e-14));
  EXPECT_EQ(terms.CompactionStress(-n, v), Eigen::Vector3d::Zero());
  for (const double speed : {0.5, 1.3})
    for (const double depth : {0.001, 0.006}) {
      PadKinematics k;
      k.p_WB = Eigen::Vector3d(0.1, 0.0, -depth);
      k.v_WB_W = speed * down;
      const ContactWrench with = ComputeContactWrench(plate, k, PlaneGround(), law, terms);
      const ContactWrench without = ComputeContactWrench(plate, k, PlaneGround(), law);
      const double expected = kc * speed * speed * L * L * std::exp(-depth / dc);
      EXPECT_NEAR(with.force_W.z() - without.force_W.z(), expected, 1e-9 * expected);
      EXPECT_NEAR(with.penetration_m, depth, 1e-15);
      EXPECT_LT((with.moment_W - without.moment_W).norm(), 1e-9 * expected * L);
    }
  // Tilted: the decay uses the deepest vertex.
  PadKinematics k;
  k.R_WB = testing::RotX(0.15);
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.002);
  k.v_WB_W = 0.9 * down;
  Eigen::Matrix3Xd vertices(3, 3 * plate.size());
  vertices << plate.p0_B, plate.p1_B, plate.p2_B;
  const double z_pad = DeepestVertexDepth(vertices, k.R_WB, k.p_WB, PlaneGround());
  EXPECT_NEAR(ComputeContactWrench(plate, k, PlaneGround(), law, terms).penetration_m, z_pad, 1e-15);
  // Doubling d_c: the transient part scales by exp(-z/(2 d_c)) / exp(-z/d_c).
  const double base = ComputeContactWrench(plate, k, PlaneGround(), law).force_W.z();
  const double a = ComputeContactWrench(plate, k, PlaneGround(), law, terms).force_W.z() - base;
  const double b = ComputeContactWrench(plate, k, PlaneGround(), law, CompactionTerms(kc, 2 * dc)).force_W.z() - base;
  EXPECT_NEAR(b / a, std::exp(-z_pad / (2 * dc)) / std::exp(-z_pad / dc), 1e-9);
}

// The footprint of a level revolved pad is the projected area of its submerged bottom (pi a^2 on
// the polygon); its rate and the penetration rate match finite differences in time along the
// motion, translating straight down (the rig's dA/dd v) and tilted, sliding and spinning.
TEST(RftAddedMass, FootprintAndItsRateOnARevolvedPad) {
  const int sectors = 128;
  // A chamfered pad: flat to x = 0.04, 45-degree chamfer to (0.05, 0.01), wall to 0.016.
  const SurfaceElements pad = testing::MakeRevolvedPad({{0.0, 0.0}, {0.04, 0.0}, {0.05, 0.01}, {0.05, 0.016}}, sectors);
  const Li2013TreersLaw law(2.0e6);
  PadLevelTerms terms;
  terms.added_mass_density_kg_m3 = 800.0;
  const double poly = 0.5 * sectors * std::sin(2 * std::numbers::pi / sectors);  // polygon area / radius^2
  auto advanced = [](PadKinematics k, double dt) {  // the pose dt later (rigid motion)
    k.p_WB += dt * k.v_WB_W;
    const double angle = k.w_WB_W.norm() * dt;
    if (angle != 0.0) k.R_WB = Eigen::AngleAxisd(angle, k.w_WB_W.normalized()).toRotationMatrix() * k.R_WB;
    return k;
  };
  for (const double d : {0.003, 0.007, 0.012}) {
    PadKinematics k;
    k.p_WB = Eigen::Vector3d(0.0, 0.0, -d);
    k.v_WB_W = Eigen::Vector3d(0.0, 0.0, -0.8);
    const ContactWrench w = ComputeContactWrench(pad, k, PlaneGround(), law, terms);
    const double a = 0.04 + std::min(d, 0.01);  // footprint radius at the surface
    EXPECT_NEAR(w.footprint_area_m2, poly * a * a, 1e-12) << d;
    EXPECT_NEAR(w.footprint_area_rate_m2_s, d < 0.01 ? 0.8 * poly * 2 * a : 0.0, 1e-9) << d;
    EXPECT_NEAR(w.penetration_rate_m_s, 0.8, 1e-15);
    // Without added mass they stay at 0 (not computed).
    EXPECT_EQ(ComputeContactWrench(pad, k, PlaneGround(), law).footprint_area_m2, 0.0);
  }
  for (const double d : {0.004, 0.009}) {
    PadKinematics k;
    k.R_WB = testing::RotX(0.12) * testing::RotY(-0.05);
    k.p_WB = Eigen::Vector3d(0.0, 0.0, -d);
    k.v_WB_W = Eigen::Vector3d(0.3, -0.1, -0.8);
    k.w_WB_W = Eigen::Vector3d(1.5, -0.7, 0.4);
    const ContactWrench w = ComputeContactWrench(pad, k, PlaneGround(), law, terms);
    const double h = 1e-7;
    const ContactWrench up = ComputeContactWrench(pad, advanced(k, h), PlaneGround(), law, terms);
    const ContactWrench dn = ComputeContactWrench(pad, advanced(k, -h), PlaneGround(), law, terms);
    const double fd_area = (up.footprint_area_m2 - dn.footprint_area_m2) / (2 * h);
    const double fd_depth = (up.penetration_m - dn.penetration_m) / (2 * h);
    std::printf("[ footprint ] tilted, spinning, d %.3f m: dA/dt %.9e (finite difference %.9e), dd/dt %.9f (%.9f)\n",
                d, w.footprint_area_rate_m2_s, fd_area, w.penetration_rate_m_s, fd_depth);
    EXPECT_NEAR(w.footprint_area_rate_m2_s, fd_area, 1e-5 * std::abs(fd_area) + 1e-9) << d;
    EXPECT_NEAR(w.penetration_rate_m_s, fd_depth, 1e-6) << d;
  }
  // The cone: (c_a rho / 3) A min(d, a), growing continuously from 0.
  const double A = std::numbers::pi * 0.04 * 0.04;
  const EntrainedMass e = EntrainedCone(800.0, 0.002, 0.5, A, 0.0);
  EXPECT_NEAR(e.mass_kg, 800.0 / 3 * A * 0.002, 1e-15);
  EXPECT_NEAR(e.rate_kg_s, 800.0 / 3 * A * 0.5, 1e-12);
  const EntrainedMass whole = EntrainedCone(800.0, 0.05, 0.5, A, 0.0);
  EXPECT_NEAR(whole.mass_kg, 800.0 * std::numbers::pi / 3 * std::pow(0.04, 3), 1e-15);
  EXPECT_EQ(whole.rate_kg_s, 0.0);
  EXPECT_EQ(EntrainedCone(800.0, 0.0, 1.0, 1.0, 1.0).mass_kg, 0.0);
}

TEST(RftPadEffectTerms, FactorySetsThemOnlyWhenTheyAct) {
  SoilParameters soil;
  soil.name = "test";
  soil.zeta_N_m3 = 2.0e6;
  soil.bulk_density_kg_m3 = 1600.0;
  EffectTerms t;
  t.depth_exponent = 1.0;
  t.compaction_k_kg_m3 = 0.0;
  t.compaction_depth_m = 0.002;
  t.added_mass_ca = 0.0;
  const SoilContactModel neutral = MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t);
  EXPECT_EQ(neutral.name(), "li2013");
  EXPECT_EQ(neutral.pad_terms.depth.exponent, 1.0);
  EXPECT_EQ(neutral.pad_terms.compaction_k_kg_m3, 0.0);
  EXPECT_EQ(neutral.pad_terms.compaction_depth_m, 1.0);  // the neutral value, not the unused d_c
  EXPECT_EQ(neutral.pad_terms.added_mass_density_kg_m3, 0.0);
  t.depth_exponent = 1.3;
  t.compaction_k_kg_m3 = 1e4;
  t.added_mass_ca = 0.5;
  const SoilContactModel model = MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t);
  EXPECT_EQ(model.name(), "li2013+depth_exponent+compaction_peak+added_mass");
  EXPECT_EQ(model.law->name(), "li2013");
  EXPECT_EQ(model.pad_terms.depth.exponent, 1.3);
  EXPECT_EQ(model.pad_terms.depth.reference_m, 0.01);
  EXPECT_EQ(model.pad_terms.compaction_k_kg_m3, 1e4);
  EXPECT_EQ(model.pad_terms.compaction_depth_m, 0.002);
  EXPECT_EQ(model.pad_terms.added_mass_density_kg_m3, 0.5 * 1600.0);
  // The per-element terms wrap the law; the pad-level terms stay beside it.
  t.damping_c_N_s_m3 = 100.0;
  t.gas_chi = 0.1;
  t.inertial_lambda = 1.0;
  const SoilContactModel all = MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t);
  EXPECT_EQ(all.name(), "li2013+dynamic+gas_cushion+rate_damping+depth_exponent+compaction_peak+added_mass");
  EXPECT_EQ(all.pad_terms.added_mass_density_kg_m3, 800.0);
  t.compaction_depth_m = 0.0;
  EXPECT_THROW(MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t), InputError);
  t.compaction_depth_m = 0.002;
  soil.bulk_density_kg_m3 = 0.0;
  t.inertial_lambda = 0.0;
  EXPECT_THROW(MakeSoilContactModel(LawKind::kLi2013, soil, 9.81, t), InputError);
}

// All three pad-level terms at once on a level flat disc pushed straight down: the power-law
// force of the rig (see LevelFlatPadIsTheRigsPowerLaw) plus the compaction transient
// k_c v^2 A exp(-d / d_c) on the bottom (the wall slides: v.n = 0); the added mass changes only
// the footprint bookkeeping, never the force.
TEST(RftPadEffectTerms, TogetherTheyAddTheirClosedForms) {
  const double r = 0.05, zeta = 2.0e6, d = 0.006, p = 1.4, kc = 2.0e4, dc = 0.004, v = 1.2;
  const int sectors = 256;
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(r, 0.016), sectors);
  const double area = 0.5 * sectors * r * r * std::sin(2 * std::numbers::pi / sectors),
               perimeter = 2 * sectors * r * std::sin(std::numbers::pi / sectors);
  const Li2013TreersLaw law(zeta);
  PadLevelTerms terms = CompactionTerms(kc, dc);
  terms.depth = {p, kZref};
  terms.added_mass_density_kg_m3 = 900.0;
  PadKinematics k;
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -d);
  k.v_WB_W = Eigen::Vector3d(0.0, 0.0, -v);
  const double wall = law.StressPerDepth(Eigen::Vector3d(1.0, 0.0, 0.0), k.v_WB_W).z();
  const double s = std::pow(kZref, 1 - p);
  const double expected = zeta * s * area * std::pow(d, p) + wall * s * perimeter * std::pow(d, p + 1) / (p + 1) +
                          kc * v * v * area * std::exp(-d / dc);
  const ContactWrench w = ComputeContactWrench(pad, k, PlaneGround(), law, terms);
  EXPECT_NEAR(w.force_W.z(), expected, 1e-10 * expected);
  EXPECT_NEAR(w.penetration_m, d, 1e-15);
  EXPECT_NEAR(w.footprint_area_m2, area, 1e-12);
  PadLevelTerms no_mass = terms;
  no_mass.added_mass_density_kg_m3 = 0.0;
  EXPECT_EQ(ComputeContactWrench(pad, k, PlaneGround(), law, no_mass).force_W, w.force_W);
}

}  // namespace
}  // namespace touchdown::rft
