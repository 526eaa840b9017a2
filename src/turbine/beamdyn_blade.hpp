#pragma once
/// \file
/// A BeamDyn blade (the primary file's key points, the blade file's 6 × 6 stations and `mu`) as a whirl
/// blade body: the blade of src/fem/blade6_body.hpp (mesh, Craig–Bampton reduction to fixed-root modes,
/// the modes as Rayleigh–Ritz shapes, frames), packed as the ElastoDyn blade beam the rotor builder
/// takes (src/turbine/elastodyn_rotor.cpp), so both blade models join the hub the same way, with the
/// same axial shortening and the same aerodynamic stations. BeamDyn keeps the sections' flap and edge
/// rotary inertia; ElastoDyn's blades keep the thin-beam convention.
#include <vector>

#include "src/fem/blade6_body.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"

namespace whirl {

using BeamDynBladeOptions = fem::Blade6Options;

struct BeamDynBladeBody {
  fem::Beam6Model model;        ///< body frame, node 0 at the root
  ElastoDynBladeBeam beam;      ///< props (mass line, offsets, EI for outputs) and the modes as shapes
  MatX K, D;                    ///< stiffness and damping of the modal coordinates (modes × modes)
  std::vector<double> freq_hz;  ///< the FE modes' frequencies, clamped root, not rotating [Hz]
  double length = 0;            ///< along z_r [m]
};

/// The BeamDyn input as the FE blade's plain data (key points, stations, mu).
fem::Blade6Input blade6Input(const io::BeamDynInput& bd);

/// fem::blade6Body of the BeamDyn blade (its modes, names and errors).
BeamDynBladeBody beamDynBladeBody(const io::BeamDynInput& bd, const BeamDynBladeOptions& opt);

/// The FE model alone (body frame, node 0 at the root).
fem::Beam6Model beamDynBladeModel(const io::BeamDynInput& bd, int elements);

}  // namespace whirl
