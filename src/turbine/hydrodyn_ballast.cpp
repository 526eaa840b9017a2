#include "src/turbine/hydrodyn_ballast.hpp"

#include <algorithm>
#include <cmath>

#include "src/base/skew.hpp"

namespace whirl::elastodyn {
namespace {

// Adds the line mass μ(s) = ρ π r(s)² ds L, s ∈ [s0, s1] of the member from a to b (r linear from ra to rb),
// to the mass matrix: three Gauss points integrate μ x xᵀ (degree 4 in s) exactly.
void addLine(Ballast& out, const Vec3& a, const Vec3& b, const Vec3& origin, double ra, double rb, double rho,
             double s0, double s1) {
  static const double kX[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double kW[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double L = (b - a).norm(), half = 0.5 * (s1 - s0);
  for (int k = 0; k < 3; ++k) {
    const double s = s0 + half * (1.0 + kX[k]);
    const double r = ra + (rb - ra) * s;
    const double dm = kW[k] * half * L * rho * M_PI * r * r;
    const Vec3 x = a + (b - a) * s;
    const Mat3 S = skew(Vec3(x - origin));
    out.mass += dm;
    out.centre += dm * x;
    out.M.block<3, 3>(0, 0) += dm * Mat3::Identity();
    out.M.block<3, 3>(0, 3) -= dm * S;
    out.M.block<3, 3>(3, 0) += dm * S;
    out.M.block<3, 3>(3, 3) -= dm * S * S;
  }
}

}  // namespace

Ballast ballastOf(const io::HydroDynMembers& m, double water_density, double g, const Vec3& origin) {
  Ballast out;
  for (const io::HydroDynFillGroup& fg : m.fills) {
    const double rho = fg.FillDens.value_or(water_density);
    for (int id : fg.members) {
      const io::HydroDynMember& mb = *m.member(id);
      const Vec3 a = m.joint(mb.joint1)->position, b = m.joint(mb.joint2)->position;
      const io::HydroDynPropSet &pa = *m.prop(mb.prop1), &pb = *m.prop(mb.prop2);
      const double ra = 0.5 * pa.D - pa.thickness, rb = 0.5 * pb.D - pb.thickness;
      // The part of the member below the free surface: z(s) = za + (zb − za) s ≤ FillFSLoc.
      double s0 = 0.0, s1 = 1.0;
      const double dz = b(2) - a(2);
      if (dz == 0.0) {
        if (a(2) > fg.FillFSLoc) continue;
      } else {
        const double sf = (fg.FillFSLoc - a(2)) / dz;
        if (dz > 0) s1 = std::min(1.0, sf);
        else s0 = std::max(0.0, sf);
      }
      if (s1 > s0) addLine(out, a, b, origin, ra, rb, rho, s0, s1);
    }
  }
  if (out.mass > 0) out.centre /= out.mass;
  const double W = out.mass * g;
  const Vec3 c = out.centre - origin;
  out.weight << 0, 0, -W, -W * c(1), W * c(0), 0;
  return out;
}

}  // namespace whirl::elastodyn
