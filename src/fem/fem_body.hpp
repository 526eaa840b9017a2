#pragma once
/// \file
/// An FE body from its description: assemble, apply the boundary conditions, reduce (none, Guyan,
/// Craig–Bampton) and turn into a whirl Ritz body (ritz_body.hpp), with DOF names; and the
/// geometric stiffness of the gravity loads it carries.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/fem/reduction.hpp"
#include "src/fem/ritz_body.hpp"

namespace whirl::fem {

enum class ReductionKind { None, Guyan, CraigBampton };

struct FemBodySpec {
  BeamModel model;                                  ///< with its fixed DOFs
  std::vector<std::pair<std::string, int>> points;  ///< named nodes (children, loads, interface)
  ReductionKind reduction = ReductionKind::None;
  std::vector<int> interface_nodes;  ///< Guyan / Craig–Bampton master nodes
  int modes = 0;                     ///< Craig–Bampton fixed-interface modes
  /// A rigid interface (rigid_interface.hpp): the interface nodes tied to this point, whose six DOFs
  /// (body axes) become the body's first six coordinates, named "<rigid_interface_name> ux" … "rz",
  /// and a body point of that name. With ReductionKind::None the other free DOFs follow as they are;
  /// with Guyan or Craig–Bampton the static modes of the tied interface, then the modes.
  std::optional<Vec3> rigid_interface;
  std::string rigid_interface_name = "interface";
};

struct FemBody {
  RitzBody body;
  std::vector<std::string> dof_names;  ///< one per elastic coordinate (without the body name)
  DofMap map;
  Assembly assembly;
  SpMat K, M;               ///< free DOFs (elastic + springs), consistent mass
  MatX basis;               ///< free DOFs × ne
  VecX fixed_interface_hz;  ///< Craig–Bampton: frequencies of the kept modes
};

/// \throws InputError for an invalid model (validate()), ComputeError when a reduction fails.
FemBody buildFemBody(const FemBodySpec& spec, const std::string& name, const ModalSolver& solver = denseModes);

/// A load carried by the body: the weight of `mass` (e.g. the bodies attached at a node) acts at `node`.
struct CarriedMass {
  int node = -1;
  double mass = 0;
};

/// Geometric stiffness of the gravity loads, in the body's coordinates (ne × ne), to add to K:
/// the element axial forces N come from a linear static solution of the FE model (free DOFs) under
/// its own weight and the carried weights, gravity g given in body axes; K_G = Φᵀ Σ_e N_e G_e Φ
/// (element.hpp). Also returns N when `axial_force` is given (one per element, tension > 0).
MatX gravityGeometricStiffness(const FemBody& fb, const BeamModel& model, const Vec3& gravity_body,
                               const std::vector<CarriedMass>& carried, VecX* axial_force = nullptr);

}  // namespace whirl::fem
