#include "modal/closed_loop_modes.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "linearize/export_point.hpp"
#include "modal/aero_roots.hpp"
#include "modal/eigen.hpp"

namespace whirl {
namespace {

const std::string kController = "controller: ";

/// The group a state belongs to for naming.
std::string groupOf(const StateSpaceVariable& v, bool pitch_loop, const std::vector<StateSpaceVariable>& x) {
  std::string n = v.name;
  if (n.rfind(kController, 0) == 0) {
    n = n.substr(kController.size());
    if (n.size() > 5 && n.compare(n.size() - 5, 5, " rate") == 0) n = n.substr(0, n.size() - 5);
    if (n == "pitch PI integral") return "rotor speed / pitch control";
    if (n == "torque PI integral") return "torque control";
    return n;
  }
  const StateSpaceVariable& d = v.rate_of >= 0 ? x[static_cast<size_t>(v.rate_of)] : v;
  if (d.azimuth || (v.rate_of < 0 && v.name.find("azimuth") != std::string::npos))
    return pitch_loop ? "rotor speed / pitch control" : "rotor speed / torque control";
  // A blade pattern's cosine and sine coordinates are one cyclic group (a whirl moves both).
  if (d.name.ends_with(" cos") || d.name.ends_with(" sin")) return d.name.substr(0, d.name.size() - 4) + " cyclic";
  return d.name;
}

/// "<pattern> cyclic" as backward or forward whirl from the phase of the mode's sine coordinate against
/// its cosine one (modal/rotor_modes.hpp: q_s/q_c = −i turns with the rotor, FW); parked, the larger
/// of the two. Other names are returned as they are.
std::string whirlName(const std::string& name, const StateSpaceModel& s, const Eigen::VectorXcd& v,
                      double rotor_speed) {
  if (!name.ends_with(" cyclic")) return name;
  const std::string base = name.substr(0, name.size() - 7);
  Eigen::Index ic = -1, is = -1;
  for (size_t i = 0; i < s.x.size(); ++i) {
    if (s.x[i].rate_of >= 0) continue;
    if (s.x[i].name == base + " cos") ic = static_cast<Eigen::Index>(i);
    if (s.x[i].name == base + " sin") is = static_cast<Eigen::Index>(i);
  }
  if (ic < 0 || is < 0 || std::abs(v(ic)) == 0) return name;
  if (std::abs(rotor_speed) < 1e-2) return base + (std::abs(v(ic)) >= std::abs(v(is)) ? " cos" : " sin");
  const bool forward = ((v(is) / v(ic)).imag() < 0) == (rotor_speed > 0);
  return base + (forward ? " FW" : " BW");
}

/// Marks the roots the unsteady-airfoil states add (modal/aero_roots.hpp): as many as there are such
/// states, by their participation share in them (`share`, one per mode).
void nameClosedLoopAeroRoots(std::vector<ClosedLoopMode>& modes, const std::vector<double>& share, int states) {
  std::vector<bool> pair(modes.size()), none(modes.size(), false);
  for (std::size_t k = 0; k < modes.size(); ++k) pair[k] = modes[k].damped_freq_hz > 0;
  const std::vector<bool> is_aero = pickAeroRoots(share, pair, none, states);
  for (std::size_t k = 0; k < modes.size(); ++k) modes[k].aero = is_aero[k];
}

}  // namespace

std::vector<ClosedLoopMode> namedModes(const StateSpaceModel& s, bool has_pitch_loop, double rotor_speed) {
  return namedModes(s, eigenStandard(s.A, true), has_pitch_loop, rotor_speed);
}

std::vector<ClosedLoopMode> namedModes(const StateSpaceModel& s, const EigenDecomposition& e, bool has_pitch_loop,
                                       double rotor_speed) {
  const Eigen::Index n = e.values.size();
  std::vector<ClosedLoopMode> modes;
  std::vector<double> aero_share;
  int aero_states = 0;
  for (const StateSpaceVariable& v : s.x) aero_states += isAeroStateName(v.name);
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::complex<double> lambda = e.values(j);
    if (lambda.imag() < 0) continue;  // one of each pair
    std::map<std::string, double> share;
    double total = 0, controller = 0, aero = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double p = std::abs(e.vectors(i, j) * std::conj(e.left(i, j)));
      const StateSpaceVariable& v = s.x[static_cast<size_t>(i)];
      total += p;
      if (isAeroStateName(v.name)) {  // names no mode: the aerodynamic roots are named apart below
        aero += p;
        continue;
      }
      share[groupOf(v, has_pitch_loop, s.x)] += p;
      if (v.name.rfind(kController, 0) == 0) controller += p;
    }
    aero_share.push_back(total > 0 ? aero / total : 0);
    ClosedLoopMode m;
    m.eigenvalue = lambda;
    const ModalFrequency f = modalFrequency(lambda);
    m.freq_hz = f.freq_hz;
    m.damped_freq_hz = f.damped_freq_hz;
    m.damping_ratio = f.damping_ratio;
    m.controller_share = total > 0 ? controller / total : 0;
    Eigen::Index big = 0;
    e.vectors.col(j).cwiseAbs().maxCoeff(&big);
    m.shape = e.vectors.col(j) / e.vectors(big, j);
    if (share.empty()) share["aerodynamic states"] = aero;  // no state but the aerodynamic ones
    m.name = std::max_element(share.begin(), share.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
    m.name = whirlName(m.name, s, e.vectors.col(j), rotor_speed);
    modes.push_back(m);
  }
  if (aero_states > 0) nameClosedLoopAeroRoots(modes, aero_share, aero_states);
  std::sort(modes.begin(), modes.end(), [](const auto& a, const auto& b) { return a.freq_hz < b.freq_hz; });
  if (aero_states > 0) {
    int k = 0;
    for (ClosedLoopMode& m : modes)
      if (m.aero) m.name = "aero " + std::to_string(++k);  // numbered by frequency, as the open loop's
  }
  return modes;
}

