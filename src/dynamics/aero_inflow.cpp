#include "src/dynamics/aero_inflow.hpp"

namespace whirl {

AeroInflow AeroRecord::inflow() const {
  AeroInflow f;
  const Eigen::Index n = static_cast<Eigen::Index>(elements.size());
  f.axial.resize(n);
  f.tangential.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const AeroElementState& e = elements[static_cast<std::size_t>(k)];
    f.axial(k) = -e.vx * e.a;
    f.tangential(k) = e.vy * e.ap;
  }
  return f;
}

}  // namespace whirl
