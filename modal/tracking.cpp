#include "modal/tracking.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "modal/aero_roots.hpp"
#include "modal/hungarian.hpp"
#include "modal/tracking_overrides.hpp"
#include "src/base/error.hpp"

namespace whirl {

namespace {

// Aerodynamic roots (modal/aero_roots.hpp) are never tracked: listed apart, they take no structural line.
std::vector<int> trackedModes(const CampbellPoint& p, const TrackingOptions& opt) {
  std::vector<int> idx;
  for (int k = 0; k < static_cast<int>(p.modes.size()); ++k)
    if ((opt.include_rigid_body || !p.modes[k].rigid_body) && !isAeroRoot(p.modes[k])) idx.push_back(k);
  return idx;
}

void checkShapes(const std::vector<CampbellPoint>& points, std::size_t p) {
  const auto& a = points[p - 1];
  const auto& b = points[p];
  if (a.modes.empty() || b.modes.empty()) return;
  for (const auto& m : b.modes)
    if (m.shape.size() != a.modes.front().shape.size())
      throw InputError(where("", 0, "Campbell point " + std::to_string(p),
                             "mode shapes have " + std::to_string(m.shape.size()) + " coordinates, point " +
                                 std::to_string(p - 1) + " has " + std::to_string(a.modes.front().shape.size())));
}

// The modes of a point as the tracking compares them: with the blade elements' aerodynamic states
// (modal/aero_roots.hpp) left out of the shapes, as the structural modes' names leave them out. Their
// entries are in other units (an unsteady-airfoil state's separation point, a DBEMT induced velocity) and,
// where a polar kinks, larger than the structure's: on the NREL 5MW with UA above rated the tip element's
// x4 became the largest entry of the first flap modes, and the MAC of the same flap mode at 12 and 13 m/s
// fell to 0.02, so the line kept its mode only by frequency, at a cost just under the limit.
std::vector<Mode> structuralShapes(const CampbellPoint& p) {
  std::vector<Eigen::Index> aero;
  for (std::size_t i = 0; i < p.coordinates.size(); ++i)
    if (isAeroStateName(p.coordinates[i])) aero.push_back(static_cast<Eigen::Index>(i));
  std::vector<Mode> modes = p.modes;
  if (aero.empty()) return modes;
  for (Mode& m : modes)
    for (Eigen::Index i : aero)
      if (i < m.shape.size()) m.shape(i) = 0.0;
  return modes;
}

double meanFrequency(const std::vector<CampbellPoint>& points, const CampbellLine& line) {
  double sum = 0;
  int n = 0;
  for (std::size_t p = 0; p < line.mode.size(); ++p)
    if (line.mode[p] >= 0) {
      sum += points[p].modes[line.mode[p]].freq_hz;
      ++n;
    }
  return n ? sum / n : 0.0;
}

}  // namespace

double modalAssurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  const double na = a.squaredNorm(), nb = b.squaredNorm();
  if (na <= 0 || nb <= 0) return 0.0;
  return std::norm(a.dot(b)) / (na * nb);  // dot() conjugates its first argument: aᴴb
}

double trackingCost(const Mode& a, const Mode& b, const TrackingOptions& opt) {
  const double scale = std::max({a.freq_hz, b.freq_hz, opt.fmin_hz});
  const double c = 1.0 - modalAssurance(a.shape, b.shape) +
                   opt.frequency_weight * std::abs(a.freq_hz - b.freq_hz) / scale;
  return std::isfinite(c) ? c : 1e3 + std::abs(opt.max_cost);  // a NaN frequency or shape never links
}

std::vector<CampbellLine> trackModes(const std::vector<CampbellPoint>& points, const TrackingOptions& opt) {
  const std::size_t P = points.size();
  std::vector<CampbellLine> lines;
  std::vector<int> prev_line;  // per mode of the previous point: its line, −1 when untracked
  for (std::size_t p = 0; p < P; ++p) {
    const auto cur = trackedModes(points[p], opt);
    std::vector<int> cur_line(points[p].modes.size(), -1);
    if (p > 0) {
      checkShapes(points, p);
      const auto prev = trackedModes(points[p - 1], opt);
      const std::vector<Mode> before = structuralShapes(points[p - 1]), now = structuralShapes(points[p]);
      const int na = static_cast<int>(prev.size()), nb = static_cast<int>(cur.size());
      // Square problem with "unmatched" dummies: leaving a and b both unlinked costs max_cost, so a
      // pair is linked exactly when linking it is cheaper than that.
      MatX c = MatX::Zero(na + nb, na + nb);
      for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) c(i, j) = trackingCost(before[prev[i]], now[cur[j]], opt);
      c.block(0, nb, na, na).setConstant(opt.max_cost / 2);
      c.block(na, 0, nb, nb).setConstant(opt.max_cost / 2);
      const auto col = solveAssignment(c);
      for (int i = 0; i < na; ++i) {
        const int j = col[i];
        if (j >= nb || !(c(i, j) < opt.max_cost)) continue;
        const int l = prev_line[prev[i]];
        cur_line[cur[j]] = l;
        lines[l].mode[p] = cur[j];
      }
    }
    for (int k : cur)
      if (cur_line[k] < 0) {
        CampbellLine line;
        line.mode.assign(P, -1);
        line.mode[p] = k;
        cur_line[k] = static_cast<int>(lines.size());
        lines.push_back(std::move(line));
      }
    prev_line = std::move(cur_line);
  }
  std::vector<double> mean(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l) mean[l] = meanFrequency(points, lines[l]);
  std::vector<std::size_t> order(lines.size());
  for (std::size_t l = 0; l < order.size(); ++l) order[l] = l;
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return mean[a] < mean[b]; });
  std::vector<CampbellLine> sorted;
  for (auto l : order) sorted.push_back(std::move(lines[l]));
  nameLines(points, sorted);
  if (!opt.overrides_file.empty()) applyTrackingOverrides(opt.overrides_file, points, sorted);
  return sorted;
}

void nameLines(const std::vector<CampbellPoint>& points, std::vector<CampbellLine>& lines) {
  std::set<std::string> used;
  for (auto& line : lines) {
    // name → (count, highest rpm, last point): the greatest key wins
    std::map<std::string, std::tuple<int, double, int>> seen;
    for (std::size_t p = 0; p < line.mode.size(); ++p) {
      if (line.mode[p] < 0) continue;
      const std::string& n = points[p].modes[line.mode[p]].name;
      auto& [count, rpm, last] = seen.try_emplace(n.empty() ? std::string("mode") : n, 0, -INFINITY, -1).first->second;
      count += 1;
      rpm = std::max(rpm, points[p].rpm);
      last = static_cast<int>(p);
    }
    std::string best = "line";
    std::tuple<int, double, int> best_key{0, -INFINITY, -1};
    for (const auto& [n, key] : seen)
      if (key > best_key) {
        best = n;
        best_key = key;
      }
    std::string name = best;
    for (int k = 2; used.count(name); ++k) name = best + " (" + std::to_string(k) + ")";
    used.insert(name);
    line.name = name;
  }
}

}  // namespace whirl
