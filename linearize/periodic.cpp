#include "linearize/periodic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "linearize/unrestrained.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

// The held coordinates' drift over one revolution under the mean of their load (kMaxHeldDrift).
void checkHeldDrift(const Model& m, const PeriodicLinearization& p) {
  const OperatingPoint& first = p.points.front();
  const LinearModel& lin = p.models.front();
  const double period = 2 * std::numbers::pi / std::abs(p.rotor_speed);
  for (size_t k = 0; k < first.held.size(); ++k) {
    const int d = first.held[k];
    double mean = 0;
    for (const OperatingPoint& op : p.points) mean += op.held_load(static_cast<Eigen::Index>(k)) / p.points.size();
    const auto at = std::find(lin.dofs.begin(), lin.dofs.end(), d) - lin.dofs.begin();
    const double drift = 0.5 * std::abs(mean) / lin.M(at, at) * period * period;
    if (!(drift <= kMaxHeldDrift)) {
      const std::string unit = loadUnit(m, d);
      throw ComputeError(fmt::format(
          "operating point: a mean load of {:.4g} {} acts along DOF '{}', which has no stiffness (a free rigid-body "
          "motion): it would move {:.3g} {} in one revolution (limit {:g}), no periodic operating point; {}",
          mean, unit, m.dofs[d].name, drift, unit == "N m" ? "rad" : "m", kMaxHeldDrift, holdAdvice(m, d)));
    }
  }
}

// "azimuth 30 deg: ", what an error at one azimuth of a periodic linearization starts with (the
// sweep adds the rotor speed, wind speed and pitch); nothing for a single linearization.
std::string atAzimuth(double psi, int n) {
  return n > 1 ? fmt::format("azimuth {:.6g} deg: ", psi * 180 / std::numbers::pi) : std::string();
}

}  // namespace

int findAzimuthDof(const Model& m) {
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].rotating) return i;
  return -1;
}

PeriodicLinearization linearizePeriodic(const Model& m, const OperatingPoint& start, const PeriodicOptions& opt) {
  PeriodicLinearization p;
  p.azimuth_dof = opt.azimuth_dof >= 0 ? opt.azimuth_dof : findAzimuthDof(m);
  if (p.azimuth_dof < 0) throw InputError("periodic linearization: the model has no rotating DOF (an azimuth)");
  if (opt.azimuths < 1) throw InputError("--azimuths: must be at least 1");
  p.rotor_speed = start.qd(p.azimuth_dof);
  OperatingPoint guess = start;
  const bool warm = opt.deflections && opt.deflections->size() == start.q.size();
  if (warm) copyDeflections(m, *opt.deflections, guess.q);
  const double psi0 = start.q(p.azimuth_dof);
  // A parked rotor is a time-invariant system at its azimuth: one linearization, whose multiblade
  // transform is exact (averaging the azimuth-dependent parked models would blur them).
  const int n = p.rotor_speed == 0.0 ? 1 : opt.azimuths;
  LinearizeWorkspace lw(m);
  for (int k = 0; k < n; ++k) {
    const double psi = psi0 + 2 * std::numbers::pi * k / n;
    guess.q(p.azimuth_dof) = psi;
    EquilibriumOptions eq;
    if (k == 0 && warm) eq.scale_from = &start;
    if (k > 0) {
      eq.chord = &p.models.back();  // the stiffness barely changes from one azimuth to the next
      eq.load_scale = p.points.front().load_scale;
      eq.held = &p.points.front().held;  // every azimuth holds the same free coordinates (a free yaw)
    }
    OperatingPoint op;
    try {
      op = solveOperatingPoint(m, guess, eq, lw);
      p.models.push_back(linearize(m, op, lw, opt.linearize));
    } catch (const InputError& e) {
      throw InputError(atAzimuth(psi, n) + e.what());
    } catch (const ComputeError& e) {
      throw ComputeError(atAzimuth(psi, n) + e.what());
    }
    p.azimuths.push_back(psi);
    p.points.push_back(op);
    guess = op;
    // The equilibrium is periodic in the azimuth, mostly its mean and first two harmonics (gravity on
    // the blades): the guess extrapolates the last five (three) points exactly for a + Σ_{h≤2} (b_h cos
    // hψ + c_h sin hψ) (for a + b cos ψ + c sin ψ) — the linear recurrence whose characteristic roots
    // are 1, e^{±iΔ}, e^{±2iΔ} (Δ = 2π/n). Against the quadratic polynomial extrapolation used before,
    // the NREL 5MW aeroelastic sweep (trim included) takes 3781 chord steps instead of 4051 and 13
    // Newton steps (AD stiffness) instead of 63.
    const std::size_t np = p.points.size();
    const double a = 2 * std::cos(2 * std::numbers::pi / n), b = 2 * std::cos(4 * std::numbers::pi / n);
    auto q = [&](std::size_t back, int i) { return p.points[np - back].q(i); };
    if (np >= 5)
      for (int i : op.solved)
        guess.q(i) = (a + b + 1) * (q(1, i) - q(4, i)) - (2 + a * b + a + b) * (q(2, i) - q(3, i)) + q(5, i);
    else if (np >= 3)
      for (int i : op.solved) guess.q(i) = (1 + a) * (q(1, i) - q(2, i)) + q(3, i);
    else if (np == 2)
      for (int i : op.solved) guess.q(i) = 2 * op.q(i) - p.points[np - 2].q(i);
  }
  if (n > 1) checkHeldDrift(m, p);
  return p;
}

PeriodicLinearization linearizePeriodic(const Model& m, const OperatingCondition& c, const PeriodicOptions& opt) {
  return linearizePeriodic(m, initialPoint(m, c), opt);
}

}  // namespace whirl
