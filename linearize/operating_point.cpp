#include "linearize/operating_point.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "linearize/jacobian.hpp"
#include "linearize/linearize.hpp"
#include "linearize/unrestrained.hpp"
#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/mooring_scale.hpp"
#include "src/dynamics/residual.hpp"

namespace whirl {
namespace {

/// K of `lm` on the solved coordinates, or an empty matrix when one of them is not a state of `lm`.
MatX chordMatrix(const LinearModel& lm, const std::vector<int>& solved) {
  std::vector<int> at;
  for (int i : solved) {
    const auto it = std::find(lm.dofs.begin(), lm.dofs.end(), i);
    if (it == lm.dofs.end()) return {};
    at.push_back(static_cast<int>(it - lm.dofs.begin()));
  }
  const int ns = static_cast<int>(at.size());
  MatX K(ns, ns);
  for (int r = 0; r < ns; ++r)
    for (int c = 0; c < ns; ++c) K(r, c) = lm.K(at[r], at[c]);
  return K;
}

// Every coordinate at its value and rate, q̈ = 0, every input at its value (before the inputs move
// the frozen coordinates they drive).
OperatingPoint modelValues(const Model& m) {
  OperatingPoint op;
  const int n = m.ndof();
  op.q = VecX::Zero(n);
  op.qd = VecX::Zero(n);
  op.qdd = VecX::Zero(n);
  for (int i = 0; i < n; ++i) {
    op.q(i) = m.dofs[i].value;
    op.qd(i) = m.dofs[i].rate;
  }
  op.u = VecX::Zero(m.ninput());
  for (int i = 0; i < m.ninput(); ++i) op.u(i) = m.inputs[i].value;
  return op;
}

// When Newton fails: the joint coordinate (index into `solved`) whose stiffness, the diagonal of the
// first Newton matrix, would let the largest load seen on it move it furthest, if that motion exceeds
// 1 rad (or 1 m) — a nearly unrestrained coordinate (a very weak yaw spring) pushed by the loads of
// a turning rotor; −1 if none.
int weakJoint(const Model& m, const std::vector<int>& solved, const MatX& K, const VecX& load) {
  if (K.rows() != static_cast<Eigen::Index>(solved.size())) return -1;
  int best = -1;
  double motion = 1.0;
  for (size_t k = 0; k < solved.size(); ++k) {
    if (m.dofs[solved[k]].kind != DofKind::Joint) continue;
    const double kii = std::abs(K(k, k)), f = load(static_cast<Eigen::Index>(k));
    const double x = kii > 0 ? f / kii : (f > 0 ? HUGE_VAL : 0.0);
    if (x > motion) {
      motion = x;
      best = static_cast<int>(k);
    }
  }
  return best;
}

// A wind beyond limits::kMaxWindSpeed is an input error, not a point: its loads (1e21 N at 1e6 m/s) would
// otherwise defeat the Newton matrix and be reported as a coordinate without stiffness.
void requireWindWithinLimit(const Model& m, const VecX& u) {
  const int w = m.roles.wind_speed_input;
  if (w < 0 || w >= u.size() || !(u(w) > limits::kMaxWindSpeed)) return;
  throw InputError(fmt::format(
      "operating point: wind speed {:g} m/s is above the limit of {:g} m/s (the aerodynamics are incompressible)", u(w),
      limits::kMaxWindSpeed));
}

// A load along a coordinate without stiffness: no static equilibrium. `motion`: how far it would
// move, if known.
std::string noEquilibrium(const Model& m, int dof, double load, const std::string& motion = "") {
  return fmt::format(
      "operating point: a load acts along DOF '{}' ({:.4g} {}), which has no stiffness (a free "
      "rigid-body motion): {}no equilibrium; {}, or mark it rotating",
      m.dofs[dof].name, load, loadUnit(m, dof),
      motion.empty() ? "" : "it would move " + motion + " (limit " + fmt::format("{:g}", kMaxHeldDrift) + "), ",
      holdAdvice(m, dof));
}

// The Newton matrix singular along an elastic coordinate, which carries its own stiffness: the loads'
// geometric (and aerodynamic) stiffness cancels it — buckling — or the loads are so large that the
// matrix is singular to round-off (an absurd gravity or rotor speed).
std::string stiffnessCancelled(const Model& m, int dof, double load) {
  return fmt::format(
      "operating point: the stiffness along DOF '{}' is cancelled (the Newton matrix is singular there, with a "
      "load of {:.4g} {} along it): no equilibrium; the loads soften the structure to buckling or beyond what "
      "the matrix resolves (check gravity, rotor speed, wind and the stiffness inputs)",
      m.dofs[dof].name, load, loadUnit(m, dof));
}

}  // namespace

OperatingPoint initialPoint(const Model& m) {
  OperatingPoint op = modelValues(m);
  for (int i = 0; i < m.ninput(); ++i)
    for (const InputDofTarget& t : m.inputs[i].dofs) op.q(t.dof) += t.gain * op.u(i);
  return op;
}

void copyDeflections(const Model& m, const VecX& from, VecX& q) {
  for (int i : m.activeDofs())
    if (!m.dofs[i].rotating) q(i) = from(i);
}

OperatingPoint initialPoint(const Model& m, const OperatingCondition& c) {
  const ModelRoles& r = m.roles;
  auto finite = [](double v, const char* field) {
    if (!std::isfinite(v)) throw InputError(std::string("operating condition: ") + field + ": not a finite number");
  };
  auto need = [](bool has, const char* field, const char* what) {
    if (!has) throw InputError(std::string("operating condition: ") + field + ": the model has no " + what);
  };
  finite(c.rotor_speed, "rotor_speed");
  OperatingPoint op = modelValues(m);
  if (c.wind_speed) {
    finite(*c.wind_speed, "wind_speed");
    need(r.wind_speed_input >= 0, "wind_speed", "wind-speed input");
    op.u(r.wind_speed_input) = *c.wind_speed;
  }
  if (c.generator_torque) {
    finite(*c.generator_torque, "generator_torque");
    need(r.generator_torque_input >= 0, "generator_torque", "generator-torque input");
    op.u(r.generator_torque_input) = *c.generator_torque;
  }
  for (int i = 0; i < m.ninput(); ++i)
    for (const InputDofTarget& t : m.inputs[i].dofs) op.q(t.dof) += t.gain * op.u(i);
  if (r.azimuth.empty()) {
    if (c.rotor_speed != 0.0)
      throw InputError("operating condition: rotor_speed: the model has no rotating coordinate (an azimuth)");
    need(!c.azimuth, "azimuth", "rotating coordinate (an azimuth)");
  }
  for (int a : r.azimuth) {
    op.qd(a) = c.rotor_speed;
    if (c.azimuth) {
      finite(*c.azimuth, "azimuth");
      op.q(a) = *c.azimuth;
    }
  }
  if (c.collective_pitch || !c.blade_pitch_offsets.empty()) {
    const char* field = c.collective_pitch ? "collective_pitch" : "blade_pitch_offsets";
    need(!r.blade_pitch.empty(), field, "blade pitch coordinates");
    if (!c.blade_pitch_offsets.empty() && c.blade_pitch_offsets.size() != r.blade_pitch.size())
      throw InputError("operating condition: blade_pitch_offsets: " + std::to_string(c.blade_pitch_offsets.size()) +
                       " values for " + std::to_string(r.blade_pitch.size()) + " blades");
    if (c.collective_pitch) finite(*c.collective_pitch, "collective_pitch");
    for (size_t k = 0; k < r.blade_pitch.size(); ++k) {
      double& pitch = op.q(r.blade_pitch[k]);
      if (c.collective_pitch) pitch = *c.collective_pitch;
      if (!c.blade_pitch_offsets.empty()) {
        finite(c.blade_pitch_offsets[k], "blade_pitch_offsets");
        pitch += c.blade_pitch_offsets[k];
      }
    }
  }
  if (c.yaw) {
    finite(*c.yaw, "yaw");
    need(r.yaw_dof >= 0, "yaw", "yaw coordinate");
    op.q(r.yaw_dof) = *c.yaw;
  }
  return op;
}

OperatingPoint solveOperatingPoint(const Model& m, const OperatingCondition& c, const EquilibriumOptions& opt) {
  return solveOperatingPoint(m, initialPoint(m, c), opt);
}

OperatingPoint solveOperatingPoint(const Model& m, const OperatingPoint& start, const EquilibriumOptions& opt) {
  LinearizeWorkspace lw(m);
  return solveOperatingPoint(m, start, opt, lw);
}

namespace {

/// One solve's state between its phases: the point, its residual (all coordinates, and on the solved
/// ones), and what the failure message and the load-jump check need.
struct EquilibriumSolve {
  const Model& m;
  const EquilibriumOptions& opt;
  LinearizeWorkspace& lw;
  OperatingPoint op;
  VecX e, es;
  int ns = 0;
  AeroRecord* record = nullptr;  ///< every residual records the blade elements (the last one is the record)
  bool fresh = true;             ///< e and the record are those of op.q
  double scale = 1;
  VecX load_seen;                       ///< the largest loads seen on each solved coordinate (for the message)
  MatX K_first;                         ///< the first Newton matrix (for the message)
  VecX q_before, q_before2, es_before;  ///< the two iterates before op.q and the residual at the last one
  LoadJump jump;

