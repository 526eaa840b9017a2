#include "linearize/ida_block_solver.hpp"

#include <ida/ida.h>
#include <nvector/nvector_serial.h>

#include <Eigen/LU>
#include <cmath>

namespace whirl {
namespace {

// idaNlsConvTest's constants (SUNDIALS 6.4.1, ida_nls.c / ida.c).
constexpr double kRateMax = 0.9;      // RATEMAX: a larger contraction factor is a divergence
constexpr double kSsAfterSetup = 20;  // ss after a linear-solver setup (idaNlsLSetup)

struct Content {
  Content(int size, void* mem, IterationBlocksFn fn, const BlockSolverOptions& o)
      : n(size),
        ida(mem),
        blocks(std::move(fn)),
        opt(o),
        dedq(size, size),
        dedqd(size, size),
        M(size, size),
        S(size, size),
        lu(size),
        rhs(size),
        x1(size),
        nz(o.first_order) {
    if (nz > 0) {
      fo.G = MatX::Zero(size, nz);
      fo.Zq = MatX::Zero(nz, size);
      fo.Zv = MatX::Zero(nz, size);
      fo.Azz = MatX::Zero(nz, nz);
      D.resize(nz, nz);
      W.resize(nz, size);
      w.resize(nz);
    }
  }
  int n;
  void* ida;
  IterationBlocksFn blocks;
  BlockSolverOptions opt;
  MatX dedq, dedqd, M;  // the blocks of the last evaluation
  MatX S;               // J21 + c J22 = ∂e/∂q + c ∂e/∂q̇ − c² M
  Eigen::PartialPivLU<MatX> lu;
  VecX rhs, x1;
  int nz;                         // first-order states (0: none)
  FirstOrderBlocks fo;            // their blocks of the last evaluation
  MatX D, W;                      // c I − A_zz; D⁻¹ (Z_q + c Z_v)
  Eigen::PartialPivLU<MatX> dlu;  // of D
  VecX w;                         // D⁻¹ (b3 − Z_v b1)

