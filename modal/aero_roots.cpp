#include "modal/aero_roots.hpp"

#include <algorithm>
#include <string>

namespace whirl {
namespace {
const std::string kPrefix = "aero ";
}  // namespace

double aeroShare(const Mode& mode, const std::vector<bool>& aero) {
  double share = 0;
  for (Eigen::Index i = 0; i < mode.participation.size() && i < static_cast<Eigen::Index>(aero.size()); ++i)
    if (aero[static_cast<std::size_t>(i)]) share += mode.participation(i);
  return share;
}

bool isAeroRoot(const Mode& mode) { return mode.first_order && mode.name.rfind(kPrefix, 0) == 0; }

int nameAeroRoots(std::vector<Mode>& modes, const std::vector<bool>& aero) {
  int left = static_cast<int>(std::count(aero.begin(), aero.end(), true));
  std::vector<double> share(modes.size());
  std::vector<std::size_t> order(modes.size());
  for (std::size_t k = 0; k < modes.size(); ++k) share[k] = aeroShare(modes[k], aero), order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return share[a] > share[b]; });
  std::vector<bool> is_aero(modes.size(), false);
  for (std::size_t k : order) {
    const int roots = modes[k].damped_freq_hz > 0 ? 2 : 1;
    if (left <= 0) break;
    if (roots > left || modes[k].rigid_body) continue;
    is_aero[k] = true;
    left -= roots;
  }
  int count = 0;
  for (std::size_t k = 0; k < modes.size(); ++k) {
    if (!is_aero[k]) continue;
    Mode& mode = modes[k];
    mode.first_order = true;
    mode.name = kPrefix + std::to_string(++count);
    setNameEvidence(mode, {{"aerodynamic states", share[k]}, {"structure", 1 - share[k]}});
  }
  return count;
}

}  // namespace whirl
