#include "linearize/unsteady_aero.hpp"

#include <algorithm>
#include <string>

#include "src/aero/dynamic_inflow.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/kinematics.hpp"

namespace whirl {
namespace {

void requireFrozenInduction(const Model& m, const OperatingPoint& op) {
  if (aeroStateCount(m.aero) == 0)
    throw ComputeError("aerodynamic states: the model has no UA_Mod 4 or 6 and no DBEMT_Mod 3 on its elements");
  if (static_cast<int>(op.inflow.axial.size()) != m.aero.nstations())
    throw ComputeError(
        "unsteady-airfoil states: the operating point carries no induction of the blade elements "
        "(solve it with solveOperatingPoint)");
}

// One column of the AD evaluation of q, q̇ or u: which argument and which index.
struct Column {
  enum Kind { Q, Qd, U } kind;
  int index;
};

// The states of each element over all blades (AeroModel order), as indices into z: its unsteady-airfoil
// states, then its dynamic-inflow states (aeroStateCount's layout).
std::vector<std::vector<int>> statesOfElements(const AeroModel& am) {
  const int ns = uaStatesPerElement(am), ni = inflowStatesPerElement(am), nua = uaStateCount(am);
  std::vector<std::vector<int>> out(static_cast<std::size_t>(am.nstations()));
  int index = 0, zi = 0;
  for (const AeroBlade& b : am.blades)
    for (const AeroStation& st : b.stations) {
      std::vector<int>& s = out[static_cast<std::size_t>(index)];
      for (int k = 0; st.ua && k < ns; ++k) s.push_back(zi++);
      for (int k = 0; k < ni; ++k) s.push_back(nua + ni * index + k);
      ++index;
    }
  return out;
}

}  // namespace

VecX unsteadyAeroSteadyStates(const Model& m, const OperatingPoint& op) {
  requireFrozenInduction(m, op);
  Workspace<double> ws(m);
  forwardKinematics(m, ws, op.q, op.qd, op.qdd);
  const int nz = aeroStateCount(m.aero), ns = uaStatesPerElement(m.aero), nua = uaStateCount(m.aero);
  VecX z = VecX::Zero(nz), e = VecX::Zero(m.ndof());
  std::vector<aero::UaInput<double>> inputs;
  if (nz > nua) {  // dynamic inflow at its steady state: v = v_qs, v1 = (1 − k) v_qs (the BEM induction)
    VecX qs = VecX::Zero(2 * m.aero.nstations());
    addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, &z, e, nullptr, nullptr, &qs);
    for (int i = 0; i < m.aero.nstations(); ++i) {
      const aero::OyeState<double> ax = aero::oyeSteady(qs(2 * i)), tn = aero::oyeSteady(qs(2 * i + 1));
      z.segment(nua + 4 * i, 4) << ax.v, tn.v, ax.v1, tn.v1;
    }
  }
  // The UA inputs with the induction the elements see (the dynamic inflow's steady one, if any).
  addUnsteadyAeroLoads<double>(m, ws, op.q, op.qd, op.u, op.inflow, &z, e, nullptr, &inputs);
  int zi = 0, k = 0;
  for (const AeroBlade& b : m.aero.blades)
    for (const AeroStation& st : b.stations) {
      if (!st.ua) continue;
      const aero::HgmState<double> x = aero::hgmSteady(uaSection(m.aero, st), inputs[static_cast<std::size_t>(k++)]);
      if (ns == 4) z.segment(zi, 4) << x.x1, x.x2, x.x3, x.x4;
      else z(zi) = x.x4;
      zi += ns;
    }
  return z;
}

UnsteadyAeroLinear unsteadyAeroLinear(const Model& m, const OperatingPoint& op, const std::vector<int>& cols,
                                      bool inputs) {
  return unsteadyAeroLinearAt(m, op, unsteadyAeroSteadyStates(m, op), cols, inputs);
}

