#pragma once
// `touchdown drop --free ... --vtk DIR`: the free pad's drop as a ParaView time series
// (docs/paraview.md). DIR/drop.pvd lists, at every sample of the trace, the pad's surface in world
// coordinates with its per-element soil stresses and forces (pad_NNNNNN.vtp), the soil's surface
// pressed in by the pad so far (crater_NNNNNN.vtp, io::CraterSurface) and the soil's surface
// (soil.vtp).
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/formats/output_path.h"

namespace touchdown::drop {

// Refuses (InputError, exit 2) a DIR that is not a new or empty directory or an earlier --vtk
// output: called before the drop runs, so a bad path costs nothing.
void CheckDropVtkTarget(const io::OutputTarget& dir);

// Writes the series of `drop` (the free drop RunDrop ran on `setup`) into `dir`, whole or not at
// all. The stresses are computed here, at the trace's samples, on the setup's pad body, terrain and
// contact model: those the drop ran on.
void WriteDropVtk(const DropSetup& setup, const PadDrop& drop, const io::OutputTarget& dir);

}  // namespace touchdown::drop
