#include "linearize/periodic.hpp"

#include <numbers>

#include "src/model/error.hpp"

namespace whirl {

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
  const double psi0 = start.q(p.azimuth_dof);
  // A parked rotor is a time-invariant system at its azimuth: one linearization, whose multiblade
  // transform is exact (averaging the azimuth-dependent parked models would blur them).
  const int n = p.rotor_speed == 0.0 ? 1 : opt.azimuths;
  LinearizeWorkspace lw(m);
  for (int k = 0; k < n; ++k) {
    const double psi = psi0 + 2 * std::numbers::pi * k / n;
    guess.q(p.azimuth_dof) = psi;
    EquilibriumOptions eq;
    if (k > 0) {
      eq.chord = &p.models.back();  // the stiffness barely changes from one azimuth to the next
      eq.load_scale = p.points.front().load_scale;
      eq.held = &p.points.front().held;  // every azimuth holds the same free coordinates (a free yaw)
    }
    OperatingPoint op = solveOperatingPoint(m, guess, eq, lw);
    p.models.push_back(linearize(m, op, lw));
    p.azimuths.push_back(psi);
    p.points.push_back(op);
    guess = op;
    // The equilibrium moves smoothly with the azimuth: extrapolating the last two leaves the chord
    // iterations a residual ~10× smaller to remove than starting from the last one.
    if (k > 0)
      for (int i : op.solved) guess.q(i) = 2 * op.q(i) - p.points[p.points.size() - 2].q(i);
  }
  return p;
}

PeriodicLinearization linearizePeriodic(const Model& m, const OperatingCondition& c, const PeriodicOptions& opt) {
  return linearizePeriodic(m, initialPoint(m, c), opt);
}

}  // namespace whirl