UnsteadyAeroLinear unsteadyAeroLinearAt(const Model& m, const OperatingPoint& op, const VecX& states,
                                        const std::vector<int>& cols, bool inputs) {
  requireFrozenInduction(m, op);
  if (states.size() != aeroStateCount(m.aero))
    throw ComputeError("aerodynamic states: " + std::to_string(states.size()) + " values for " +
                       std::to_string(aeroStateCount(m.aero)) + " states");
  UnsteadyAeroLinear out;
  out.z = states;
  uaStateNames(m.aero, out.names, out.groups);
  inflowStateNames(m.aero, out.names, out.groups);
  const int n = m.ndof(), nz = static_cast<int>(out.z.size()), nc = static_cast<int>(cols.size());
  const int nu = inputs ? m.ninput() : 0;
  std::vector<Column> all;
  for (int c : cols) all.push_back({Column::Q, c});
  for (int c : cols) all.push_back({Column::Qd, c});
  for (int i = 0; i < nu; ++i) all.push_back({Column::U, i});
  Workspace<ADChunk> ws(m);
  auto load = [](const VecX& v) {
    VecXT<ADChunk> a(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) a(i) = ADChunk(v(i));
    return a;
  };
  VecXT<ADChunk> q = load(op.q), qd = load(op.qd), qdd = load(op.qdd), u = load(op.u), z = load(out.z);
  VecXT<ADChunk> e_ua(n), e_qs(n), zdot(nz);
  // Seeds direction k of a column (on: 1, off: 0); an input that drives frozen coordinates (pitch) seeds
  // them with its gain, as residualJacobian does.
  auto seed = [&](const Column& c, int k, bool on) {
    const double s = on ? 1.0 : 0.0;
    switch (c.kind) {
      case Column::Q: q(c.index).derivatives()(k) = s; break;
      case Column::Qd: qd(c.index).derivatives()(k) = s; break;
      case Column::U:
        u(c.index).derivatives()(k) = s;
        for (const InputDofTarget& t : m.inputs[c.index].dofs) q(t.dof).derivatives()(k) = on ? t.gain : 0.0;
        break;
    }
  };
  auto clear = [&](VecXT<ADChunk>& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = ADChunk(0.0);
  };
  const int nqu = static_cast<int>(all.size());  // the columns of q, q̇ and u, then the nz of the states
  MatX Je(n, nqu + nz);
  MatX Jz = MatX::Zero(nz, nqu + nz);
  // The columns of q, q̇, u: the kinematics seeded, every element with and without its states (one pass over
  // the elements: their frames once for both).
  for (int c0 = 0; c0 < nqu; c0 += kChunk) {
    const int w = std::min(kChunk, nqu - c0);
    for (int k = 0; k < w; ++k) seed(all[c0 + k], k, true);
    forwardKinematics(m, ws, q, qd, qdd);
    clear(e_ua);
    clear(e_qs);
    addUnsteadyAeroLoads<ADChunk>(m, ws, q, qd, u, op.inflow, &z, e_ua, &zdot, nullptr, nullptr, -1, &e_qs);
    for (int k = 0; k < w; ++k) {
      for (int i = 0; i < n; ++i) Je(i, c0 + k) = e_ua(i).derivatives()(k) - e_qs(i).derivatives()(k);
      for (int i = 0; i < nz; ++i) Jz(i, c0 + k) = zdot(i).derivatives()(k);
    }
    for (int k = 0; k < w; ++k) seed(all[c0 + k], k, false);
  }
  // The columns of the states, element by element: a state of element i enters only element i's loads and
  // only its rows of ż (aeroStateCount's layout), so each chunk evaluates that element alone, on the
  // kinematics at the point (unseeded, formed once; z enters neither them nor e_QS). Seeding chunks of
  // states through every element of every blade cost nz / 8 evaluations of all elements (51 for the
  // NREL 5MW with UA and DBEMT) where one suffices.
  if (nz > 0) forwardKinematics(m, ws, q, qd, qdd);
  const std::vector<std::vector<int>> by_element = statesOfElements(m.aero);
  for (int el = 0; el < static_cast<int>(by_element.size()); ++el) {
    const std::vector<int>& s = by_element[static_cast<std::size_t>(el)];
    for (std::size_t k0 = 0; k0 < s.size(); k0 += kChunk) {
      const int w = static_cast<int>(std::min<std::size_t>(kChunk, s.size() - k0));
      for (int k = 0; k < w; ++k) z(s[k0 + k]).derivatives()(k) = 1.0;
      clear(e_ua);
      addUnsteadyAeroLoads<ADChunk>(m, ws, q, qd, u, op.inflow, &z, e_ua, &zdot, nullptr, nullptr, el);
      for (int k = 0; k < w; ++k) {
        const int col = nqu + s[k0 + k];
        for (int i = 0; i < n; ++i) Je(i, col) = e_ua(i).derivatives()(k);
        for (int r : s) Jz(r, col) = zdot(r).derivatives()(k);
      }
      for (int k = 0; k < w; ++k) z(s[k0 + k]).derivatives()(k) = 0.0;
    }
  }
  out.dK = -Je.leftCols(nc);
  out.dC = -Je.middleCols(nc, nc);
  out.dQ = Je.middleCols(2 * nc, nu);
  out.G = Je.rightCols(nz);
  out.Zq = Jz.leftCols(nc);
  out.Zqd = Jz.middleCols(nc, nc);
  out.Zu = Jz.middleCols(2 * nc, nu);
  out.Azz = Jz.rightCols(nz);
  return out;
}

}  // namespace whirl
