#pragma once
/// \file
/// Nonlinear time simulation of the equations of motion e(q, q̇, q̈, u) = 0 with SUNDIALS IDA
/// (variable-order BDF, Hindmarsh et al. 2005, "SUNDIALS: Suite of nonlinear and differential/algebraic
/// equation solvers", ACM TOMS 31(3)).
///
/// The states are the active coordinates that are not prescribed, y = [q; v], written as the
/// implicit first-order system
///   F(t, y, ẏ) = [ q̇ − v ; e(q, v, v̇, u(t), t) ] = 0,
/// whose iteration matrix ∂F/∂y + c ∂F/∂ẏ = [[c I, −I], [−K, −C − c M]] takes K = −∂e/∂q and
/// C = −∂e/∂q̇ from the same AD passes as the linearization (residualJacobian) and M from the mass
/// matrix assembly (linearize/linearize.hpp): no finite differences. IDA's Newton iteration solves
/// with it by block elimination, K + c C + c² M of size n, re-factored for every c, K and C re-evaluated
/// when the Newton iteration slows down or the rotor has turned by 1 rad, M by 0.1 rad
/// (linearize/ida_block_solver.hpp); the vector kernels are linearize/ida_vector.hpp's.
///
/// Rheonomic coordinates — frozen ones (moving at their rate), the rotating ones of a driven rotor,
/// those on a prescribed motion (DrivenDof), those an input drives (q = value + gain u(t), e.g. a
/// pitch history) — are known functions of time
/// with their rates and accelerations; their rows of e are not equations of the simulation.
/// With aerodynamics, the induction is re-solved at every evaluation (quasi-steady BEM,
/// src/dynamics/aero_loads.hpp). With SimulationOptions::aero_states the blade elements' unsteady-airfoil
/// and dynamic-inflow states of the model (AeroDyn UA_Mod 4 or 6, DBEMT_Mod 3) are integrated too, after
/// [q; v] in y, from the linear model's equations (linearize/simulate_aero.hpp).
#include <functional>
#include <vector>

#include "linearize/operating_point.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/model/model.hpp"
#include "src/model/time_signal.hpp"

namespace whirl {

/// An input following a function of time (its other inputs stay at the start point's value).
struct InputSignal {
  int input = -1;
  TimeSignal signal;
};

/// A coordinate following a function of time from its start value: q = q0 + s(t) − s(0), with the
/// signal's rate and acceleration (rheonomic: e.g. Kane's imposed rotation, spinup(15, 6)).
struct DrivenDof {
  int dof = -1;
  TimeSignal signal;
};

/// A discrete-time controller in the loop, as ROSCO runs in OpenFAST (called every `dt` with the
/// motion there, its commands held until the next call): at t = 0, dt, 2dt, … `step` gets the time,
/// the coordinates, their rates and the inputs and returns the values of `inputs` (e.g. generator
/// torque and collective pitch). The integrator stops and restarts at each call (the held inputs jump).
struct DiscreteController {
  double dt = 0.01;         ///< [s], > 0
  std::vector<int> inputs;  ///< the inputs it sets (not driven by InputSignal at the same time)
  std::function<VecX(double, const VecX&, const VecX&, const VecX&)> step;
};

struct SimulationOptions {
  double t_end = 10;     ///< [s], > 0
  double dt_out = 0.01;  ///< interval of the recorded instants [s], > 0
  double rtol = 1e-6;    ///< IDA relative tolerance
  double atol = 1e-8;    ///< IDA absolute tolerance [m, rad, m/s, rad/s]
  /// Active coordinates moving at their start rate, q = q0 + q̇0 t (a driven rotor: the rotating
  /// coordinates). Not states.
  std::vector<int> prescribed;
  std::vector<InputSignal> inputs;
  std::vector<DrivenDof> driven;  ///< active coordinates on a prescribed motion; not states
  long max_steps = 200000;        ///< IDA steps between two recorded instants; more is a ComputeError (never hangs)
  /// A controller in the loop (empty `step`: none).
  DiscreteController controller;
  /// The blade elements' unsteady-airfoil and dynamic-inflow states as the model has them
  /// (aeroStateCount, src/dynamics/aero_unsteady.hpp) integrated with the structure, starting at their
  /// steady values (linearize/simulate_aero.hpp); false: the quasi-steady polar whatever the model has.
  bool aero_states = false;
  /// With aero_states and no dynamic inflow: the elements' induced velocities held at these values (a linear
  /// model's frozen wake) instead of the quasi-steady BEM's at every evaluation; empty: the BEM's.
  AeroInflow frozen_inflow;
  /// Called after each recorded instant with (t, t_end).
  std::function<void(double, double)> progress;
  /// Called after each recorded instant after the start with (t, q: all coordinates, dim ndof); true
  /// ends the integration there, the record kept up to and including that instant
  /// (Simulation::stopped). E.g. stopAtInvalidMotion: a diverging model is not integrated to t_end.
  std::function<bool(double, const VecX&)> stop;
};

/// The root tolerance of the induction's residual in a time simulation's residuals and outputs:
/// AeroDyn's own in double precision (IndToler "default", 5e-10: what OpenFAST's simulation solves
/// to), tightened to 1e-3·rtol for a tighter integration (the loads' error, ~10 × the tolerance
/// relative, stays far below IDA's), never below the model's (`model_tolerance`, the linearization's
/// 1e-13). The Newton matrix's AD passes keep the model's.
double simulationBemTolerance(double model_tolerance, double rtol);

/// The recorded time series. Row k of each matrix is instant time[k].
struct Simulation {
  std::vector<double> time;  ///< [s]
  MatX q, qd;                ///< all coordinates (ndof columns, model order) and their rates
  MatX u;                    ///< inputs (ninput columns)
  MatX y;                    ///< the model's outputs (noutput columns)
  MatX z;                    ///< the aerodynamic states (SimulationOptions::aero_states; 0 columns without)
  std::vector<int> states;   ///< the coordinates integrated (the others are prescribed)
  long steps = 0, residual_evaluations = 0, jacobian_evaluations = 0;  ///< IDA statistics
  long mass_matrix_evaluations = 0;  ///< M alone, to refresh IDA's iteration matrix between Jacobians
  long nonlinear_iterations = 0;     ///< Newton iterations (one residual and one linear solve each)
  long convergence_failures = 0;     ///< Newton iterations that failed to converge (the step is retried)
  long error_test_failures = 0;      ///< steps rejected by the local error test
  bool stopped = false;              ///< ended before t_end by SimulationOptions::stop
};

/// Integrates from `start` (coordinates, rates and inputs at t = 0; its q̈ is not used: the initial
/// accelerations are solved from M q̈ = F) to options.t_end.
/// \throws InputError for options out of range (t_end, dt_out, tolerances, an index), or a model with
///         first-order states of a body (Model::body_states: they are in the linear model only);
///         ComputeError "simulate: t = … s: <reason>" when IDA fails (no convergence, too many steps,
///         a non-finite residual), naming the time reached, or when M is not positive definite.
Simulation simulate(const Model& model, const OperatingPoint& start, const SimulationOptions& options);

}  // namespace whirl
