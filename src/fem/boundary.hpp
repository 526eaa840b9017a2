#pragma once
/// \file
/// Boundary conditions of a beam FE model: the fixed DOFs (clamped nodes, suppressed DOF kinds)
/// are removed; what is left are the free DOFs, the coordinates of the FE body.
#include <string>
#include <vector>

#include "src/fem/assembly.hpp"

namespace whirl::fem {

/// Free DOFs of the model and the map back.
struct DofMap {
  int nfull = 0;
  std::vector<int> free;   ///< full index of each free DOF, increasing
  std::vector<int> index;  ///< free index of each full DOF, −1 = fixed (dim nfull)
  int nfree() const { return static_cast<int>(free.size()); }
};

DofMap freeDofs(const BeamModel& model);

/// Holds every DOF of node `node` (a clamped end).
void clamp(BeamModel& model, int node);
/// Holds the DOF kinds not in `active` at every node (e.g. {uz, ry}: planar bending in x–z).
void keepOnly(BeamModel& model, const std::array<bool, 6>& active);

/// A(free, free).
SpMat restrictTo(const SpMat& A, const DofMap& map);

/// Name of a full DOF: "n<node> <ux|uy|uz|rx|ry|rz>".
std::string dofName(int full_dof);

}  // namespace whirl::fem
