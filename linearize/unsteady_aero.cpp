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

// The blade whose elements alone a coordinate moves (its pitch, its body's elastic coordinates, the frames under
// it that move no other blade), or −1: a coordinate of the tower, nacelle, drivetrain or hub moves every blade.
std::vector<int> bladeOfDof(const Model& m) {
  const AeroModel& am = m.aero;
  std::vector<int> count(static_cast<std::size_t>(m.ndof()), 0), owner(count.size(), -1);
  for (std::size_t b = 0; b < am.blades.size(); ++b) {
    const Body& body = m.bodies[am.blades[b].body];
    std::vector<int> moves = m.support[am.blades[b].body];
    for (int j = 0; j < body.inertia.ne; ++j) moves.push_back(body.elastic_dof + j);
    if (am.blades[b].pitch_dof >= 0) moves.push_back(am.blades[b].pitch_dof);
    std::sort(moves.begin(), moves.end());
    moves.erase(std::unique(moves.begin(), moves.end()), moves.end());
    for (int d : moves) {
      ++count[static_cast<std::size_t>(d)];
      owner[static_cast<std::size_t>(d)] = static_cast<int>(b);
    }
  }
  for (int d : m.support[am.hub_body]) count[static_cast<std::size_t>(d)] += 2;  // the hub moves every blade
  for (std::size_t d = 0; d < count.size(); ++d)
    if (count[d] != 1) owner[d] = -1;
  return owner;
}

// The derivative directions of the columns of q, q̇ and u (indices into `all`): a column that moves every blade
// has a direction of its own; columns that move one blade each, of different blades, share one. The loads are a
// sum of the blades' terms, each a function of the common columns and its own blade's (partial separability,
// Griewank & Toint 1982): evaluated apart, a blade's term has zero columns for the other blades' coordinates, so
// they share its columns' directions (Curtis, Powell & Reid 1974).
std::vector<std::vector<int>> sharedDirections(const std::vector<int>& blade_of_column, int nblades) {
  std::vector<std::vector<int>> out, by_blade(static_cast<std::size_t>(nblades));
  for (std::size_t c = 0; c < blade_of_column.size(); ++c) {
    const int b = blade_of_column[c];
    if (b < 0) out.push_back({static_cast<int>(c)});
    else by_blade[static_cast<std::size_t>(b)].push_back(static_cast<int>(c));
  }
  for (std::size_t j = 0;; ++j) {
    std::vector<int> group;
    for (const std::vector<int>& cols : by_blade)
      if (j < cols.size()) group.push_back(cols[j]);
    if (group.empty()) break;
    out.push_back(group);
  }
  return out;
}

}  // namespace

VecX unsteadyAeroSteadyStates(const Model& m, const OperatingPoint& op) {
  Workspace<double> ws(m);
  return unsteadyAeroSteadyStates(m, op, ws);
}