  bool have_blocks = false, factored = false, refresh = false;
  double c = NAN;                           // of the factorization
  double t_last = NAN;                      // the Newton iteration of the last solve: its time, step count,
  long nst_last = -1, ncfn_last = 0;        // failed steps so far
  long nst_blocks = 0;                      // step count when the blocks were evaluated
  double angle_blocks = 0, angle_mass = 0;  // rotor angle when the blocks, M were evaluated
  double ss = kSsAfterSetup, oldnrm = 0;    // the convergence test's rate estimate and first correction
  sunindextype last_flag = SUNLS_SUCCESS;
  BlockSolverStatistics stats;
};

Content& content(SUNLinearSolver s) { return *static_cast<Content*>(s->content); }

SUNLinearSolver_Type type(SUNLinearSolver) { return SUNLINEARSOLVER_MATRIX_EMBEDDED; }
SUNLinearSolver_ID id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }

// Called by IDA at its (re)initialization: its counters restart there, so does the solver.
int initialize(SUNLinearSolver s) {
  Content& p = content(s);
  p.have_blocks = p.factored = p.refresh = false;
  p.t_last = NAN;
  p.nst_last = -1;
  p.ncfn_last = 0;
  p.ss = kSsAfterSetup;
  p.last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

int evaluate(Content& p, double t, N_Vector yy, N_Vector yp, bool mass_only) {
  int flag = 0;
  try {
    flag = p.blocks(t, NV_DATA_S(yy), NV_DATA_S(yp), mass_only, p.dedq, p.dedqd, p.M);
    if (flag == 0 && !mass_only && p.nz > 0)
      flag = p.opt.first_order_blocks(t, NV_DATA_S(yy), NV_DATA_S(yp), p.dedq, p.dedqd, p.fo);
  } catch (...) {
    flag = -1;
  }
  ++(mass_only ? p.stats.mass_evaluations : p.stats.evaluations);
  p.factored = false;
  if (!mass_only) p.ss = kSsAfterSetup;  // new blocks: the matrix's contraction is not known yet
  if (flag != 0) p.have_blocks = false;
  return flag == 0 ? SUNLS_SUCCESS : flag > 0 ? SUNLS_PACKAGE_FAIL_REC : SUNLS_PACKAGE_FAIL_UNREC;
}

int factor(Content& p, double c) {
  p.S = p.dedq + c * p.dedqd - (c * c) * p.M;
  bool regular = std::isfinite(c);
  if (p.nz > 0) {  // the first-order states eliminated (header): S += G D⁻¹ (Z_q + c Z_v)
    p.D = -p.fo.Azz;
    p.D.diagonal().array() += c;
    p.dlu.compute(p.D);
    const auto dd = p.dlu.matrixLU().diagonal();
    for (int k = 0; k < p.nz; ++k) regular = regular && std::isfinite(dd(k)) && dd(k) != 0.0;
    p.W.noalias() = p.dlu.solve(p.fo.Zq + c * p.fo.Zv);
    p.S.noalias() += p.fo.G * p.W;
  }
  p.lu.compute(p.S);
  ++p.stats.factorizations;
  // The rate estimate survives a c that grows or falls by at most 25 % (the header): the blocks are
  // as old as they were, and a larger c weighs them less.
  if (!(c / p.c >= 0.75)) p.ss = kSsAfterSetup;
  p.c = c;
  const auto d = p.lu.matrixLU().diagonal();
  for (int k = 0; k < p.n; ++k) regular = regular && std::isfinite(d(k)) && d(k) != 0.0;
  p.factored = regular;
  return regular ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}

int solve(SUNLinearSolver s, SUNMatrix, N_Vector x, N_Vector b, double) {
  Content& p = content(s);
  double t = 0, cj = 0;
  N_Vector yypred, yppred, yy, yp, res;
  void* user = nullptr;
  long nst = 0, ncfn = 0;
  if (IDAGetNonlinearSystemData(p.ida, &t, &yypred, &yppred, &yy, &yp, &res, &cj, &user) != IDA_SUCCESS ||
      IDAGetNumSteps(p.ida, &nst) != IDA_SUCCESS || IDAGetNumStepSolveFails(p.ida, &ncfn) != IDA_SUCCESS)
    return static_cast<int>(p.last_flag = SUNLS_MEM_NULL);
  // The first solve of a Newton iteration (a new step, or the step retried with another size):
  // the matrix may change here, not between the iterates of one Newton iteration.
  const bool first = !(t == p.t_last && nst == p.nst_last && ncfn == p.ncfn_last);
  const bool failed_step = ncfn != p.ncfn_last;
  p.t_last = t;
  p.nst_last = nst;
  p.ncfn_last = ncfn;
  if (first || !p.have_blocks) {
    // The blocks at the current iterate (IDA's yy, yp: where b was evaluated).
    const double angle = p.opt.angle ? p.opt.angle(t, NV_DATA_S(yy)) : 0.0;
    if (!p.have_blocks || failed_step || p.refresh || nst - p.nst_blocks >= p.opt.max_age ||
        std::abs(angle - p.angle_blocks) > p.opt.max_turn) {
      p.refresh = false;
      if (const int f = evaluate(p, t, yy, yp, false); f != SUNLS_SUCCESS) return static_cast<int>(p.last_flag = f);
      p.have_blocks = true;
      p.nst_blocks = nst;
      p.angle_blocks = p.angle_mass = angle;
    } else if (std::abs(angle - p.angle_mass) > p.opt.max_mass_turn) {
      if (const int f = evaluate(p, t, yy, yp, true); f != SUNLS_SUCCESS) return static_cast<int>(p.last_flag = f);
      p.angle_mass = angle;
    }
  }
  if (!p.factored || cj != p.c)
    if (const int f = factor(p, cj); f != SUNLS_SUCCESS) return static_cast<int>(p.last_flag = f);

  const int n = p.n;
  const double* bd = NV_DATA_S(b);
  double* xd = NV_DATA_S(x);
  const Eigen::Map<const VecX> b1(bd, n), b2(bd + n, n);
  // J22 b1 = ∂e/∂q̇ b1 − c M b1
  p.rhs.noalias() = p.dedqd * b1;
  p.rhs.noalias() -= p.c * (p.M * b1);
  p.rhs += b2;
  if (p.nz > 0) {  // w = D⁻¹ (b3 − Z_v b1), rhs −= G w
    const Eigen::Map<const VecX> b3(bd + 2 * n, p.nz);
    p.w.noalias() = p.dlu.solve(b3 - p.fo.Zv * b1);
    p.rhs.noalias() -= p.fo.G * p.w;
  }
  p.x1.noalias() = p.lu.solve(p.rhs);
  Eigen::Map<VecX>(xd, n) = p.x1;
  Eigen::Map<VecX>(xd + n, n) = p.c * p.x1 - b1;
  if (p.nz > 0) Eigen::Map<VecX>(xd + 2 * n, p.nz) = p.w + p.W * p.x1;
  return static_cast<int>(p.last_flag = SUNLS_SUCCESS);
}

// idaNlsConvTest with the rate estimate held here (see the header); a slow contraction asks for
// fresh blocks at the next Newton iteration.
int convergenceTest(SUNNonlinearSolver nls, N_Vector, N_Vector del, double tol, N_Vector ewt, void* data) {
  Content& p = content(static_cast<SUNLinearSolver>(data));
  const double delnrm = N_VWrmsNorm(del, ewt);
  int m = 0;
  if (SUNNonlinSolGetCurIter(nls, &m) != SUN_NLS_SUCCESS) return SUN_NLS_MEM_NULL;
  if (m == 0) {
    p.oldnrm = delnrm;
    if (delnrm <= 1e-8 * tol) return SUN_NLS_SUCCESS;  // IDA: PT0001 · toldel, toldel = PT0001 · epsNewt
  } else {
    const double rate = std::pow(delnrm / p.oldnrm, 1.0 / m);
    if (rate > p.opt.max_rate) p.refresh = true;
    if (rate > kRateMax) return SUN_NLS_CONV_RECVR;
    p.ss = rate / (1 - rate);
  }
  return p.ss * delnrm <= tol ? SUN_NLS_SUCCESS : SUN_NLS_CONTINUE;
}

sunindextype lastFlag(SUNLinearSolver s) { return content(s).last_flag; }

int space(SUNLinearSolver s, long* lenrw, long* leniw) {
  const long n = content(s).n;
  *lenrw = 5 * n * n + 2 * n;
  *leniw = n;
  return SUNLS_SUCCESS;
}

int release(SUNLinearSolver s) {
  if (!s) return SUNLS_SUCCESS;
  delete static_cast<Content*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver newBlockEliminationSolver(int n, void* ida_mem, IterationBlocksFn blocks,
                                          const BlockSolverOptions& options, SUNContext ctx) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (!s) return nullptr;
  s->ops->gettype = type;
  s->ops->getid = id;
  s->ops->initialize = initialize;
  s->ops->solve = solve;
  s->ops->lastflag = lastFlag;
  s->ops->space = space;
  s->ops->free = release;
  try {
    s->content = new Content(n, ida_mem, std::move(blocks), options);
  } catch (...) {
    release(s);
    return nullptr;
  }
  return s;
}

int attachConvergenceTest(SUNNonlinearSolver nls, SUNLinearSolver s) {
  return SUNNonlinSolSetConvTestFn(nls, convergenceTest, s);
}

BlockSolverStatistics blockSolverStatistics(SUNLinearSolver s) { return content(s).stats; }

}  // namespace whirl
