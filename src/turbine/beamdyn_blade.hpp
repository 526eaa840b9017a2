#pragma once
/// \file
/// A BeamDyn blade as a whirl blade body: the reference axis and 6 × 6 sections of the BeamDyn files
/// meshed with the two-node 6 × 6 element (src/fem/beam6_model.hpp), clamped at the root (the pitch
/// bearing), reduced to its lowest fixed-root modes (Craig–Bampton with the clamped root as the
/// interface: no interface coordinates are left), and those modes turned into the tabulated shapes of
/// a Rayleigh–Ritz beam (src/shapes/beam.hpp), so the blade joins the multibody where ElastoDyn's blade
/// joins it, with the same axial shortening (centrifugal stiffening, spin softening, gravity) and
/// the same aerodynamic stations.
///
/// Frames: BeamDyn's blade-root frame (x_r flapwise = ElastoDyn's j1, y_r edgewise = j2, z_r along the
/// pitch axis = j3) → whirl's blade body frame (x, y, z) = (z_r, x_r, y_r), the frame of
/// elastodyn_blade_shapes.hpp. Sections: BeamDyn's section frame at the reference axis
/// (BeamDyn_Subs.f90, BD_ComputeIniNodalCrv: e3 the tangent, e1 ⟂ e3 with no y_r component, turned by
/// −initial_twist about e3), its 6 × 6 matrices turned into body axes.
///
/// What the body takes from the FE model: the elastic stiffness Φᵀ K Φ and the stiffness-proportional
/// damping Φᵀ D Φ (D = diag(μ) C per section, BeamDyn's `mu`) of the kept modes exactly; the inertia
/// from the integrals of the shapes over the sections' mass (mass per length, mass-centre offsets) and
/// the whole inertia tensor of each section about its mass centre (`BeamProperties::J`: torsion, flap
/// and edge rotary inertia, BeamDyn's M44, M55, M66 and their couplings), the section turning with the
/// shapes' slopes and twist. ElastoDyn's blades keep the thin-beam convention (no flap or edge rotary
/// inertia); BeamDyn keeps it, and so does the BeamDyn blade here.
#include <vector>

#include "src/fem/beam6_model.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"

namespace whirl {

struct BeamDynBladeOptions {
  int elements = 60;  ///< equal elements along z_r (every 6 × 6 station interpolated linearly in η)
  int modes = 8;      ///< fixed-root modes kept
};

struct BeamDynBladeBody {
  fem::Beam6Model model;        ///< body frame, node 0 at the root
  ElastoDynBladeBeam beam;      ///< props (mass line, offsets, EI for outputs) and the modes as shapes
  MatX K, D;                    ///< stiffness and damping of the modal coordinates (modes × modes)
  std::vector<double> freq_hz;  ///< the FE modes' frequencies, clamped root, not rotating [Hz]
  double length = 0;            ///< along z_r [m]
};

/// The lowest opt.modes fixed-root modes that are not axial (the body has no axial shapes), named
/// "flap k", "edge k" or "torsion k" after the family that holds most of
/// the mode's kinetic energy (flap: u_y and θ_z; edge: u_z and θ_y; torsion: θ_x; axial: u_x).
/// \throws InputError for fewer than 2 elements or 1 mode, ComputeError when the modes fail.
BeamDynBladeBody beamDynBladeBody(const io::BeamDynInput& bd, const BeamDynBladeOptions& opt);

/// The FE model alone (body frame, node 0 at the root).
fem::Beam6Model beamDynBladeModel(const io::BeamDynInput& bd, int elements);

}  // namespace whirl
