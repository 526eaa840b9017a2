#include "linearize/simulate.hpp"

#include <fmt/format.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_newton.h>

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>

#include "linearize/ida_block_solver.hpp"
#include "linearize/ida_vector.hpp"
#include "linearize/jacobian.hpp"
#include "linearize/simulate_aero.hpp"
#include "linearize/unsteady_aero.hpp"
#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace {

// The record's pages mapped in one call instead of one page fault per 4 KiB page as rows are
// written (a 600 s run at 0.05 s of the 5MW records 6 MB; a fault costs ~13 µs on a virtual machine,
// 7 % of that run). A hint: an older kernel without MADV_POPULATE_WRITE ignores it.
void prefault(void* data, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintptr_t page = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

// The SUNDIALS objects of one run, released in reverse order of creation.
struct IdaHandles {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, yp = nullptr;
  SUNLinearSolver ls = nullptr;
  SUNNonlinearSolver nls = nullptr;
  void* mem = nullptr;
  ~IdaHandles() {
    if (mem) IDAFree(&mem);
    if (nls) SUNNonlinSolFree(nls);
    if (ls) SUNLinSolFree(ls);
    if (yp) N_VDestroy(yp);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

// What the IDA callbacks see: the model, the time functions of the prescribed coordinates and
// inputs, and the buffers of one evaluation.
struct Problem {
  const Model& m;
  const OperatingPoint& start;
  const SimulationOptions& opt;
  std::vector<int> states;  // coordinates integrated
  Workspace<double> ws;
  JacobianWorkspace jw;
  VecX q, qd, qdd, u, e;
  VecX q_kinematics;  // the coordinates of the kinematics in ws, when known
  bool kinematics_known = false;
  MatX Mfull;
  int nz = 0;             // aerodynamic states after [q; v] in y (linearize/simulate_aero.hpp)
  VecX z, zdot;           // their values and rates f(q, v, z) at the last evaluation
  AeroRecord record;      // the quasi-steady BEM of the last residual (with aerodynamic states)
  AeroInflow bem_inflow;  // its induced velocities
  AeroStateLoads aero_loads;
  VecX held;                 // the controller's commands (SimulationOptions::controller), per controlled input
  std::string ida_message;   // the last message IDA reported
  std::exception_ptr error;  // an exception thrown inside a callback, rethrown after IDASolve

  Problem(const Model& model, const OperatingPoint& s, const SimulationOptions& o)
      : m(model),
        start(s),
        opt(o),
        ws(model),
        jw(model),
        e(VecX::Zero(model.ndof())),
        nz(simulationAeroStateCount(model, o)),
        z(VecX::Zero(nz)),
        zdot(VecX::Zero(nz)),
        aero_loads(model) {
    const double tolerance = simulationBemTolerance(model.aero.bem.tolerance, o.rtol);
    for (BemRoot& r : ws.bem) r.tolerance = tolerance;
  }

  int n() const { return static_cast<int>(states.size()); }

  // Every coordinate, rate and input at time t; the states' entries are then overwritten from y.
  void prescribe(double t) {
    q = start.q + start.qd * t;
    qd = start.qd;
    qdd.setZero(m.ndof());
    u = start.u;
    for (const InputSignal& in : opt.inputs) {
      const SignalValue v = evaluateSignal(in.signal, start.u(in.input), t);
      const double du = v.value - start.u(in.input);
      u(in.input) = v.value;
      for (const InputDofTarget& d : m.inputs[in.input].dofs) {
        q(d.dof) += d.gain * du;
        qd(d.dof) += d.gain * v.rate;
        qdd(d.dof) += d.gain * v.acceleration;
      }
    }
    for (size_t k = 0; k < opt.controller.inputs.size(); ++k) {
      const int i = opt.controller.inputs[k];
      const double du = held(static_cast<Eigen::Index>(k)) - start.u(i);
      u(i) = held(static_cast<Eigen::Index>(k));
      for (const InputDofTarget& d : m.inputs[i].dofs) q(d.dof) += d.gain * du;
    }
    for (const DrivenDof& d : opt.driven) {
      const SignalValue v = evaluateSignal(d.signal, 0.0, t);
      q(d.dof) = start.q(d.dof) + v.value - evaluateSignal(d.signal, 0.0, 0.0).value;
      qd(d.dof) = v.rate;
      qdd(d.dof) = v.acceleration;
    }
  }

  // e at the loaded q, q̇, q̈, u (and z, with their rates zdot), recording the coordinates of the
  // kinematics it leaves in ws.
  void evaluateResidual() {
    kinematics_known = false;  // should the residual throw
    if (nz > 0) {
      residual(m, ws, q, qd, qdd, u, e, nullptr, &record);
      bem_inflow = record.inflow();
      addAeroStateLoads(m, ws, q, qd, u, bem_inflow, opt.frozen_inflow, z, aero_loads, e, zdot);
    } else {
      residual(m, ws, q, qd, qdd, u, e);
    }
    q_kinematics = q;  // same size each time: no allocation
    kinematics_known = true;
  }

  // Mfull at q. IDA asks for the blocks at the iterate whose residual it has just evaluated: the
  // kinematics in ws are then at q (their positions do not depend on the rates), not evaluated again.
  void massAtQ() {
    if (kinematics_known && q_kinematics == q) {
      massMatrixAtKinematics(m, ws, Mfull);
    } else {
      kinematics_known = false;
      massMatrix(m, ws, q, Mfull);
      q_kinematics = q;
      kinematics_known = true;
    }
  }

  void load(double t, const double* y, const double* yp) {
    prescribe(t);
    const int ns = n();
    for (int k = 0; k < ns; ++k) {
      q(states[k]) = y[k];
      qd(states[k]) = y[ns + k];
      if (yp) qdd(states[k]) = yp[ns + k];
    }
    for (int k = 0; k < nz; ++k) z(k) = y[2 * ns + k];
  }
};

// F(t, y, ẏ) = [q̇ − v; e(q, v, v̇)] on the states.
int residualFn(double t, N_Vector yy, N_Vector yp, N_Vector rr, void* data) {
  Problem& p = *static_cast<Problem*>(data);
  try {
    const double* y = N_VGetArrayPointer(yy);
    const double* d = N_VGetArrayPointer(yp);
    double* r = N_VGetArrayPointer(rr);
    p.load(t, y, d);
    p.evaluateResidual();
    const int ns = p.n();
    bool finite = true;
    for (int k = 0; k < ns; ++k) {
      r[k] = d[k] - y[ns + k];
      r[ns + k] = p.e(p.states[k]);
      finite = finite && std::isfinite(r[ns + k]);
    }
    for (int k = 0; k < p.nz; ++k) {  // ż − f(q, v, z)
      r[2 * ns + k] = d[2 * ns + k] - p.zdot(k);
      finite = finite && std::isfinite(r[2 * ns + k]);
    }
    return finite ? 0 : 1;  // recoverable: IDA retries with a smaller step
  } catch (...) {
    p.error = std::current_exception();
    return -1;
  }
}

// The blocks of IDA's iteration matrix at (t, y, ẏ) (linearize/ida_block_solver.hpp): ∂e/∂q and
// ∂e/∂q̇ from the AD passes of the linearization, M from the mass-matrix assembly, on the states.
int iterationBlocks(Problem& p, double t, const double* y, const double* yp, bool mass_only, MatX& dedq, MatX& dedqd,
                    MatX& M) {
  p.load(t, y, yp);
  const int ns = p.n();
  if (mass_only) {
    p.massAtQ();
    for (int r = 0; r < ns; ++r)
      for (int k = 0; k < ns; ++k) M(r, k) = p.Mfull(p.states[r], p.states[k]);
    return M.allFinite() ? 0 : 1;
  }
  const MatX dq = residualJacobian(p.m, p.jw, p.q, p.qd, p.qdd, p.u, Wrt::Q, p.states);
  const MatX dqd = residualJacobian(p.m, p.jw, p.q, p.qd, p.qdd, p.u, Wrt::Qd, p.states);
  p.massAtQ();
  for (int r = 0; r < ns; ++r)
    for (int k = 0; k < ns; ++k) {
      dedq(r, k) = dq(p.states[r], k);
      dedqd(r, k) = dqd(p.states[r], k);
      M(r, k) = p.Mfull(p.states[r], p.states[k]);
    }
  return dedq.allFinite() && dedqd.allFinite() && M.allFinite() ? 0 : 1;
}

// The aerodynamic states' blocks at (t, y, ẏ) (linearize/ida_block_solver.hpp): the linear model's
// (unsteadyAeroLinearAt) at the states' current values, on the induction the loads see there; their load
// derivatives replace the quasi-steady ones in ∂e/∂q and ∂e/∂q̇ (held induction: an approximate Newton matrix).
int aeroStateBlocks(Problem& p, double t, const double* y, const double* yp, MatX& dedq, MatX& dedqd,
                    FirstOrderBlocks& fo) {
  p.load(t, y, yp);
  p.evaluateResidual();
  OperatingPoint at = p.start;
  at.q = p.q;
  at.qd = p.qd;
  at.qdd = p.qdd;
  at.u = p.u;
  at.inflow = p.opt.frozen_inflow.empty() ? p.bem_inflow : p.opt.frozen_inflow;
  const UnsteadyAeroLinear ua = unsteadyAeroLinearAt(p.m, at, p.z, p.states, false);
  const int ns = p.n();
  for (int r = 0; r < ns; ++r) {
    const int i = p.states[r];
    for (int k = 0; k < ns; ++k) {
      dedq(r, k) -= ua.dK(i, k);
      dedqd(r, k) -= ua.dC(i, k);
    }
    fo.G.row(r) = ua.G.row(i);
  }
  fo.Zq = ua.Zq;
  fo.Zv = ua.Zqd;
  fo.Azz = ua.Azz;
  return dedq.allFinite() && dedqd.allFinite() && fo.G.allFinite() && fo.Zq.allFinite() && fo.Zv.allFinite() &&
                 fo.Azz.allFinite()
             ? 0
             : 1;
}

void errorHandler(int, const char*, const char*, char* msg, void* data) {
  static_cast<Problem*>(data)->ida_message = msg ? msg : "";
}

// ẏ consistent with y at t: q̇ = v, v̇ from M v̇ = e(q, v, 0) (e = F − M q̈).
void consistentRates(Problem& p, double t, const double* y, double* yp) {
  p.load(t, y, nullptr);
  p.evaluateResidual();
  p.massAtQ();
  const int ns = p.n();
  MatX M(ns, ns);
  VecX F(ns);
  for (int r = 0; r < ns; ++r) {
    F(r) = p.e(p.states[r]);
    for (int k = 0; k < ns; ++k) M(r, k) = p.Mfull(p.states[r], p.states[k]);
  }
  Eigen::LDLT<MatX> ldlt(M);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() <= 0)
    throw ComputeError(fmt::format("simulate: t = {:g} s: the mass matrix is not positive definite", t));
  const VecX a = ldlt.solve(F);
  if (!a.allFinite())
    throw ComputeError(fmt::format("simulate: t = {:g} s: the initial accelerations are not finite", t));
  for (int k = 0; k < ns; ++k) {
    yp[k] = y[ns + k];
    yp[ns + k] = a(k);
  }
  for (int k = 0; k < p.nz; ++k) yp[2 * ns + k] = p.zdot(k);
}

void check(int flag, const char* what) {
  if (flag < 0) throw ComputeError(std::string("simulate: SUNDIALS: ") + what + " failed");
}

std::string flagName(int flag) {
  char* s = IDAGetReturnFlagName(flag);
  std::string name = s ? s : std::to_string(flag);
  std::free(s);
  return name;
}

/// What an IDA failure means for a user, in words, then SUNDIALS' flag name (for a bug report): its own
/// message (`p.ida_message`) names internal options (mxstep, tout) a user cannot set.
std::string idaFailure(int flag, double t, const SimulationOptions& opt) {
  std::string why;
  switch (flag) {
    case IDA_TOO_MUCH_WORK:
      why = fmt::format(
          "more than {} integrator steps between two output instants ({:g} s apart): the motion is too "
          "fast for the time step it needs (a rotor spinning up, a diverging model?)",
          opt.max_steps, opt.dt_out);
      break;
    case IDA_TOO_MUCH_ACC: why = "the tolerances cannot be met (--rtol, --atol too small for double precision?)"; break;
    case IDA_ERR_FAIL:
    case IDA_CONV_FAIL:
      why =
          "the integrator's step size fell to its minimum without meeting the tolerances: the motion diverges or "
          "jumps (an unstable model, an input step too large, an operating point outside the model's range?)";
      break;
    case IDA_LSETUP_FAIL:
    case IDA_LSOLVE_FAIL:
      why = "the iteration matrix could not be factored or solved (a singular mass matrix along the motion?)";
      break;
    case IDA_RES_FAIL:
    case IDA_REP_RES_ERR:
      why = "the equations could not be evaluated along the motion (a state outside the model's range?)";
      break;
    default: why = "the integration failed";
  }
  return fmt::format("simulate: t = {:.6g} s: {} (SUNDIALS IDA: {})", t, why, flagName(flag));
}

// IDA's counters of the segment since the last (re)initialization.
void addStatistics(void* mem, Simulation& sim) {
  long nsteps = 0, nres = 0, nni = 0, nnf = 0, netf = 0;
  IDAGetNumSteps(mem, &nsteps);
  IDAGetNumResEvals(mem, &nres);
  IDAGetNonlinSolvStats(mem, &nni, &nnf);
  IDAGetNumErrTestFails(mem, &netf);
  sim.steps += nsteps;
  sim.residual_evaluations += nres;
  sim.nonlinear_iterations += nni;
  sim.convergence_failures += nnf;
  sim.error_test_failures += netf;
}

/// The size of a simulation, estimated before anything is allocated or integrated (issue 48, item 3):
/// the recorded instants and values (memory), and the rotor's revolutions (the step count grows with
/// them). InputError naming the options to change.
void checkSimulationSize(const Model& m, const OperatingPoint& start, const SimulationOptions& opt) {
  const double records = std::floor(opt.t_end / opt.dt_out + 1e-9) + 2;  // + t_end off the grid
  if (records > static_cast<double>(limits::kMaxSimulationRecords))
    throw InputError(
        fmt::format("simulate: tmax: {:g} s recorded every {:g} s (dt-out) are {:.3g} instants, more than {} "
                    "(src/base/limits.hpp): give a larger --dt-out or a shorter --tmax",
                    opt.t_end, opt.dt_out, records, limits::kMaxSimulationRecords));
  const double columns = 2.0 * m.ndof() + m.ninput() + m.noutput() + simulationAeroStateCount(m, opt);
  if (records * columns > limits::kMaxSimulationValues)
    throw InputError(fmt::format(
        "simulate: tmax: {:.3g} instants of {:g} values each ({:.0f} MB in memory) are more than {:.3g} values "
        "(src/base/limits.hpp): give a larger --dt-out or a shorter --tmax",
        records, columns, records * columns * 8e-6, limits::kMaxSimulationValues));
  double rate = 0;  // [rad/s]
  for (int i : m.roles.azimuth) rate = std::max(rate, std::abs(start.qd(i)));
  const double revolutions = opt.t_end * rate / (2 * M_PI);
  if (!(revolutions <= limits::kMaxSimulationRevolutions))
    throw InputError(fmt::format(
        "simulate: the rotor turns {:.3g} revolutions in tmax = {:g} s at {:.6g} rpm, more than {:g} "
        "(src/base/limits.hpp: the integrator's steps grow with them): give a lower --rpm or a shorter --tmax",
        revolutions, opt.t_end, rate * 30 / M_PI, limits::kMaxSimulationRevolutions));
}

/// The options and the start point against the model: times, tolerances, the controller's step, sizes,
/// the signals' inputs and the driven coordinates.
void checkOptions(const Model& m, const OperatingPoint& start, const SimulationOptions& opt) {
  if (!(opt.t_end > 0) || !std::isfinite(opt.t_end)) throw InputError("simulate: tmax: must be a finite time > 0");
  if (!(opt.dt_out > 0) || !std::isfinite(opt.dt_out)) throw InputError("simulate: dt-out: must be a finite time > 0");
  if (!(opt.rtol > 0) || !(opt.atol > 0)) throw InputError("simulate: tolerances: must be > 0");
  if (opt.controller.step && (!(opt.controller.dt > 0) || !(opt.t_end / opt.controller.dt <= 1e6)))
    throw InputError("simulate: controller time step: must be > 0 and at most 1e6 steps in the simulated time");
  if (start.q.size() != m.ndof() || start.qd.size() != m.ndof() || start.u.size() != m.ninput())
    throw InputError("simulate: the start point does not match the model's coordinates and inputs");
  if (!m.body_states.empty())
    throw InputError(
        "simulate: the model has first-order states of the linear model only (HydroDyn's state-space "
        "radiation, RdtnMod = 2); --set RdtnMod=0 simulates without the radiation memory");
  if (!opt.frozen_inflow.empty() && (opt.frozen_inflow.axial.size() != m.aero.nstations() ||
                                     opt.frozen_inflow.tangential.size() != m.aero.nstations()))
    throw InputError("simulate: frozen inflow: not one induced velocity per blade element of the model");
  for (const InputSignal& in : opt.inputs)
    if (in.input < 0 || in.input >= m.ninput()) throw InputError("simulate: input signal: no such input");
  const std::vector<int> active = m.activeDofs();
  for (const DrivenDof& d : opt.driven)
    if (std::find(active.begin(), active.end(), d.dof) == active.end())
      throw InputError("simulate: driven coordinate: not an active coordinate of the model");
}

/// Breakpoints of the inputs inside (0, t_end), the controller's calls, then t_end: IDA stops and
/// restarts there.
std::vector<double> stopTimes(const SimulationOptions& opt) {
  std::vector<double> stops;
  for (const InputSignal& in : opt.inputs)
    for (double b : signalBreakpoints(in.signal))
      if (b > 0 && b < opt.t_end) stops.push_back(b);
  for (const DrivenDof& d : opt.driven)
    for (double b : signalBreakpoints(d.signal))
      if (b > 0 && b < opt.t_end) stops.push_back(b);
  if (opt.controller.step)
    for (long k = 1; k * opt.controller.dt < opt.t_end; ++k)
      stops.push_back(static_cast<double>(k) * opt.controller.dt);
  stops.push_back(opt.t_end);
  std::sort(stops.begin(), stops.end());
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
  return stops;
}

/// IDA on the residual with whirl's block-elimination linear solver and Newton, the tolerances and the
/// step limit of `opt`, started from h.y, h.yp at t = 0.
void attachIntegrator(IdaHandles& h, Problem& p, const Model& m, int ns, const SimulationOptions& opt) {
  h.mem = IDACreate(h.ctx);
  if (!h.mem) throw ComputeError("simulate: SUNDIALS: IDACreate failed");
  check(IDASetErrHandlerFn(h.mem, errorHandler, &p), "IDASetErrHandlerFn");
  check(IDAInit(h.mem, residualFn, 0.0, h.y, h.yp), "IDAInit");
  check(IDASStolerances(h.mem, opt.rtol, opt.atol), "IDASStolerances");
  check(IDASetUserData(h.mem, &p), "IDASetUserData");
  // The rotor angle tells the linear solver when M's coupling of rotating and fixed coordinates has
  // turned too far (linearize/ida_block_solver.hpp): the azimuth state, or its prescribed motion.
  BlockSolverOptions bo;
  bo.first_order = p.nz;
  if (p.nz > 0)
    bo.first_order_blocks = [&p](double t, const double* yy, const double* ypp, MatX& dq, MatX& dqd,
                                 FirstOrderBlocks& fo) {
      try {
        return aeroStateBlocks(p, t, yy, ypp, dq, dqd, fo);
      } catch (...) {
        p.error = std::current_exception();
        return -1;
      }
    };
  if (!m.roles.azimuth.empty()) {
    const int az = m.roles.azimuth.front();
    bo.angle = [&p, az](double t, const double* yy) {
      for (int k = 0; k < p.n(); ++k)
        if (p.states[k] == az) return yy[k];
      p.prescribe(t);
      return p.q(az);
    };
  }
  h.ls = newBlockEliminationSolver(
      ns, h.mem,
      [&p](double t, const double* yy, const double* ypp, bool mass_only, MatX& dq, MatX& dqd, MatX& M) {
        try {
          return iterationBlocks(p, t, yy, ypp, mass_only, dq, dqd, M);
        } catch (...) {
          p.error = std::current_exception();
          return -1;
        }
      },
      bo, h.ctx);
  if (!h.ls) throw ComputeError("simulate: SUNDIALS: cannot allocate the linear solver");
  check(IDASetLinearSolver(h.mem, h.ls, nullptr), "IDASetLinearSolver");
  h.nls = SUNNonlinSol_Newton(h.y, h.ctx);
  if (!h.nls) throw ComputeError("simulate: SUNDIALS: cannot allocate the Newton solver");
  check(IDASetNonlinearSolver(h.mem, h.nls), "IDASetNonlinearSolver");
  check(attachConvergenceTest(h.nls, h.ls), "SUNNonlinSolSetConvTestFn");
  check(IDASetMaxNumSteps(h.mem, opt.max_steps), "IDASetMaxNumSteps");
}

}  // namespace

double simulationBemTolerance(double model_tolerance, double rtol) {
  constexpr double kAeroDynIndToler = 5e-10;  // AeroDyn: IndToler "default" in double precision
  return std::max(model_tolerance, std::min(kAeroDynIndToler, 1e-3 * rtol));
}

namespace {

// The coordinates IDA integrates: the model's active ones, neither prescribed nor driven.
std::vector<int> integratedStates(const Model& m, const SimulationOptions& opt) {
  auto held = [&](int i) {
    return std::find(opt.prescribed.begin(), opt.prescribed.end(), i) != opt.prescribed.end() ||
           std::any_of(opt.driven.begin(), opt.driven.end(), [i](const DrivenDof& d) { return d.dof == i; });
  };
  std::vector<int> states;
  for (int i : m.activeDofs())
    if (!held(i)) states.push_back(i);
  return states;
}

// The number of recorded instants: every dt_out from 0 [s], and t_end when it is off that grid.
long recordCount(const SimulationOptions& opt) {
  const long nout = static_cast<long>(std::floor(opt.t_end / opt.dt_out + 1e-9)) + 1;
  const bool last_extra = (nout - 1) * opt.dt_out < opt.t_end * (1 - 1e-12);
  return nout + (last_extra ? 1 : 0);
}

// The record's matrices sized for nrec instants, their pages mapped at once (prefault).
void allocateRecord(const Model& m, long nrec, int nz, Simulation& sim) {
  sim.z.resize(nrec, nz);
  sim.q.resize(nrec, m.ndof());
  sim.qd.resize(nrec, m.ndof());
  sim.u.resize(nrec, m.ninput());
  sim.y.resize(nrec, m.noutput());
  sim.time.reserve(static_cast<std::size_t>(nrec));
  for (MatX* a : {&sim.q, &sim.qd, &sim.u, &sim.y}) prefault(a->data(), a->size() * sizeof(double));
}

// Writes the record's rows: time, coordinates, rates, inputs and the model's outputs at an instant.
class Recorder {
 public:
  Recorder(const Model& m, const SimulationOptions& opt, Problem& p, Simulation& sim)
      : m_(m), opt_(opt), p_(p), sim_(sim), wy_(m), y_out_(m.noutput()) {}

  // Row k at time t [s] from IDA's y, ẏ (null: the prescribed motion alone).
  void operator()(long k, double t, const double* y, const double* yp) {
    p_.load(t, y, yp);
    sim_.time.push_back(t);
    sim_.q.row(k) = p_.q.transpose();
    sim_.qd.row(k) = p_.qd.transpose();
    if (m_.ninput() > 0) sim_.u.row(k) = p_.u.transpose();
    if (p_.nz > 0) sim_.z.row(k) = p_.z.transpose();  // row k of a 0-column matrix: offset on a null pointer
    if (m_.noutput() > 0) {
      // The BEM roots of the integrator's last residual start the outputs' root searches: a step
      // away instead of one recorded interval (the outputs' own last roots); the same roots.
      wy_.bem = p_.ws.bem;
      if (p_.nz > 0) {  // the loads of the states, on the induction the equations of motion take
        const AeroInflow inflow = simulationElementInflow(m_, wy_, p_.q, p_.qd, p_.qdd, p_.u, opt_);
        evaluateOutputs(m_, wy_, p_.q, p_.qd, p_.qdd, y_out_, &p_.u, &inflow, {}, &p_.z);
      } else {
        evaluateOutputs(m_, wy_, p_.q, p_.qd, p_.qdd, y_out_, &p_.u);
      }
      sim_.y.row(k) = y_out_.transpose();
    }
    if (opt_.progress) opt_.progress(t, opt_.t_end);
  }

 private:
  const Model& m_;
  const SimulationOptions& opt_;
  Problem& p_;
  Simulation& sim_;
  Workspace<double> wy_;
  VecX y_out_;
};

// The controller's commands at a stop tc [s]: from the motion y there (the held values before the call).
void applyController(Problem& p, const SimulationOptions& opt, double tc, const double* y) {
  p.load(tc, y, nullptr);
  p.held = opt.controller.step(tc, p.q, p.qd, p.u);
  if (p.held.size() != static_cast<Eigen::Index>(opt.controller.inputs.size()) || !p.held.allFinite())
    throw ComputeError(fmt::format("simulate: t = {:.6g} s: the controller's commands are not finite", tc));
}

// IDA started at t = 0: its state vectors from `start`, the controller's first commands (from the start
// point's inputs), consistent rates, the integrator attached and stopping at the first stop.
void startIntegrator(IdaHandles& h, Problem& p, const Model& m, const OperatingPoint& start,
                     const SimulationOptions& opt, const std::vector<double>& stops) {
  const int ns = p.n();
  check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
  h.y = newFastSerialVector(2 * ns + p.nz, h.ctx);
  h.yp = newFastSerialVector(2 * ns + p.nz, h.ctx);
  if (!h.y || !h.yp) throw ComputeError("simulate: SUNDIALS: cannot allocate the state vectors");
  double* y = N_VGetArrayPointer(h.y);
  double* yp = N_VGetArrayPointer(h.yp);
  for (int k = 0; k < ns; ++k) {
    y[k] = start.q(p.states[k]);
    y[ns + k] = start.qd(p.states[k]);
  }
  if (p.nz > 0) {  // the aerodynamic states at their steady values at the start
    const VecX z0 = simulationAeroStart(m, start, opt);
    for (int k = 0; k < p.nz; ++k) y[2 * ns + k] = z0(k);
  }
  if (opt.controller.step) {
    p.held = VecX(static_cast<Eigen::Index>(opt.controller.inputs.size()));
    for (size_t k = 0; k < opt.controller.inputs.size(); ++k)
      p.held(static_cast<Eigen::Index>(k)) = start.u(opt.controller.inputs[k]);
    applyController(p, opt, 0.0, y);
  }
  consistentRates(p, 0.0, y, yp);
  attachIntegrator(h, p, m, ns, opt);
  check(IDASetStopTime(h.mem, stops[0]), "IDASetStopTime");
}

// IDA from t to tout [s], restarting at every stop it meets (an input breakpoint, a controller call):
// from consistent rates under the inputs after it, the controller called first when due. ComputeError
// when IDA fails or the run's steps exceed limits::kMaxSimulationSteps.
void integrateTo(IdaHandles& h, Problem& p, const SimulationOptions& opt, const std::vector<double>& stops,
                 size_t& next_stop, double tout, double& t, Simulation& sim) {
  double* y = N_VGetArrayPointer(h.y);
  double* yp = N_VGetArrayPointer(h.yp);
  while (true) {
    const int flag = IDASolve(h.mem, tout, &t, h.y, h.yp, IDA_NORMAL);
    if (p.error) std::rethrow_exception(p.error);
    long steps = 0;
    IDAGetNumSteps(h.mem, &steps);
    if (sim.steps + steps > limits::kMaxSimulationSteps)
      throw ComputeError(fmt::format(
          "simulate: t = {:.6g} s: more than {} integrator steps (src/base/limits.hpp) for {:g} s of {:g}: the "
          "motion is too fast for the time step it needs (a rotor spinning up, a diverging model?)",
          t, limits::kMaxSimulationSteps, t, opt.t_end));
    if (flag < 0) throw ComputeError(idaFailure(flag, t, opt));
    if (flag != IDA_TSTOP_RETURN) break;
    // At an input breakpoint: restart from consistent rates under the inputs after it.
    const double ts = stops[next_stop];
    if (next_stop + 1 < stops.size()) {
      ++next_stop;
      addStatistics(h.mem, sim);
      if (opt.controller.step && std::abs(ts / opt.controller.dt - std::round(ts / opt.controller.dt)) < 1e-9)
        applyController(p, opt, ts, y);
      consistentRates(p, ts, y, yp);
      check(IDAReInit(h.mem, ts, h.y, h.yp), "IDAReInit");
      check(IDASetStopTime(h.mem, stops[next_stop]), "IDASetStopTime");
    }
    if (ts >= tout * (1 - 1e-12)) break;
  }
}

}  // namespace

Simulation simulate(const Model& m, const OperatingPoint& start, const SimulationOptions& opt) {
  checkOptions(m, start, opt);
  checkSimulationSize(m, start, opt);
  Problem p(m, start, opt);
  p.states = integratedStates(m, opt);
  const int ns = p.n();

  Simulation sim;
  sim.states = p.states;
  const long nrec = recordCount(opt);
  allocateRecord(m, nrec, p.nz, sim);
  Recorder record(m, opt, p, sim);
  const std::vector<double> stops = stopTimes(opt);

  if (ns == 0 && p.nz == 0) {  // everything prescribed: the motion is known
    for (long k = 0; k < nrec; ++k) record(k, std::min(k * opt.dt_out, opt.t_end), nullptr, nullptr);
    return sim;
  }

  IdaHandles h;
  startIntegrator(h, p, m, start, opt, stops);
  size_t next_stop = 0;
  record(0, 0.0, N_VGetArrayPointer(h.y), N_VGetArrayPointer(h.yp));
  double t = 0;
  for (long k = 1; k < nrec; ++k) {
    const double tout = std::min(k * opt.dt_out, opt.t_end);
    integrateTo(h, p, opt, stops, next_stop, tout, t, sim);
    record(k, tout, N_VGetArrayPointer(h.y), N_VGetArrayPointer(h.yp));
    if (opt.stop && opt.stop(tout, sim.q.row(k).transpose())) {
      for (MatX* a : {&sim.q, &sim.qd, &sim.u, &sim.y, &sim.z}) a->conservativeResize(k + 1, Eigen::NoChange);
      sim.stopped = true;
      break;
    }
  }
  addStatistics(h.mem, sim);
  sim.jacobian_evaluations = blockSolverStatistics(h.ls).evaluations;
  sim.mass_matrix_evaluations = blockSolverStatistics(h.ls).mass_evaluations;
  return sim;
}

}  // namespace whirl
