#pragma once
/// \file
/// A Campbell diagram in openfast_toolbox's layout (OpenFAST/openfast_toolbox,
/// `openfast_toolbox/linearization/campbell_data.py`: campbellData2CSV, campbellData2TXT), the files its
/// `postproMBC(csvModesIDFile=…)` and `plotCampbellDataFile('Campbell_ModesID.csv')` read
/// (`openfast_toolbox/linearization/campbell.py`). Comma-separated, no quoting (commas in names become
/// spaces), numbers at full precision (the toolbox writes `{:f}`, 6 decimals; its reader parses either).
///
/// - `Campbell_OP.csv`: 3 rows of 1 + P fields (P points): `Operating Points` and P empty fields;
///   `Wind Speed (mps)` and the wind speeds [m/s] (`nan` for a point without one, as OpenFAST's files
///   without a wind speed); `Rotor Speed (rpm)` and the rotor speeds [rpm].
/// - `Campbell_ModesID.csv`: `Mode Number Table` and P empty fields; `Wind Speed (mps)` (or `Rotor Speed
///   (rpm)` when a point has no wind speed) and the operating values; then one row per Campbell line: its
///   name (the toolbox's name when whirl's maps to one: campbellToolboxName) and per point the 1-based
///   number of the line's mode in that point's Campbell_PointNN.csv, 0 where the line has no mode.
/// - `Campbell_PointNN.csv` (NN = 01, 02, … the point's 1-based number): 5 fields per mode, every row
///   5 M fields (M modes of the point, sorted by frequency, rigid-body modes included): `Mode Number:`
///   and the number; `Natural (undamped) frequency (Hz):`, `Damped frequency (Hz):`, `Damping Ratio (-):`
///   each with its value; the column heads; then one row per coordinate, the mode's coordinates sorted
///   by magnitude: description (Campbell point's coordinate name), 1 when this mode has the largest
///   magnitude of the point's modes in that coordinate (else 0), signed magnitude (largest 1; negative
///   when the phase to the leading coordinate exceeds ±90°) and the phase to the leading coordinate
///   folded into (−90°, 90°] [deg] (campbell_diagram_data_oneOP's rules). Magnitudes for the "largest
///   of the point's modes" test are of the coordinate vector scaled to unit 2-norm (numpy's eig scales
///   the state vector, coordinates and rates, to unit norm: a ranking that differs only for states
///   near a tie).
/// - `Campbell_Summary.txt`: per point 5 comment lines (`# --- OP n - WS w - RPM r`, `# ID; Freq [Hz];
///   Zeta [-]; Mode content`), then `NNN ; freq ; zeta ; content` (`{:03d} ; {:8.3f} ; {:7.4f} ; …`)
///   for the modes with 1e-5 ≤ |ζ| and ζ ≤ 0.96, then a `# --- Skipped (rigid-body mode)` section
///   (Mode::rigid_body) and a `# --- Skipped (Damping outside …)` section with the others (undamped and
///   overdamped roots). The content is whirl's mode name, `?` when
///   ambiguous (Mode::ambiguous), and the coordinates whose largest magnitude is in this mode, joined
///   by ` - `. The toolbox's skip of modes without ElastoDyn/BeamDyn states does not apply.
#include <string>

#include "modal/campbell.hpp"

namespace whirl {

/// Text of Campbell_OP.csv.
std::string openfastCampbellOp(const CampbellDiagram& d);

/// Text of Campbell_ModesID.csv.
std::string openfastCampbellModesId(const CampbellDiagram& d);

/// Text of Campbell_PointNN.csv for point p (0-based).
std::string openfastCampbellPoint(const CampbellDiagram& d, std::size_t p);

/// File name of point p (0-based): `Campbell_Point01.csv` for p = 0.
std::string openfastCampbellPointName(std::size_t p);

/// Text of Campbell_Summary.txt.
std::string openfastCampbellSummary(const CampbellDiagram& d);

/// openfast_toolbox's name for a whirl line name (IdentifyModes' list): `tower FA 1` → `1st Tower FA`,
/// `flap 2 BW` → `2nd Blade Flap (Regressive)`, `edge 1 FW` → `1st Blade Edge (Progressive)`,
/// `flap 1 collective` → `1st Blade Flap (Collective)`, `drivetrain` → `1st Drivetrain Torsion`,
/// `yaw` → `Nacelle Yaw`, `platform surge` → `Platform surge`; a repeated line's ` (k)` is kept; any
/// other name as it is. Commas become spaces (the toolbox's files are not quoted).
std::string campbellToolboxName(const std::string& whirl_name);

}  // namespace whirl
