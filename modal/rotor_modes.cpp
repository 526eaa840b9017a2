#include "modal/rotor_modes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>

#include "modal/eigen.hpp"
#include "modal/floquet.hpp"
#include "linearize/mbc.hpp"

namespace whirl {
namespace {

// A mode this slow and carried by an azimuth is the rotor turning as a whole, not a vibration: the
// multiblade average leaves it a residual frequency of order 1e-4 Hz.
constexpr double kRigidAzimuthHz = 5e-3;
constexpr double kHeldAloneShare = 0.05;

// Names the mode from the coordinate group with the largest energy share. A vibration dominated
// by an azimuth (a free generator turning against the rotor) or by a held coordinate
// (OperatingPoint::held: a free yaw turning the nacelle against the whirling blades) is named after
// its next group, e.g. "drivetrain", "flap 2 FW". A mode carried by a held coordinate is a
// rigid-body mode when it is slow or does not oscillate: the yaw has no structural stiffness, and
// what the tilt of the deflected tower and the aerodynamics add (a yaw damping) split its zero pair
// into a near-zero root and a decay (ws03 at 3 m/s: 0.007 Hz "frequency", damping ratio 21).
}  // namespace

void nameRotorMode(Mode& mode, const std::vector<NamingCoordinate>& coords, const std::vector<bool>& azimuth,
                   const std::vector<bool>& held, double rotor_speed) {
  std::map<std::string, double> share, rigid_share;
  double az = 0, hd = 0;
  for (size_t i = 0; i < coords.size(); ++i) {
    const bool h = i < held.size() && held[i];
    (azimuth[i] || h ? rigid_share : share)[coords[i].group] += mode.participation(i);
    if (h) hd += mode.participation(i);
    if (azimuth[i]) az += mode.participation(i);
  }
  // A mode the held coordinates carry almost alone (every other group below kHeldAloneShare of them)
  // is their own zero pair, split by weak couplings however fast it turns out (SWRT at 188 rpm: free
  // yaw and free azimuth, 95 % yaw, 0.0086 Hz, damping −0.26, the same for 12, 36 and 72 azimuths):
  // naming it after a group with a share of 5e-6 would give a confident wrong name.
  double next = 0;
  for (const auto& [g, v] : share) next = std::max(next, v);
  if (share.empty() || (mode.freq_hz < kRigidAzimuthHz && az > 0.5) ||
      (hd > 0.5 && (mode.freq_hz < kRigidAzimuthHz || mode.damped_freq_hz == 0 || next < kHeldAloneShare * hd))) {
    mode.rigid_body = true;
    share = rigid_share;
  }
  const auto best = std::max_element(share.begin(), share.end(), [](auto& a, auto& b) { return a.second < b.second; });
  const std::string& group = best->first;
  int collective = -1, cosine = -1, sine = -1;
  double cyclic = 0, coll = 0;
  bool blade = false;
  for (size_t i = 0; i < coords.size(); ++i) {
    if (coords[i].group != group) continue;
    switch (coords[i].kind.kind) {
      case MbcKind::Fixed: break;
      case MbcKind::Collective: collective = static_cast<int>(i); coll += mode.participation(i); blade = true; break;
      case MbcKind::Cosine:
        if (coords[i].kind.harmonic == 1) cosine = static_cast<int>(i);
        cyclic += mode.participation(i);
        blade = true;
        break;
      case MbcKind::Sine:
        if (coords[i].kind.harmonic == 1) sine = static_cast<int>(i);
        cyclic += mode.participation(i);
        blade = true;
        break;
      case MbcKind::Differential: cyclic += mode.participation(i); blade = true; break;
    }
  }
  std::string name = group;
  if (blade) {
    if (coll >= cyclic || cosine < 0 || sine < 0) {
      name += collective >= 0 && coll >= cyclic ? " collective" : " cyclic";
    } else if (std::abs(rotor_speed) < 1e-9) {
      // Parked: forward and backward whirl coincide; say which cyclic pattern the mode took.
      name += std::abs(mode.shape(cosine)) >= std::abs(mode.shape(sine)) ? " cos" : " sin";
    } else {
      const std::complex<double> r = mode.shape(sine) / mode.shape(cosine);
      const bool forward = (r.imag() < 0) == (rotor_speed > 0);
      name += forward ? " FW" : " BW";
    }
  }
  if (mode.rigid_body) name += " (rigid body)";
  mode.name = name;
}

std::string bladeBaseName(const std::string& n) {
  std::string lower = n;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower.rfind("blade ", 0) == 0) {
    size_t k = 6;
    while (k < n.size() && std::isdigit(static_cast<unsigned char>(n[k]))) ++k;
    if (k > 6 && k < n.size() && n[k] == ' ') return n.substr(k + 1);
  }
  return n;
}

