#include "src/dynamics/mooring_scale.hpp"

#include <algorithm>
#include <cmath>

#include "src/dynamics/catenary.hpp"

namespace whirl {

double largestMooringTension(const Model& m, const Workspace<double>& ws) {
  double largest = 0;
  for (const MooringLine& ln : m.mooring) {
    const auto& f = ws.frames[ln.body];
    const Vec3 d = f.r + f.R * ln.fairlead - ln.anchor;  // anchor → fairlead, ground frame
    const CatenaryTension<double> t = catenaryTension<double>(ln, std::hypot(d(0), d(1)), d(2));
    largest = std::max(largest, std::hypot(t.H, t.V));
  }
  return largest;
}

}  // namespace whirl
