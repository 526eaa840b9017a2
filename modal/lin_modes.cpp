#include "modal/lin_modes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <utility>

#include "src/base/error.hpp"
#include "src/io/lin/openfast_lin_names.hpp"

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
    const bool first_order = std::find(layout.velocity_of.begin(), layout.velocity_of.end(), i) ==
                             layout.velocity_of.end();
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

std::string linRootName(const std::string& path) {
  static const std::regex convention(R"(^(.*)\.\d+\.lin$)", std::regex::icase);
  std::smatch m;
  return std::regex_match(path, m, convention) ? m[1].str() : std::string();
}

namespace {

// Same operating point: rotor speeds within `tolerance` of the larger one (OpenFAST writes them with
// 4 decimals and a trimmed turbine's differ in the 4th between azimuths), wind speeds likewise.
bool samePoint(const OpenFastLin& a, const OpenFastLin& b, double tolerance) {
  auto close = [&](double x, double y, double floor) {
    return std::abs(x - y) <= tolerance * std::max({std::abs(x), std::abs(y), floor});
  };
  if (a.wind_speed.has_value() != b.wind_speed.has_value()) return false;
  return close(a.rotor_speed, b.rotor_speed, 1e-3) && (!a.wind_speed || close(*a.wind_speed, *b.wind_speed, 1e-2));
}

}  // namespace

std::vector<std::vector<OpenFastLin>> groupLinByOperatingPoint(std::vector<OpenFastLin> files, double tolerance) {
  struct Group {
    std::string root;
    std::vector<OpenFastLin> files;
  };
  std::vector<Group> groups;
  for (OpenFastLin& lin : files) {
    if (lin.A.size() == 0) throw InputError(lin.path + ": no A matrix (no continuous states)");
    const std::string root = linRootName(lin.path);
    Group* into = nullptr;
    for (Group& g : groups)
      if (g.root == root && samePoint(g.files.front(), lin, tolerance)) into = &g;
    if (!into) into = &groups.emplace_back(Group{root, {}});
    for (const OpenFastLin& other : into->files)
      if (std::abs(std::remainder(lin.azimuth - other.azimuth, 2 * M_PI)) < 1e-6)
        throw InputError(lin.path + ": same operating point and azimuth as " + other.path +
                         " (a repeated azimuth would bias the multiblade average; give each file once)");
    into->files.push_back(std::move(lin));
  }
  std::stable_sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
    const OpenFastLin &x = a.files.front(), &y = b.files.front();
    if (x.rotor_speed != y.rotor_speed) return x.rotor_speed < y.rotor_speed;
    return x.wind_speed.value_or(-1) < y.wind_speed.value_or(-1);
  });
  std::vector<std::vector<OpenFastLin>> out;
  for (Group& g : groups) out.push_back(std::move(g.files));
  return out;
}

std::string fewAzimuthsWarning(const std::vector<OpenFastLin>& group) {
  if (group.size() >= 3 || group.front().rotor_speed == 0.0) return "";
  char rpm[32];
  std::snprintf(rpm, sizeof rpm, "%.6g", group.front().rotor_speed * 30 / M_PI);
  return group.front().path + ": only " + std::to_string(group.size()) + " azimuth" + (group.size() == 1 ? "" : "s") +
         " at " + rpm +
         " rpm: the multiblade average of a turning rotor needs at least 3 (OpenFAST's NLinTimes >= 3), the modes of "
         "this point are approximate";
}

CampbellPoint linCampbellPoint(const std::vector<OpenFastLin>& group, std::vector<std::string>* notes) {
  std::vector<std::size_t> left_out;
  const MbcLayout layout = mbcLayoutFromLin(group.front(), 0, &left_out);
  if (!left_out.empty() && notes) {
    std::string list;
    for (std::size_t k = 0; k < left_out.size(); ++k) {
      const LinVariable& y = group.front().y[left_out[k]];
      list += (k ? ", " : "") + y.description.substr(0, y.description.find(',')) + " (line " + std::to_string(y.line) +
              ")";
    }
    notes->push_back(group.front().path + ": " + std::to_string(left_out.size()) +
                     " rotating outputs do not pair across blades and were left out of the multiblade transform "
                     "(the modes do not use outputs): " +
                     list);
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
