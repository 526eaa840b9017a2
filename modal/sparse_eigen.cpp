#include "modal/sparse_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "src/base/error.hpp"
#include "src/parallel/session.hpp"

#ifdef WHIRL_HAVE_PETSC
#include <slepceps.h>
#include <slepcpep.h>
#endif

namespace whirl {

double sparseAutoTarget(const SparseMatrix& K, const SparseMatrix& M, bool quadratic) {
  // max K_ii/M_ii: a Rayleigh quotient, so at most ω_max², and of its order on FE meshes.
  const Eigen::VectorXd kd = K.diagonal(), md = M.diagonal();
  double hi = 0;
  for (Eigen::Index i = 0; i < kd.size(); ++i)
    if (kd(i) > 0 && md(i) > 0) hi = std::max(hi, kd(i) / md(i));
  if (!(hi > 0) || !std::isfinite(hi)) hi = 1.0;  // no stiffness at all: every mode is rigid
  return quadratic ? -std::sqrt(1e-10 * hi) : -1e-10 * hi;
}

#ifdef WHIRL_HAVE_PETSC
namespace {

/// PETSc error code → ComputeError naming the step; PETSc prints nothing (its handler is swapped
/// for PetscReturnErrorHandler while we are inside), the message carries PETSc's text instead.
void check(PetscErrorCode ierr, const char* step) {
  if (!ierr) return;
  const char* text = nullptr;
  PetscErrorMessage(ierr, &text, nullptr);
  throw ComputeError(std::string("sparse eigen: ") + step + " failed: " + (text ? text : "PETSc error") +
                     " (PETSc error " + std::to_string(ierr) + ")");
}

/// WHIRL_PETSC_TRACEBACK=1 in the environment keeps PETSc's own traceback, for debugging.
struct QuietErrors {
  const bool quiet = !std::getenv("WHIRL_PETSC_TRACEBACK");
  QuietErrors() {
    if (quiet) PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  }
  ~QuietErrors() {
    if (quiet) PetscPopErrorHandler();
  }
};

/// Owning handles: PETSc objects are destroyed however we leave.
struct PMat {
  Mat m = nullptr;
  ~PMat() { MatDestroy(&m); }
};
struct PVec {
  Vec v = nullptr;
  ~PVec() { VecDestroy(&v); }
};
struct PScatter {
  VecScatter s = nullptr;
  ~PScatter() { VecScatterDestroy(&s); }
};
struct PEps {
  EPS e = nullptr;
  ~PEps() { EPSDestroy(&e); }
};
struct PPep {
  PEP p = nullptr;
  ~PPep() { PEPDestroy(&p); }
};

/// An Eigen sparse matrix as a PETSc AIJ matrix on comm; each rank inserts the rows it owns.
void toPetsc(const SparseMatrix& A, MPI_Comm comm, PMat& out) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> R = A;
  PetscInt n = static_cast<PetscInt>(A.rows()), nloc = PETSC_DECIDE;
  check(PetscSplitOwnership(comm, &nloc, &n), "PetscSplitOwnership");
  PetscInt rend = 0;
  check(MPI_Scan(&nloc, &rend, 1, MPIU_INT, MPI_SUM, comm) == MPI_SUCCESS ? 0 : PETSC_ERR_MPI, "MPI_Scan");
  const PetscInt rstart = rend - nloc;
  std::vector<PetscInt> dnnz(static_cast<size_t>(nloc), 0), onnz(static_cast<size_t>(nloc), 0);
  for (PetscInt i = rstart; i < rend; ++i)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(R, i); it; ++it)
      ++((it.col() >= rstart && it.col() < rend) ? dnnz : onnz)[static_cast<size_t>(i - rstart)];
  check(MatCreateAIJ(comm, nloc, nloc, n, n, 0, dnnz.data(), 0, onnz.data(), &out.m), "MatCreateAIJ");
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> vals;
  for (PetscInt i = rstart; i < rend; ++i) {
    cols.clear();
    vals.clear();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(R, i); it; ++it) {
      cols.push_back(static_cast<PetscInt>(it.col()));
      vals.push_back(it.value());
    }
    if (!cols.empty())
      check(MatSetValues(out.m, 1, &i, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), INSERT_VALUES),
            "MatSetValues");
  }
  check(MatAssemblyBegin(out.m, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(out.m, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

/// The whole of a (possibly distributed) vector on every rank.
Eigen::VectorXd gatherAll(Vec v) {
  PScatter sc;
  PVec all;
  check(VecScatterCreateToAll(v, &sc.s, &all.v), "VecScatterCreateToAll");
  check(VecScatterBegin(sc.s, v, all.v, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(sc.s, v, all.v, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  PetscInt n = 0;
  check(VecGetSize(all.v, &n), "VecGetSize");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(all.v, &a), "VecGetArrayRead");
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(a, n);
  check(VecRestoreArrayRead(all.v, &a), "VecRestoreArrayRead");
  return out;
}

/// What actually ran, after the options database had its say: "krylovschur, ST sinvert, LU by mumps".
std::string describe(const char* solver_type, ST st) {
  STType st_type;
  KSP ksp;
  PC pc;
  PCType pc_type;
  check(STGetType(st, &st_type), "STGetType");
  check(STGetKSP(st, &ksp), "STGetKSP");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCGetType(pc, &pc_type), "PCGetType");
  std::string d = std::string(solver_type) + ", ST " + st_type + ", PC " + (pc_type ? pc_type : "none");
  MatSolverType solver = nullptr;
  if (pc_type && (std::string(pc_type) == PCLU || std::string(pc_type) == PCCHOLESKY)) {
    check(PCFactorGetMatSolverType(pc, &solver), "PCFactorGetMatSolverType");
    if (solver) d += std::string(" by ") + solver;
  }
  return d;
}

/// Shift-and-invert with a direct solve: MUMPS when PETSc has it (parallel, fast orderings), else
/// PETSc's own sequential factorization; LDLᵀ ("cholesky") for the symmetric K − σM (on the
/// 1e5-DOF benchmark 20 s and 630 MiB against LU's 24 s and 950 MiB), LU otherwise. Options given
/// later (-st_*) still override.
void configureShiftInvert(ST st, Mat A, MPI_Comm comm, bool symmetric) {
  check(STSetType(st, STSINVERT), "STSetType");
  KSP ksp;
  PC pc;
  check(STGetKSP(st, &ksp), "STGetKSP");
  check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU), "PCSetType");
  PetscBool mumps = PETSC_FALSE;
  check(MatGetFactorAvailable(A, MATSOLVERMUMPS, symmetric ? MAT_FACTOR_CHOLESKY : MAT_FACTOR_LU, &mumps),
        "MatGetFactorAvailable");
  PetscMPIInt size = 1;
  MPI_Comm_size(comm, &size);
  if (mumps) {
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    return;
  }
  if (size > 1) throw ComputeError("sparse eigen: PETSc has no MUMPS, needed for a distributed factorization");
}

void requireSquare(const SparseMatrix& A, Eigen::Index n, const char* name) {
  if (A.rows() != n || A.cols() != n)
    throw ComputeError(where("", 0, "sparse eigen",
                             std::string(name) + " is " + std::to_string(A.rows()) + " x " + std::to_string(A.cols()) +
                                 ", expected " + std::to_string(n) + " x " + std::to_string(n)));
  for (Eigen::Index k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      if (!std::isfinite(it.value()))
        throw ComputeError(where("", 0, "sparse eigen",
                                 std::string(name) + "(" + std::to_string(it.row()) + "," + std::to_string(it.col()) +
                                     ") is not finite"));
}

/// Converged pairs nearest the target; a complex pair cut by nev is kept whole.
int keepCount(int nconv, int nev, const std::vector<SparseEigenpair>& pairs) {
  int keep = std::min(nconv, nev);
  if (keep > 0 && keep < nconv && pairs[keep - 1].value.imag() != 0 &&
      pairs[keep].value == std::conj(pairs[keep - 1].value))
    ++keep;
  return keep;
}

void sortByDistance(std::vector<SparseEigenpair>& pairs, double sigma) {
  // Pairs first by distance to σ, conjugates adjacent with Im > 0 first, so the order is stable.
  std::stable_sort(pairs.begin(), pairs.end(), [sigma](const SparseEigenpair& a, const SparseEigenpair& b) {
    const double da = std::abs(a.value - sigma), db = std::abs(b.value - sigma);
    if (std::abs(da - db) > 1e-12 * std::max(da, db)) return da < db;
    return a.value.imag() > b.value.imag();
  });
}

Eigen::VectorXcd unitVector(const Eigen::VectorXd& re, const Eigen::VectorXd& im) {
  Eigen::VectorXcd v(re.size());
  for (Eigen::Index i = 0; i < re.size(); ++i) v(i) = {re(i), im(i)};
  const double norm = v.norm();
  if (norm > 0) v /= norm;
  return v;
}

// SLEPc's linear (EPS) and polynomial (PEP) solvers read their results with getters that differ only
// in name; these overloads let one function collect either.
PetscErrorCode converged(EPS e, PetscInt* n) { return EPSGetConverged(e, n); }
PetscErrorCode converged(PEP p, PetscInt* n) { return PEPGetConverged(p, n); }
PetscErrorCode iterations(EPS e, PetscInt* n) { return EPSGetIterationNumber(e, n); }
PetscErrorCode iterations(PEP p, PetscInt* n) { return PEPGetIterationNumber(p, n); }
PetscErrorCode eigenpair(EPS e, PetscInt i, PetscScalar* kr, PetscScalar* ki, Vec xr, Vec xi) {
  return EPSGetEigenpair(e, i, kr, ki, xr, xi);
}
PetscErrorCode eigenpair(PEP p, PetscInt i, PetscScalar* kr, PetscScalar* ki, Vec xr, Vec xi) {
  return PEPGetEigenpair(p, i, kr, ki, xr, xi);
}
PetscErrorCode backwardError(EPS e, PetscInt i, PetscReal* err) {
  return EPSComputeError(e, i, EPS_ERROR_BACKWARD, err);
}
PetscErrorCode backwardError(PEP p, PetscInt i, PetscReal* err) {
  return PEPComputeError(p, i, PEP_ERROR_BACKWARD, err);
}

/// Reads the converged pairs of a solved EPS or PEP into `res` (vectors gathered on every rank, unit
/// length), keeps the nev nearest the target and refuses fewer. `like`: a matrix of the problem's size;
/// `prefix`: the solver's options prefix ("eps", "pep") for the advice in the message.
template <class Solver>
void collectPairs(Solver solver, Mat like, int nev, const std::string& prefix, SparseEigenResult& res) {
  PetscInt nconv = 0, its = 0;
  check(converged(solver, &nconv), "GetConverged");
  check(iterations(solver, &its), "GetIterationNumber");
  res.iterations = static_cast<int>(its);
  PVec xr, xi;
  check(MatCreateVecs(like, &xr.v, nullptr), "MatCreateVecs");
  check(VecDuplicate(xr.v, &xi.v), "VecDuplicate");
  for (PetscInt i = 0; i < nconv; ++i) {
    PetscScalar kr, ki;
    PetscReal err;
    check(eigenpair(solver, i, &kr, &ki, xr.v, xi.v), "GetEigenpair");
    check(backwardError(solver, i, &err), "ComputeError");
    res.pairs.push_back({{kr, ki}, unitVector(gatherAll(xr.v), gatherAll(xi.v)), err});
  }
  sortByDistance(res.pairs, res.target);
  res.pairs.resize(static_cast<size_t>(keepCount(static_cast<int>(nconv), nev, res.pairs)));
  if (static_cast<int>(res.pairs.size()) < nev)
    throw ComputeError("sparse eigen: only " + std::to_string(res.pairs.size()) + " of " + std::to_string(nev) +
                       " eigenpairs converged in " + std::to_string(its) + " iterations (raise -" + prefix +
                       "_max_it or -" + prefix + "_ncv, or move the target)");
}

}  // namespace

SparseEigenResult sparseGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M, const SparseEigenOptions& opt) {
  const Eigen::Index n = K.rows();
  requireSquare(K, n, "K");
  requireSquare(M, n, "M");
  SparseEigenResult res;
  if (n == 0 || opt.nev <= 0) return res;
  parallel::requirePetsc("--solver sparse");
  QuietErrors quiet;
  const MPI_Comm comm = opt.distributed ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
  const int nev = static_cast<int>(std::min<Eigen::Index>(opt.nev, n));
  res.target = opt.target ? *opt.target : sparseAutoTarget(K, M, false);

  PMat A, B;
  toPetsc(K, comm, A);
  toPetsc(M, comm, B);
  PEps eps;
  check(EPSCreate(comm, &eps.e), "EPSCreate");
  check(EPSSetOperators(eps.e, A.m, B.m), "EPSSetOperators");
  check(EPSSetProblemType(eps.e, EPS_GHEP), "EPSSetProblemType");
  check(EPSSetType(eps.e, EPSKRYLOVSCHUR), "EPSSetType");
  check(EPSSetDimensions(eps.e, nev, PETSC_DEFAULT, PETSC_DEFAULT), "EPSSetDimensions");
  check(EPSSetTarget(eps.e, res.target), "EPSSetTarget");
  check(EPSSetWhichEigenpairs(eps.e, EPS_TARGET_MAGNITUDE), "EPSSetWhichEigenpairs");
  check(EPSSetTolerances(eps.e, opt.tol, opt.max_it > 0 ? opt.max_it : PETSC_DEFAULT), "EPSSetTolerances");
  ST st;
  check(EPSGetST(eps.e, &st), "EPSGetST");
  check(MatSetOption(A.m, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  check(MatSetOption(B.m, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  configureShiftInvert(st, A.m, comm, true);
  check(EPSSetFromOptions(eps.e), "EPSSetFromOptions");
  EPSType eps_type;
  check(EPSGetType(eps.e, &eps_type), "EPSGetType");
  PetscScalar target = res.target;
  check(EPSGetTarget(eps.e, &target), "EPSGetTarget");  // -eps_target may have moved it
  res.target = target;
  check(EPSSolve(eps.e), "EPSSolve (factorization of K - target*M and Krylov-Schur)");
  res.method = "EPS " + describe(eps_type, st);

  collectPairs(eps.e, A.m, nev, "eps", res);
  return res;
}

namespace {

/// Scale of the nev eigenvalues λ of (λ²M + λC + K) nearest a target near zero: the geometric mean
/// of the lowest and the highest of the ⌈nev/2⌉ undamped frequencies ω (K_s x = ω² M_s x with the
/// symmetric parts, to 1e-4: only the order matters; damping moves λ off ±iω by ζω). 1 (no scaling)
/// when that estimate fails or finds only zero frequencies (all modes rigid).
double wantedScale(const SparseMatrix& M, const SparseMatrix& K, int nev, const SparseEigenOptions& opt) {
  SparseEigenOptions est;
  est.nev = std::max(1, (nev + 1) / 2);
  est.tol = 1e-4;
  est.distributed = opt.distributed;
  double lo = 0, hi = 0;
  try {
    const SparseMatrix Ks = 0.5 * (K + SparseMatrix(K.transpose())), Ms = 0.5 * (M + SparseMatrix(M.transpose()));
    for (const SparseEigenpair& p : sparseGeneralizedEigen(Ks, Ms, est).pairs) {
      const double w = std::sqrt(std::abs(p.value.real()));
      if (!(w > 0) || !std::isfinite(w)) continue;
      lo = lo > 0 ? std::min(lo, w) : w;
      hi = std::max(hi, w);
    }
  } catch (const ComputeError&) {
    return 1.0;
  }
  return lo > 0 ? std::sqrt(lo * hi) : 1.0;
}

}  // namespace

SparseEigenResult sparseQuadraticEigen(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K,
                                       const SparseEigenOptions& opt) {
  const Eigen::Index n = M.rows();
  requireSquare(M, n, "M");
  requireSquare(C, n, "C");
  requireSquare(K, n, "K");
  SparseEigenResult res;
  if (n == 0 || opt.nev <= 0) return res;
  parallel::requirePetsc("--solver sparse");
  QuietErrors quiet;
  const MPI_Comm comm = opt.distributed ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
  const int nev = static_cast<int>(std::min<Eigen::Index>(opt.nev, 2 * n));
  res.target = opt.target ? *opt.target : sparseAutoTarget(K, M, true);

  PMat A0, A1, A2;
  toPetsc(K, comm, A0);
  toPetsc(C, comm, A1);
  toPetsc(M, comm, A2);
  Mat ops[3] = {A0.m, A1.m, A2.m};  // P(λ) = A0 + λ A1 + λ² A2
  PPep pep;
  check(PEPCreate(comm, &pep.p), "PEPCreate");
  check(PEPSetOperators(pep.p, 3, ops), "PEPSetOperators");
  check(PEPSetProblemType(pep.p, PEP_GENERAL), "PEPSetProblemType");
  check(PEPSetType(pep.p, PEPTOAR), "PEPSetType");
  check(PEPSetDimensions(pep.p, nev, PETSC_DEFAULT, PETSC_DEFAULT), "PEPSetDimensions");
  check(PEPSetTarget(pep.p, res.target), "PEPSetTarget");
  check(PEPSetWhichEigenpairs(pep.p, PEP_TARGET_MAGNITUDE), "PEPSetWhichEigenpairs");
  check(PEPSetTolerances(pep.p, opt.tol, opt.max_it > 0 ? opt.max_it : PETSC_DEFAULT), "PEPSetTolerances");
  // λ = α μ with α of the order of the wanted eigenvalues (wantedScale). Unscaled (α = 1), TOAR
  // stagnated on a 40-element cantilever whose wanted |λ| run from 3.5 to 300 rad/s: one pair
  // every ~25 restarts, the last at restart 86 of 100 with GCC and past 100 with clang (measured);
  // with α = 2…100 all 12 converge in 1–14 restarts. SLEPc's own α = √(‖K‖/‖M‖) ~ ω_max scales for
  // the whole FE spectrum instead and cost the low modes two digits (measured; Betcke 2008).
  const double alpha = wantedScale(M, K, nev, opt);
  check(PEPSetScale(pep.p, alpha != 1.0 ? PEP_SCALE_SCALAR : PEP_SCALE_NONE, alpha, nullptr, nullptr, PETSC_DEFAULT,
                    PETSC_DEFAULT),
        "PEPSetScale");
  ST st;
  check(PEPGetST(pep.p, &st), "PEPGetST");
  configureShiftInvert(st, A0.m, comm, false);
  check(PEPSetFromOptions(pep.p), "PEPSetFromOptions");
  PEPType pep_type;
  check(PEPGetType(pep.p, &pep_type), "PEPGetType");
  PetscScalar target = res.target;
  check(PEPGetTarget(pep.p, &target), "PEPGetTarget");
  res.target = target;
  check(PEPSolve(pep.p), "PEPSolve (factorization of P(target) and TOAR)");
  res.method = "PEP " + describe(pep_type, st);

  collectPairs(pep.p, A0.m, nev, "pep", res);
  return res;
}

#else  // built without PETSc

SparseEigenResult sparseGeneralizedEigen(const SparseMatrix&, const SparseMatrix&, const SparseEigenOptions&) {
  parallel::requirePetsc("--solver sparse");  // throws "unavailable"
  return {};
}

SparseEigenResult sparseQuadraticEigen(const SparseMatrix&, const SparseMatrix&, const SparseMatrix&,
                                       const SparseEigenOptions&) {
  parallel::requirePetsc("--solver sparse");
  return {};
}

#endif

}  // namespace whirl
