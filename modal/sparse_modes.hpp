#pragma once
/// \file
/// Modes of M q̈ + C q̇ + K q = 0 from the sparse SLEPc solvers (modal/sparse_eigen.hpp): the
/// lowest `nmodes` modes, named and sorted as the dense path (modal/modes.hpp) names and sorts
/// them, each with the backward error of its eigenpair. C = 0 with symmetric K, M: the symmetric
/// generalized problem K x = ω² M x (EPS); otherwise the quadratic problem (PEP).
#include <string>
#include <vector>

#include "modal/modes.hpp"
#include "modal/sparse_eigen.hpp"

namespace whirl {

/// How the modes were computed (for the user's log).
struct SparseModesInfo {
  std::string method;
  double target = 0;
  int iterations = 0;
};

/// The lowest nmodes modes (opt.nev is set from nmodes). names: one per coordinate (dim n).
std::vector<Mode> computeModesSparse(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K,
                                     const std::vector<std::string>& names, int nmodes, SparseEigenOptions opt,
                                     SparseModesInfo* info = nullptr);

/// Which path `--solver auto` takes for a model with n coordinates.
inline bool useSparseSolver(const std::string& solver, int n) {
  return solver == "sparse" || (solver == "auto" && n >= kSparseSolverThreshold);
}

}  // namespace whirl
