#include "modal/rotor_modes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "linearize/mbc.hpp"
#include "modal/aero_roots.hpp"
#include "modal/eigen.hpp"
#include "modal/floquet.hpp"
#include "modal/participation.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

// A mode this slow and carried by an azimuth is the rotor turning as a whole, not a vibration: the
// multiblade average leaves it a residual frequency of order 1e-4 Hz.
constexpr double kRigidAzimuthHz = 5e-3;
constexpr double kHeldAloneShare = 0.05;

// Slower than this (0.1 rpm) the rotor is named as parked: forward and backward whirl would differ
// by 2Ω < 0.003 Hz, less than what separates a parked rotor's cosine and sine patterns (the
// toolbox's standstill .lin files are linearized at Ω = 2e-4 rad/s).
constexpr double kParkedRadPerS = 1e-2;

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
  // A real root carried by an azimuth (the free rotor's decay) is no vibration either.
  // A mode the held coordinates carry almost alone (every other group below kHeldAloneShare of them)
  // is their own zero pair, split by weak couplings however fast it turns out (SWRT at 188 rpm: free
  // yaw and free azimuth, 95 % yaw, 0.0086 Hz, damping −0.26, the same for 12, 36 and 72 azimuths):
  // naming it after a group with a share of 5e-6 would give a confident wrong name.
  // Likewise a mode an azimuth carries almost alone: the parked, unbraked rotor turning as a whole
  // (AWT-27 Test02 in 12 m/s: 100 % generator azimuth at 0.083 Hz, held by the weight of its teetered
  // rotor and the aerodynamics), not a vibration of the group with a share of 1e-6.
  double next = 0;
  for (const auto& [g, v] : share) next = std::max(next, v);
  if (share.empty() || ((mode.freq_hz < kRigidAzimuthHz || mode.damped_freq_hz == 0) && az > 0.5) ||
      (az > 0.5 && next < kHeldAloneShare * az) ||
      (hd > 0.5 && (mode.freq_hz < kRigidAzimuthHz || mode.damped_freq_hz == 0 || next < kHeldAloneShare * hd))) {
    mode.rigid_body = true;
    share = rigid_share;
  }
  setNameEvidence(mode, {share.begin(), share.end()});
  const auto best = std::max_element(share.begin(), share.end(), [](auto& a, auto& b) { return a.second < b.second; });
  const std::string& group = best->first;
  int collective = -1, cosine = -1, sine = -1;
  double cyclic = 0, coll = 0;
  bool blade = false;
  for (size_t i = 0; i < coords.size(); ++i) {
    if (coords[i].group != group) continue;
    switch (coords[i].kind.kind) {
      case MbcKind::Fixed: break;
      case MbcKind::Collective:
        collective = static_cast<int>(i);
        coll += mode.participation(i);
        blade = true;
        break;
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
      case MbcKind::Differential:
        cyclic += mode.participation(i);
        blade = true;
        break;
    }
  }
  std::string name = group;
  if (blade) {
    if (coll >= cyclic || cosine < 0 || sine < 0) {
      name += collective >= 0 && coll >= cyclic ? " collective" : " cyclic";
    } else if (std::abs(rotor_speed) < kParkedRadPerS) {
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

namespace {

// Share of a mode in the coordinates of `group` that a name suffix stands for.
double labelShare(const Mode& mode, const std::vector<NamingCoordinate>& coords, const std::string& group,
                  const std::string& label) {
  double share = 0;
  for (size_t i = 0; i < coords.size(); ++i) {
    if (coords[i].group != group) continue;
    const MbcCoordinate k = coords[i].kind;
    const bool take = label == "collective" ? k.kind == MbcKind::Collective
                      : label == "cos"      ? k.kind == MbcKind::Cosine && k.harmonic == 1
                      : label == "sin"      ? k.kind == MbcKind::Sine && k.harmonic == 1
                                            : k.kind == MbcKind::Cosine || k.kind == MbcKind::Sine;  // BW, FW, cyclic
    if (take) share += mode.participation(static_cast<Eigen::Index>(i));
  }
  return share;
}

// One name per mode pattern: where two modes of one point got the same blade name ("flap 2 cos"
// twice on a parked WindPACT rotor, whose collective and cosine flap patterns both couple with the
// tower fore-aft and mix), the names of that group that no mode took (rotating: collective only) are
// handed out again, each mode of the clash taking the name whose coordinates carry most of it
// (largest total share over the permutations; a clash of more modes than names stays).
void distinctBladeNames(std::vector<Mode>& modes, const std::vector<NamingCoordinate>& coords, double rotor_speed) {
  std::set<std::string> blade_groups;
  for (const auto& c : coords)
    if (c.kind.kind != MbcKind::Fixed) blade_groups.insert(c.group);
  // Rotating, the shares tell collective from cyclic, not backward from forward whirl.
  const std::vector<std::string> labels = std::abs(rotor_speed) < kParkedRadPerS
                                              ? std::vector<std::string>{"collective", "cos", "sin"}
                                              : std::vector<std::string>{"collective"};
  for (const std::string& group : blade_groups) {
    std::map<std::string, std::vector<size_t>> by_label;
    for (size_t m = 0; m < modes.size(); ++m) {
      if (modes[m].rigid_body || modes[m].name.rfind(group + " ", 0) != 0) continue;
      by_label[modes[m].name.substr(group.size() + 1)].push_back(m);
    }
    for (const auto& [label, clash] : by_label) {
      if (clash.size() < 2) continue;
      std::vector<std::string> names = {label};
      for (const auto& l : labels)
        if (l != label && !by_label.count(l)) names.push_back(l);
      if (names.size() < clash.size()) continue;
      std::vector<size_t> perm(names.size()), best;
      for (size_t k = 0; k < perm.size(); ++k) perm[k] = k;
      double best_score = -1;
      do {
        double score = 0;
        for (size_t k = 0; k < clash.size(); ++k) score += labelShare(modes[clash[k]], coords, group, names[perm[k]]);
        if (score > best_score + 1e-12) best_score = score, best = perm;
      } while (std::next_permutation(perm.begin(), perm.end()));
      for (size_t k = 0; k < clash.size(); ++k) modes[clash[k]].name = group + " " + names[best[k]];
    }
  }
}

}  // namespace

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

namespace {

// The name of a rotating coordinate's multiblade set: bladeBaseName, and an inner " blade <k>" dropped, as
// the blade elements' aerodynamic states carry it ("UA x1 blade 1 element 10" → "UA x1 element 10", their
// group "UA x1 blade 1" → "UA x1").
std::string multibladeBaseName(const std::string& n) {
  const std::string s = bladeBaseName(n);
  const std::string tag = " blade ";
  const std::size_t at = s.find(tag);
  if (at == std::string::npos) return s;
  std::size_t k = at + tag.size();
  while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
  if (k == at + tag.size() || (k < s.size() && s[k] != ' ')) return s;
  return s.substr(0, at) + s.substr(k);
}

// Coordinates of a linear model for naming; with first-order states (HydroDyn radiation) the modes come
// from participation factors, which weigh states of any kind alike: one coordinate per DOF (its
// displacement and rate) and one per first-order state, grouped by what it belongs to.
RotorCoordinates linearCoordinates(const Model& m, const LinearModel& first, const std::vector<int>& held) {
  const int n = static_cast<int>(first.dofs.size());
  RotorCoordinates c;
  c.names = first.dof_names;
  for (int i = 0; i < n; ++i) {
    c.blade.push_back(m.dofs[first.dofs[i]].blade);
    c.azimuth.push_back(m.dofs[first.dofs[i]].rotating);
    c.held.push_back(std::find(held.begin(), held.end(), first.dofs[i]) != held.end());
    c.teeter.push_back(first.dofs[i] == m.roles.teeter_dof);
  }
  // Shapes are in multiblade coordinates: blade coordinates weigh by their diagonal of M (blade entries
  // alike). The fixed-frame coordinates keep their whole mass block: on a floating platform the first
  // tower shapes move with platform pitch and surge through large off-diagonal masses, and by the
  // diagonal alone the platform's inertia times its small motion would name the first tower mode
  // after the platform (OC3-Hywind, parked: with the coupling the tower's own share of that mode is 0.90).
  c.weights = first.M;
  for (int i = 0; i < n; ++i) {
    if (c.blade[i] < 0) continue;
    const double d = first.M(i, i);
    c.weights.row(i).setZero();
    c.weights.col(i).setZero();
    c.weights(i, i) = d;
  }
  const int nz = static_cast<int>(first.first_order_names.size());
  if (nz == 0) return c;
  c.groups = c.names;
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < n; ++i) c.coordinate_of_state.push_back(i);
  for (int k = 0; k < nz; ++k) {
    c.coordinate_of_state.push_back(n + k);
    c.names.push_back(first.first_order_names[k]);
    c.groups.push_back(first.first_order_groups[k]);
    // Rotating first-order states (a blade's unsteady-airfoil states) go through the multiblade transform.
    c.blade.push_back(k < static_cast<int>(first.first_order_blades.size()) ? first.first_order_blades[k] : -1);
    c.azimuth.push_back(false);
    c.held.push_back(false);
    c.teeter.push_back(false);
  }
  return c;
}

MbcLayout linearLayout(const RotorCoordinates& c, const LinearModel& first) {
  const std::size_t n = first.dofs.size();
  int nb = 0;
  for (int b : c.blade) nb = std::max(nb, b + 1);
  const std::vector<int> dof_blade(c.blade.begin(), c.blade.begin() + static_cast<std::ptrdiff_t>(n));
  std::vector<int> fo_blade(first.first_order_names.size(), -1);
  for (std::size_t k = 0; k < fo_blade.size() && k < first.first_order_blades.size(); ++k)
    fo_blade[k] = first.first_order_blades[k];
  return secondOrderLayout(std::max(nb, 3), dof_blade, fo_blade);
}

}  // namespace

RotorModes rotorModes(const Model& m, const PeriodicLinearization& p) {
  const LinearModel& first = p.models.front();
  const RotorCoordinates c = linearCoordinates(m, first, p.points.front().held);
  std::vector<MbcSample> samples;
  for (size_t k = 0; k < p.models.size(); ++k) {
    MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    samples.push_back(std::move(s));
  }
  return multibladeModes(c, linearLayout(c, first), samples);
}

RotorModes linearModelModes(const Model& m, const LinearModel& lin, const std::vector<int>& held) {
  const RotorCoordinates c = linearCoordinates(m, lin, held);
  MbcSample s;
  s.A = lin.A;
  return multibladeModes(c, linearLayout(c, lin), {s});
}

namespace {

/// Per coordinate of c, the state that carries it: its displacement, or its first-order state.
std::vector<int> stateOfCoordinate(const RotorCoordinates& c) {
  const int n = static_cast<int>(c.names.size());
  std::vector<int> state_of(n);
  for (int i = 0; i < n; ++i) state_of[i] = i;
  if (!c.coordinate_of_state.empty())
    for (int s = static_cast<int>(c.coordinate_of_state.size()) - 1; s >= 0; --s)
      state_of[c.coordinate_of_state[s]] = s;
  return state_of;
}

/// Per coordinate of c, how many states carry it: 2 (displacement and rate) or 1 (a first-order state);
/// 0 without first-order states.
std::vector<int> statesPerCoordinate(const RotorCoordinates& c) {
  std::vector<int> states_per(c.names.size(), 0);
  for (int k : c.coordinate_of_state) ++states_per[k];
  return states_per;
}

/// The naming group of coordinate i: its group when c has groups, else its name.
const std::string& namingGroup(const RotorCoordinates& c, int i) { return c.groups.empty() ? c.names[i] : c.groups[i]; }

/// Whether the samples' azimuths [rad] cover the revolution evenly (sample k at 2πk/N past the first).
bool evenAzimuths(const std::vector<MbcSample>& samples) {
  bool even = true;
  for (std::size_t k = 1; k < samples.size(); ++k)
    even = even && std::abs(samples[k].azimuth - samples[0].azimuth -
                            2 * std::numbers::pi * double(k) / double(samples.size())) < 1e-6;
  return even;
}

/// Floquet analysis of samples that cover the revolution evenly (fewer than 3 blades, turning).
/// InputError when c has first-order states: Floquet's fixed-frame view pairs every coordinate with a rate.
RotorModes floquetRotorModes(const RotorCoordinates& c, const std::vector<MbcSample>& samples) {
  const std::vector<int> states_per = statesPerCoordinate(c);
  if (std::find(states_per.begin(), states_per.end(), 1) != states_per.end())
    throw InputError(
        "Floquet analysis (fewer than 3 blades, turning) of a model with first-order states "
        "(HydroDyn radiation, unsteady-airfoil states) is not supported: --set RdtnMod=0 leaves the "
        "radiation out, --quasi-steady-aero the airfoil and dynamic-inflow states");
  return floquetModes(c, samples);
}

/// With 3 or more blades: the azimuth average of A in multiblade coordinates (out.A), and the names
/// and naming groups of those coordinates: the j-th coordinate of every blade forms one set named
/// after blade 1's, with its multiblade kind (collective, cosine, …).
void multibladeCoordinates(const RotorCoordinates& c, const MbcLayout& layout, const std::vector<MbcSample>& samples,
                           int nb, RotorModes& out, std::vector<NamingCoordinate>& coords) {
  const int n = static_cast<int>(c.names.size());
  const std::vector<int> state_of = stateOfCoordinate(c);
  out.num_blades = nb;
  const MbcResult mbc = mbcAverage(layout, samples);
  out.A = mbc.A;
  std::vector<std::vector<int>> per_blade(nb);
  for (int i = 0; i < n; ++i)
    if (c.blade[i] >= 0) per_blade[c.blade[i]].push_back(i);
  out.coordinates.resize(n);
  for (int i = 0; i < n; ++i) {
    coords[i].kind = mbc.states[state_of[i]];
    if (c.blade[i] < 0) {
      coords[i].group = namingGroup(c, i);
      out.coordinates[i] = c.names[i];
      continue;
    }
    const auto& list = per_blade[c.blade[i]];
    const size_t j = std::find(list.begin(), list.end(), i) - list.begin();
    coords[i].group = multibladeBaseName(namingGroup(c, per_blade[0].at(j)));
    out.coordinates[i] = multibladeBaseName(c.names[per_blade[0].at(j)]) + " " + toString(coords[i].kind);
  }
}

/// Names every mode (nameRotorMode). With the blade elements' aerodynamic states (rotating first-order
/// states, modal/aero_roots.hpp) their own roots are named apart, every other mode from its structural
/// coordinates alone.
void nameMultibladeModes(std::vector<Mode>& modes, const RotorCoordinates& c,
                         const std::vector<NamingCoordinate>& coords, double rotor_speed) {
  const int n = static_cast<int>(c.names.size());
  std::vector<bool> aero(static_cast<std::size_t>(n), false);
  if (!c.coordinate_of_state.empty()) {
    const std::vector<int> per = statesPerCoordinate(c);
    for (int i = 0; i < n; ++i) aero[i] = per[i] == 1 && c.blade[i] >= 0;
  }
  const bool any_aero = std::find(aero.begin(), aero.end(), true) != aero.end();
  if (any_aero) nameAeroRoots(modes, aero);
  for (auto& mode : modes) {
    if (!any_aero) {
      nameRotorMode(mode, coords, c.azimuth, c.held, rotor_speed);
      continue;
    }
    if (isAeroRoot(mode)) continue;
    const VecX full = mode.participation;
    for (int i = 0; i < n; ++i)
      if (aero[i]) mode.participation(i) = 0;
    nameRotorMode(mode, coords, c.azimuth, c.held, rotor_speed);
    mode.participation = full;
  }
}

/// Marks the modes carried by first-order states (Mode::first_order). A zero root carried by them (a
/// coordinate with one state: HydroDyn's wave-excitation filter) is no rigid-body motion but a state
/// that does not change by itself: renamed "… (zero root)".
void markFirstOrderModes(std::vector<Mode>& modes, const RotorCoordinates& c) {
  const int n = static_cast<int>(c.names.size());
  const std::vector<int> states_per = statesPerCoordinate(c);
  for (auto& mode : modes) {
    double first_order = 0;
    for (int i = 0; i < n; ++i)
      if (states_per[i] == 1) first_order += mode.participation(i);
    if (!isAeroRoot(mode)) mode.first_order = first_order > 0.5;  // an aerodynamic root stays one
    const std::string tag = " (rigid body)";
    if (mode.rigid_body && first_order > 0.5 && mode.name.size() > tag.size() &&
        mode.name.compare(mode.name.size() - tag.size(), tag.size(), tag) == 0) {
      mode.rigid_body = false;
      mode.name = mode.name.substr(0, mode.name.size() - tag.size()) + " (zero root)";
    }
  }
}

/// Real roots listed one by one (participationModes) but one rigid-body motion: the two roots of a
/// free azimuth (the multiblade average leaves them ~1e-4 Hz apart from zero) or of a free yaw (zero
/// and its decay) are one mode, as whirl's own modes count them. The pair's frequency [Hz] and damping
/// as modal/modes.hpp gives them: f = √(λ₁λ₂)/2π, ζ = −(λ₁+λ₂)/(2√(λ₁λ₂)), zero when a root is zero.
std::vector<Mode> mergeRigidBodyRoots(std::vector<Mode>& modes) {
  std::vector<Mode> kept;
  for (auto& mode : modes) {
    const auto k = std::find_if(kept.begin(), kept.end(), [&](const Mode& m) {
      return m.rigid_body && m.damped_freq_hz == 0 && m.name == mode.name;
    });
    if (!mode.rigid_body || mode.damped_freq_hz != 0 || k == kept.end()) {
      kept.push_back(std::move(mode));
      continue;
    }
    const double l1 = -k->damping_ratio * k->freq_hz, l2 = -mode.damping_ratio * mode.freq_hz;  // λ/2π
    const double f = std::sqrt(std::abs(l1 * l2));
    k->damping_ratio = f > 0 ? -(l1 + l2) / (2 * f) : 0;
    k->freq_hz = f;
  }
  return kept;
}

}  // namespace

RotorModes multibladeModes(const RotorCoordinates& c, const MbcLayout& layout, const std::vector<MbcSample>& samples) {
  RotorModes out;
  const int n = static_cast<int>(c.names.size());
  const bool by_participation = !c.coordinate_of_state.empty();
  int nb = 0;
  for (int b : c.blade) nb = std::max(nb, b + 1);
  const double rotor_speed = samples.front().rotor_speed;
  std::vector<NamingCoordinate> coords(n);
  const bool teeter = std::find(c.teeter.begin(), c.teeter.end(), true) != c.teeter.end();
  // A single blade with no fixed-frame coordinate (a blade-only deck) needs no transform: its rotating
  // coordinates are its multiblade ones (N = 1), and the azimuth average of A is MBC3's.
  const bool blade_only = nb == 1 && !teeter && std::find(c.blade.begin(), c.blade.end(), -1) == c.blade.end();
  // With fewer than 3 blades (or a teeter, which only 2 blades have) the transformed system stays
  // periodic: Floquet analysis, when the azimuths cover the revolution evenly (else the first
  // sample, as below).
  if ((nb > 0 || teeter) && nb < 3 && !blade_only && std::abs(rotor_speed) > 0 && samples.size() >= 2 &&
      evenAzimuths(samples))
    return floquetRotorModes(c, samples);
  // Parked (or uneven azimuths): the first model, fixed-frame names; a single blade (a blade-only deck)
  // has no pattern across blades to name, its modes take its coordinates' names below.
  if ((nb > 1 || teeter) && nb < 3 && !by_participation) return parkedRotorModes(c, samples.front());
  if (nb < 3) {
    // No transform: with fewer than 3 blades the transformed system stays periodic.
    out.A = samples.front().A;
    if (blade_only) {
      for (std::size_t k = 1; k < samples.size(); ++k) out.A += samples[k].A;
      out.A /= static_cast<double>(samples.size());
    }
    for (int i = 0; i < n; ++i) coords[i].group = namingGroup(c, i);
    out.coordinates = c.names;
  } else {
    multibladeCoordinates(c, layout, samples, nb, out, coords);
  }
  out.modes = by_participation ? participationModes(eigenStandard(out.A, true), c.coordinate_of_state, out.coordinates)
                               : modesFromEigen(eigenStandard(out.A), n, c.weights, out.coordinates);
  nameMultibladeModes(out.modes, c, coords, rotor_speed);
  if (nb >= 3) distinctBladeNames(out.modes, coords, rotor_speed);
  if (by_participation) {
    markFirstOrderModes(out.modes, c);
    out.modes = mergeRigidBodyRoots(out.modes);
  }
  return out;
}

}  // namespace whirl
