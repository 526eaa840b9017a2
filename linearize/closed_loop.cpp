#include "linearize/closed_loop.hpp"

#include <algorithm>

#include "src/base/error.hpp"

namespace whirl {
namespace {

/// A signal of the controller as a linear combination of its states and its inputs: the generator
/// speed ω_g, the wind U, the disturbances d_τ, d_θ added at the torque and actuator inputs and the
/// floating feedback's velocity v.
struct Signal {
  VecX x;
  double w = 0, u = 0, dt = 0, dp = 0, v = 0;
};

/// Columns of the controller's inputs: fed by the plant (ω_g, U, v) and the two disturbances.
constexpr int kPlantFed[3] = {0, 1, 4};
constexpr int kDisturbance[2] = {2, 3};

/// The controller's equations, filled block by block: ẋ = A x + B [ω_g; U; d_τ; d_θ; v].
struct Builder {
  MatX A, B;
  std::vector<std::string> names;
  int next = 0;

  explicit Builder(int n) : A(MatX::Zero(n, n)), B(MatX::Zero(n, 5)) {}
  Signal zero() const { return {VecX::Zero(A.rows()), 0, 0, 0, 0, 0}; }
  int add(const std::string& name) {
    names.push_back("controller: " + name);
    return next++;
  }
  /// ẋ_i += k · s
  void feed(int i, const Signal& s, double k) {
    A.row(i) += k * s.x.transpose();
    B(i, 0) += k * s.w;
    B(i, 1) += k * s.u;
    B(i, 2) += k * s.dt;
    B(i, 3) += k * s.dp;
    B(i, 4) += k * s.v;
  }
  Signal state(int i) const {
    Signal s = zero();
    s.x(i) = 1;
    return s;
  }
};

Signal combine(const Signal& a, double ka, const Signal& b, double kb) {
  return {ka * a.x + kb * b.x,   ka * a.w + kb * b.w,   ka * a.u + kb * b.u,
          ka * a.dt + kb * b.dt, ka * a.dp + kb * b.dp, ka * a.v + kb * b.v};
}

/// First- or second-order low pass of `in` (unit static gain).
Signal lowPass(Builder& b, const Signal& in, int order, double wc, double zeta, const std::string& name) {
  if (order == 0) return in;
  if (order == 1) {
    const int i = b.add(name);
    b.feed(i, b.state(i), -wc);
    b.feed(i, in, wc);
    return b.state(i);
  }
  const int i = b.add(name), j = b.add(name + " rate");
  b.feed(i, b.state(j), 1);
  b.feed(j, b.state(i), -wc * wc);
  b.feed(j, b.state(j), -2 * zeta * wc);
  b.feed(j, in, wc * wc);
  return b.state(i);
}

/// (s² + 2β_n ω s + ω²)/(s² + 2β_d ω s + ω²) = 1 + 2(β_n − β_d) ω s/(s² + 2β_d ω s + ω²).
Signal notch(Builder& b, const Signal& in, const SpeedNotch& n, const std::string& name) {
  const int i = b.add(name), j = b.add(name + " rate");
  b.feed(i, b.state(j), 1);
  b.feed(j, b.state(i), -n.freq * n.freq);
  b.feed(j, b.state(j), -2 * n.beta_den * n.freq);
  b.feed(j, in, 1);
  return combine(in, 1, b.state(j), 2 * (n.beta_num - n.beta_den) * n.freq);
}

/// s/(s + ω_h) = 1 − ω_h/(s + ω_h).
Signal highPass(Builder& b, const Signal& in, double wh, const std::string& name) {
  if (wh <= 0) return in;
  const int i = b.add(name);
  b.feed(i, b.state(i), -wh);
  b.feed(i, in, wh);
  return combine(in, 1, b.state(i), -1);
}

bool hasFloatingFeedback(const LinearController& c) { return c.pitch_active && c.floating_mode > 0; }

/// −K_fl · F(s) v: ROSCO's low pass, high pass and tower-top notches on the velocity.
Signal floatingFeedback(Builder& b, const LinearController& c) {
  Signal v = b.zero();
  v.v = 1;
  v = lowPass(b, v, 2, c.floating_lpf_freq, c.floating_lpf_damping, "floating feedback filter");
  v = highPass(b, v, c.floating_hpf_freq, "floating feedback high pass");
  for (size_t k = 0; k < c.floating_notches.size(); ++k)
    v = notch(b, v, c.floating_notches[k], "floating feedback notch " + std::to_string(k + 1));
  return combine(v, -c.floating_kp, b.zero(), 0);
}

bool hasReferenceFilter(const LinearController& c) { return c.reference_per_wind != 0 && c.reference_filter_freq > 0; }

int stateCount(const LinearController& c) {
  int n = c.lpf_order + 2 * static_cast<int>(c.notches.size());
  if (c.pitch_active) n += 1 + c.actuator_order;
  if (hasFloatingFeedback(c))
    n += 2 + (c.floating_hpf_freq > 0 ? 1 : 0) + 2 * static_cast<int>(c.floating_notches.size());
  if (c.torque == LinearController::Torque::PI) n += 1 + (hasReferenceFilter(c) ? 1 : 0);
  return n;
}

int indexOf(const std::vector<StateSpaceVariable>& v, const std::string& name, const char* what) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  throw InputError(where("", 0, name, std::string("the plant has no ") + what + " of this name"));
}

}  // namespace

