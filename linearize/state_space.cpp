#include "linearize/state_space.hpp"

#include <cmath>

#include "linearize/jacobian.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/outputs.hpp"

namespace whirl {

std::string dofUnit(const Model& m, int dof) {
  const Dof& d = m.dofs[dof];
  if (d.kind == DofKind::Elastic) return "m";
  const Body& b = m.bodies[d.body];
  switch (b.joint) {
    case JointType::Revolute: return "rad";
    case JointType::Free: return d.local < 3 ? "m" : "rad";
    default: return "m";
  }
}

namespace {

// HydroDyn's radiation states are a fit's internal states (only C z has units, N and N m); of the HGM
// model's (Hansen, Gaunaa & Madsen 2004) x1, x2 are angles of attack, x3 a normal-force coefficient and x4
// a separation point; OpenFAST's .lin gives them rad, rad, -, - (tests/data/openfast-lin/ua4-dbemt3). The
// dynamic-inflow states (DBEMT v, v1) are induced velocities, m/s.
std::string firstOrderUnit(const std::string& name) {
  if (name.rfind("DBEMT v", 0) == 0) return "m/s";
  return name.rfind("UA x1 ", 0) == 0 || name.rfind("UA x2 ", 0) == 0 ? "rad" : "-";
}

// Where the aerodynamic states start among lin's first-order states (after the body states, HydroDyn's
// radiation: linearize.cpp), or −1 when the linear model has none (quasi-steady aerodynamics).
int aeroStatesStart(const Model& m, const LinearModel& lin) {
  int nb = 0;
  for (const BodyStateSpace& bs : m.body_states) nb += static_cast<int>(bs.A.rows());
  const int nz = static_cast<int>(lin.first_order_names.size()), na = aeroStateCount(m.aero);
  if (na == 0 || nz == nb) return -1;
  if (nz != nb + na || lin.first_order_values.size() != nz)
    throw ComputeError("state space: " + std::to_string(nz - nb) + " first-order states after the body states, " +
                       std::to_string(na) + " aerodynamic states in the model");
  return nb;
}

}  // namespace

std::vector<bool> firstOrderStates(const std::vector<StateSpaceVariable>& x) {
  std::vector<bool> first(x.size(), true);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i].rate_of >= 0) {
      first[i] = false;
      if (x[i].rate_of < static_cast<int>(x.size())) first[x[i].rate_of] = false;
    }
  return first;
}

StateSpaceModel stateSpace(const Model& m, const OperatingPoint& op, const LinearModel& lin) {
  StateSpaceModel s;
  const int n = static_cast<int>(lin.dofs.size());
  for (int k = 0; k < n; ++k) {
    const Dof& d = m.dofs[lin.dofs[k]];
    StateSpaceVariable v;
    v.name = d.name;
    v.unit = dofUnit(m, lin.dofs[k]);
    v.op = op.q(lin.dofs[k]);
    v.blade = d.blade;
    v.azimuth = d.rotating;
    s.x.push_back(v);
  }
  for (int k = 0; k < n; ++k) {
    StateSpaceVariable v = s.x[k];
    v.name = "d(" + v.name + ")/dt";
    v.unit += "/s";
    v.op = op.qd(lin.dofs[k]);
    v.rate_of = k;
    v.azimuth = false;
    s.x.push_back(v);
  }
  for (std::size_t k = 0; k < lin.first_order_names.size(); ++k) {
    StateSpaceVariable v;
    v.name = lin.first_order_names[k];
    v.unit = firstOrderUnit(v.name);
    // Body states rest at 0 at a static point; the unsteady-airfoil states at their steady values, on
    // their blade in the rotating frame (so that the multiblade transform takes them with it).
    if (k < static_cast<std::size_t>(lin.first_order_values.size()))
      v.op = lin.first_order_values(static_cast<Eigen::Index>(k));
    if (k < lin.first_order_blades.size()) v.blade = lin.first_order_blades[k];
    s.x.push_back(v);
  }
  const int nx = static_cast<int>(s.x.size());
  for (int i = 0; i < m.ninput(); ++i) {
    const Input& in = m.inputs[i];
    StateSpaceVariable v;
    v.name = in.name;
    v.unit = in.unit;
    // An input that drives frozen coordinates reports their value (e.g. the pitch angle), since the
    // model keeps the operating value there and the input is the increment.
    v.op = in.dofs.empty() ? op.u(i) : op.q(in.dofs.front().dof) / in.dofs.front().gain;
    v.blade = in.blade;
    s.u.push_back(v);
  }
  s.A = lin.A;
  s.B = lin.B;
  s.xdot_op = VecX::Zero(nx);
  Eigen::LDLT<MatX> ldlt(lin.M);
  for (int k = 0; k < n; ++k) s.xdot_op(k) = op.qd(lin.dofs[k]);
  if (n > 0) s.xdot_op.segment(n, n) = ldlt.solve(lin.residual);

  const int ny = m.noutput();
  VecX y(ny);
  Workspace<double> ws(m);
  // With the aerodynamic states in the model, the load outputs take their loads, as the equations of motion do.
  const int z0 = aeroStatesStart(m, lin), nza = z0 >= 0 ? aeroStateCount(m.aero) : 0;
  const VecX z = z0 >= 0 ? VecX(lin.first_order_values.segment(z0, nza)) : VecX();
  const VecX* zp = z0 >= 0 ? &z : nullptr;
  // The rotor outputs with the frozen wake of the point, as the linearization (linearize.cpp); with the states
  // and no induction (WakeMod 0) the point's zero induction.
  const AeroInflow* frozen = m.aero.active() && (m.aero.induction || zp) && !op.inflow.empty() ? &op.inflow : nullptr;
  evaluateOutputs(m, ws, op.q, op.qd, op.qdd, y, &op.u, frozen, {}, zp);
  for (int i = 0; i < ny; ++i) {
    if (!std::isfinite(y(i)))
      throw ComputeError("output '" + m.outputs[i].name + "' is not finite at the operating point");
    StateSpaceVariable v;
    v.name = m.outputs[i].name;
    v.unit = m.outputs[i].unit;
    v.op = y(i);
    v.blade = m.outputs[i].blade;
    s.y.push_back(v);
  }
  std::vector<int> inputs(m.ninput());
  for (int i = 0; i < m.ninput(); ++i) inputs[i] = i;
  s.C = MatX::Zero(ny, nx);
  s.D = MatX::Zero(ny, m.ninput());
  if (ny > 0) {
    JacobianWorkspace jw(m);
    const MatX Hq = outputJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Q, lin.dofs, frozen, zp);
    const MatX Hqd = outputJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Qd, lin.dofs, frozen, zp);
    const MatX Hqdd = outputJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Qdd, lin.dofs, frozen, zp);
    const MatX Hu = outputJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::U, inputs, frozen, zp);
    s.C.leftCols(n) = Hq;
    s.C.middleCols(n, n) = Hqd;
    if (zp) {  // the aerodynamic states' direct columns; other first-order states (radiation) enter no output
      std::vector<int> states(static_cast<std::size_t>(nza));
      for (int k = 0; k < nza; ++k) states[static_cast<std::size_t>(k)] = k;
      s.C.middleCols(2 * n + z0, nza) = outputJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Z, states, frozen, zp);
    }
    s.C += Hqdd * lin.A.middleRows(n, n);
    s.D = Hu + Hqdd * lin.B.middleRows(n, n);
  }
  // The rotor's azimuth and speed from its rotating coordinate, a state or not: with the generator
  // DOF off (GenDOF = False) the rotor still turns at the prescribed speed, and a `.lin` header saying
  // 0 rad/s makes MBC3 silently wrong (issue 41).
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].rotating) {
      s.azimuth = op.q(i);
      s.rotor_speed = op.qd(i);
      break;
    }
  return s;
}

