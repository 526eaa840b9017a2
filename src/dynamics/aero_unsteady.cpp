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
#include "src/dynamics/point_force.hxx"

namespace whirl {
namespace {

template <class T>
T atan2S(const T& y, const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::atan2(y, x);
  } else {  // the fixed-size AD type (Eigen's overload goes through a dynamic-size derivative vector)
    const double xv = x.value(), yv = y.value(), h = xv * xv + yv * yv;
    return T(std::atan2(yv, xv), (xv * y.derivatives() - yv * x.derivatives()) / h);
  }
}

// The section loads from the UA coefficients at the frozen-wake flow (x, y) = (Vx + AxInd, Vy + TnInd),
// as aero::frozenLoads forms them from the static polar (AeroDyn SetOutputsFromBEMT).
template <class T>
aero::SectionLoads<T> loadsOfCoefficients(const T& x, const T& y, const T& phi, const T& alpha, const T& W,
                                          const aero::Coefficients<T>& c, double chord, double rho) {
  aero::SectionLoads<T> L;
  L.phi = phi;
  L.alpha = alpha;
  L.W = W;
  L.cl = c.cl;
  L.cd = c.cd;
  L.cm = c.cm;
  const T sphi = x / W, cphi = y / W;
  L.cx = c.cl * cphi + c.cd * sphi;
  L.cy = c.cl * sphi - c.cd * cphi;
  const T qd = 0.5 * rho * W * W;
  L.fx = L.cx * qd * chord;
  L.fy = -L.cy * qd * chord;
  L.mz = c.cm * qd * (chord * chord);
  return L;
}

// The quasi-steady induced velocity of an element at (vx, vy, θ): the BEM root solved in double at the values
// (kept in `root` and reused while the values agree to round-off: the AD passes of one linearization), the
// derivatives by the implicit-function theorem (aero::quasiSteadyInducedVelocity). No valid root: AeroDyn's
// geometric fallback, no induction.
template <class T>
aero::InducedVelocity<T> quasiSteadyInduction(const AeroModel& am, aero::BemStation b, const T& vx, const T& vy,
                                              const T& theta, const T& r, BemRoot& root) {
  const double x = valueOf(vx), y = valueOf(vy), th = valueOf(theta);
  b.theta = th;
  const double tol = std::is_same_v<T, double> ? 0.0 : 1e-12, vscale = tol * (std::abs(x) + std::abs(y));
  if (!(root.valid && std::abs(root.vx - x) <= vscale && std::abs(root.vy - y) <= vscale &&
        std::abs(root.theta - th) <= tol && std::abs(root.r - b.r) <= tol * b.r)) {
    const aero::InflowRoot sol = aero::findInflowRoot(b, x, y, am.bem,
                                                      root.valid ? std::optional<double>(root.phi) : std::nullopt);
    root = BemRoot{};
    root.valid = true;
    root.vx = x;
    root.vy = y;
    root.theta = th;
    root.r = b.r;
    root.phi = sol.phi;
    root.a = sol.a;
    root.ap = sol.ap;
    root.bem_valid = sol.valid;
  }
  if (!root.bem_valid) return {T(0.0), T(0.0), false};
  if constexpr (!std::is_same_v<T, double>) {
    // An AD pass that seeds none of the inflow (the chunks of state columns): no derivatives, and the value
    // is the root's own (−Vx a, Vy a'), without the implicit-function step in the AD scalar.
    if (vx.derivatives().isZero(0.0) && vy.derivatives().isZero(0.0) && theta.derivatives().isZero(0.0) &&
        r.derivatives().isZero(0.0))
      return {T(-x * root.a), T(y * root.ap), aero::hasFixedInductions(b, am.bem)};
  }
  return aero::quasiSteadyInducedVelocity<T>(b, vx, vy, theta, root.phi, am.bem, &r, &root.slope);
}

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
      const T vx = rel.dot(g.xn), vy = rel.dot(g.ya);
      const Vec3T<T> d = g.pos - hub.r;
      const T r_t = detail::distanceFromAxis<T>(d, disk);
      const double r = valueOf(r_t);
      const T theta = T(st.twist) + T(pitch - g.twist);
      const double ax = frozen.axial(index), tn = frozen.tangential(index);
      // The relative flow (x, y) = (Vx(1−a), Vy(1+a')): the frozen wake's, or with the dynamic-inflow states
      // v (AeroDyn calculate_Inductions_from_DBEMT), their rates driven by the quasi-steady induction.
      T x = valueOf(vx) == 0 ? vx : T(vx + ax), y = valueOf(vy) == 0 ? vy : T(vy + tn);
      T v_ax(0.0), v_tn(0.0);  // the induced velocities the loads see, with dynamic inflow
      if (dynamic) {
        const aero::BemStation b = detail::bemStation(am, st, r);
        const aero::InducedVelocity<T> qs = quasiSteadyInduction(am, b, vx, vy, theta, r_t,
                                                                 ws.bem[static_cast<std::size_t>(index)]);
        const int k = zi_inflow + 4 * index;  // v axial, v tangential, v1 axial, v1 tangential
        // Elements with fixed inductions (a loss constant of 0) take the BEM ones (AeroDyn skips DBEMT there).
        v_ax = qs.fixed ? qs.axial : (*z)(k);
        v_tn = qs.fixed ? qs.tangential : (*z)(k + 1);
        if (skew.active && !qs.fixed && valueOf(vx) != 0)
          v_ax = v_ax * detail::skewFactor<T>(am, blade_skew.template at<T>(skew, r_t), T(-v_ax / vx));
        std::tie(x, y) = aero::inducedFlow<T>(vx, vy, v_ax, v_tn, &weight);
        if (zdot) {
          const double tau2 = aero::dbemtTau2(am.tau1, st.span_ratio);
          const aero::OyeState<T> da = aero::oyeDerivative<T>({(*z)(k + 2), (*z)(k)}, qs.axial, am.tau1, tau2);
          const aero::OyeState<T> dt = aero::oyeDerivative<T>({(*z)(k + 3), (*z)(k + 1)}, qs.tangential, am.tau1, tau2);
          (*zdot)(k) = da.v;
          (*zdot)(k + 1) = dt.v;
          (*zdot)(k + 2) = da.v1;
          (*zdot)(k + 3) = dt.v1;
        }
        if (quasi_steady) {
          (*quasi_steady)(2 * index) = qs.axial;
          (*quasi_steady)(2 * index + 1) = qs.tangential;
        }
      }
      aero::SectionLoads<T> L;
      if (!z) {
        L = aero::frozenLoads(detail::bemStation(am, st, r), vx, vy, theta, ax, tn, am.air_density, am.bem);
      } else if (!st.ua) {
        L = dynamic ? aero::inducedVelocityLoads<T>(detail::bemStation(am, st, r), vx, vy, theta, v_ax, v_tn,
                                                    am.air_density, &weight)
                    : aero::frozenLoads(detail::bemStation(am, st, r), vx, vy, theta, ax, tn, am.air_density, am.bem);
      } else {
        const T phi = atan2S(x, y), alpha = phi - theta, W = sqrt(x * x + y * y);
        // The section's rotation rate about the span axis: the body frame's and the elastic twist's.
        Vec3T<T> twist_rate = Vec3T<T>::Zero();
        for (int j = 0; j < body.inertia.ne; ++j) twist_rate += pt.theta.col(j) * qde[j];
        const T omega = (f.w + f.R * twist_rate).dot(g.zn);
        using std::cos;
        using std::sin;
        aero::UaInput<T> in{atan2S(T(W * sin(alpha) + omega * (0.5 * st.chord)), T(W * cos(alpha))), alpha, W, omega};
        const aero::UaSection sec = uaSection(am, st);
        aero::HgmState<T> xs{T(0.0), T(0.0), T(0.0), T(0.0)};
        if (ns == 4) xs = {(*z)(zi), (*z)(zi + 1), (*z)(zi + 2), (*z)(zi + 3)};
        else xs.x4 = (*z)(zi);
        L = loadsOfCoefficients(x, y, phi, alpha, W, aero::hgmLoads(sec, xs, in), st.chord, am.air_density);
        if (zdot) {
          const aero::HgmState<T> dx = aero::hgmDerivative(sec, xs, in);
          if (ns == 4) {
            (*zdot)(zi) = dx.x1;
            (*zdot)(zi + 1) = dx.x2;
            (*zdot)(zi + 2) = dx.x3;
            (*zdot)(zi + 3) = dx.x4;
          } else {
            (*zdot)(zi) = dx.x4;
          }
        }
        if (inputs) inputs->push_back(in);
      }
      if (st.ua) zi += ns;
      const Vec3T<T> Fb = L.fx * g.xnb + L.fy * g.yab;
      const Vec3T<T> Mb = L.mz * g.znb;
      if (totals) {  // ground components about and along the rotor axis through the apex (addAeroLoads')
        const Vec3T<T> Fg = L.fx * g.xn + L.fy * g.ya, Mg = L.mz * g.zn;
        totals->thrust += st.weight * Fg.dot(disk);
        totals->torque += st.weight * (Vec3T<T>(d.cross(Fg)) + Mg).dot(disk);
      }
      if (!minus_quasi_steady) {
        sum.addBody(pt, g.s, Fb, Mb, st.weight);
      } else if (z && (st.ua || dynamic)) {  // less the loads without states on the frozen wake
        const aero::SectionLoads<T> Q = aero::frozenLoads(detail::bemStation(am, st, r), vx, vy, theta, ax, tn,
                                                          am.air_density, am.bem);
        sum.addBody(pt, g.s, Vec3T<T>(Fb - Q.fx * g.xnb - Q.fy * g.yab), Vec3T<T>(Mb - Q.mz * g.znb), st.weight);
      }
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
