#include "src/fem/fem_body.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/SparseCholesky>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/fem/rigid_interface.hpp"

namespace whirl::fem {

FemBody buildFemBody(const FemBodySpec& spec, const std::string& name, const ModalSolver& solver) {
  validate(spec.model, name);
  FemBody fb;
  fb.assembly = assemble(spec.model, true);
  fb.map = freeDofs(spec.model);
  if (fb.map.nfree() == 0) throw InputError("FE body '" + name + "': every DOF is fixed");
  fb.K = restrictTo(fb.assembly.K, fb.map);
  fb.M = restrictTo(fb.assembly.M, fb.map);
  const int n = fb.map.nfree();
  std::vector<int> interface;  // free indices of the interface nodes' DOFs
  for (int node : spec.interface_nodes)
    for (int k = 0; k < kNodeDofs; ++k)
      if (const int f = fb.map.index[kNodeDofs * node + k]; f >= 0) interface.push_back(f);
  MatX tie;  // rigid interface: free DOFs × 6
  if (spec.rigid_interface) {
    if (spec.interface_nodes.empty())
      throw InputError("FE body '" + name + "': a rigid interface needs interface nodes");
    tie = rigidTie(spec.model, fb.map, spec.interface_nodes, *spec.rigid_interface);
    for (int k = 0; k < kNodeDofs; ++k) fb.dof_names.push_back(spec.rigid_interface_name + " " + kNodeDofNames[k]);
  }
  // The body's coordinates, before any dense matrix of that size is allocated.
  const long coordinates = spec.reduction == ReductionKind::None
                               ? (spec.rigid_interface ? 6L + n - static_cast<long>(interface.size()) : n)
                               : static_cast<long>(spec.rigid_interface ? 6 : interface.size()) +
                                     (spec.reduction == ReductionKind::CraigBampton ? spec.modes : 0);
  if (coordinates > limits::kMaxFemBodyCoordinates)
    throw InputError(
        "FE body '" + name + "': " + std::to_string(coordinates) + " coordinates (" +
        (spec.reduction == ReductionKind::None ? "every free DOF of the unreduced model" : "interface DOFs and modes") +
        "), more than " + std::to_string(limits::kMaxFemBodyCoordinates) +
        " (src/base/limits.hpp): reduce it (guyan or craig_bampton) or use fewer elements");
  if (spec.reduction == ReductionKind::None && !spec.rigid_interface) {
    fb.basis = MatX::Identity(n, n);
    for (int f : fb.map.free) fb.dof_names.push_back(dofName(f));
  } else if (spec.reduction == ReductionKind::None) {
    // [T, the other free DOFs as they are].
    std::vector<bool> tied(n, false);
    for (int f : interface) tied[f] = true;
    fb.basis = MatX::Zero(n, 6 + n - static_cast<int>(interface.size()));
    fb.basis.leftCols(6) = tie;
    int col = 6;
    for (int f = 0; f < n; ++f)
      if (!tied[f]) {
        fb.basis(f, col++) = 1.0;
        fb.dof_names.push_back(dofName(fb.map.free[f]));
      }
  } else {
    if (interface.empty()) throw InputError("FE body '" + name + "': the interface has no free DOF");
    if (!spec.rigid_interface)
      for (int f : interface) fb.dof_names.push_back(dofName(fb.map.free[f]));
    const int modes = spec.reduction == ReductionKind::CraigBampton ? spec.modes : 0;
    const Reduction r = modes > 0 ? craigBampton(fb.K, fb.M, interface, modes, solver) : guyan(fb.K, interface);
    const int nb = static_cast<int>(interface.size());
    if (spec.rigid_interface) {
      // Static modes of the tied interface: Φ_b T_b, T_b the interface rows of T.
      MatX Tb(nb, 6);
      for (int k = 0; k < nb; ++k) Tb.row(k) = tie.row(interface[k]);
      fb.basis.resize(n, 6 + modes);
      fb.basis.leftCols(6) = r.basis.leftCols(nb) * Tb;
      fb.basis.rightCols(modes) = r.basis.rightCols(modes);
    } else {
      fb.basis = r.basis;
    }
    fb.fixed_interface_hz = r.fixed_interface_omega2.cwiseMax(0.0).cwiseSqrt() / (2 * std::numbers::pi);
    for (int j = 0; j < modes; ++j) fb.dof_names.push_back("CB " + std::to_string(j + 1));
  }
  fb.body = ritzBody(spec.model, fb.assembly, fb.map, fb.basis, fb.K, spec.points);
  if (spec.rigid_interface)
    fb.body.points.push_back(
        rigidInterfacePoint(spec.rigid_interface_name, *spec.rigid_interface, static_cast<int>(fb.basis.cols())));
  return fb;
}

MatX gravityGeometricStiffness(const FemBody& fb, const BeamModel& model, const Vec3& g,
                               const std::vector<CarriedMass>& carried, VecX* axial_force) {
  const DofMap& map = fb.map;
  // Generalized gravity force on the full DOFs: ∫ gᵀ P dm over columns 1.. (work g·s per DOF).
  const Mat3X& m1 = fb.assembly.integrals.m1;
  VecX f = (g.transpose() * m1.rightCols(map.nfull)).transpose();
  for (const CarriedMass& c : carried) f.segment<3>(kNodeDofs * c.node) += c.mass * g;
  VecX ff(map.nfree());
  for (int i = 0; i < map.nfree(); ++i) ff(i) = f(map.free[i]);
  Eigen::SimplicialLDLT<SpMat> ldlt(fb.K);
  if (ldlt.info() != Eigen::Success)
    throw ComputeError("geometric stiffness: the FE body is not held (singular stiffness); fix or support it");
  const VecX uf = ldlt.solve(ff);
  VecX u = VecX::Zero(map.nfull);
  for (int i = 0; i < map.nfree(); ++i) u(map.free[i]) = uf(i);
  const VecX N = axialForces(model, u);
  if (axial_force) *axial_force = N;
  const SpMat G = restrictTo(geometricStiffness(model, N), map);
  const MatX KG = fb.basis.transpose() * (G * fb.basis);
  return 0.5 * (KG + KG.transpose());
}

}  // namespace whirl::fem