StateSpaceModel controllerStateSpace(const LinearController& c) {
  if (c.lpf_order < 0 || c.lpf_order > 2 || c.actuator_order < 0 || c.actuator_order > 2)
    throw InputError(where("", 0, "controller", "filter and actuator orders are 0, 1 or 2"));
  Builder b(stateCount(c));
  Signal speed = b.zero();
  speed.w = 1;
  speed = lowPass(b, speed, c.lpf_order, c.lpf_freq, c.lpf_damping, "speed filter");
  for (size_t k = 0; k < c.notches.size(); ++k)
    speed = notch(b, speed, c.notches[k], "speed notch " + std::to_string(k + 1));
  Signal pitch = b.zero(), torque = b.zero(), pitch_in = b.zero();
  if (c.pitch_active) {
    // e = ω_ref − ω_f; İ = K_i e; θ_c = K_p e + I (ROSCO's PIController, ITerm = ∫K_i e).
    const int i = b.add("pitch PI integral");
    b.feed(i, speed, -c.pitch_ki);
    pitch_in = combine(speed, -c.pitch_kp, b.state(i), 1);
    if (hasFloatingFeedback(c)) pitch_in = combine(pitch_in, 1, floatingFeedback(b, c), 1);
    pitch_in.dp += 1;
    pitch = lowPass(b, pitch_in, c.actuator_order, c.actuator_freq, c.actuator_damping, "pitch actuator");
  }
  switch (c.torque) {
    case LinearController::Torque::Held: break;
    case LinearController::Torque::Static: torque = combine(speed, c.torque_slope, b.zero(), 0); break;
    case LinearController::Torque::PI: {
      Signal ref = b.zero();
      ref.u = c.reference_per_wind;
      if (hasReferenceFilter(c)) ref = lowPass(b, ref, 1, c.reference_filter_freq, 0, "speed reference filter");
      const Signal e = combine(ref, 1, speed, -1);
      const int i = b.add("torque PI integral");
      b.feed(i, e, c.torque_ki);
      torque = combine(e, c.torque_kp, b.state(i), 1);
      break;
    }
  }
  torque.dt += 1;
  StateSpaceModel s;
  s.A = b.A;
  s.B = b.B;
  s.C = MatX(3, b.A.rows());
  s.D = MatX(3, 5);
  s.C.row(0) = torque.x.transpose();
  s.C.row(1) = pitch.x.transpose();
  s.C.row(2) = pitch_in.x.transpose();
  s.D << torque.w, torque.u, torque.dt, torque.dp, torque.v, pitch.w, pitch.u, pitch.dt, pitch.dp, pitch.v, pitch_in.w,
      pitch_in.u, pitch_in.dt, pitch_in.dp, pitch_in.v;
  for (const std::string& n : b.names) s.x.push_back({n, "", 0, -1, -1, false});
  s.u = {{"generator speed", "rad/s"},
         {"wind speed", "m/s"},
         {"torque disturbance", "N m"},
         {"pitch disturbance", "rad"},
         {"floating feedback velocity", c.floating_mode == 2 ? "rad/s" : "m/s"}};
  s.y = {{"generator torque", "N m"}, {"collective pitch", "rad"}, {"actuator input", "rad"}};
  return s;
}

