#pragma once
/// \file
/// IDA's Newton iteration for a second-order system written in first order (linearize/simulate.cpp):
/// the linear solver and the convergence test.
///
/// With the states y = [q; v] (n each) and F = [q̇ − v; e(q, v, v̇)], IDA's iteration matrix is
///   J = ∂F/∂y + c ∂F/∂ẏ = [[c I, −I], [J21, J22]],  J21 = ∂e/∂q = −K,  J22 = ∂e/∂q̇ − c M = −C − c M.
/// Block elimination of the first row (x2 = c x1 − b1) leaves one system of size n:
///   (J21 + c J22) x1 = b2 + J22 b1,   J21 + c J22 = ∂e/∂q + c ∂e/∂q̇ − c² M,
/// so a factorization is of an n × n matrix (LU with partial pivoting, Eigen) instead of 2n × 2n.
///
/// The solver is matrix-embedded (SUNLINEARSOLVER_MATRIX_EMBEDDED): it decides itself when to evaluate
/// the blocks ∂e/∂q, ∂e/∂q̇ (the AD passes, the costly part) and M, and re-forms J21 + c J22 from the
/// blocks it holds whenever c changes (one n × n LU, cheap) — IDA's own rule keeps a factorization
/// while c stays within 25 % and rescales the correction instead. The blocks are evaluated
///  - at the first solve after IDA's (re)initialization and after a step whose Newton iteration failed;
///  - when the last Newton iteration contracted the correction by less than `max_rate` per iteration;
///  - when the rotor has turned by `max_turn` since (the blocks depend on the azimuth), or after
///    `max_age` steps;
/// and M alone when the rotor has turned by `max_mass_turn`: for a turning rotor c² M dominates the
/// matrix (c ≈ 1/h), and M's coupling of the blade and the fixed-frame coordinates turns with the
/// rotor — a few degrees make the Newton corrections of a stale M poor.
///
/// The convergence test is IDA's (idaNlsConvTest, SUNDIALS 6.4: the correction's WRMS norm times
/// the rate estimate ss = ρ/(1 − ρ) below the tolerance, divergence when ρ > 0.9). The rate estimate is
/// reset to IDA's value after a setup (ss = 20) whenever the blocks ∂e/∂q, ∂e/∂q̇ are evaluated, and
/// when c falls by more than 25 % (longer steps: stale ∂e/∂q, ∂e/∂q̇ weigh more against c² M). IDA
/// itself does not reset it for a matrix-embedded solver, and an estimate from a fresh matrix then lets
/// a stale one pass unchecked iterates (measured: a 600 s NREL 5MW run whose blades drifted to 700 m).
/// The estimate is kept
///  - when c grows, or falls by less, as IDA's own rule keeps it while c stays within 25 %: the matrix
///    re-factored with the exact c and blocks as old as before contracts as well or better;
///  - when M alone is evaluated: the matrix is then fresher than the one the estimate was measured on.
/// (Resetting at every change of c cost the aeroelastic start-up a second Newton iterate after most
/// factorizations, 59.5k instead of 47.1k residuals with both rules; keeping it across a doubled step
/// cost the structural benchmark 6× its error-test failures. The start-up's outputs stay within 7.7e-5
/// of their ranges from a 1e-10 / 1e-12 run, tests/validation/test_simulate_tolerance.cpp.)
///
/// First-order states z (dim nz, e.g. the blade elements' unsteady-airfoil and dynamic-inflow states) may
/// follow: y = [q; v; z], F = [q̇ − v; e(q, v, v̇, z); ż − f(q, v, z)], and with G = ∂e/∂z, Z_q = ∂f/∂q,
/// Z_v = ∂f/∂v, A_zz = ∂f/∂z the third block row [−Z_q, −Z_v, D], D = c I − A_zz, is eliminated as well:
///   x3 = w + W x1,  w = D⁻¹ (b3 − Z_v b1),  W = D⁻¹ (Z_q + c Z_v),
///   (J21 + c J22 + G W) x1 = b2 + J22 b1 − G w,
/// one more LU (of D, nz × nz) per factorization; the blocks of z are evaluated with ∂e/∂q and ∂e/∂q̇.
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <functional>

#include "src/base/types.hpp"

namespace whirl {

/// The blocks of the iteration matrix at (t, y, ẏ) (y, ẏ of dimension 2n): ∂e/∂q, ∂e/∂q̇ and M, each
/// n × n in the order of the states; with `mass_only` only M (the others are left as they are).
/// Returns 0 on success, > 0 for a recoverable failure (a non-finite entry: IDA retries with a smaller
/// step), < 0 to stop the integration.
using IterationBlocksFn =
    std::function<int(double t, const double* y, const double* yp, bool mass_only, MatX& dedq, MatX& dedqd, MatX& M)>;

/// The blocks of the first-order states (header): G (n × nz), Z_q, Z_v (nz × n), A_zz (nz × nz).
struct FirstOrderBlocks {
  MatX G, Zq, Zv, Azz;
};

/// Evaluates the first-order states' blocks at (t, y, ẏ) (dimension 2n + nz), called right after the
/// IterationBlocksFn (not for M alone), which it may correct: it gets that call's ∂e/∂q and ∂e/∂q̇ to
/// add the states' load derivatives to. Returns as IterationBlocksFn.
using FirstOrderBlocksFn =
    std::function<int(double t, const double* y, const double* yp, MatX& dedq, MatX& dedqd, FirstOrderBlocks& z)>;

struct BlockSolverOptions {
  double max_rate = 0.2;  ///< evaluate the blocks when a Newton iteration contracts less than this
  long max_age = 1000;    ///< evaluate the blocks after this many steps
  /// The rotor angle at (t, y) [rad], or null (no rotor).
  std::function<double(double t, const double* y)> angle;
  double max_turn = 1.0;                  ///< evaluate the blocks after the rotor turned this much [rad]
  double max_mass_turn = 0.1;             ///< evaluate M alone after the rotor turned this much [rad]
  int first_order = 0;                    ///< nz: first-order states after the 2n of the second-order system
  FirstOrderBlocksFn first_order_blocks;  ///< their blocks (required when first_order > 0)
};

struct BlockSolverStatistics {
  long evaluations = 0;       ///< of the blocks (∂e/∂q, ∂e/∂q̇, M)
  long mass_evaluations = 0;  ///< of M alone
  long factorizations = 0;    ///< LU of J21 + c J22
};

/// The solver for n coordinates (and options.first_order states) of the IDA integrator `ida_mem`, for
/// IDASetLinearSolver(ida_mem, S, NULL). Null when SUNDIALS cannot allocate it. A singular or non-finite n × n matrix,
/// or blocks that cannot be evaluated, are a recoverable failure of the solve (IDA retries with a smaller step).
SUNLinearSolver newBlockEliminationSolver(int n, void* ida_mem, IterationBlocksFn blocks,
                                          const BlockSolverOptions& options, SUNContext ctx);

/// Gives `nls` (a SUNDIALS Newton solver attached to the same integrator with IDASetNonlinearSolver)
/// the convergence test above, which shares the rate estimate with `s`. Call after IDASetNonlinearSolver.
int attachConvergenceTest(SUNNonlinearSolver nls, SUNLinearSolver s);

/// Its counters since it was created.
BlockSolverStatistics blockSolverStatistics(SUNLinearSolver s);

}  // namespace whirl
