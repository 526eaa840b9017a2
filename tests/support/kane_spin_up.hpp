#pragma once
// Kane's driver experiment [Branlard2019, §5.2] as the time-domain tests run it: the coordinate
// `theta` driven by θ̈ = (2/5)(1 − cos(πt/7.5)) for 15 s, then 6 rad/s, over 0–20 s recorded every
// 0.05 s at tight IDA tolerances (cases/kane_beam, cases/prebent_beam and their chain references).
#include "linearize/simulate.hpp"

namespace whirl::test {

inline Simulation kaneSpinUp(const Model& m) {
  SimulationOptions so;
  so.t_end = 20;
  so.dt_out = 0.05;
  so.rtol = 1e-8;
  so.atol = 1e-10;
  TimeSignal s;
  s.kind = TimeSignal::Kind::Spinup;
  s.parameters = {15, 6};
  so.driven.push_back({*m.findDof("theta"), s});
  return simulate(m, initialPoint(m), so);
}

}  // namespace whirl::test
