#include "linearize/operating_point.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "linearize/jacobian.hpp"
#include "linearize/linearize.hpp"
#include "linearize/unrestrained.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/mooring_scale.hpp"
#include "src/dynamics/residual.hpp"
#include "src/model/error.hpp"

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

// A load along a coordinate without stiffness: no static equilibrium. `motion`: how far it would
// move, if known.
std::string noEquilibrium(const Model& m, int dof, double load, const std::string& motion = "") {
  return fmt::format("operating point: a load acts along DOF '{}' ({:.4g} {}), which has no stiffness (a free "
                     "rigid-body motion): {}no equilibrium; {}, or mark it rotating",
                     m.dofs[dof].name, load, loadUnit(m, dof),
                     motion.empty() ? "" : "it would move " + motion + " (limit " + fmt::format("{:g}", kMaxHeldDrift) + "), ",
                     holdAdvice(m, dof));
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

OperatingPoint solveOperatingPoint(const Model& m, const OperatingPoint& start, const EquilibriumOptions& opt,
                                   LinearizeWorkspace& lw) {
  OperatingPoint op = start;
  op.solved.clear();
  op.held = opt.held ? *opt.held : unrestrainedCoordinates(m, start.q, start.qd, start.u);
  for (int i : m.activeDofs()) {
    if (m.dofs[i].rotating) continue;
    if (op.qd(i) != 0.0)
      throw ComputeError("DOF '" + m.dofs[i].name + "': a non-rotating coordinate has a rate; mark it rotating or freeze it");
    if (std::find(op.held.begin(), op.held.end(), i) != op.held.end()) continue;
    op.solved.push_back(i);
  }
  Workspace<double>& ws = lw.ws;
  JacobianWorkspace& jw = lw.jw;
  VecX e(m.ndof());
  const int ns = static_cast<int>(op.solved.size());
  // Every residual records the blade elements, so that the last one, at the solution, is the record
  // (no evaluation again at the end); `fresh`: e and the record are those of op.q.
  AeroRecord* record = m.aero.active() ? &op.aero : nullptr;
  bool fresh = true;
  auto solvedResidual = [&]() {
    residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, record);
    VecX es(ns);
    for (int k = 0; k < ns; ++k) es(k) = e(op.solved[k]);
    return es;
  };
  double cold_scale = -1;
  if (!(opt.load_scale > 0) && opt.scale_from) {
    const OperatingPoint& c = *opt.scale_from;
    residual(m, ws, c.q, c.qd, c.qdd, c.u, e);
    cold_scale = 0;
    for (int i : op.solved) cold_scale = std::max(cold_scale, std::abs(e(i)));
  }
  VecX es = solvedResidual();
  if (!e.allFinite()) throw ComputeError("operating point: the residual is not finite (NaN in the model or inputs)");
  // Load scale: the residual at the undeflected start, or the gravity/centrifugal loads it holds; moored,
  // at least the line tensions, whose balance at a symmetric start leaves a residual of their round-off.
  double scale = opt.load_scale;
  if (!(scale > 0))
    scale = std::max({1.0, cold_scale >= 0 ? cold_scale : es.lpNorm<Eigen::Infinity>(), largestMooringTension(m, ws)});
  op.load_scale = scale;
  op.iterations = 0;
  const double target = opt.tolerance * scale;
  // For the message when Newton fails: the stiffness of the first Newton matrix and the largest
  // loads seen on each solved coordinate over the iterations.
  VecX load_seen = es.cwiseAbs();
  // The two iterates before op.q and the residual at the last one: a jump of the loads between them.
  VecX q_before, q_before2, es_before;
  LoadJump jump;
  MatX K_first;
  if ((opt.chord || opt.chord_matrix) && ns > 0 && es.lpNorm<Eigen::Infinity>() > target) {
    // Chord steps are a residual and a back-substitution each, a fifth of a Newton step (which
    // needs the AD stiffness); a step that gains less than 4× is undone and Newton goes on.
    MatX Kc = opt.chord ? chordMatrix(*opt.chord, op.solved) : *opt.chord_matrix;
    if (Kc.rows() == ns && Kc.cols() == ns) {
      // A regular chord matrix is inverted once and its inverse follows the Broyden updates by
      // Sherman–Morrison (n² per step instead of a factorization); a rank-deficient one (a rigid-body
      // motion the hold rule does not catch) keeps the minimum-norm steps of its factorization.
      Eigen::CompleteOrthogonalDecomposition<MatX> cod(Kc);
      MatX Kinv;
      if (cod.rank() == ns) Kinv = Kc.partialPivLu().inverse();
      double prev = es.lpNorm<Eigen::Infinity>();
      while (op.iterations < 8 && prev > target) {
        if (op.iterations > 0 && Kinv.size() == 0) cod.compute(Kc);
        const VecX dq = Kinv.size() > 0 ? VecX(Kinv * es) : VecX(cod.solve(es));
        for (int k = 0; k < ns; ++k) op.q(op.solved[k]) += dq(k);
        const VecX next = solvedResidual();
        const double now = next.lpNorm<Eigen::Infinity>();
        if (!(now < 0.25 * prev)) {
          for (int k = 0; k < ns; ++k) op.q(op.solved[k]) -= dq(k);
          fresh = false;
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
        es = next;
        prev = now;
        ++op.iterations;
      }
      // The updated matrix is nearer the Jacobian here than the one given: a next solve nearby (the
      // trim's next rotor speed or pitch) starts from it (a Newton step below replaces it).
      if (opt.newton_matrix && op.iterations > 0) *opt.newton_matrix = Kc;
    }
  }
  while (ns > 0 && es.lpNorm<Eigen::Infinity>() > opt.tolerance * scale) {
    if (op.iterations >= opt.max_iterations) {
      Eigen::Index worst;
      es.cwiseAbs().maxCoeff(&worst);
      std::string msg = "operating point did not converge in " + std::to_string(opt.max_iterations) +
                        " Newton iterations: residual " + std::to_string(es(worst)) + " on DOF '" +
                        m.dofs[op.solved[worst]].name + "'";
      if (jump.dof >= 0) msg += ": " + describe(m, jump);
      const int weak = weakJoint(m, op.solved, K_first, load_seen);
      if (weak >= 0) {
        // The load on it is what the rest of the structure pushes with while it is held: solve
        // again with it held at its start value (the iterates above wander).
        const int d = op.solved[weak];
        std::string load = fmt::format("up to {:.4g}", load_seen(weak));
        try {
          std::vector<int> held = op.held;
          held.push_back(d);
          EquilibriumOptions again = opt;
          again.chord = nullptr;
          again.held = &held;
          const OperatingPoint h = solveOperatingPoint(m, start, again, lw);
          load = fmt::format("{:.4g}", h.e(d));
        } catch (const ComputeError&) {
        }
        const std::string unit = loadUnit(m, d);
        msg += fmt::format(": DOF '{}' is nearly unrestrained (stiffness {:.4g} {}/{}) and a load of {} {} acts on it; {}",
                           m.dofs[d].name, std::abs(K_first(weak, weak)), unit, unit == "N m" ? "rad" : "m", load, unit,
                           holdAdvice(m, d));
      }
      throw ComputeError(msg);
    }
    // The AD passes see the element inflows of the residual just evaluated: hand them its BEM roots
    // (aero_section.hxx) instead of solving every element again.
    jw.ws.bem = ws.bem;
    const MatX J = residualJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::Q, op.solved);
    MatX K(ns, ns);
    for (int r = 0; r < ns; ++r) K.row(r) = -J.row(op.solved[r]);
    if (K_first.size() == 0) K_first = K;
    if (opt.newton_matrix) *opt.newton_matrix = K;
    // Coordinates without stiffness are held above; a singular K left (a rigid-body motion the rule
    // does not catch, e.g. with a spring of zero stiffness elsewhere in the chain) is fine as long as
    // nothing pushes along it. Minimum-norm step; refuse a load in the null space.
    Eigen::CompleteOrthogonalDecomposition<MatX> cod(K);
    const VecX dq = cod.solve(es);
    if (cod.rank() < ns) {
      const double unbalanced = (K * dq - es).lpNorm<Eigen::Infinity>();
      if (unbalanced > 1e-6 * scale) {
        Eigen::FullPivLU<MatX> lu(K);
        const MatX ker = lu.kernel();
        Eigen::Index worst = 0;
        ker.col(0).cwiseAbs().maxCoeff(&worst);
        const int d = op.solved[worst];
        throw ComputeError(noEquilibrium(m, d, es(worst)));
      }
    }
    q_before2 = std::move(q_before);
    q_before = op.q;
    es_before = es;
    for (int k = 0; k < ns; ++k) op.q(op.solved[k]) += dq(k);
    ++op.iterations;
    es = solvedResidual();
    fresh = true;
    if (!es.allFinite()) throw ComputeError("operating point: Newton diverged (residual not finite)");
    load_seen = load_seen.cwiseMax(es.cwiseAbs());
    // Back where it was two steps ago: the two last iterates may straddle a jump of the loads.
    if (q_before2.size() > 0 &&
        (op.q - q_before2).lpNorm<Eigen::Infinity>() <= 1e-3 * (op.q - q_before).lpNorm<Eigen::Infinity>()) {
      AeroRecord other;
      VecX e_other(m.ndof());
      residual(m, ws, q_before, op.qd, op.qdd, op.u, e_other, nullptr, record ? &other : nullptr);
      jump = loadJump(op.solved, op.q, q_before, es, es_before, record, record ? &other : nullptr);
      const bool on_jump = jump.dof >= 0 && jump.size <= kMaxLoadJump * scale;
      if (on_jump && es_before.norm() < es.norm()) op.q = q_before;
      // Again at op.q: the workspace's BEM roots are those the next Jacobian (or the linearization) starts from.
      es = solvedResidual();
      if (on_jump) {
        op.load_jump = jump;
        break;
      }
    }
    if (dq.lpNorm<Eigen::Infinity>() < 1e-14 * (1.0 + op.q.lpNorm<Eigen::Infinity>())) break;
  }
  op.residual_norm = es.norm();
  if (!fresh) residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, record);
  if (!record) op.aero = AeroRecord{};
  op.e = e;
  op.inflow = op.aero.inflow();
  op.held_load.resize(static_cast<Eigen::Index>(op.held.size()));
  for (size_t k = 0; k < op.held.size(); ++k) op.held_load(static_cast<Eigen::Index>(k)) = e(op.held[k]);
  if (op.qd.isZero(0.0) && !op.held.empty()) {
    // Nothing turns: the load on a held coordinate is steady (at rotor speed linearizePeriodic
    // checks its mean over the revolution).
    MatX M;
    massMatrix(m, ws, op.q, M);
    for (int d : op.held) {
      const double drift = 0.5 * std::abs(e(d)) / M(d, d) * kHeldDriftTime * kHeldDriftTime;
      if (!(drift <= kMaxHeldDrift))
        throw ComputeError(noEquilibrium(m, d, e(d), fmt::format("{:.3g} {} in {:g} s", drift,
                                                                    loadUnit(m, d) == "N m" ? "rad" : "m",
                                                                    kHeldDriftTime)));
    }
  }
  op.residual_max_active = 0;
  for (int i : m.activeDofs())
    if (std::abs(e(i)) >= op.residual_max_active) {
      op.residual_max_active = std::abs(e(i));
      op.residual_max_dof = m.dofs[i].name;
    }
  return op;
}

}  // namespace whirl
