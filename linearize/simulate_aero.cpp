#include "linearize/simulate_aero.hpp"

#include "linearize/unsteady_aero.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/residual.hpp"

namespace whirl {

int simulationAeroStateCount(const Model& m, const SimulationOptions& opt) {
  return opt.aero_states && m.aero.active() ? aeroStateCount(m.aero) : 0;
}

AeroInflow quasiSteadyInflow(const Model& m, const OperatingPoint& point) {
  Workspace<double> ws(m);
  AeroRecord record;
  VecX e(m.ndof());
  residual(m, ws, point.q, point.qd, point.qdd, point.u, e, nullptr, &record);
  return record.inflow();
}

VecX simulationAeroStart(const Model& m, const OperatingPoint& start, const SimulationOptions& opt) {
  if (simulationAeroStateCount(m, opt) == 0) return VecX();
  OperatingPoint at = start;
  at.inflow = opt.frozen_inflow.empty() ? quasiSteadyInflow(m, start) : opt.frozen_inflow;
  return unsteadyAeroSteadyStates(m, at);
}

AeroInflow simulationElementInflow(const Model& m, Workspace<double>& ws, const VecX& q, const VecX& qd,
                                   const VecX& qdd, const VecX& u, const SimulationOptions& opt) {
  if (!opt.frozen_inflow.empty()) return opt.frozen_inflow;
  AeroRecord record;
  residual(m, ws, q, qd, qdd, u, ws.scratch, nullptr, &record);
  return record.inflow();
}

AeroStateLoads::AeroStateLoads(const Model& m) : delta(m.ndof()), e_qs(m.ndof()) {}

void addAeroStateLoads(const Model& m, Workspace<double>& ws, const VecX& q, const VecX& qd, const VecX& u,
                       const AeroInflow& bem, const AeroInflow& held, const VecX& z, AeroStateLoads& b, VecX& e,
                       VecX& zdot) {
  b.delta.setZero();
  // e_QS: the quasi-steady loads residual() added, on the frozen wake of its own induction: the same loads
  // to the BEM root's tolerance (the frozen-wake linearization rests on it). On that same wake the difference
  // comes out of one pass over the elements.
  // The elements' root searches of the dynamic inflow keep the simulation's tolerance (BemRoot::tolerance).
  const double tolerance = ws.bem.empty() ? 0.0 : ws.bem.front().tolerance;
  if (held.empty()) {
    addUnsteadyAeroLoads<double>(m, ws, q, qd, u, bem, &z, b.delta, &zdot, nullptr, nullptr, -1, true);
  } else {
    b.e_qs.setZero();
    addUnsteadyAeroLoads<double>(m, ws, q, qd, u, bem, nullptr, b.e_qs, nullptr);
    addUnsteadyAeroLoads<double>(m, ws, q, qd, u, held, &z, b.delta, &zdot);
    b.delta -= b.e_qs;
  }
  for (BemRoot& r : ws.bem) r.tolerance = tolerance;
  e += b.delta;
}

}  // namespace whirl
