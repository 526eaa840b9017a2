// The buffers of one evaluation (workspace.hpp), sized once from the model, for double and the AD
// chunk type.
#include <algorithm>
#include <type_traits>

#include "src/base/scalar.hpp"
#include "src/dynamics/kinematics.hxx"
#include "src/dynamics/workspace.hpp"

namespace whirl {

namespace {
int maxBasisSize(const Model& m) {
  int ncmax = 1;
  for (const Body& b : m.bodies) ncmax = std::max(ncmax, b.inertia.nc());
  return ncmax;
}
}  // namespace

template <class T>
Workspace<T>::Workspace(const Model& m)
    : bem(static_cast<std::size_t>(m.aero.nstations())),
      jets{std::vector<SectionJet>(static_cast<std::size_t>(m.aero.nstations())),
           std::vector<BladeJet>(m.aero.blades.size()),
           std::vector<UnsteadySectionJet>(static_cast<std::size_t>(m.aero.nstations()))},
      prod(maxBasisSize(m)),
      prod_dt(maxBasisSize(m)) {
  const int n = m.ndof();
  scratch = VecXT<T>::Zero(n);
  int ncmax = 1, nemax = 1;
  frames.resize(m.bodies.size());
  basis.resize(m.bodies.size());
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyInertia& in = m.bodies[i].inertia;
    frames[i].Jv = Mat3XT<T>::Zero(3, n);
    frames[i].Jw = Mat3XT<T>::Zero(3, n);
    basis[i].c = VecXT<T>::Zero(in.nc());
    basis[i].cd = VecXT<T>::Zero(in.nc());
    basis[i].cdd = VecXT<T>::Zero(in.nc());
    basis[i].D = MatXT<T>::Zero(in.nc(), in.ne);
    detail::initBasisD(in, basis[i]);  // its constant part; forwardKinematics writes the rest
    ncmax = std::max(ncmax, in.nc());
    nemax = std::max(nemax, in.ne);
  }
  g = VecXT<T>::Zero(ncmax);
  size_t supmax = 0;
  for (const auto& sup : m.support) supmax = std::max(supmax, sup.size());
  const int nsup = static_cast<int>(supmax);
  for (VecX& y : mass.y) y = VecX::Zero(ncmax);
  mass.Mb = MatX::Zero(6 + nemax, 6 + nemax);
  mass.Jb = MatX::Zero(6, nsup);
  mass.MJ = MatX::Zero(6, nsup);
  mass.zero = VecX::Zero(n);
  if constexpr (!std::is_same_v<T, double>)
    for (const Body& b : m.bodies) constant_basis.emplace_back(b.inertia.nc(), b.inertia.ne);
  else
    for (const Body& b : m.bodies) body_products.emplace_back(b.inertia.nc());
  h = VecXT<T>::Zero(nemax);
}

template struct Workspace<double>;
template struct Workspace<ADChunk>;

}  // namespace whirl
