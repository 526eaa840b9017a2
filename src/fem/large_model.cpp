#include "src/fem/large_model.hpp"

#include "src/fem/boundary.hpp"

namespace whirl::fem {

SparseModel fineTowerModel(int elements) {
  BeamStations p;
  const double L = 87.6;
  p.x = VecX::LinSpaced(11, 0, L);
  p.m.resize(11);
  p.EIy.resize(11);
  p.m << 5590.87, 5232.43, 4885.76, 4550.87, 4227.75, 3916.41, 3616.83, 3329.03, 3053.01, 2788.75, 2536.27;
  p.EIy << 6.14343e11, 5.34821e11, 4.63267e11, 3.99131e11, 3.41883e11, 2.91011e11, 2.46027e11, 2.06457e11, 1.71851e11,
      1.41776e11, 1.15820e11;
  p.EIz = p.EIy;
  // Thin steel tube: EA = E A, I = A r²/2 ⇒ A = m/ρ, GJ = G 2I, polar mass moment ρ 2I.
  const double E = 210e9, G = 80.8e9, rho = 8500;
  const VecX A = p.m / rho, I = p.EIy / E;
  p.EA = E * A;
  p.GJ = G * 2 * I;
  p.iy2 = p.iz2 = rho * I;
  BeamModel m = straightBeam(p, meshStations(0, L, elements, {}), false);
  clamp(m, 0);
  m.masses.push_back({elements, 350000.0, Vec3(2.5e7, 2.3e7, 3.9e7).asDiagonal()});
  const Assembly a = assemble(m, false);
  const DofMap d = freeDofs(m);
  return {restrictTo(a.K, d), restrictTo(a.M, d)};
}

}  // namespace whirl::fem
