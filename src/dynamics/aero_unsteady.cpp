// Blade-element loads with unsteady-airfoil states (aero_unsteady.hpp); instantiated for double and ADChunk.
#include "src/dynamics/aero_unsteady.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "src/aero/bem.hpp"
#include "src/aero/dynamic_inflow.hpp"
#include "src/dynamics/aero_element.hxx"
#include "src/dynamics/aero_section.hxx"
#include "src/dynamics/aero_skew.hxx"
#include "src/dynamics/aero_unsteady_section.hxx"
#include "src/dynamics/point_force.hxx"

namespace whirl {
namespace {

// AeroDyn's BEM weight of the rotor's tip-speed ratio (check_turnOffBEMT), as addAeroLoads forms it.
template <class T>
T inductionWeightOf(const AeroModel& am, const FrameState<T>& hub, const T& speed, const Vec3& wind_dir) {
  const Vec3T<T> disk = hub.R.col(0);
  const T omega = hub.w.dot(disk);
  const T along = speed * T(wind_dir.template cast<T>().dot(disk));
  const T va = valueOf(along) < 0 ? T(-along) : along;
  const T om = valueOf(omega) < 0 ? T(-omega) : omega;
  if (valueOf(va) > 0) return aero::inductionWeight<T>(om * am.tip_radius / va);
  return T(valueOf(om) > 0 ? 1.0 : 0.0);
}

}  // namespace

int inflowStatesPerElement(const AeroModel& am) { return am.dbemt_mod == 3 && am.induction ? 4 : 0; }

int inflowStateCount(const AeroModel& am) { return inflowStatesPerElement(am) * am.nstations(); }

int aeroStateCount(const AeroModel& am) { return uaStateCount(am) + inflowStateCount(am); }

void inflowStateNames(const AeroModel& am, std::vector<std::string>& names, std::vector<std::string>& groups) {
  if (inflowStatesPerElement(am) == 0) return;
  static const char* const kinds[4] = {"DBEMT v axial", "DBEMT v tangential", "DBEMT v1 axial", "DBEMT v1 tangential"};
  for (std::size_t b = 0; b < am.blades.size(); ++b)
    for (std::size_t j = 0; j < am.blades[b].stations.size(); ++j)
      for (const char* kind : kinds) {
        groups.push_back(std::string(kind) + " blade " + std::to_string(b + 1));
        names.push_back(groups.back() + " element " + std::to_string(j + 1));
      }
}

void removeDynamicInflow(AeroModel& am) {
  am.dbemt_mod = 0;
  am.tau1 = 0;
}

int uaStatesPerElement(const AeroModel& am) { return am.ua_mod == 4 ? 4 : am.ua_mod == 6 ? 1 : 0; }

int uaStateCount(const AeroModel& am) {
  int n = 0;
  for (const AeroBlade& b : am.blades)
    for (const AeroStation& st : b.stations) n += st.ua ? 1 : 0;
  return n * uaStatesPerElement(am);
}

void uaStateNames(const AeroModel& am, std::vector<std::string>& names, std::vector<std::string>& groups) {
  const int ns = uaStatesPerElement(am);
  for (std::size_t b = 0; b < am.blades.size(); ++b)
    for (std::size_t j = 0; j < am.blades[b].stations.size(); ++j) {
      if (!am.blades[b].stations[j].ua) continue;
      for (int k = 0; k < ns; ++k) {
        const std::string x = "UA x" + std::to_string(ns == 1 ? 4 : k + 1);
        groups.push_back(x + " blade " + std::to_string(b + 1));
        names.push_back(groups.back() + " element " + std::to_string(j + 1));
      }
    }
}

void removeUnsteadyAirfoils(AeroModel& am) {
  am.ua_mod = 0;
  am.ua_tables.clear();
  am.ua_has_cm.clear();
  for (AeroBlade& b : am.blades)
    for (AeroStation& st : b.stations) st.ua = false;
}

aero::UaSection uaSection(const AeroModel& am, const AeroStation& st) {
  const auto p = static_cast<std::size_t>(st.polar);
  return {&am.polars[p], &am.ua_tables[p], st.chord, static_cast<bool>(am.ua_has_cm[p]), am.ua_mod};
}

template <class T>
void addUnsteadyAeroLoads(const Model& m, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& u,
                          const AeroInflow& frozen, const VecXT<T>* z, VecXT<T>& e, VecXT<T>* zdot,
                          std::vector<aero::UaInput<T>>* inputs, VecXT<T>* quasi_steady, int element,
                          bool minus_quasi_steady, RotorTotals<T>* totals, int only_blade) {
  using std::sqrt;
  const AeroModel& am = m.aero;
  if (!am.active()) return;
  if (minus_quasi_steady && totals)
    throw std::logic_error("addUnsteadyAeroLoads: totals of loads less quasi-steady ones");
  const FrameState<T>& hub = ws.frames[am.hub_body];
  const Vec3T<T> disk = hub.R.col(0);
  const T speed = m.roles.wind_speed_input >= 0 ? u(m.roles.wind_speed_input) : T(0);
  const Vec3 wind_dir = detail::windDirection(am.wind);
  const int ns = uaStatesPerElement(am);
  // Dynamic inflow: with states given, the elements' induction is the states' (DBEMT_Mod 3).
  const bool dynamic = z && inflowStatesPerElement(am) > 0;
  const int zi_inflow = uaStateCount(am);  // the first dynamic-inflow state in z
  const T weight = dynamic ? inductionWeightOf(am, hub, speed, wind_dir) : T(1.0);
  // The skewed-wake correction of the dynamic inflow's induction (AeroDyn applies it after DBEMT); a frozen
  // induction carries it from its operating point.
  const detail::RotorSkew<T> skew = dynamic ? detail::rotorSkew<T>(am, disk, wind_dir, valueOf(speed))
                                            : detail::RotorSkew<T>{};
  if (inputs) inputs->clear();
  if (totals) {  // blades without the element asked for keep zero resultants
    totals->thrust = totals->torque = T(0.0);
    totals->blade_force.assign(am.blades.size(), Vec3T<T>::Zero());
    totals->blade_moment.assign(am.blades.size(), Vec3T<T>::Zero());
  }
  int index = 0, zi = 0;  // element over all blades, first state of the next element with states
  for (std::size_t bi = 0; bi < am.blades.size(); ++bi) {
    const AeroBlade& blade = am.blades[bi];
    const int nst = static_cast<int>(blade.stations.size());
    // A blade not asked for, or without the element asked for.
    if ((only_blade >= 0 && static_cast<int>(bi) != only_blade) ||
        (element >= 0 && (element < index || element >= index + nst))) {
      for (const AeroStation& st : blade.stations) zi += st.ua ? ns : 0;
      index += nst;
      continue;
    }
    const Body& body = m.bodies[blade.body];
    const FrameState<T>& f = ws.frames[blade.body];
    const BasisState<T>& bs = ws.basis[blade.body];
    const T pitch = blade.pitch_dof >= 0 ? q(blade.pitch_dof) : T(0);
    const T* qe = body.inertia.ne > 0 ? q.data() + body.elastic_dof : nullptr;
    const T* qde = body.inertia.ne > 0 ? qd.data() + body.elastic_dof : nullptr;
    const detail::BladeMotion<T> bm{f.R, f.r, f.v, f.w, bs.c, bs.cd, qe, pitch};
    const detail::BladeAxes<T> axes = detail::bladeAxes(body, bm);
    const detail::BladeSkew<T> blade_skew =
        skew.active ? detail::bladeSkew(skew, f.R, detail::bladeTipRadius(body, blade, f.R, f.r, bs.c, hub.r, disk))
                    : detail::BladeSkew<T>{};
    detail::BodyLoadSum<T> sum(body.inertia.ne, body.points[blade.stations.front().point].P.cols());
    for (std::size_t si = 0; si < blade.stations.size(); ++si, ++index) {
      const AeroStation& st = blade.stations[si];
      // An element asked not for, or whose loads less the quasi-steady ones are zero (no states, no dynamic inflow).
      if ((element >= 0 && index != element) || (minus_quasi_steady && !(z && (st.ua || dynamic)))) {
        zi += st.ua ? ns : 0;
        continue;
      }
      const BodyPoint& pt = body.points[st.point];
      const detail::ElementFrame<T> g = detail::elementFrame(body, pt, bm, axes, st.curve);
      const Vec3T<T> rel = detail::steadyWind(am.wind, wind_dir, speed, g.pos(2)) - g.vel;
      const Vec3T<T> d = g.pos - hub.r;
      detail::UnsteadySectionInputs<T> s{rel.dot(g.xn),
                                         rel.dot(g.ya),
                                         T(st.twist) + T(pitch - g.twist),
                                         detail::distanceFromAxis<T>(d, disk),
                                         T(0.0),
                                         weight,
                                         {}};
      if (z && st.ua) {  // the section's rotation rate about the span axis: the body frame's and the elastic twist's
        Vec3T<T> twist_rate = Vec3T<T>::Zero();
        for (int j = 0; j < body.inertia.ne; ++j) twist_rate += pt.theta.col(j) * qde[j];
        s.omega = (f.w + f.R * twist_rate).dot(g.zn);
      }
      if (dynamic && skew.active) s.skew = blade_skew.template at<T>(skew, s.r);
      const detail::UnsteadySectionContext c{am,           st,      frozen.axial(index), frozen.tangential(index),
                                             z != nullptr, dynamic, skew.active,         minus_quasi_steady};
      const int n_ua = z && st.ua ? ns : 0, n_in = dynamic ? 4 : 0, k_in = zi_inflow + 4 * index;
      const T* z_ua = n_ua ? z->data() + zi : nullptr;
      const T* z_in = n_in ? z->data() + k_in : nullptr;
      BemRoot& root = ws.bem[static_cast<std::size_t>(index)];
      detail::UnsteadySectionOutputs<T> o;
      if constexpr (std::is_same_v<T, ADChunk>) {
        // A linearization's pass (loads less the quasi-steady ones) that seeds none of the element's states and
        // asks for nothing but loads and rates: the element's jet.
        bool seeded = false;
        for (int k = 0; k < n_ua; ++k) seeded = seeded || !z_ua[k].derivatives().isZero(0.0);
        for (int k = 0; k < n_in; ++k) seeded = seeded || !z_in[k].derivatives().isZero(0.0);
        if (minus_quasi_steady && z && !seeded && !inputs && !quasi_steady)
          o = detail::unsteadySectionByJet(c, s, z_ua, z_in, n_ua, n_in, root,
                                           ws.jets.unsteady[static_cast<std::size_t>(index)]);
        else o = detail::unsteadySection(c, s, z_ua, z_in, root);
      } else {
        o = detail::unsteadySection(c, s, z_ua, z_in, root);
      }
      if (zdot) {
        for (int k = 0; k < n_ua; ++k) (*zdot)(zi + k) = o.zdot[static_cast<std::size_t>(k)];
        for (int k = 0; k < n_in; ++k) (*zdot)(k_in + k) = o.zdot[static_cast<std::size_t>(n_ua + k)];
      }
      if (quasi_steady && dynamic) {
        (*quasi_steady)(2 * index) = o.qs_axial;
        (*quasi_steady)(2 * index + 1) = o.qs_tangential;
      }
      if (inputs && z && st.ua) inputs->push_back(o.ua_input);
      if (st.ua) zi += ns;
      const Vec3T<T> Fb = o.fx * g.xnb + o.fy * g.yab;
      const Vec3T<T> Mb = o.mz * g.znb;
      if (totals) {  // ground components about and along the rotor axis through the apex (addAeroLoads')
        const Vec3T<T> Fg = o.fx * g.xn + o.fy * g.ya, Mg = o.mz * g.zn;
        totals->thrust += st.weight * Fg.dot(disk);
        totals->torque += st.weight * (Vec3T<T>(d.cross(Fg)) + Mg).dot(disk);
      }
      if (minus_quasi_steady)  // less the loads without states on the frozen wake
        sum.addBody(pt, g.s, Vec3T<T>(Fb - o.qs_fx * g.xnb - o.qs_fy * g.yab), Vec3T<T>(Mb - o.qs_mz * g.znb),
                    st.weight);
      else sum.addBody(pt, g.s, Fb, Mb, st.weight);
    }
    sum.project(m, ws, blade.body, e);
    if (totals) sum.resultant(f.R, totals->blade_force[bi], totals->blade_moment[bi]);
  }
}

template void addUnsteadyAeroLoads<double>(const Model&, Workspace<double>&, const VecX&, const VecX&, const VecX&,
                                           const AeroInflow&, const VecX*, VecX&, VecX*,
                                           std::vector<aero::UaInput<double>>*, VecX*, int, bool, RotorTotals<double>*,
                                           int);
template void addUnsteadyAeroLoads<ADChunk>(const Model&, Workspace<ADChunk>&, const VecXT<ADChunk>&,
                                            const VecXT<ADChunk>&, const VecXT<ADChunk>&, const AeroInflow&,
                                            const VecXT<ADChunk>*, VecXT<ADChunk>&, VecXT<ADChunk>*,
                                            std::vector<aero::UaInput<ADChunk>>*, VecXT<ADChunk>*, int, bool,
                                            RotorTotals<ADChunk>*, int);

}  // namespace whirl
