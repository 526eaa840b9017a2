#include "modal/lin_modes.hpp"

#include <cmath>
#include <map>
#include <utility>

#include "src/io/openfast_lin_names.hpp"
#include "src/model/error.hpp"

namespace whirl {

RotorCoordinates linRotorCoordinates(const OpenFastLin& lin, const MbcLayout& layout) {
  std::vector<bool> displacement(lin.x.size(), false);
  for (int v : layout.velocity_of)
    if (v >= 0) displacement[v] = true;
  int n = 0;
  while (n < static_cast<int>(displacement.size()) && displacement[n]) ++n;
  for (size_t i = n; i < displacement.size(); ++i)
    if (displacement[i])
      throw InputError(where(lin.path, lin.x[i].line, "", "displacement states must come first in the state vector"));
  if (n == 0) throw InputError(where(lin.path, 0, "", "no second-order (displacement, rate) states to analyse"));
  RotorCoordinates c;
  for (int i = 0; i < n; ++i) {
    c.names.push_back(dofNameFromLinDescription(lin.x[i].description));
    c.blade.push_back(layout.state_blade[i]);
    c.azimuth.push_back(isAzimuthLinDescription(lin.x[i].description));
  }
  c.weights = MatX::Identity(n, n);
  return c;
}

std::vector<std::vector<OpenFastLin>> groupLinByOperatingPoint(std::vector<OpenFastLin> files) {
  std::map<std::pair<long long, long long>, std::vector<OpenFastLin>> groups;
  for (OpenFastLin& lin : files) {
    if (lin.A.size() == 0) throw InputError(lin.path + ": no A matrix (no continuous states)");
    const long long w = std::llround(1e6 * lin.rotor_speed), v = std::llround(1e4 * lin.wind_speed.value_or(-1));
    for (const OpenFastLin& other : groups[{w, v}])
      if (std::abs(std::remainder(lin.azimuth - other.azimuth, 2 * M_PI)) < 1e-6)
        throw InputError(lin.path + ": same operating point and azimuth as " + other.path +
                         " (a repeated azimuth would bias the multiblade average; give each file once)");
    groups[{w, v}].push_back(std::move(lin));
  }
  std::vector<std::vector<OpenFastLin>> out;
  for (auto& [key, group] : groups) out.push_back(std::move(group));
  return out;
}

CampbellPoint linCampbellPoint(const std::vector<OpenFastLin>& group) {
  const MbcLayout layout = mbcLayoutFromLin(group.front());
  std::vector<MbcSample> samples;
  for (const auto& lin : group) {
    if (lin.A.rows() != group.front().A.rows())
      throw InputError(lin.path + ": its states differ from " + group.front().path + " (same operating point)");
    samples.push_back(mbcSampleFromLin(lin));
  }
  const RotorModes r = multibladeModes(linRotorCoordinates(group.front(), layout), layout, samples);
  CampbellPoint p;
  p.rpm = group.front().rotor_speed * 30 / M_PI;
  p.wind_speed = group.front().wind_speed;
  p.coordinates = r.coordinates;
  p.modes = r.modes;
  return p;
}

}  // namespace whirl
