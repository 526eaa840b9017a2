#include "src/aero/unsteady_airfoil_linear.hpp"

#include <Eigen/LU>

#include "src/base/scalar.hpp"

namespace whirl::aero {

Eigen::Matrix<double, 3, 3> UaElementLinear::staticGain() const { return D - C * A.partialPivLu().solve(B); }

UaElementLinear uaElementLinear(const UaSection& s, const HgmState<double>& x, const UaInput<double>& in) {
  static_assert(kChunk >= 7, "one pass over 4 states and 3 inputs");
  auto seeded = [](double v, int k) {
    ADChunk a(v, ADChunk::DerType::Zero());
    a.derivatives()(k) = 1.0;
    return a;
  };
  const HgmState<ADChunk> xa{seeded(x.x1, 0), seeded(x.x2, 1), seeded(x.x3, 2), seeded(x.x4, 3)};
  const UaInput<ADChunk> ia{seeded(in.alpha_34, 4), ADChunk(in.alpha_ac), seeded(in.u, 5), seeded(in.omega, 6)};
  const HgmState<ADChunk> d = hgmDerivative(s, xa, ia);
  const Coefficients<ADChunk> l = hgmLoads(s, xa, ia);
  const ADChunk* rows[4] = {&d.x1, &d.x2, &d.x3, &d.x4};
  const ADChunk* loads[3] = {&l.cl, &l.cd, &l.cm};
  UaElementLinear lin;
  for (int r = 0; r < 4; ++r) {
    lin.A.row(r) = rows[r]->derivatives().head<4>().transpose();
    lin.B.row(r) = rows[r]->derivatives().segment<3>(4).transpose();
  }
  for (int r = 0; r < 3; ++r) {
    lin.C.row(r) = loads[r]->derivatives().head<4>().transpose();
    lin.D.row(r) = loads[r]->derivatives().segment<3>(4).transpose();
  }
  return lin;
}

}  // namespace whirl::aero
