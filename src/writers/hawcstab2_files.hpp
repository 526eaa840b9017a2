#pragma once
/// \file
/// A Campbell diagram in HAWCStab2's result formats, as DLR's CampbellViewer
/// (`campbellviewer/interfaces/hawcstab2.py`) and DTU's wetb (`wetb/prepost/hawcstab2.py`) read them.
/// One mode number per Campbell line (1 = the first line), one row per operating point; numbers in
/// HAWCStab2's Fortran E14.6 form (`  0.100000E+01`), `nan` where a line has no mode at a point.
///
/// - `<name>.cmb`: one header line `  # Wind [m/s]` (or `  # Rotor speed [rpm]` when a point has no
///   wind speed) followed by the mode numbers 1 … N three times; then per point the operating value,
///   N damped frequencies [Hz], N damping ratios [%], N real parts of the eigenvalue Re λ = −ζ ω [1/s]
///   (3N + 1 columns: CampbellViewer's aeroelastic layout, wetb's `real_eig`).
/// - `<name>.amp`: 5 header lines (`# Modal MAGNITUDE | PHASE …`, `# Last node of: tower, shaft,
///   blade1`, `# Mode number:`, `# Column num.:`, the column names), then per point the operating
///   value and, per mode, 15 DOFs × (amplitude, phase [deg]): TWR x (side-side), TWR y (fore-aft) [m],
///   TWR yaw [rad] at the tower top; SFT x, SFT y [m] (lateral, vertical), SFT tor [rad] at the hub;
///   Sym/BW/FW edge, Sym/BW/FW flap [m], Sym/BW/FW tors [rad] at the tip of the blades (the multiblade
///   content of modal/mode_motion.hpp; without one, blade 1's motion as Sym). Amplitudes divided by the
///   largest of the 15, as HAWCStab2 does; 30 N + 1 columns.
/// - `<name>.opt`: a header line starting with the number of points, then per point wind speed [m/s]
///   (0 when none), pitch [deg] (0 when none), rotor speed [rpm], aero power [kW] and aero thrust [kN]
///   (`nan`: a Campbell sweep does not compute them).
#include <string>

#include "modal/campbell.hpp"

namespace whirl {

std::string hawcstab2Cmb(const CampbellDiagram& d);
std::string hawcstab2Amp(const CampbellDiagram& d);
std::string hawcstab2Opt(const CampbellDiagram& d);

/// The 15 complex amplitudes of the .amp file for one mode (unscaled; order as above); zeros where
/// the motion has no tower, hub or blade.
Eigen::Matrix<std::complex<double>, 15, 1> hawcstab2Dofs(const ModeMotion& motion);

/// HAWCStab2's number format: 14 characters, `  0.100000E+01`, `-0.123404E+03`; `nan` right-aligned.
std::string fortranE(double x);

}  // namespace whirl