namespace {

/// The loop closed, with the controller's disturbance inputs and its actuator-input output kept in
/// `extra_in` (n + m) × 2 (d_τ, d_θ), `extra_out` 2 × (n + m) and `extra_d` 2 × 2 (τ command, actuator input).
struct Closed {
  StateSpaceModel cl;
  MatX extra_in, extra_out, extra_d;
};

/// Columns `cols` of m.
MatX columns(const MatX& m, const int* cols, int count) {
  MatX out(m.rows(), count);
  for (int j = 0; j < count; ++j) out.col(j) = m.col(cols[j]);
  return out;
}

Closed close(const StateSpaceModel& plant, const LinearController& c, const ClosedLoopPorts& ports) {
  const StateSpaceModel full = controllerStateSpace(c);
  StateSpaceModel k = full;
  k.B = columns(full.B, kPlantFed, 3);
  k.C = full.C.topRows(2);
  k.D = columns(full.D.topRows(2), kPlantFed, 3);
  const int it = indexOf(plant.u, ports.torque_input, "input");
  const int ip = indexOf(plant.u, ports.pitch_input, "input");
  const int ig = indexOf(plant.y, ports.speed_output, "output");
  int iw = -1, iv = -1;
  if (k.B.col(1).any() || k.D.col(1).any()) iw = indexOf(plant.u, ports.wind_input, "input");
  if (hasFloatingFeedback(c)) iv = indexOf(plant.y, floatingFeedbackOutput(c, ports), "output");
  if (plant.D(ig, it) != 0 || plant.D(ig, ip) != 0)
    throw InputError(
        where("", 0, ports.speed_output, "depends directly on the torque or the pitch (an algebraic loop)"));
  if (iv >= 0 && (plant.D(iv, it) != 0 || plant.D(iv, ip) != 0))
    throw InputError(where("", 0, plant.y[static_cast<size_t>(iv)].name,
                           "depends directly on the torque or the pitch (an algebraic loop)"));
  const Eigen::Index n = plant.A.rows(), m = k.A.rows(), nu = plant.B.cols();
  // Controller inputs [ω_g; U; v] = G_x x + G_u u, with ω_g = C_g x + D_g u, U the plant's wind input
  // and v the floating feedback's velocity output.
  MatX Gx = MatX::Zero(3, n), Gu = MatX::Zero(3, nu);
  Gx.row(0) = plant.C.row(ig);
  Gu.row(0) = plant.D.row(ig);
  if (iw >= 0) Gu(1, iw) = 1;
  if (iv >= 0) {
    Gx.row(2) = plant.C.row(iv);
    Gu.row(2) = plant.D.row(iv);
  }
  // Plant inputs: u_plant = u + S (C_k x_k + D_k [ω_g; U]), S placing torque and pitch.
  MatX S = MatX::Zero(nu, 2);
  S(it, 0) = 1;
  S(ip, 1) = 1;
  const MatX BS = plant.B * S, DS = plant.D * S;
  StateSpaceModel cl = plant;
  cl.A = MatX::Zero(n + m, n + m);
  cl.A.topLeftCorner(n, n) = plant.A + BS * k.D * Gx;
  cl.A.topRightCorner(n, m) = BS * k.C;
  cl.A.bottomLeftCorner(m, n) = k.B * Gx;
  cl.A.bottomRightCorner(m, m) = k.A;
  cl.B = MatX(n + m, nu);
  cl.B.topRows(n) = plant.B + BS * k.D * Gu;
  cl.B.bottomRows(m) = k.B * Gu;
  cl.C = MatX(plant.C.rows(), n + m);
  cl.C.leftCols(n) = plant.C + DS * k.D * Gx;
  cl.C.rightCols(m) = DS * k.C;
  cl.D = plant.D + DS * k.D * Gu;
  // The controller's commands as outputs too (a Bode plot of wind to pitch): [τ; θ] = D_k G_x x + C_k x_k + D_k G_u u.
  const Eigen::Index ny = plant.C.rows();
  cl.C.conservativeResize(ny + 2, n + m);
  cl.D.conservativeResize(ny + 2, nu);
  cl.C.bottomLeftCorner(2, n) = k.D * Gx;
  cl.C.bottomRightCorner(2, m) = k.C;
  cl.D.bottomRows(2) = k.D * Gu;
  cl.y.push_back({"controller: generator torque", "N m", plant.u[static_cast<size_t>(it)].op, -1, -1, false});
  cl.y.push_back({"controller: collective pitch", "rad", plant.u[static_cast<size_t>(ip)].op, -1, -1, false});
  cl.x.insert(cl.x.end(), k.x.begin(), k.x.end());
  if (cl.xdot_op.size() == n) {
    cl.xdot_op.conservativeResize(n + m);
    cl.xdot_op.tail(m).setZero();
  }
  // Disturbances d = [d_τ; d_θ] enter the controller's outputs through D_d (2 × 2 of full.D) and its
  // states through B_d; the plant sees them through BS.
  const MatX Bd = columns(full.B, kDisturbance, 2), Dd = columns(full.D.topRows(2), kDisturbance, 2);
  Closed out{cl, MatX(n + m, 2), MatX(2, n + m), MatX(2, 2)};
  out.extra_in.topRows(n) = BS * Dd;
  out.extra_in.bottomRows(m) = Bd;
  // Outputs: the torque command (row 0 of the controller) and the actuator input (row 2).
  MatX Ck(2, m), Dk(2, 5);
  Ck << full.C.row(0), full.C.row(2);
  Dk << full.D.row(0), full.D.row(2);
  out.extra_out.leftCols(n) = columns(Dk, kPlantFed, 3) * Gx;
  out.extra_out.rightCols(m) = Ck;
  out.extra_d = columns(Dk, kDisturbance, 2);
  return out;
}

}  // namespace

std::string floatingFeedbackOutput(const LinearController& c, const ClosedLoopPorts& ports) {
  if (!hasFloatingFeedback(c)) return "";
  return c.floating_mode == 2 ? ports.nacelle_pitch_rate_output : ports.tower_top_velocity_output;
}

StateSpaceModel closeLoop(const StateSpaceModel& plant, const LinearController& c, const ClosedLoopPorts& ports) {
  return close(plant, c, ports).cl;
}

LoopSensitivity loopSensitivity(const StateSpaceModel& plant, const LinearController& c, BrokenLoop loop,
                                const ClosedLoopPorts& ports) {
  const Closed k = close(plant, c, ports);
  const int i = loop == BrokenLoop::Torque ? 0 : 1;
  LoopSensitivity s;
  s.A = k.cl.A;
  s.b = k.extra_in.col(i);
  s.c = k.extra_out.row(i).transpose();
  s.d = k.extra_d(i, i);
  return s;
}

}  // namespace whirl
