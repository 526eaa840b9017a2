#include "src/turbine/beamdyn_blade.hpp"

#include <utility>

namespace whirl {

fem::Blade6Input blade6Input(const io::BeamDynInput& bd) {
  fem::Blade6Input in;
  for (const io::BeamDynKeyPoint& k : bd.key_points) in.key_points.push_back({k.r, k.twist});
  for (const io::BeamDynStation& s : bd.blade.stations) in.stations.push_back({s.eta, s.K, s.M});
  in.mu = bd.blade.mu;
  return in;
}

BeamDynBladeBody beamDynBladeBody(const io::BeamDynInput& bd, const BeamDynBladeOptions& opt) {
  fem::Blade6Body b = fem::blade6Body(blade6Input(bd), opt);
  BeamDynBladeBody out;
  out.model = std::move(b.model);
  out.beam.props = std::move(b.props);
  out.beam.shapes = std::move(b.shapes);
  out.beam.nodes = opt.elements;
  out.beam.tip_mass = 0;
  out.K = std::move(b.K);
  out.D = std::move(b.D);
  out.freq_hz = std::move(b.freq_hz);
  out.length = b.length;
  return out;
}

fem::Beam6Model beamDynBladeModel(const io::BeamDynInput& bd, int elements) {
  return fem::blade6Model(blade6Input(bd), elements);
}

}  // namespace whirl
