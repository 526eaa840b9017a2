#include "src/model/body.hpp"

#include <stdexcept>

namespace whirl {

BodyInertia rigidBodyInertia(double mass, const Vec3& rho, const Mat3& inertia_cog) {
  BodyInertia b;
  b.ne = 0;
  b.quadratic = false;
  b.mass = mass;
  b.m1 = mass * rho;
  // ∫ r rᵀ dm about the COG follows from the inertia tensor: I = tr(Θ) 1 − Θ  ⇒  Θ = ½ tr(I) 1 − I.
  const Mat3 theta = 0.5 * inertia_cog.trace() * Mat3::Identity() - inertia_cog;
  for (int j = 0; j < 3; ++j)
    for (int l = 0; l < 3; ++l) {
      b.S[3 * j + l] = MatX::Constant(1, 1, mass * rho(j) * rho(l) + theta(j, l));
    }
  return b;
}

void addInertia(BodyInertia& into, const BodyInertia& other) {
  if (into.nc() != other.nc()) throw std::logic_error("addInertia: bases differ");
  into.mass += other.mass;
  into.m1 += other.m1;
  for (int k = 0; k < 9; ++k) into.S[k] += other.S[k];
}

}  // namespace whirl