RotorModes rotorModes(const Model& m, const PeriodicLinearization& p) {
  const LinearModel& first = p.models.front();
  const int n = static_cast<int>(first.dofs.size());
  RotorCoordinates c;
  c.names = first.dof_names;
  int nb = 0;
  for (int i = 0; i < n; ++i) {
    c.blade.push_back(m.dofs[first.dofs[i]].blade);
    c.azimuth.push_back(m.dofs[first.dofs[i]].rotating);
    const std::vector<int>& held = p.points.front().held;
    c.held.push_back(std::find(held.begin(), held.end(), first.dofs[i]) != held.end());
    nb = std::max(nb, c.blade.back() + 1);
  }
  // Shapes are in multiblade coordinates: weigh them by the diagonal of M (blade entries alike).
  c.weights = first.M.diagonal().asDiagonal();
  std::vector<MbcSample> samples;
  for (size_t k = 0; k < p.models.size(); ++k) {
    MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    samples.push_back(std::move(s));
  }
  return multibladeModes(c, secondOrderLayout(std::max(nb, 3), c.blade), samples);
}

RotorModes multibladeModes(const RotorCoordinates& c, const MbcLayout& layout, const std::vector<MbcSample>& samples) {
  RotorModes out;
  const int n = static_cast<int>(c.names.size());
  int nb = 0;
  for (int b : c.blade) nb = std::max(nb, b + 1);
  const double rotor_speed = samples.front().rotor_speed;
  std::vector<NamingCoordinate> coords(n);
  MbcResult mbc;
  if (nb > 0 && nb < 3 && std::abs(rotor_speed) > 0 && samples.size() >= 2) {
    // With fewer than 3 blades the transformed system stays periodic: Floquet analysis, when the
    // azimuths cover the revolution evenly (else the first sample, as below).
    bool even = true;
    for (std::size_t k = 1; k < samples.size(); ++k)
      even = even && std::abs(samples[k].azimuth - samples[0].azimuth - 2 * std::numbers::pi * double(k) / double(samples.size())) < 1e-6;
    if (even) return floquetModes(c, samples);
  }
  if (nb < 3) {
    // No transform: with fewer than 3 blades the transformed system stays periodic.
    out.A = samples.front().A;
    for (int i = 0; i < n; ++i) coords[i].group = c.names[i];
    out.coordinates = c.names;
  } else {
    out.num_blades = nb;
    mbc = mbcAverage(layout, samples);
    out.A = mbc.A;
    // Coordinate groups: the j-th coordinate of every blade forms one set named after blade 1's.
    std::vector<std::vector<int>> per_blade(nb);
    for (int i = 0; i < n; ++i)
      if (c.blade[i] >= 0) per_blade[c.blade[i]].push_back(i);
    for (int i = 0; i < n; ++i) {
      coords[i].kind = mbc.states[i];
      if (c.blade[i] < 0) {
        coords[i].group = c.names[i];
        continue;
      }
      const auto& list = per_blade[c.blade[i]];
      const size_t j = std::find(list.begin(), list.end(), i) - list.begin();
      coords[i].group = bladeBaseName(c.names[per_blade[0].at(j)]);
    }
    out.coordinates.resize(n);
    for (int i = 0; i < n; ++i)
      out.coordinates[i] = c.blade[i] < 0 ? coords[i].group : coords[i].group + " " + toString(coords[i].kind);
  }
  out.modes = modesFromEigen(eigenStandard(out.A), n, c.weights, out.coordinates);
  for (auto& mode : out.modes) nameRotorMode(mode, coords, c.azimuth, c.held, rotor_speed);
  return out;
}

}  // namespace whirl