namespace {

std::vector<int> indicesOf(const std::vector<StateSpaceVariable>& vars, const std::vector<std::string>& names,
                           const char* what) {
  std::vector<int> idx;
  if (names.empty()) {
    for (size_t i = 0; i < vars.size(); ++i) idx.push_back(static_cast<int>(i));
    return idx;
  }
  for (const auto& n : names) {
    int found = -1;
    for (size_t i = 0; i < vars.size(); ++i)
      if (vars[i].name == n) found = static_cast<int>(i);
    if (found < 0) {
      std::string all;
      for (const auto& v : vars) all += (all.empty() ? "" : ", ") + v.name;
      throw InputError(std::string("unknown ") + what + " '" + n + "' (" + what + "s: " + (all.empty() ? "none" : all) +
                       ")");
    }
    idx.push_back(found);
  }
  return idx;
}

std::vector<StateSpaceVariable> pick(const std::vector<StateSpaceVariable>& v, const std::vector<int>& idx) {
  std::vector<StateSpaceVariable> out;
  for (int i : idx) out.push_back(v[i]);
  return out;
}

MatX pickRows(const MatX& M, const std::vector<int>& idx) {
  MatX out(static_cast<Eigen::Index>(idx.size()), M.cols());
  // A row of a matrix without columns (B of a model without inputs) offsets Eigen's null data
  // pointer (UBSan; fuzz_cli: export --drop-azimuth of cases/floating_3dof).
  if (M.cols() == 0) return out;
  for (size_t k = 0; k < idx.size(); ++k) out.row(k) = M.row(idx[k]);
  return out;
}

MatX pickCols(const MatX& M, const std::vector<int>& idx) { return pickRows(M.transpose(), idx).transpose(); }

}  // namespace

StateSpaceModel selectInputsOutputs(const StateSpaceModel& s, const std::vector<std::string>& inputs,
                                    const std::vector<std::string>& outputs) {
  const std::vector<int> iu = indicesOf(s.u, inputs, "input"), iy = indicesOf(s.y, outputs, "output");
  StateSpaceModel r = s;
  r.u = pick(s.u, iu);
  r.y = pick(s.y, iy);
  r.B = pickCols(s.B, iu);
  r.C = pickRows(s.C, iy);
  r.D = pickCols(pickRows(s.D, iy), iu);
  return r;
}

StateSpaceModel dropAzimuth(const StateSpaceModel& s) {
  std::vector<int> keep, new_index(s.x.size(), -1);
  for (size_t i = 0; i < s.x.size(); ++i)
    if (!s.x[i].azimuth) {
      new_index[i] = static_cast<int>(keep.size());
      keep.push_back(static_cast<int>(i));
    }
  StateSpaceModel r = s;
  r.x = pick(s.x, keep);
  for (auto& v : r.x) v.rate_of = v.rate_of >= 0 ? new_index[v.rate_of] : -1;
  r.xdot_op = VecX(static_cast<Eigen::Index>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k) r.xdot_op(k) = s.xdot_op(keep[k]);
  r.A = pickCols(pickRows(s.A, keep), keep);
  r.B = pickRows(s.B, keep);
  r.C = pickCols(s.C, keep);
  return r;
}

int bladeCount(const StateSpaceModel& s) {
  int n = 0;
  for (const auto* vars : {&s.x, &s.u, &s.y})
    for (const auto& v : *vars) n = std::max(n, v.blade + 1);
  return n;
}

}  // namespace whirl
