#include "drop_tests/scenario/lander_vtk.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>

#include "drop_tests/formats/vtk_pieces.h"
#include "drop_tests/formats/vtk_series.h"
#include "drop_tests/scenario/lander_leg_load.h"
#include "rft/element_stresses.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace {
using lander::kNumLegs;

Eigen::Matrix3d Rotation(const Eigen::Vector4d& q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix(); }

// The soil stresses on pad i at sample s. A free pad: RFT under the soil at its joint, with the
// lander's low-speed ramp (LanderModel::soil_ramp_speed_m_s and soil_ramp, as FreePadSoilWrench
// applies it: on each element, or on the whole pad). A held
// pad carries a constraint force, not an RFT stress: its elements show 0 (its `held` and
// `pad_force_N` fields say so).
void PadStresses(const LanderRun& run, const lander::LanderSample& s, int i, rft::ElementStresses* out) {
  const lander::Leg& leg = run.setup.model.legs[i];
  const rft::Terrain& terrain = run.setup.terrain;
  const rft::SoilContactModel& contact = terrain.soils[terrain.SoilAt(s.p_WJ[i].x(), s.p_WJ[i].y())].contact;
  rft::PadKinematics k{Rotation(s.q_WP[i]), s.p_WJ[i], s.v_WJ_W[i], s.w_WP_W[i]};
  if (contact.has_janosi_shear()) k.shear_mobilisation = contact.ShearMobilisation(s.shear_displacement_m[i]);
  const lander::LanderModel& model = run.setup.model;
  const bool per_element = model.soil_ramp == lander::SoilRamp::kElement;
  if (per_element) k.element_ramp_speed_m_s = model.soil_ramp_speed_m_s;
  rft::ComputeElementStresses(leg.pad->surface, k, *terrain.surface, *contact.law, contact.pad_terms.depth, out);
  const double radius = leg.pad->vertices_B.colwise().norm().maxCoeff();
  const double speed = s.v_WJ_W[i].norm() + s.w_WP_W[i].norm() * radius;
  const double pad_ramp = per_element ? 1.0 : std::min(speed / model.soil_ramp_speed_m_s, 1.0);
  const double scale = s.pad_held[i] ? 0.0 : pad_ramp;
  if (scale == 1.0) return;
  out->force_W *= scale;
  out->normal_Pa *= scale;
  out->shear_Pa *= scale;
}

io::VtkPolyData PadPiece(const LanderRun& run, const io::PadSurfaceMesh& mesh, const lander::LanderSample& s, int i,
                         rft::ElementStresses* stresses) {
  PadStresses(run, s, i, stresses);
  io::VtkPolyData piece = io::PadSurfacePiece(mesh, Rotation(s.q_WP[i]), s.p_WJ[i], *stresses);
  const size_t n = mesh.triangles.size();
  piece.AddCellField("pad_number", std::vector<double>(n, i + 1));
  piece.AddCellField("held", std::vector<double>(n, s.pad_held[i]));
  piece.AddCellField("pad_force_N", std::vector<double>(n, s.pad_force_W[i].norm()));
  return piece;
}

Eigen::Vector3d HipW(const LanderRun& run, const lander::LanderSample& s, int i) {
  return s.p_WB + Rotation(s.q_WB) * run.setup.model.legs[i].hip_B;
}

// The body: the polygon of the four hips (pads are numbered clockwise seen from above, so listed
// backwards it faces up).
io::VtkPolyData BodyPiece(const LanderRun& run, const lander::LanderSample& s) {
  io::VtkPolyData piece;
  for (int i = kNumLegs - 1; i >= 0; --i) piece.points.push_back(HipW(run, s, i));
  piece.polygons.push_back({0, 1, 2, 3});
  return piece;
}

// The legs with their axial load (lander_leg_load.h: the absorber's force, or on a rigid leg the
// pad's soil force along it), as the load plot and the studies' peak leg load take it.
io::VtkPolyData LegsPiece(const LanderRun& run, const lander::LanderSample& s) {
  io::VtkPolyData piece;
  std::vector<double> number, force, stroke;
  for (int i = 0; i < kNumLegs; ++i) {
    piece.points.push_back(HipW(run, s, i));
    piece.points.push_back(s.p_WJ[i]);
    piece.lines.push_back({2 * i, 2 * i + 1});
    number.push_back(i + 1);
    force.push_back(LegAxialForce(run.scenario.lander, s, i));
    stroke.push_back(s.stroke_m[i]);
  }
  piece.AddCellField("leg_number", std::move(number));
  piece.AddCellField("leg_force_N", std::move(force));
  piece.AddCellField("stroke_m", std::move(stroke));
  return piece;
}

