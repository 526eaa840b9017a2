#pragma once
/// \file
/// A straight FE beam body as a case file describes it — plain data, positions along body x [m] —
/// and the FE assembly from it: the mesh (equal elements with the named points and the soil table's
/// ends as nodes), Winkler soil springs, the active DOF kinds, clamped points, point springs and
/// lumped masses, then the reduced body (fem_body.hpp). The YAML case reader fills the spec
/// (src/io/case/case_fem.cpp); it does no assembly itself.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/fem/fem_body.hpp"

namespace whirl::fem {

/// Distributed soil springs per length [N/m²] along x, linear between the stations; an empty
/// column is no spring in that direction.
struct BeamSoil {
  VecX x;           ///< stations [m], increasing, on the beam
  VecX kx, ky, kz;  ///< stiffness per length at the stations (each empty or of x's size)
};

/// A 6×6 spring (body axes; ux, uy, uz, rx, ry, rz) from a named point to the ground.
struct BeamPointSpring {
  int point = -1;         ///< index into StraightBeamSpec::points
  Mat6 K = Mat6::Zero();  ///< symmetric
};

/// A lumped mass with its rotational inertia about the node (body axes).
struct BeamPointMass {
  int point = -1;  ///< index into StraightBeamSpec::points
  double mass = 0;
  Mat3 inertia = Mat3::Zero();
};

struct StraightBeamSpec {
  double length = 0;  ///< [m]
  int elements = 20;  ///< equal elements before the points are inserted
  bool timoshenko = false;
  BeamStations props;                                  ///< spanwise properties (stations on [0, length])
  std::vector<std::pair<std::string, double>> points;  ///< named stations (name, x [m]), nodes of the mesh
  std::optional<BeamSoil> soil;
  std::array<bool, 6> active{true, true, true, true, true, true};  ///< DOF kinds kept (ux … rz)
  std::vector<int> clamped;                                        ///< points fixed to the ground
  std::vector<BeamPointSpring> supports;
  std::vector<BeamPointMass> masses;
  ReductionKind reduction = ReductionKind::None;
  std::vector<int> interface_points;  ///< Guyan / Craig–Bampton master points
  int modes = 0;                      ///< Craig–Bampton fixed-interface modes
};

/// The assembled FE model, the reduced body and the node each named point became.
struct StraightBeamBody {
  BeamModel model;
  FemBody body;
  std::vector<int> point_node;  ///< node of StraightBeamSpec::points[i]
};

/// Meshes, assembles and reduces the beam of `spec`.
/// \throws InputError for an invalid model (validate()), ComputeError when a reduction fails.
StraightBeamBody buildStraightBeamBody(const StraightBeamSpec& spec, const std::string& name);

}  // namespace whirl::fem
