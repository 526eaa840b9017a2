#pragma once
/// \file
/// Superelement reduction of a free FE model [Branlard2019, §3.4]: a basis Φ (n × r) with u = Φ p.
/// - Guyan: p = interface DOFs u_b; Φ = [I; −K_ii⁻¹ K_ib] (static constraint modes).
/// - Craig–Bampton: p = [u_b; η]; Φ = [[I, 0], [−K_ii⁻¹ K_ib, Φ_i]] with Φ_i the lowest
///   fixed-interface modes (K_ii − ω² M_ii) φ = 0.
/// Rows are in the order of the free DOFs; columns are the interface DOFs in the order given, then
/// the modes. The fixed-interface eigenproblem goes through a ModalSolver: the dense LAPACK one by
/// default, a sparse one (SLEPc) for large models.
#include <functional>
#include <vector>

#include "src/fem/assembly.hpp"

namespace whirl::fem {

/// Lowest eigenpairs of K φ = ω² M φ: ω² ascending, vectors M-orthonormal (n × count).
struct GeneralizedModes {
  VecX omega2;
  MatX vectors;
};

/// K, M symmetric (n × n), M positive definite; returns the `count` lowest pairs.
using ModalSolver = std::function<GeneralizedModes(const SpMat& K, const SpMat& M, int count)>;

/// Dense LAPACK (dsygvd) solver: fine up to a few thousand DOFs.
/// \throws ComputeError when M is not positive definite or LAPACK fails.
GeneralizedModes denseModes(const SpMat& K, const SpMat& M, int count);

struct Reduction {
  MatX basis;                   ///< n × (interface + modes)
  std::vector<int> interface;   ///< free indices of the interface DOFs (basis columns 0..)
  VecX fixed_interface_omega2;  ///< ω² of the kept fixed-interface modes [rad²/s²]
};

/// \param interface free indices of the interface DOFs (distinct).
/// \throws ComputeError when K_ii is singular (the interior is not held by the interface).
Reduction guyan(const SpMat& K, const std::vector<int>& interface);

/// Each fixed-interface mode is scaled to a largest entry of 1 (positive).
Reduction craigBampton(const SpMat& K, const SpMat& M, const std::vector<int>& interface, int modes,
                       const ModalSolver& solver = denseModes);

}  // namespace whirl::fem