// The soil: a square around the joints' paths, a lander's half span beyond them on every side.
io::VtkPolyData SoilPiece(const LanderRun& run) {
  const std::vector<lander::LanderSample>& trace = run.result.trace;
  Eigen::Vector2d lo = trace.front().p_WJ[0].head<2>(), hi = lo;
  for (const lander::LanderSample& s : trace)
    for (int i = 0; i < kNumLegs; ++i) {
      lo = lo.cwiseMin(s.p_WJ[i].head<2>());
      hi = hi.cwiseMax(s.p_WJ[i].head<2>());
    }
  const double half_width = 0.5 * (hi - lo).maxCoeff() * 1.5;
  const rft::Terrain& terrain = run.setup.terrain;
  return io::SoilSurfacePiece(*terrain.surface, 0.5 * (lo + hi), half_width, 40,
                              [&terrain](double x, double y) { return terrain.SoilAt(x, y); });
}
double PadRadius(const LanderRun& run, int i) {
  return run.setup.model.legs[i].pad->vertices_B.colwise().norm().maxCoeff();  // from the joint centre
}

// A crater grid per pad over its joint's path in the soil, a pad radius (from the joint: it bounds the
// pad's footprint at any attitude) and two grid steps beyond it. A pad that never touches gets a
// flat one where it ends.
std::vector<io::CraterSurface> Craters(const LanderRun& run) {
  const std::vector<lander::LanderSample>& trace = run.result.trace;
  std::vector<io::CraterSurface> craters;
  for (int i = 0; i < kNumLegs; ++i) {
    Eigen::Vector2d lo = trace.back().p_WJ[i].head<2>(), hi = lo;
    for (const lander::LanderSample& s : trace)
      if (s.pad_depth_m[i] > 0.0) {
        lo = lo.cwiseMin(s.p_WJ[i].head<2>());
        hi = hi.cwiseMax(s.p_WJ[i].head<2>());
      }
    const int step_mm = io::CraterSurface::StepFor(PadRadius(run, i));
    const double margin = PadRadius(run, i) + 2.0 * step_mm / units::kMmPerM;
    craters.emplace_back(*run.setup.terrain.surface, lo.array() - margin, hi.array() + margin, step_mm);
  }
  return craters;
}

// Which samples become frames (lander_vtk.h): the stroke whole, the fall thinned, the rest once.
bool IsFrame(const LanderRun& run, const lander::LanderSample& s, double next_frame_s) {
  const std::optional<double>& rest = run.result.rest_time_s;
  if (rest && s.t_s > *rest) return false;
  for (int i = 0; i < kNumLegs; ++i)
    if (s.pad_depth_m[i] > 0.0 && !s.pad_held[i]) return true;
  return s.t_s >= next_frame_s - 1e-9;  // 1e-9 s: sample times are multiples of the period up to rounding
}
}  // namespace

void WriteLanderVtk(const LanderRun& run, const std::string& directory) {
  const std::vector<lander::LanderSample>& trace = run.result.trace;
  if (trace.empty()) return;
  std::filesystem::create_directories(directory);
  std::array<io::PadSurfaceMesh, kNumLegs> meshes;
  for (int i = 0; i < kNumLegs; ++i) meshes[i] = io::MakePadSurfaceMesh(run.setup.model.legs[i].pad->surface);
  io::VtkSeries series(directory, "lander");
  rft::ElementStresses stresses;
  std::vector<io::CraterSurface> craters = Craters(run);
  double next_frame_s = trace.front().t_s;
  for (size_t n = 0; n < trace.size(); ++n) {
    const lander::LanderSample& s = trace[n];
    if (!IsFrame(run, s, next_frame_s) && n + 1 != trace.size()) continue;
    next_frame_s = s.t_s + kLanderVtkFrameInterval_s;
    std::vector<io::VtkPolyData> pads;
    for (int i = 0; i < kNumLegs; ++i) pads.push_back(PadPiece(run, meshes[i], s, i, &stresses));
    series.AddFrame(s.t_s, "pads", pads);
    series.AddFrame(s.t_s, "body", {BodyPiece(run, s)});
    series.AddFrame(s.t_s, "legs", {LegsPiece(run, s)});
    // Pressed at the frames: every sample of a pad moving in the soil is one, and a held pad stays.
    for (int i = 0; i < kNumLegs; ++i)
      if (s.pad_depth_m[i] > 0.0) craters[i].Press(meshes[i], Rotation(s.q_WP[i]), s.p_WJ[i]);
    std::vector<io::VtkPolyData> crater_pieces;
    for (const io::CraterSurface& c : craters) crater_pieces.push_back(c.Piece());
    series.AddFrame(s.t_s, "crater", crater_pieces);
  }
  series.AddStaticPart("soil", {SoilPiece(run)});
  series.Finish();
}

}  // namespace touchdown::scenario
