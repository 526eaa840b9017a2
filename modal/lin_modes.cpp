#include "modal/lin_modes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "src/io/openfast_lin_names.hpp"
#include "src/model/error.hpp"

namespace whirl {

RotorCoordinates linRotorCoordinates(const OpenFastLin& lin, const MbcLayout& layout) {
  const int N = static_cast<int>(lin.x.size());
  RotorCoordinates c;
  std::vector<int> coordinate(static_cast<size_t>(N), -1);
  // Displacements and first-order states in state order; a rate takes its displacement's coordinate,
  // wherever it sits (ElastoDyn q, q̇ then BeamDyn q, q̇: pairs by derivative order and description).
  for (int i = 0; i < N; ++i) {
    if (layout.velocity_of[i] >= 0) continue;
    coordinate[i] = static_cast<int>(c.names.size());
    const std::string& d = lin.x[i].description;
    const bool first_order = std::find(layout.velocity_of.begin(), layout.velocity_of.end(), i) == layout.velocity_of.end();
    c.names.push_back(dofNameFromLinDescription(d));
    c.groups.push_back(first_order ? firstOrderGroupFromLinDescription(d) : c.names.back());
    c.blade.push_back(layout.state_blade[i]);
    c.azimuth.push_back(!first_order && isAzimuthLinDescription(d));
  }
  for (int i = 0; i < N; ++i)
    if (layout.velocity_of[i] >= 0) coordinate[i] = coordinate[layout.velocity_of[i]];
  c.coordinate_of_state = coordinate;
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

CampbellPoint linCampbellPoint(const std::vector<OpenFastLin>& group, std::vector<std::string>* notes) {
  std::vector<std::size_t> left_out;
  const MbcLayout layout = mbcLayoutFromLin(group.front(), 0, &left_out);
  if (!left_out.empty() && notes) {
    std::string list;
    for (std::size_t k = 0; k < left_out.size(); ++k) {
      const LinVariable& y = group.front().y[left_out[k]];
      list += (k ? ", " : "") + y.description.substr(0, y.description.find(',')) + " (line " + std::to_string(y.line) + ")";
    }
    notes->push_back(group.front().path + ": " + std::to_string(left_out.size()) +
                     " rotating outputs do not pair across blades and were left out of the multiblade transform "
                     "(the modes do not use outputs): " + list);
  }
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
