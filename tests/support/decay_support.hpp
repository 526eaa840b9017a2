#pragma once
// The free decay of one coordinate of a simulation, identified (frequency, damping), and the mode of a
// linear model it is compared with: the steps every time-domain validation shares.
#include <cmath>
#include <string>
#include <vector>

#include "linearize/simulate.hpp"
#include "modal/decay_identification.hpp"
#include "modal/era.hpp"
#include "modal/modes.hpp"
#include "modal/nonlinear_check.hpp"

namespace whirl::test {

/// Frequency and damping of coordinate `dof`'s decay about `equilibrium`.
inline IdentifiedDecay identifyDofDecay(const Simulation& sim, int dof, double equilibrium) {
  std::vector<double> x(sim.time.size());
  for (size_t k = 0; k < x.size(); ++k) x[k] = sim.q(static_cast<Eigen::Index>(k), dof);
  return identifyDecay(sim.time, x, equilibrium);
}

/// The mode named `name`, nullptr if none.
inline const Mode* modeNamed(const std::vector<Mode>& modes, const std::string& name) {
  for (const Mode& md : modes)
    if (md.name == name) return &md;
  return nullptr;
}

}  // namespace whirl::test
