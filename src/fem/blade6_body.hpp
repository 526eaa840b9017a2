#pragma once
/// \file
/// A blade described by 6 × 6 sections along a curved, twisted reference axis (BeamDyn's description,
/// whatever file it came from: a BeamDyn deck, src/turbine/beamdyn_blade.hpp, or a YAML case's
/// `fe_blade` body, src/io/case/case_blade6.cpp) as a Rayleigh–Ritz blade body: meshed with the two-node
/// 6 × 6 element (beam6_model.hpp), clamped at the root (the pitch bearing), reduced to its lowest
/// fixed-root modes (Craig–Bampton with the clamped root as the interface: no interface coordinates are
/// left), and those modes turned into the tabulated shapes of a beam (src/shapes/beam.hpp), so the blade
/// joins the multibody where ElastoDyn's blade joins it, with the same axial shortening.
///
/// Frames: the blade-root frame (x_r flapwise = ElastoDyn's j1, y_r edgewise = j2, z_r along the pitch
/// axis = j3) → whirl's blade body frame (x, y, z) = (z_r, x_r, y_r), the frame of
/// src/turbine/elastodyn_blade_shapes.hpp. Sections: BeamDyn's section frame at the reference axis
/// (BeamDyn_Subs.f90, BD_ComputeIniNodalCrv: e3 the tangent, e1 ⟂ e3 with no y_r component, turned by
/// −initial_twist about e3), its 6 × 6 matrices turned into body axes.
///
/// What the body takes from the FE model: the elastic stiffness Φᵀ K Φ and the stiffness-proportional
/// damping Φᵀ D Φ (D = diag(μ) C per section, BeamDyn's `mu`) of the kept modes exactly; the inertia
/// from the integrals of the shapes over the sections' mass (mass per length, mass-centre offsets) and
/// the whole inertia tensor of each section about its mass centre (`BeamProperties::J`: torsion, flap
/// and edge rotary inertia, BeamDyn's M44, M55, M66 and their couplings), the section turning with the
/// shapes' slopes and twist.
#include <array>
#include <vector>

#include "src/fem/beam6_model.hpp"
#include "src/shapes/beam.hpp"
#include "src/shapes/shape.hpp"

namespace whirl::fem {

/// A key point of the reference axis, blade-root frame: position [m] and the initial twist [rad]
/// (BeamDyn's kp_xr, kp_yr, kp_zr, initial_twist; the axis a not-a-knot cubic spline in z_r through
/// them, a parabola through three).
struct Blade6KeyPoint {
  Vec3 r = Vec3::Zero();
  double twist = 0;
};

/// A cross-section station: η ∈ [0, 1], the fraction of the reference axis' arc length, and its
/// symmetric 6 × 6 stiffness [N, N m, N m²] and mass [kg/m, kg, kg m] in BeamDyn's section frame
/// (index 2 extension, 5 torsion). Linear between stations in η, as BeamDyn.
struct Blade6Station {
  double eta = 0;
  Mat6s K = Mat6s::Zero();
  Mat6s M = Mat6s::Zero();
};

/// The blade: at least 3 key points with z_r increasing from the root, stations from η = 0 to 1
/// increasing, each matrix symmetric (K positive definite, M positive semi-definite: the readers check).
struct Blade6Input {
  std::vector<Blade6KeyPoint> key_points;
  std::vector<Blade6Station> stations;
  std::array<double, 6> mu{};  ///< stiffness-proportional damping per strain component [s] (BeamDyn's mu)
};

struct Blade6Options {
  int elements = 60;  ///< equal elements along z_r (every 6 × 6 station interpolated linearly in η)
  int modes = 8;      ///< fixed-root modes kept
};

struct Blade6Body {
  Beam6Model model;              ///< body frame, node 0 at the root
  BeamProperties props;          ///< mass line, offsets, inertia tensors, EI for outputs (body frame)
  std::vector<ShapePtr> shapes;  ///< the kept modes as table shapes, named flap k, edge k, torsion k
  MatX K, D;                     ///< stiffness and damping of the modal coordinates (modes × modes)
  MatX modes;                    ///< the kept modes over the FE DOFs (6 nodes × modes, zero at the root)
  std::vector<double> freq_hz;   ///< the FE modes' frequencies, clamped root, not rotating [Hz]
  double length = 0;             ///< along z_r [m]
};

/// The lowest opt.modes fixed-root modes that are not axial (the body has no axial shapes), named
/// "flap k", "edge k" or "torsion k" after the family that holds most of the mode's kinetic energy
/// (flap: u_y and θ_z; edge: u_z and θ_y; torsion: θ_x; axial: u_x).
/// \throws InputError ("blade_elements: …", "blade_modes: …") for fewer than 2 elements or 1 mode,
/// ComputeError when the modes fail.
Blade6Body blade6Body(const Blade6Input& in, const Blade6Options& opt);

/// The FE model alone (body frame, node 0 at the root).
Beam6Model blade6Model(const Blade6Input& in, int elements);

}  // namespace whirl::fem