ClosedLoopPoint closedLoopPoint(const Model& model, const SteadyState& steady, const LinearController& controller,
                                const ClosedLoopOptions& opt) {
  Model plant_model = model;
  plant_model.generator.speed_output = -1;  // the controller sets the generator torque
  if (!opt.outputs.empty()) {
    std::vector<std::string> wanted = opt.outputs;
    const std::string floating = floatingFeedbackOutput(controller, opt.ports);  // the loop reads it too
    if (!floating.empty()) wanted.push_back(floating);
    std::vector<Output> kept;
    for (const Output& o : plant_model.outputs)
      if (std::find(wanted.begin(), wanted.end(), o.name) != wanted.end()) kept.push_back(o);
    plant_model.outputs = std::move(kept);
  }
  OperatingCondition c = steady.condition;
  c.generator_torque = steady.generator_torque;
  ExportOptions eo;
  eo.azimuths = opt.azimuths;
  eo.drop_azimuth = true;
  eo.frozen_wake = opt.frozen_wake;
  if (!steady.azimuth_q.empty()) eo.deflections = &steady.azimuth_q.front();
  return closedLoopPoint(exportOperatingPoint(plant_model, c, eo).model, steady, controller, opt);
}

ClosedLoopPoint closedLoopPoint(const StateSpaceModel& plant, const SteadyState& steady,
                                const LinearController& controller, const ClosedLoopOptions& opt) {
  const OperatingCondition& c = steady.condition;
  ClosedLoopPoint p;
  p.steady = steady;
  p.plant = plant;
  p.closed = closeLoop(p.plant, controller, opt.ports);
  p.open_modes = namedModes(p.plant, false, c.rotor_speed);
  // One decomposition of the closed loop's A for its modes and both loops' margins (the broken loops'
  // sensitivities share it).
  const EigenDecomposition e = eigenStandard(p.closed.A, true);
  const ModalBasis basis{e.values, e.vectors, e.left};
  p.closed_modes = namedModes(p.closed, e, controller.pitch_active, c.rotor_speed);
  p.least_damping = 1;
  for (const ClosedLoopMode& m : p.closed_modes) {
    if (m.eigenvalue.real() >= 0) p.stable = false;
    p.least_damping = std::min(p.least_damping, m.damping_ratio);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  p.pitch = p.torque = LoopMargins{nan, nan, nan, nan, nan, nan, nan};
  if (controller.pitch_active)
    p.pitch = loopMargins(loopSensitivity(p.plant, controller, BrokenLoop::Pitch, opt.ports), basis, opt.margins);
  if (controller.torque != LinearController::Torque::Held)
    p.torque = loopMargins(loopSensitivity(p.plant, controller, BrokenLoop::Torque, opt.ports), basis, opt.margins);
  return p;
}

}  // namespace whirl
