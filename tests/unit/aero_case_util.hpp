#pragma once
// The rotor of tests/support/aero_rotor_model.hpp written as a YAML case (`wind:`, `aero:` and the
// blades' `aero:` blocks), with its thin-airfoil polar as an AeroDyn airfoil file: the same model
// through the case reader instead of the C++ API. Rotations and offsets are written as matrices and
// vectors to 17 digits, so the two models agree to round-off.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tests/support/aero_rotor_model.hpp"

namespace whirl::test {

/// The thin-airfoil polar of aeroRotorModel (Cl = 2π α, constant Cd, no Cm) as an AeroDyn airfoil file.
inline std::string thinAirfoilFile(double cd) {
  const double cl = 2 * std::numbers::pi * std::numbers::pi;
  return fmt::format(R"(! ------------ AirfoilInfo v1.01.x Input File -------------
! Thin airfoil: Cl = 2 pi alpha, constant Cd (tests/support/aero_rotor_model.hpp)
          1   InterpOrd
          1   NonDimArea
          0   NumCoords
          1   NumTabs
       0.75   Re
          0   UserProp
False         InclUAdata
          3   NumAlf
!    Alpha      Cl      Cd        Cm
   -180.0  {:.17g}  {:.17g}  0
      0.0  0  {:.17g}  0
    180.0  {:.17g}  {:.17g}  0
)",
                     -cl, cd, cd, cl, cd);
}

inline std::string vec(const Vec3& v) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v(0), v(1), v(2)); }

/// aeroRotorModel(o) as a case file naming the airfoil file `airfoil`.
inline std::string aeroRotorCase(const AeroRotorOptions& o, const std::string& airfoil = "thin.dat") {
  using std::numbers::pi;
  const double hub_radius = 1.5, length = 40;
  std::string s = fmt::format(R"(name: aero rotor
gravity: 0
inputs:
  - {{name: collective pitch, value: {:.17g}, dofs: [blade 1 pitch, blade 2 pitch, blade 3 pitch]}}
bodies:
  - name: hub
    type: rigid
    offset: [0, 0, {:.17g}]
    joint: {{type: revolute, axis: [1, 0, 0], dof: azimuth}}
    mass: 1.0e4
    inertia: [1.0e6, 5.0e3, 5.0e3]
)",
                              o.pitch_deg * pi / 180, o.hub_height);
  Mat3 span_first;
  span_first.col(0) = Vec3::UnitZ();
  span_first.col(1) = Vec3::UnitX();
  span_first.col(2) = Vec3::UnitY();
  std::string x, chord, twist, airfoil_ids;
  for (int s_ = 0; s_ < o.elements; ++s_) {
    const double xs = length * s_ / (o.elements - 1);
    const char* sep = s_ ? ", " : "";
    x += fmt::format("{}{:.17g}", sep, xs);
    chord += fmt::format("{}{:.17g}", sep, 3.5 - 2.0 * xs / length);
    twist += fmt::format("{}{:.17g}", sep, (10.0 - 10.0 * xs / length) * pi / 180);
    airfoil_ids += fmt::format("{}1", sep);
  }
  for (int k = 0; k < 3; ++k) {
    const Mat3 coned = Eigen::AngleAxisd(2 * pi * k / 3, Vec3::UnitX()).toRotationMatrix() *
                       Eigen::AngleAxisd(o.precone_deg * pi / 180, Vec3::UnitY()).toRotationMatrix();
    const Mat3 R = coned * span_first;
    const std::string name = "blade " + std::to_string(k + 1);
    s += fmt::format(R"(  - name: {0}
    type: beam
    parent: hub
    offset: {1}
    rotation: [{2}, {3}, {4}]
    joint: {{type: revolute, axis: [-1, 0, 0], dof: {0} pitch}}
    length: {5}
    uniform: {{m: 300, EIy: 4.0e9, EIz: 1.0e10}}
    integration: {{method: gauss, n: 40}}
    shapes:
      - {{name: {0} flap 1, type: clamped_topmass, direction: y, mode: 1, tip_mass_ratio: 0}}
      - {{name: {0} edge 1, type: clamped_topmass, direction: z, mode: 1, tip_mass_ratio: 0}}
    aero:
      pitch: {0} pitch
      stations:
        x: [{6}]
        chord: [{7}]
        twist: [{8}]
        airfoil: [{9}]
)",
                     name, vec(hub_radius * coned.col(2)), vec(R.row(0).transpose()), vec(R.row(1).transpose()),
                     vec(R.row(2).transpose()), length, x, chord, twist, airfoil_ids);
  }
  s += fmt::format(R"(dofs:
  azimuth: {{frozen: true, rotating: true, rate: {:.17g}}}
  blade 1 pitch: {{frozen: true}}
  blade 2 pitch: {{frozen: true}}
  blade 3 pitch: {{frozen: true}}
wind:
  speed: {:.17g}
  reference_height: {:.17g}
aero:
  hub: hub
  induction: {}
  AIDrag: false
  TIDrag: false
  airfoils: [{}]
)",
                   o.rpm * 2 * pi / 60, o.wind, o.hub_height, o.induction ? "true" : "false", airfoil);
  return s;
}

}  // namespace whirl::test
