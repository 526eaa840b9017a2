#pragma once
/// \file
/// Mode shapes as tables (modal/mode_motion.hpp): the `motion` object of a mode in campbell_modes.json
/// and `whirl modes --format json`, and the per-point CSV `mode_shapes_<point>.csv`.
///
/// JSON `motion` (numbers at full precision): `normalisation` (text), `frame` (text), `components`
/// ["ux","uy","uz","rx","ry","rz"], `bodies`: per body `body`, `blade` (1-based, null in the fixed
/// frame), `role` (BodyMotion::role), `nodes` (names), `x_m` (stations), `position_m` (per node [x, y, z], ground), `R`
/// (body → ground, rows), `amplitude` and `phase_deg` (per node the 6 components: m, rad; deg in (−180, 180]); with a
/// rotor of 3 or more blades `multiblade`: `nodes`, `x_m` and per kind (`collective`, `backward`, `forward`)
/// `amplitude`, `phase_deg` as above.
///
/// CSV, one row per mode and node: `mode,line,name,freq_hz,damping_ratio,body,blade,node,x_m,` then
/// `<c>_amp,<c>_phase_deg` for c = ux, uy, uz, rx, ry, rz (blade 1-based, empty in the fixed frame;
/// line empty when the mode is on no line).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "modal/campbell.hpp"

namespace whirl {

/// The `motion` object of one mode (null JSON when the motion is empty).
nlohmann::ordered_json modeMotionJson(const ModeMotion& motion);

/// Text of mode_shapes_<point>.csv for point p of the diagram (every mode with a motion).
std::string modeShapesCsv(const CampbellDiagram& d, std::size_t p);

/// Phase in degrees of a complex amplitude, in (−180, 180]; 0 for an amplitude below 1e-12.
double phaseDeg(std::complex<double> u);

}  // namespace whirl
