#pragma once
/// \file
/// A large sparse FE model for benchmarks of sparse eigensolvers: the NREL 5MW onshore tower
/// (87.6 m, ElastoDyn distributed mass and bending stiffness; EA, GJ, polar inertia of a steel tube
/// with the same EI) meshed finely, clamped at the base, with the 350 t rotor–nacelle mass at the top.
#include "src/fem/assembly.hpp"

namespace whirl::fem {

struct SparseModel {
  SpMat K, M;  ///< free DOFs (6 × elements), symmetric, M positive definite
};

/// \param elements number of equal elements (DOFs = 6 × elements; 16667 gives 100002).
SparseModel fineTowerModel(int elements);

}  // namespace whirl::fem