  EquilibriumSolve(const Model& model, const EquilibriumOptions& o, LinearizeWorkspace& w, const OperatingPoint& start)
      : m(model), opt(o), lw(w), op(start), e(model.ndof()) {}

  VecX solvedResidual() {
    residual(m, lw.ws, op.q, op.qd, op.qdd, op.u, e, nullptr, record);
    VecX r(ns);
    for (int k = 0; k < ns; ++k) r(k) = e(op.solved[k]);
    return r;
  }
  double target() const { return opt.tolerance * scale; }
};

/// The coordinates Newton solves: the active, non-rotating ones not held (unrestrained or given).
void chooseSolved(const Model& m, const EquilibriumOptions& opt, OperatingPoint& op) {
  op.solved.clear();
  op.held = opt.held ? *opt.held : unrestrainedCoordinates(m, op.q, op.qd, op.u);
  for (int i : m.activeDofs()) {
    if (m.dofs[i].rotating) continue;
    if (op.qd(i) != 0.0)
      throw ComputeError("DOF '" + m.dofs[i].name +
                         "': a non-rotating coordinate has a rate; mark it rotating or freeze it");
    if (std::find(op.held.begin(), op.held.end(), i) != op.held.end()) continue;
    op.solved.push_back(i);
  }
}

/// The residual at the undeflected start (EquilibriumOptions::scale_from) on the solved coordinates,
/// −1 without one. Evaluated before the start's residual: the workspace then holds the start's BEM roots,
/// which the first Jacobian starts from.
double coldScale(EquilibriumSolve& s) {
  if (s.opt.load_scale > 0 || !s.opt.scale_from) return -1;
  const OperatingPoint& c = *s.opt.scale_from;
  residual(s.m, s.lw.ws, c.q, c.qd, c.qdd, c.u, s.e);
  double cold = 0;
  for (int i : s.op.solved) cold = std::max(cold, std::abs(s.e(i)));
  return cold;
}

/// Load scale: the residual at the undeflected start, or the gravity/centrifugal loads it holds; moored,
/// at least the line tensions, whose balance at a symmetric start leaves a residual of their round-off.
double loadScale(EquilibriumSolve& s, double cold) {
  if (s.opt.load_scale > 0) return s.opt.load_scale;
  return std::max({1.0, cold >= 0 ? cold : s.es.lpNorm<Eigen::Infinity>(), largestMooringTension(s.m, s.lw.ws)});
}

/// Chord steps from a given matrix (a neighbour's), Broyden-updated: a residual and a back-substitution
/// each, a fifth of a Newton step (which needs the AD stiffness); a step that gains less than 4× is
/// undone and Newton goes on.
void chordSteps(EquilibriumSolve& s) {
  const EquilibriumOptions& opt = s.opt;
  OperatingPoint& op = s.op;
  const int ns = s.ns;
  if (!(opt.chord || opt.chord_matrix) || ns == 0 || !(s.es.lpNorm<Eigen::Infinity>() > s.target())) return;
  MatX Kc = opt.chord ? chordMatrix(*opt.chord, op.solved) : *opt.chord_matrix;
  if (Kc.rows() != ns || Kc.cols() != ns) return;
  // A regular chord matrix is inverted once and its inverse follows the Broyden updates by
  // Sherman–Morrison (n² per step instead of a factorization); a rank-deficient one (a rigid-body
  // motion the hold rule does not catch) keeps the minimum-norm steps of its factorization.
  Eigen::CompleteOrthogonalDecomposition<MatX> cod(Kc);
  MatX Kinv;
  if (cod.rank() == ns) Kinv = Kc.partialPivLu().inverse();
  double prev = s.es.lpNorm<Eigen::Infinity>();
  while (op.iterations < 8 && prev > s.target()) {
    if (op.iterations > 0 && Kinv.size() == 0) cod.compute(Kc);
    const VecX dq = Kinv.size() > 0 ? VecX(Kinv * s.es) : VecX(cod.solve(s.es));
    for (int k = 0; k < ns; ++k) op.q(op.solved[k]) += dq(k);
    const VecX next = s.solvedResidual();
    const double now = next.lpNorm<Eigen::Infinity>();
    if (!(now < 0.25 * prev)) {
      for (int k = 0; k < ns; ++k) op.q(op.solved[k]) -= dq(k);
      s.fresh = false;
      break;
    }
    // Broyden's update (Broyden 1965): the matrix that maps this step onto the residual's change,
    // Kc dq = es − next, nearest the last one; as Kc dq = es, the correction is −next dqᵀ / dqᵀdq.
    const double dq2 = dq.squaredNorm();
    Kc -= next * dq.transpose() / dq2;
    if (Kinv.size() > 0) {
      // (Kc + u dqᵀ)⁻¹ = Kinv − (Kinv u)(dqᵀ Kinv) / (1 + dqᵀ Kinv u), u = −next / dqᵀdq.
      const VecX Ku = -(Kinv * next) / dq2;
      const double denom = 1.0 + dq.dot(Ku);
      if (std::abs(denom) > 1e-8) {
        const Eigen::RowVectorXd dK = dq.transpose() * Kinv;
        Kinv -= Ku * dK / denom;
      } else {  // nearly singular after the update: factorize it
        Kinv.resize(0, 0);
      }
    }
    s.es = next;
    prev = now;
    ++op.iterations;
  }
  // The updated matrix is nearer the Jacobian here than the one given: a next solve nearby (the
  // trim's next rotor speed or pitch) starts from it (a Newton step below replaces it).
  if (opt.newton_matrix && op.iterations > 0) *opt.newton_matrix = Kc;
}

/// Newton gave up: the largest residual, a load jump it straddled, and a nearly unrestrained coordinate
/// with the load on it (solved again with it held at its start value: the iterates above wander).
[[noreturn]] void notConverged(EquilibriumSolve& s, const OperatingPoint& start) {
  const Model& m = s.m;
  Eigen::Index worst;
  s.es.cwiseAbs().maxCoeff(&worst);
  std::string msg = "operating point did not converge in " + std::to_string(s.opt.max_iterations) +
                    " Newton iterations: residual " + std::to_string(s.es(worst)) + " on DOF '" +
                    m.dofs[s.op.solved[worst]].name + "'";
  if (s.jump.dof >= 0) msg += ": " + describe(m, s.jump);
  const int weak = weakJoint(m, s.op.solved, s.K_first, s.load_seen);
  if (weak >= 0) {
    const int d = s.op.solved[weak];
    std::string load = fmt::format("up to {:.4g}", s.load_seen(weak));
    try {
      std::vector<int> held = s.op.held;
      held.push_back(d);
      EquilibriumOptions again = s.opt;
      again.chord = nullptr;
      again.held = &held;
      const OperatingPoint h = solveOperatingPoint(m, start, again, s.lw);
      load = fmt::format("{:.4g}", h.e(d));
    } catch (const ComputeError&) {
    }
    const std::string unit = loadUnit(m, d);
    msg += fmt::format(": DOF '{}' is nearly unrestrained (stiffness {:.4g} {}/{}) and a load of {} {} acts on it; {}",
                       m.dofs[d].name, std::abs(s.K_first(weak, weak)), unit, unit == "N m" ? "rad" : "m", load, unit,
                       holdAdvice(m, d));
  }
  throw ComputeError(msg);
}

/// One Newton step; false when the iteration should stop before the tolerance (on a load jump, or a
/// step at round-off).
bool newtonStep(EquilibriumSolve& s) {
  const Model& m = s.m;
  OperatingPoint& op = s.op;
  const int ns = s.ns;
  // The AD passes see the element inflows of the residual just evaluated: hand them its BEM roots
  // (aero_section.hxx) instead of solving every element again.
  s.lw.jw.ws.bem = s.lw.ws.bem;
  const MatX J = residualJacobian(m, s.lw.jw, op.q, op.qd, op.qdd, op.u, Wrt::Q, op.solved);
  MatX K(ns, ns);
  for (int r = 0; r < ns; ++r) K.row(r) = -J.row(op.solved[r]);
  if (s.K_first.size() == 0) s.K_first = K;
  if (s.opt.newton_matrix) *s.opt.newton_matrix = K;
  // Coordinates without stiffness are held above; a singular K left (a rigid-body motion the rule
  // does not catch, e.g. with a spring of zero stiffness elsewhere in the chain) is fine as long as
  // nothing pushes along it. Minimum-norm step; refuse a load in the null space.
  Eigen::CompleteOrthogonalDecomposition<MatX> cod(K);
  const VecX dq = cod.solve(s.es);
  if (cod.rank() < ns) {
    const double unbalanced = (K * dq - s.es).lpNorm<Eigen::Infinity>();
    if (unbalanced > 1e-6 * s.scale) {
      Eigen::FullPivLU<MatX> lu(K);
      const MatX ker = lu.kernel();
      Eigen::Index worst = 0;
      ker.col(0).cwiseAbs().maxCoeff(&worst);
      const int d = op.solved[worst];
      throw ComputeError(m.dofs[d].kind == DofKind::Elastic ? stiffnessCancelled(m, d, s.es(worst))
                                                            : noEquilibrium(m, d, s.es(worst)));
    }
  }
  s.q_before2 = std::move(s.q_before);
  s.q_before = op.q;
  s.es_before = s.es;
  for (int k = 0; k < ns; ++k) op.q(op.solved[k]) += dq(k);
  ++op.iterations;
  s.es = s.solvedResidual();
  s.fresh = true;
  if (!s.es.allFinite()) throw ComputeError("operating point: Newton diverged (residual not finite)");
  s.load_seen = s.load_seen.cwiseMax(s.es.cwiseAbs());
  // Back where it was two steps ago: the two last iterates may straddle a jump of the loads.
  if (s.q_before2.size() > 0 &&
      (op.q - s.q_before2).lpNorm<Eigen::Infinity>() <= 1e-3 * (op.q - s.q_before).lpNorm<Eigen::Infinity>()) {
    AeroRecord other;
    VecX e_other(m.ndof());
    residual(m, s.lw.ws, s.q_before, op.qd, op.qdd, op.u, e_other, nullptr, s.record ? &other : nullptr);
    s.jump = loadJump(op.solved, op.q, s.q_before, s.es, s.es_before, s.record, s.record ? &other : nullptr);
    const bool on_jump = s.jump.dof >= 0 && s.jump.size <= kMaxLoadJump * s.scale;
    if (on_jump && s.es_before.norm() < s.es.norm()) op.q = s.q_before;
    // Again at op.q: the workspace's BEM roots are those the next Jacobian (or the linearization) starts from.
    s.es = s.solvedResidual();
    if (on_jump) {
      op.load_jump = s.jump;
      return false;
    }
  }
  return !(dq.lpNorm<Eigen::Infinity>() < 1e-14 * (1.0 + op.q.lpNorm<Eigen::Infinity>()));
}

/// The solved point's record: residuals, inflow, the loads on the held coordinates — which must not
/// move a resting turbine far (at rotor speed linearizePeriodic checks their mean over the revolution).
void finish(EquilibriumSolve& s) {
  const Model& m = s.m;
  OperatingPoint& op = s.op;
  op.residual_norm = s.es.norm();
  if (!s.fresh) residual(m, s.lw.ws, op.q, op.qd, op.qdd, op.u, s.e, nullptr, s.record);
  if (!s.record) op.aero = AeroRecord{};
  op.e = s.e;
  op.inflow = op.aero.inflow();
  op.held_load.resize(static_cast<Eigen::Index>(op.held.size()));
  for (size_t k = 0; k < op.held.size(); ++k) op.held_load(static_cast<Eigen::Index>(k)) = s.e(op.held[k]);
  if (op.qd.isZero(0.0) && !op.held.empty()) {
    MatX M;
    massMatrix(m, s.lw.ws, op.q, M);
    for (int d : op.held) {
      const double drift = 0.5 * std::abs(s.e(d)) / M(d, d) * kHeldDriftTime * kHeldDriftTime;
      if (!(drift <= kMaxHeldDrift))
        throw ComputeError(noEquilibrium(m, d, s.e(d),
                                         fmt::format("{:.3g} {} in {:g} s", drift,
                                                     loadUnit(m, d) == "N m" ? "rad" : "m", kHeldDriftTime)));
    }
  }
  op.residual_max_active = 0;
  for (int i : m.activeDofs())
    if (std::abs(s.e(i)) >= op.residual_max_active) {
      op.residual_max_active = std::abs(s.e(i));
      op.residual_max_dof = m.dofs[i].name;
    }
}

}  // namespace

OperatingPoint solveOperatingPoint(const Model& m, const OperatingPoint& start, const EquilibriumOptions& opt,
                                   LinearizeWorkspace& lw) {
  requireWindWithinLimit(m, start.u);
  EquilibriumSolve s(m, opt, lw, start);
  chooseSolved(m, opt, s.op);
  s.ns = static_cast<int>(s.op.solved.size());
  s.record = m.aero.active() ? &s.op.aero : nullptr;
  const double cold = coldScale(s);
  s.es = s.solvedResidual();
  if (!s.e.allFinite()) throw ComputeError("operating point: the residual is not finite (NaN in the model or inputs)");
  s.scale = loadScale(s, cold);
  s.op.load_scale = s.scale;
  s.op.iterations = 0;
  s.load_seen = s.es.cwiseAbs();
  chordSteps(s);
  while (s.ns > 0 && s.es.lpNorm<Eigen::Infinity>() > s.target()) {
    if (s.op.iterations >= opt.max_iterations) notConverged(s, start);
    if (!newtonStep(s)) break;
  }
  finish(s);
  return s.op;
}

}  // namespace whirl
