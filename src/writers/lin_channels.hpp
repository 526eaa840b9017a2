#pragma once
/// \file
/// OpenFAST's names of whirl's inputs and outputs in a `.lin` file: the description text, unit and
/// scale factor OpenFAST's modules write for the same channel, so that tools matching descriptions
/// exactly (ROSCO's linear models, openfast_toolbox's and WEIS's channel look-ups) find them.
///
/// Inputs keep SI units as OpenFAST writes them ("ED Generator torque, Nm"); outputs take OpenFAST's
/// output units (rpm, deg, kN, kN-m, kW), so their C and D rows and operating points are scaled by
/// `scale` (file value = scale × SI value). Sources: the descriptions and units in OpenFAST's own files
/// copied to tests/data/openfast-lin/ (v2.5 to v3.3), InflowWind's and ElastoDyn's extended inputs
/// (OpenFAST, modules/inflowwind/src/InflowWind.f90 and modules/elastodyn/src/ElastoDyn.F90, routines
/// `*_Init_Jacobian`), ElastoDyn's, AeroDyn's and ServoDyn's output lists (their `*_IO.f90` files).
/// A channel without an OpenFAST counterpart is "whirl <name>" in SI units.
#include <string>

#include "linearize/state_space.hpp"

namespace whirl {

/// A channel as a `.lin` file writes it.
struct LinChannel {
  std::string text;    ///< description without the unit: "ED GenSpeed", "IfW Extended input: …"
  std::string unit;    ///< unit in the file: "rpm", "kN-m", "m/s" …
  double scale = 1.0;  ///< file value = scale × whirl's SI value
  int rank = 99;       ///< inputs: OpenFAST's order (InflowWind's wind first, then ElastoDyn's); others last
};

/// The `.lin` channel of input `u`.
LinChannel linInputChannel(const StateSpaceVariable& u);

/// The `.lin` channel of output `y`.
LinChannel linOutputChannel(const StateSpaceVariable& y);

/// The full `.lin` description of an input ("ED Generator torque, Nm") or output ("ED GenSpeed, (rpm)").
std::string linInputDescription(const StateSpaceVariable& u);
std::string linOutputDescription(const StateSpaceVariable& y);

}  // namespace whirl
