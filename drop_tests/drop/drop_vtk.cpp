#include "drop_tests/drop/drop_vtk.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>
#include <variant>

#include "drop_tests/formats/vtk_pieces.h"
#include "drop_tests/formats/vtk_series.h"
#include "rft/bekker_law.h"
#include "rft/element_stresses.h"
#include "rft/units.h"

namespace touchdown::drop {

namespace {
// The soil square: around the pad's path, two pad radii beyond it on every side.
io::VtkPolyData SoilPiece(const pad::FreeDropResult& r, const io::PadSurfaceMesh& mesh) {
  const double radius = mesh.points_B.colwise().norm().maxCoeff();
  Eigen::Vector2d lo = r.trace.front().p_WB.head<2>(), hi = lo;
  for (const pad::FreeDropSample& s : r.trace) {
    lo = lo.cwiseMin(s.p_WB.head<2>());
    hi = hi.cwiseMax(s.p_WB.head<2>());
  }
  const double half_width = 0.5 * (hi - lo).maxCoeff() + 2.0 * radius;
  return io::SoilSurfacePiece(rft::PlaneGround(), 0.5 * (lo + hi), half_width, 20, [](double, double) { return 0; });
}

// The crater grid: over the pad's path, a pad radius (from its reference point) and two grid steps
// beyond it.
io::CraterSurface Crater(const pad::FreeDropResult& r, const io::PadSurfaceMesh& mesh, const rft::GroundSurface& ground) {
  const double radius = mesh.points_B.colwise().norm().maxCoeff();
  Eigen::Vector2d lo = r.trace.front().p_WB.head<2>(), hi = lo;
  for (const pad::FreeDropSample& s : r.trace) {
    lo = lo.cwiseMin(s.p_WB.head<2>());
    hi = hi.cwiseMax(s.p_WB.head<2>());
  }
  const int step_mm = io::CraterSurface::StepFor(radius);
  const double margin = radius + 2.0 * step_mm / units::kMmPerM;
  return io::CraterSurface(ground, lo.array() - margin, hi.array() + margin, step_mm);
}
}  // namespace

void CheckDropVtkTarget(const io::OutputTarget& dir) { io::CheckOutputDirectory(dir, io::OutputKind::kDropVtk); }

void WriteDropVtk(const DropSetup& setup, const PadDrop& drop, const io::OutputTarget& dir) {
  const auto* free = std::get_if<pad::FreeDropSetup>(&setup.run);
  if (!free || !drop.free) throw std::logic_error("WriteDropVtk: not a free drop");
  const pad::FreeDropResult& r = *drop.free;
  const geom::PadBody& body = *free->body;
  const rft::SoilContactModel& contact = free->terrain.soils.front().contact;  // a uniform bed
  const rft::GroundSurface& ground = *free->terrain.surface;
  const io::PadSurfaceMesh mesh = io::MakePadSurfaceMesh(body.surface);
  io::WriteOutputDirectory(dir, io::OutputKind::kDropVtk, [&](const std::string& staging) {
    io::VtkSeries series(staging, "drop");
    rft::ElementStresses stresses;
    io::CraterSurface crater = Crater(r, mesh, ground);
    for (const pad::FreeDropSample& s : r.trace) {
      const Eigen::Matrix3d R_WB = Eigen::Quaterniond(s.q_WB[0], s.q_WB[1], s.q_WB[2], s.q_WB[3]).toRotationMatrix();
      rft::PadKinematics k{R_WB, s.p_WB, s.v_WB_W, s.w_W};
      if (contact.has_janosi_shear()) k.shear_mobilisation = contact.ShearMobilisation(s.shear_displacement_m);
      rft::ComputeElementStresses(body.surface, k, ground, *contact.law, contact.pad_terms.depth, &stresses);
      series.AddFrame(s.t_s, "pad", {io::PadSurfacePiece(mesh, R_WB, s.p_WB, stresses)});
      crater.Press(mesh, R_WB, s.p_WB);
      series.AddFrame(s.t_s, "crater", {crater.Piece()});
    }
    series.AddStaticPart("soil", {SoilPiece(r, mesh)});
    series.Finish();
  });
}

}  // namespace touchdown::drop