VecX unsteadyAeroSteadyStates(const Model& m, const OperatingPoint& op, Workspace<double>& ws) {
  requireFrozenInduction(m, op);
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

UnsteadyAeroLinear unsteadyAeroLinear(const Model& m, const OperatingPoint& op, const std::vector<int>& cols,
                                      bool inputs, Workspace<double>& ws, JacobianWorkspace& jw) {
  return unsteadyAeroLinearAt(m, op, unsteadyAeroSteadyStates(m, op, ws), cols, inputs, jw.ws);
}

UnsteadyAeroLinear unsteadyAeroLinearAt(const Model& m, const OperatingPoint& op, const VecX& states,
                                        const std::vector<int>& cols, bool inputs) {
  Workspace<ADChunk> ws(m);
  return unsteadyAeroLinearAt(m, op, states, cols, inputs, ws);
}

UnsteadyAeroLinear unsteadyAeroLinearAt(const Model& m, const OperatingPoint& op, const VecX& states,
                                        const std::vector<int>& cols, bool inputs, Workspace<ADChunk>& ws) {
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
  auto load = [](const VecX& v) {
    VecXT<ADChunk> a(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) a(i) = ADChunk(v(i));
    return a;
  };
  VecXT<ADChunk> q = load(op.q), qd = load(op.qd), qdd = load(op.qdd), u = load(op.u), z = load(out.z);
  VecXT<ADChunk> e_ua(n), zdot(nz);
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
  const int nqu = static_cast<int>(all.size());  // the columns of q, q̇, u, then the nz of the states
  MatX Je = MatX::Zero(n, nqu + nz);
  MatX Jz = MatX::Zero(nz, nqu);  // ż's columns of q, q̇, u; those of z straight into out.Azz (nz² entries)
  out.Azz = MatX::Zero(nz, nz);
  // The columns of q, q̇, u: the kinematics seeded, one blade's elements at a time with and without their states
  // (one pass over the elements: their frames once for both). A column that moves one blade only shares its
  // direction with other blades' (sharedDirections): the NREL 5MW's 42 columns take 4 passes instead of 6.
  const std::vector<int> blade_of_dof = bladeOfDof(m);
  std::vector<int> blade_of_column;
  for (const Column& c : all) blade_of_column.push_back(c.kind == Column::U ? -1 : blade_of_dof[c.index]);
  const int nblades = static_cast<int>(m.aero.blades.size());
  const std::vector<std::vector<int>> directions = sharedDirections(blade_of_column, nblades);
  const std::vector<std::vector<int>> by_element = statesOfElements(m.aero);
  std::vector<std::vector<int>> blade_states(static_cast<std::size_t>(nblades));  // each blade's rows of z
  for (int b = 0, el = 0; b < nblades; ++b)
    for (std::size_t si = 0; si < m.aero.blades[b].stations.size(); ++si, ++el)
      for (int r : by_element[static_cast<std::size_t>(el)]) blade_states[static_cast<std::size_t>(b)].push_back(r);
  const int nd = static_cast<int>(directions.size());
  for (int d0 = 0; d0 < nd; d0 += kChunk) {
    const int w = std::min(kChunk, nd - d0);
    for (int k = 0; k < w; ++k)
      for (int c : directions[d0 + k]) seed(all[c], k, true);
    forwardKinematics(m, ws, q, qd, qdd);
    for (int b = 0; b < nblades; ++b) {
      clear(e_ua);  // receives the loads less the quasi-steady ones the base linearization holds
      addUnsteadyAeroLoads<ADChunk>(m, ws, q, qd, u, op.inflow, &z, e_ua, &zdot, nullptr, nullptr, -1, true, nullptr,
                                    b);
      for (int k = 0; k < w; ++k)
        for (int c : directions[d0 + k]) {
          if (blade_of_column[c] >= 0 && blade_of_column[c] != b) continue;  // the direction's other blade's column
          for (int i = 0; i < n; ++i) Je(i, c) += e_ua(i).derivatives()(k);
          for (int i : blade_states[static_cast<std::size_t>(b)]) Jz(i, c) = zdot(i).derivatives()(k);
        }
    }
    for (int k = 0; k < w; ++k)
      for (int c : directions[d0 + k]) seed(all[c], k, false);
  }
  // The columns of the states, element by element: a state of element i enters only element i's loads and
  // only its rows of ż (aeroStateCount's layout), so each chunk evaluates that element alone, on the
  // kinematics at the point (unseeded, formed once; z enters neither them nor e_QS). Seeding chunks of
  // states through every element of every blade cost nz / 8 evaluations of all elements (51 for the
  // NREL 5MW with UA and DBEMT) where one suffices.
  if (nz > 0) forwardKinematics(m, ws, q, qd, qdd);
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
        for (int r : s) out.Azz(r, s[k0 + k]) = zdot(r).derivatives()(k);
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
  return out;
}

}  // namespace whirl
