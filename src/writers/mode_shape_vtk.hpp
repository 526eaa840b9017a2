#pragma once
/// \file
/// A mode's motion (modal/mode_motion.hpp) as a VTK animation ParaView plays: a `.pvd` collection
/// (VTK's XML "Collection" file) of one `.vtp` PolyData file per phase step over one period of the mode,
/// the turbine drawn as polylines (VTK file formats, kitware.com "VTK File Formats", XML PolyData:
/// `<Piece NumberOfPoints NumberOfLines>`, `<Points>`, `<Lines>` with `connectivity` and `offsets`).
///
/// Geometry, from the bodies in their order: every body with two or more nodes is one polyline through
/// its nodes (tower, blades, a platform's points); a run of one-node bodies (nacelle, generator, hub) is
/// one polyline starting at the last node of the body before the run (the tower top); a blade's polyline
/// starts at the last one-node body before it (the hub centre), so the rotor hangs on the shaft. A
/// point shared by two polylines is written once per polyline, each moving with its own body.
///
/// Frame k of N (k = 0 … N−1) puts every node at p + s Re(R u e^{iφ_k}), φ_k = 2πk/N: p its position at
/// the operating point (ground, m), R u its translation amplitude in ground components (the motion is
/// normalised to a largest component amplitude of 1), s the drawing scale = `scale_fraction` × the
/// diagonal of the bounding box of the undeformed nodes [m]. The frame's `timestep` in the .pvd is k T/N with T = 1/f_d
/// the mode's damped period [s] (1/f when f_d = 0; k/N, a fraction of a cycle, for a rigid-body mode).
/// Point data `displacement` (the drawn displacement s Re(R u e^{iφ_k}) [m]) and `amplitude` (|R u|, per
/// unit of the mode); cell data `body`: the index of the polyline's body in ModeMotion::bodies (the
/// order of the `motion.bodies` of campbell_modes.json). ASCII, Float64 points, Int64 connectivity.
#include <string>
#include <utility>
#include <vector>

#include "modal/mode_motion.hpp"

namespace whirl {

struct VtkAnimationOptions {
  int frames = 16;              ///< phase steps per period
  double scale_fraction = 0.1;  ///< drawn amplitude over the model's size
};

/// The files of one mode's animation: (`<stem>.pvd`, its text), then (`<stem>_KK.vtp`, text) per frame
/// (KK = 00, 01, …). Empty when the motion is empty or has no node. `freq_hz`, `damped_freq_hz`: the
/// mode's frequencies (timesteps). `stem` must be a file name without a folder part.
std::vector<std::pair<std::string, std::string>> modeShapeVtk(const ModeMotion& motion, const std::string& stem,
                                                              double freq_hz, double damped_freq_hz,
                                                              const VtkAnimationOptions& opt = {});

/// A name made safe as part of a file name: letters and digits kept, anything else `_` (runs joined).
std::string vtkFileStem(const std::string& name);

}  // namespace whirl
