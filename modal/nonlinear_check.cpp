#include "modal/nonlinear_check.hpp"

#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>

#include "linearize/linearize.hpp"
#include "linearize/simulate_aero.hpp"
#include "modal/aero_roots.hpp"
#include "modal/rotor_modes.hpp"
#include "src/base/error.hpp"
#include "src/base/limits.hpp"

namespace whirl {

std::vector<IdentifiedPole> realizedPoles(const Simulation& sim, const OperatingPoint& eq, double dt_out) {
  const auto ns = static_cast<Eigen::Index>(sim.states.size());
  const bool off_grid = sim.time.size() > 1 &&
                        std::abs(sim.time.back() - static_cast<double>(sim.time.size() - 1) * dt_out) > 1e-9 * dt_out;
  const Eigen::Index rows = static_cast<Eigen::Index>(sim.time.size()) - (off_grid ? 1 : 0);
  MatX y(rows, ns);
  for (Eigen::Index c = 0; c < ns; ++c) {
    const int j = sim.states[static_cast<size_t>(c)];
    for (Eigen::Index k = 0; k < rows; ++k)
      y(k, c) = sim.q(k, j) - eq.q(j) - eq.qd(j) * sim.time[static_cast<size_t>(k)];
  }
  try {
    return identifyPoles(y, dt_out);
  } catch (const InputError&) {  // too few instants for the Hankel matrix (a short --tmax)
    return {};
  }
}

void requireCheckOptions(const NonlinearCheckOptions& opt) {
  if (!(opt.amplitude > 0) || !(opt.amplitude <= limits::kMaxVerifyAmplitude))
    throw InputError(fmt::format(
        "verify: amplitude: must be a positive number of at most {:g} (m or rad: a perturbation in the linear range)",
        limits::kMaxVerifyAmplitude));
  // At least 2 to observe the order; 8 halve ε to ε/128, where the difference meets the integrator's tolerance.
  if (opt.levels < 2 || opt.levels > 8) throw InputError("verify: levels: must lie in [2, 8]");
  if (!(opt.t_end > 0) || !std::isfinite(opt.t_end)) throw InputError("verify: tmax: must be a positive number [s]");
  if (!(opt.dt_out > 0) || !std::isfinite(opt.dt_out))
    throw InputError("verify: dt_out: must be a positive number [s]");
}

NonlinearCheck checkAgainstLinear(const Model& m, const OperatingPoint& eq, const NonlinearCheckOptions& opt) {
  // A parked rotor (no rotating coordinate moving) is time-invariant, blades and all.
  bool turning = false;
  for (int i = 0; i < m.ndof(); ++i) turning = turning || (m.dofs[i].rotating && eq.qd(i) != 0);
  for (const Dof& d : m.dofs)
    if (!d.frozen && d.blade >= 0 && turning)
      throw InputError(
          "verify: the model has a bladed rotor, whose linear model is periodic; verify takes "
          "time-invariant models (no rotor, or an axisymmetric rigid rotor)");
  requireCheckOptions(opt);
  SimulationOptions so;
  so.t_end = opt.t_end;
  so.dt_out = opt.dt_out;
  so.rtol = opt.rtol;
  so.atol = opt.atol;
  so.aero_states = opt.aero_states;
  const int nz = simulationAeroStateCount(m, so);
  LinearizeOptions lo;
  // Without aerodynamic states the simulation re-solves the induction at every evaluation; with them both
  // hold the equilibrium's frozen wake (the states' linear model is on it).
  lo.frozen_wake = nz > 0;
  lo.unsteady_aero = nz > 0;
  lo.inputs = false;
  if (nz > 0) so.frozen_inflow = eq.inflow;
  const LinearModel lin = linearize(m, eq, lo);
  NonlinearCheck out;
  out.aero_states = nz;
  out.modes = nz > 0 ? linearModelModes(m, lin, eq.held).modes : computeModes(lin.M, lin.C, lin.K, lin.dof_names);
  const int n = static_cast<int>(lin.dofs.size());
  const auto nx = lin.A.rows();
  std::vector<int> perturbed = opt.dofs;
  if (perturbed.empty())
    for (int i : lin.dofs)
      if (!m.dofs[i].rotating) perturbed.push_back(i);
  if (perturbed.empty()) throw InputError("verify: no coordinate to perturb");
  for (int i : perturbed)
    if (std::find(lin.dofs.begin(), lin.dofs.end(), i) == lin.dofs.end())
      throw InputError("verify: '" + m.dofs[i].name + "' is not a state of the linear model (frozen)");

  const MatX step = (lin.A * opt.dt_out).exp();  // x(t + Δ) = exp(A Δ) x(t)
  // With the aerodynamic states the quasi-steady equilibrium is their steady state only to the HGM model's
  // reconstruction of the static polar (~1e-4 of the loads, docs/theory/unsteady-aero.md): the perturbed runs
  // are measured from an unperturbed one, not from the equilibrium.
  Simulation base;
  if (nz > 0) base = simulate(m, eq, so);
  double eps = opt.amplitude;
  for (int level = 0; level < opt.levels; ++level, eps /= 2) {
    OperatingPoint start = eq;
    VecX x0 = VecX::Zero(nx);
    for (int i : perturbed) {
      start.q(i) += eps;
      x0(std::find(lin.dofs.begin(), lin.dofs.end(), i) - lin.dofs.begin()) = eps;
    }
    // The states start steady at the perturbed point: their deviation from the equilibrium's.
    if (nz > 0) x0.tail(nz) = simulationAeroStart(m, start, so) - lin.first_order_values.tail(nz);
    VecX x = x0;
    const Simulation sim = simulate(m, start, so);
    NonlinearCheckLevel l;
    l.amplitude = eps;
    for (size_t k = 0; k < sim.time.size(); ++k) {
      const auto r = static_cast<Eigen::Index>(k);
      // Recorded instants are k Δ, and t_end last when it is not a multiple of Δ.
      const double t = sim.time[k], tk = static_cast<double>(k) * opt.dt_out;
      if (k > 0) x = std::abs(t - tk) <= 1e-9 * opt.dt_out ? VecX(step * x) : VecX((lin.A * t).exp() * x0);
      for (int j = 0; j < n; ++j) {
        const int i = lin.dofs[j];
        const double dq = nz > 0 ? sim.q(r, i) - base.q(r, i) : sim.q(r, i) - eq.q(i) - eq.qd(i) * sim.time[k];
        l.max_difference = std::max(l.max_difference, std::abs(dq - x(j)));
        l.max_response = std::max(l.max_response, std::abs(x(j)));
      }
    }
    out.levels.push_back(l);
  }
  // Identification: one decay per coordinate, perturbed alone by the largest amplitude (two modes of
  // close frequency excited together exchange energy and bias the logarithmic decrement).
  for (int i : perturbed) {
    OperatingPoint start = eq;
    start.q(i) += opt.amplitude;
    const Simulation sim = simulate(m, start, so);
    std::vector<double> s(sim.time.size());
    for (size_t k = 0; k < s.size(); ++k) s[k] = sim.q(static_cast<Eigen::Index>(k), i);
    out.identified_dofs.push_back(m.dofs[i].name);
    out.poles.push_back(realizedPoles(sim, eq, opt.dt_out));
    try {
      out.identified.push_back(identifyDecay(sim.time, s, eq.q(i)));
    } catch (const ComputeError&) {  // no oscillation along it (overdamped, or too short): NaN
      out.identified.push_back({NAN, NAN, NAN, 0});
    }
  }
  for (size_t k = 1; k < out.levels.size(); ++k)
    out.orders.push_back(std::log2(out.levels[k - 1].max_difference / out.levels[k].max_difference));
  return out;
}

std::vector<IdentifiedComparison> compareWithModes(const Model& m, const NonlinearCheck& c) {
  const std::vector<int> active = m.activeDofs();  // the coordinates of the modes' participations
  std::vector<IdentifiedComparison> out;
  for (size_t k = 0; k < c.identified.size(); ++k) {
    IdentifiedComparison r;
    r.coordinate = c.identified_dofs[k];
    r.decay = c.identified[k];
    const auto j = static_cast<Eigen::Index>(
        std::find_if(active.begin(), active.end(), [&](int i) { return m.dofs[i].name == r.coordinate; }) -
        active.begin());
    for (size_t i = 0; i < c.modes.size(); ++i) {
      const Mode& md = c.modes[i];
      if (!md.rigid_body && !isAeroRoot(md) && j < md.participation.size() &&
          (r.mode < 0 || md.participation(j) > c.modes[static_cast<size_t>(r.mode)].participation(j)))
        r.mode = static_cast<int>(i);
    }
    if (r.mode >= 0)
      if (const IdentifiedPole* p = nearestPole(c.poles[k], c.modes[static_cast<size_t>(r.mode)].damped_freq_hz))
        r.pole = *p;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace whirl
