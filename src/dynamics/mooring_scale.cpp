#include "src/dynamics/mooring_scale.hpp"

#include <algorithm>

#include "src/dynamics/catenary.hpp"

namespace whirl {

double largestMooringTension(const Model& m, const Workspace<double>& ws) {
  double largest = 0;
  for (const MooringLine& ln : m.mooring) {
    const auto& f = ws.frames[ln.body];
    const Vec3 d = f.r + f.R * ln.fairlead - ln.anchor;  // anchor → fairlead, ground frame
    largest = std::max(largest, mooringFairleadForce<double>(ln, d).norm());
  }
  return largest;
}

}  // namespace whirl
