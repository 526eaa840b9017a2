// The HGM unsteady-airfoil model (UA_Mod 4, src/aero/unsteady_airfoil) and Øye's dynamic inflow
// (DBEMT_Mod 3, src/aero/dynamic_inflow): the indicial response against Jones's closed form, the steady
// state against the static polar, the AD Jacobian against central differences, and the element blocks of
// OpenFAST's own linearization (r-test Fake5MW_AeroLin_B1_UA4_DBEMT3, tests/data/openfast-lin/ua4-dbemt3).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>
#include <type_traits>
#include <vector>

#include "src/aero/dynamic_inflow.hpp"
#include "src/aero/unsteady_airfoil.hpp"
#include "src/aero/unsteady_airfoil_linear.hpp"
#include "src/base/scalar.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_ua.hpp"

namespace {

using namespace whirl::aero;
using whirl::ADChunk;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

std::filesystem::path uaDeckDir() {
  return std::filesystem::path(WHIRL_SOURCE_DIR) / "tests/data/openfast-lin/ua4-dbemt3";
}

/// A thin-airfoil polar: Cl = 2π α within ±10°, a stall plateau to 20°, flat-plate-like beyond; Cd small in
/// the linear region. alpha0 = 0, C_lalpha = 2π given.
struct ThinAirfoil {
  Polar polar;
  UaTable ua;
  ThinAirfoil() {
    std::vector<double> a, cl, cd, cm;
    for (int d = -180; d <= 180; d += 1) {
      const double x = d * kDeg;
      double l;
      if (std::abs(d) <= 10) l = 2 * kPi * x;
      else if (std::abs(d) <= 20) l = std::copysign(2 * kPi * 10 * kDeg - 0.06 * (std::abs(d) - 10), x);
      else l = std::sin(2 * x);
      a.push_back(x);
      cl.push_back(l);
      cd.push_back(0.01 + 1.2 * std::sin(x) * std::sin(x));
      cm.push_back(-0.05 * std::sin(x));
    }
    UaGiven g;
    g.alpha0 = 0.0;
    g.c_lalpha = 2 * kPi;
    g.c_nalpha = 2 * kPi;
    polar = makePolar("thin", a, cl, cd, cm, PolarInterp::Linear, "thin");
    ua = uaTable(g, a, cl, cd, cm, PolarInterp::Linear, 4, "thin");
  }
  UaSection section(double chord) const { return {&polar, &ua, chord, true}; }
};

HgmState<double> add(const HgmState<double>& x, const HgmState<double>& d, double h) {
  return {x.x1 + h * d.x1, x.x2 + h * d.x2, x.x3 + h * d.x3, x.x4 + h * d.x4};
}

TEST(UnsteadyAirfoil, StepInAngleOfAttackFollowsJonesIndicialResponse) {
  // Attached flow (f_st = 1 along the whole path): after a step of α34 from 0 to Δα at s = 0 the lift is
  // the circulatory indicial response Cl(s) = C_lalpha Δα (1 − A1 e^{−b1 s} − A2 e^{−b2 s}), s = t/Tu =
  // 2Ut/c (Jones's approximation of Wagner's function with AeroDyn's A1 = 0.3, A2 = 0.7, b1 = 0.14,
  // b2 = 0.53; Hansen, Gaunaa & Madsen 2004, eqs. 8–9, 16, 19). RK4 with s-step 0.01: error ~1e-9.
  const ThinAirfoil af;
  const UaSection s = af.section(2.0);
  const double u = 40.0, tu = 1.0 / 40.0, da = 4 * kDeg;
  HgmState<double> x = hgmSteady(s, UaInput<double>{0.0, 0.0, u, 0.0});
  const UaInput<double> in{da, da, u, 0.0};
  const double h = 0.01 * tu;
  double t = 0;
  for (int step = 1; step <= 3000; ++step) {
    const auto k1 = hgmDerivative(s, x, in);
    const auto k2 = hgmDerivative(s, add(x, k1, h / 2), in);
    const auto k3 = hgmDerivative(s, add(x, k2, h / 2), in);
    const auto k4 = hgmDerivative(s, add(x, k3, h), in);
    x = {x.x1 + h / 6 * (k1.x1 + 2 * k2.x1 + 2 * k3.x1 + k4.x1), x.x2 + h / 6 * (k1.x2 + 2 * k2.x2 + 2 * k3.x2 + k4.x2),
         x.x3 + h / 6 * (k1.x3 + 2 * k2.x3 + 2 * k3.x3 + k4.x3),
         x.x4 + h / 6 * (k1.x4 + 2 * k2.x4 + 2 * k3.x4 + k4.x4)};
    t += h;
    if (step % 500 == 0) {
      const double sdim = t / tu;
      const double expected = 2 * kPi * da * (1 - 0.3 * std::exp(-0.14 * sdim) - 0.7 * std::exp(-0.53 * sdim));
      EXPECT_NEAR(hgmLoads(s, x, in).cl, expected, 1e-8) << "s = " << sdim;
      EXPECT_DOUBLE_EQ(x.x4, 1.0);
    }
  }
}

TEST(UnsteadyAirfoil, SteadyStateIsTheStaticPolar) {
  // At the steady state (ω = 0) the HGM loads equal the static Cl, Cd, Cm wherever AeroDyn's separation
  // columns reproduce Cl (0 < f_st < 1 or the linear region with Cl = C_lalpha (α − alpha0)) — attached,
  // near stall, in stall and deep stall — and dx/dt = 0 there. Exactly at the table's knots: between two
  // knots f_st and Cl_fs are interpolated linearly, and their product is not the linear Cl (as in AeroDyn;
  // 3.6e-3 at 12.5 deg for this table, half-way between knots 1 deg apart).
  const ThinAirfoil af;
  const UaSection s = af.section(1.5);
  for (double d : {-30.0, -12.0, -5.0, 0.0, 3.0, 9.5, 11.0, 13.0, 17.0, 25.0, 60.0}) {
    const UaInput<double> in{d * kDeg, d * kDeg, 50.0, 0.0};
    const HgmState<double> x = hgmSteady(s, in);
    const HgmState<double> dx = hgmDerivative(s, x, in);
    EXPECT_NEAR(dx.x1, 0, 1e-12);
    EXPECT_NEAR(dx.x2, 0, 1e-12);
    EXPECT_NEAR(dx.x3, 0, 1e-12);
    EXPECT_NEAR(dx.x4, 0, 1e-12);
    const auto ua = hgmLoads(s, x, in);
    const auto st = evaluate(af.polar, d * kDeg);
    EXPECT_NEAR(ua.cl, st.cl, 1e-12) << d;
    EXPECT_NEAR(ua.cd, st.cd, 1e-12) << d;
    EXPECT_NEAR(ua.cm, st.cm, 1e-12) << d;
  }
  // Beyond UACutout (45°) the loads are the static ones whatever the states.
  const UaInput<double> far{60 * kDeg, 60 * kDeg, 50.0, 0.0};
  EXPECT_DOUBLE_EQ(hgmLoads(s, HgmState<double>{0.1, 0.2, 0.3, 0.4}, far).cl, evaluate(af.polar, 60 * kDeg).cl);
}

TEST(UnsteadyAirfoil, AdJacobianEqualsCentralDifferences) {
  // ∂(dx/dt, Cl, Cd, Cm)/∂(x1..x4, α34, U, ω) at a point in stall (0 < x4 < 1), AD (ADChunk) vs central
  // differences with step 1e-6: agreement to 1e-6 relative (truncation ~1e-10, one-sided polar segments
  // are avoided by a point between knots).
  const ThinAirfoil af;
  const UaSection s = af.section(1.5);
  const double v0[7] = {0.03, 0.15, 1.2, 0.6, 13.3 * kDeg, 45.0, 0.4};
  auto eval = [&](const auto* v) {
    using T = std::remove_cv_t<std::remove_reference_t<decltype(v[0])>>;
    const HgmState<T> x{v[0], v[1], v[2], v[3]};
    const UaInput<T> in{v[4], v[4], v[5], v[6]};
    const auto d = hgmDerivative(s, x, in);
    const auto l = hgmLoads(s, x, in);
    return std::vector<T>{d.x1, d.x2, d.x3, d.x4, l.cl, l.cd, l.cm};
  };
  ADChunk va[7];
  for (int i = 0; i < 7; ++i) {
    va[i] = ADChunk(v0[i], ADChunk::DerType::Zero());
    va[i].derivatives()(i) = 1.0;
  }
  const std::vector<ADChunk> fa = eval(va);
  for (int i = 0; i < 7; ++i) {
    double vp[7], vm[7];
    std::copy(v0, v0 + 7, vp);
    std::copy(v0, v0 + 7, vm);
    const double h = 1e-6 * std::max(1.0, std::abs(v0[i]));
    vp[i] += h;
    vm[i] -= h;
    const auto fp = eval(static_cast<const double*>(vp));
    const auto fm = eval(static_cast<const double*>(vm));
    for (std::size_t r = 0; r < fa.size(); ++r) {
      const double fd = (fp[r] - fm[r]) / (2 * h);
      EXPECT_NEAR(fa[r].derivatives()(i), fd, 1e-6 * std::max(1.0, std::abs(fd))) << "row " << r << " col " << i;
    }
  }
}

/// OpenFAST's A and its operating point (tests/data/openfast-lin/ua4-dbemt3).
struct Reference {
  std::vector<double> a, x, xdot;
  double A(int r, int c) const { return a[static_cast<std::size_t>((r - 1) * 30 + (c - 1))]; }
  Reference() {
    std::ifstream in(uaDeckDir() / "A_30x30.txt");
    for (double v; in >> v;) a.push_back(v);
    std::ifstream s(uaDeckDir() / "states_inputs.txt");
    std::string line;
    int section = 0;
    while (std::getline(s, line)) {
      if (line.rfind("# --- continuous", 0) == 0) section = 1;
      else if (line.rfind("# --- state derivatives", 0) == 0) section = 2;
      else if (line.rfind("# --- inputs", 0) == 0) section = 3;
      if (line.empty() || line[0] == '#') continue;
      std::istringstream ls(line);
      int k;
      double v;
      ls >> k >> v;
      if (section == 1) x.push_back(v);
      if (section == 2) xdot.push_back(v);
    }
  }
};

TEST(UnsteadyAirfoil, ElementBlockMatchesOpenFastLinearization) {
  // The UA rows and columns of OpenFAST's A (states 19–30: x1..x4 at nodes 2–4) depend on the element
  // only through Tu, the constants and the slope of f_st at alphaF. Tu and α34 follow from the
  // operating point's x1, x2 and their xdot (dx_i/dt = b_i/Tu (A_i α34 − x_i)), independently of A.
  // whirl's AD Jacobian ∂(dx/dt)/∂x at OpenFAST's x then matches A's 4x4 block. Measured: the diagonal
  // within 5e-12, ∂ẋ3/∂x1 = ∂ẋ3/∂x2 = C_lalpha/(T_p Tu) within 5.8e-7 at all three nodes (a constant
  // factor: AeroDyn's single-precision constants), ∂ẋ4/∂x3 (the f_st slope, which OpenFAST forms by
  // central differences on its piecewise-linear table) within 1.7e-6; OpenFAST's other entries are below
  // 1e-14 (zero here). Tolerances 1e-6 and, for the f_st slope, 1e-5.
  const Reference ref;
  ASSERT_EQ(ref.a.size(), 900u);
  ASSERT_EQ(ref.x.size(), 30u);
  const auto af = whirl::io::readAirfoil(uaDeckDir() / "case/NACA64_A17_2Prop.dat");
  const Polar polar = whirl::io::airfoilPolar(af, true);
  const UaTable ua = whirl::io::airfoilUa(af, 0, 4);
  const double chord[3] = {4.249, 3.010, 1.419};  // AD_blade_4stations.dat, nodes 2–4
  for (int node = 0; node < 3; ++node) {
    const int b = 19 + 4 * node;  // first UA state of the node (1-based)
    const double x1 = ref.x[b - 1], x2 = ref.x[b], d1 = ref.xdot[b - 1], d2 = ref.xdot[b];
    const UaConstants& c = ua.c;
    // [d1/b1, −A1; d2/b2, −A2] [Tu; α34] = [−x1; −x2]
    const double det = d1 / c.b1 * -c.A2 - -c.A1 * d2 / c.b2;
    const double tu = (-x1 * -c.A2 - -c.A1 * -x2) / det;
    const double a34 = (d1 / c.b1 * -x2 - d2 / c.b2 * -x1) / det;
    const UaSection s{&polar, &ua, chord[node], true};
    const double u = chord[node] / (2 * tu);
    HgmState<ADChunk> xa;
    ADChunk* slots[4] = {&xa.x1, &xa.x2, &xa.x3, &xa.x4};
    for (int i = 0; i < 4; ++i) {
      *slots[i] = ADChunk(ref.x[static_cast<std::size_t>(b - 1 + i)], ADChunk::DerType::Zero());
      slots[i]->derivatives()(i) = 1.0;
    }
    const UaInput<ADChunk> in{ADChunk(a34), ADChunk(a34), ADChunk(u), ADChunk(0.0)};
    const HgmState<ADChunk> d = hgmDerivative(s, xa, in);
    const ADChunk* rows[4] = {&d.x1, &d.x2, &d.x3, &d.x4};
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) {
        const double ofa = ref.A(b + r, b + k), mine = rows[r]->derivatives()(k);
        const double tol = (r == 3 && k == 2) ? 1e-5 * std::abs(ofa) : 1e-6 * std::max(std::abs(ofa), 1e-8);
        EXPECT_NEAR(mine, ofa, tol) << "node " << node + 2 << " A(" << b + r << "," << b + k << ")";
      }
    // And the state derivatives themselves at OpenFAST's point (ω unknown: x3's row is left out).
    HgmState<double> xd{ref.x[b - 1], ref.x[b], ref.x[b + 1], ref.x[b + 2]};
    const auto dd = hgmDerivative(s, xd, UaInput<double>{a34, a34, u, 0.0});
    EXPECT_NEAR(dd.x4, ref.xdot[b + 2], 2e-6 / (c.T_f0 * tu)) << "node " << node + 2;
  }
}

TEST(DynamicInflow, OyeStatesMatchOpenFastLinearization) {
  // DBEMT_Mod 3, tau1_const = 100 s: OpenFAST's A rows of the induced velocities (states 3–10, "vind") and of
  // the intermediate states (11–18, labelled "First time derivative of vind" in the .lin file, but with
  // d/dt = −x/τ1 + …: Øye's v1). dv/dt = (v1 − v + k v_qs)/τ2 gives A(v, v) = −1/τ2, A(v, v1) = 1/τ2;
  // dv1/dt = (−v1 + (1 − k) v_qs)/τ1 gives A(v1, v1) = −1/τ1. τ2 = (0.39 − 0.26 (r/R)²) τ1 with r/R the
  // node's distance from the axis over the tip's: exact at the tip (node 4: τ2 = 13 s); nodes 1–3 with
  // r/R from the straight blade, (HubRad + BlSpn)/(HubRad + 61.4999) (ED.dat HubRad 1.5 m; AeroDyn's
  // rLocal also holds precone and prebend: 2e-4 relative here).
  const Reference ref;
  const double span[4] = {0.0, 22.55, 43.05, 61.4999};
  for (int node = 0; node < 4; ++node) {
    const double ratio = (1.5 + span[node]) / (1.5 + span[3]);
    const double tau2 = dbemtTau2(100.0, ratio);
    OyeState<ADChunk> x{ADChunk(1.0, ADChunk::DerType::Unit(whirl::kChunk, 0)),
                        ADChunk(2.0, ADChunk::DerType::Unit(whirl::kChunk, 1))};
    const OyeState<ADChunk> d = oyeDerivative(x, ADChunk(3.0), 100.0, tau2);
    for (int comp = 0; comp < 2; ++comp) {
      const int v = 3 + 2 * node + comp, v1 = 11 + 2 * node + comp;
      const double tol = node == 3 ? 1e-9 : 2e-4;
      EXPECT_NEAR(d.v.derivatives()(1), ref.A(v, v), tol * std::abs(ref.A(v, v))) << v;
      EXPECT_NEAR(d.v.derivatives()(0), ref.A(v, v1), tol * std::abs(ref.A(v, v1))) << v;
      EXPECT_NEAR(d.v1.derivatives()(0), ref.A(v1, v1), 1e-12) << v1;
    }
  }
}

TEST(DynamicInflow, SteadyStateAndTimeConstants) {
  // Steady state: v = v_qs, dx/dt = 0. A step in v_qs: v(t) = v_qs (1 − (τ1 − kτ1)/(τ1 − τ2) e^{−t/τ1}
  // − (kτ1 − τ2)/(τ1 − τ2) e^{−t/τ2}) … checked here through the eigenvalues −1/τ1, −1/τ2 of the
  // state matrix and the instantaneous jump-free start (v̇(0) = k v_qs/τ2).
  const OyeState<double> x = oyeSteady(2.5);
  const OyeState<double> d = oyeDerivative(x, 2.5, 10.0, 3.0);
  EXPECT_DOUBLE_EQ(x.v, 2.5);
  EXPECT_NEAR(d.v1, 0, 1e-15);
  EXPECT_NEAR(d.v, 0, 1e-15);
  const OyeState<double> start = oyeDerivative(OyeState<double>{0.0, 0.0}, 1.0, 10.0, 3.0);
  EXPECT_DOUBLE_EQ(start.v, kOyeK / 3.0);
  EXPECT_DOUBLE_EQ(start.v1, (1 - kOyeK) / 10.0);
  EXPECT_DOUBLE_EQ(dbemtTau2(100.0, 1.0), 13.0);
  EXPECT_DOUBLE_EQ(dbemtTau2(100.0, 0.0), 39.0);
}

}  // namespace

namespace {

// Polynomial coefficients, lowest power first.
using Poly = std::vector<double>;
Poly times(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
Poly plus(Poly a, const Poly& b) {
  a.resize(std::max(a.size(), b.size()), 0.0);
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  return a;
}
// The roots of a polynomial (eigenvalues of its companion matrix).
Eigen::VectorXcd roots(const Poly& p) {
  const int n = static_cast<int>(p.size()) - 1;
  Eigen::MatrixXd comp = Eigen::MatrixXd::Zero(n, n);
  for (int i = 1; i < n; ++i) comp(i, i - 1) = 1.0;
  for (int i = 0; i < n; ++i) comp(i, n - 1) = -p[static_cast<std::size_t>(i)] / p.back();
  return Eigen::EigenSolver<Eigen::MatrixXd>(comp).eigenvalues();
}

// A plunging typical section (mass m and stiffness k per span, plunge h up, lift only, attached flow at 2°):
// its eigenvalues with the element's HGM states, assembled here from the element's linear model
// (uaElementLinear: δα34 = −ḣ/U, δU = δω = 0 to first order) [1/s], the quasi-steady ones first.
struct PlungeSection {
  double m, k, chord, u, rho = 1.225;
  Eigen::VectorXcd withStates(const UaSection& s) const {
    const UaInput<double> in{2 * kDeg, 2 * kDeg, u, 0.0};
    const UaElementLinear lin = uaElementLinear(s, hgmSteady(s, in), in);
    const double q = 0.5 * rho * u * u * chord;       // lift per span per unit Cl [N/m]
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);  // [h, ḣ, x1..x4]
    a(0, 1) = 1.0;
    a(1, 0) = -k / m;
    a(1, 1) = -q * lin.D(0, 0) / (u * m);
    a.block<1, 4>(1, 2) = q * lin.C.row(0) / m;
    a.block<4, 1>(2, 1) = -lin.B.col(0) / u;
    a.block<4, 4>(2, 2) = lin.A;
    return Eigen::EigenSolver<Eigen::MatrixXd>(a).eigenvalues();
  }
  // Theodorsen's circulatory lift on a plunging plate, L = −2π ρ U b C(k) ḣ (b = c/2; Theodorsen 1935),
  // with C in R. T. Jones's rational form in reduced Laplace variable p = s b/U (Jones 1940):
  // C(p) = 1 − A1 p/(p + b1) − A2 p/(p + b2). m s² + k + 2π ρ U b s C = 0 times (p + b1)(p + b2) is a
  // polynomial of degree 4 in p; its roots [1/s]. The apparent mass π ρ b² ḧ is left out, as the HGM
  // model (AeroDyn UA_Mod 4) leaves it out.
  Eigen::VectorXcd theodorsenJones(double A1, double b1, double A2, double b2) const {
    const double tu = chord / (2 * u), ca = kPi * rho * u * chord;
    const Poly p1{b1, 1.0}, p2{b2, 1.0}, p12 = times(p1, p2);
    const Poly structure{k, 0.0, m / (tu * tu)};
    const Poly lift = times(Poly{0.0, ca / tu}, plus(plus(p12, times(Poly{0.0, -A1}, p2)), times(Poly{0.0, -A2}, p1)));
    return roots(plus(times(structure, p12), lift)) / tu;
  }
};

TEST(UnsteadyAirfoilLinear, PlungingSectionMatchesTheodorsenWithJonesApproximation) {
  // A flap-like mode heavily damped by its lift (quasi-steady ζ = 0.8 at 0.6 Hz; c = 3 m, U = 60 m/s as at
  // the outer NREL 5MW blade at rated). With Jones's constants (A1 = 0.165, b1 = 0.0455, A2 = 0.335,
  // b2 = 0.3) the HGM element reproduces Theodorsen's plunge with Jones's C(k); with AeroDyn's (0.3, 0.14,
  // 0.7, 0.53) the same lift with that C. Four eigenvalues are the polynomial's roots, to round-off; the
  // other two are the lags of x3 and x4, which do not feed the attached lift: −1/(T_p Tu), −1/(T_f0 Tu).
  const ThinAirfoil af;
  PlungeSection sec{0, 0, 3.0, 60.0};
  const double w0 = 2 * kPi * 0.6, ca = kPi * sec.rho * sec.u * sec.chord, zeta = 0.8;
  sec.m = ca / (2 * zeta * w0);
  sec.k = sec.m * w0 * w0;
  const double tu = sec.chord / (2 * sec.u);
  struct Constants {
    double A1, b1, A2, b2;
  };
  for (const Constants& j : {Constants{0.165, 0.0455, 0.335, 0.3}, Constants{0.3, 0.14, 0.7, 0.53}}) {
    UaTable table = af.ua;
    table.c.A1 = j.A1;
    table.c.b1 = j.b1;
    table.c.A2 = j.A2;
    table.c.b2 = j.b2;
    const Eigen::VectorXcd ua = sec.withStates(UaSection{&af.polar, &table, sec.chord, true});
    Eigen::VectorXcd expected(6);
    expected << sec.theodorsenJones(j.A1, j.b1, j.A2, j.b2), -1.0 / (table.c.T_p * tu), -1.0 / (table.c.T_f0 * tu);
    std::vector<bool> used(6, false);
    for (int i = 0; i < 6; ++i) {
      int best = -1;
      for (int k = 0; k < 6; ++k)
        if (!used[static_cast<std::size_t>(k)] &&
            (best < 0 || std::abs(ua(k) - expected(i)) < std::abs(ua(best) - expected(i))))
          best = k;
      used[static_cast<std::size_t>(best)] = true;
      EXPECT_LT(std::abs(ua(best) - expected(i)), 1e-9 * std::abs(expected(i)))
          << "A1 = " << j.A1 << ": " << expected(i);
    }
    // The mechanism (docs/theory/unsteady-aero.md): the lagged lift of a heavily damped mode stiffens it.
    // Quasi-steady (C = 1) the pair is at 0.6 Hz with ζ = 0.8 (damped 0.36 Hz); with the lag its natural
    // frequency rises and its damping ratio falls: 0.770 Hz, ζ 0.671 with Jones's constants (Theodorsen's
    // theory itself), 1.016 Hz, ζ 0.627 with AeroDyn's, where all the lift is lagged (A1 + A2 = 1).
    const std::complex<double> pair = *std::max_element(ua.begin(), ua.end(), [](const auto& a, const auto& b) {
      return a.imag() < b.imag();
    });
    EXPECT_GT(std::abs(pair) / (2 * kPi), 0.6 * (j.A1 + j.A2 < 0.9 ? 1.25 : 1.6)) << pair;
    EXPECT_LT(-pair.real() / std::abs(pair), 0.7) << pair;
  }
}

TEST(UnsteadyAirfoilLinear, SlowInputsGiveTheQuasiSteadyDerivative) {
  // Reduced frequency → 0: the linear model's static gain D − C A⁻¹ B equals the derivative of the model's
  // own steady loads Cl(hgmSteady(α), α) (central differences, 1e-6 relative) everywhere, and in the
  // attached region the static polar's slope C_lalpha = 2π — the quasi-steady value whirl's frozen-wake
  // linearization uses. The direct term D (the instantaneous response) is not that slope: in attached flow
  // ∂Cl/∂α34 at fixed states is C_lalpha (1 − A1 − A2) = 0 (Jones's split: all lift is lagged).
  const ThinAirfoil af;
  const UaSection s = af.section(1.5);
  for (double deg : {3.3, 12.4, 15.7, 30.2}) {
    const UaInput<double> in{deg * kDeg, deg * kDeg, 45.0, 0.0};
    const UaElementLinear lin = uaElementLinear(s, hgmSteady(s, in), in);
    const auto gain = lin.staticGain();
    const double h = 1e-6;
    auto steadyCl = [&](double a) {
      const UaInput<double> i{a, a, 45.0, 0.0};
      return hgmLoads(s, hgmSteady(s, i), i);
    };
    const auto p = steadyCl(deg * kDeg + h), m = steadyCl(deg * kDeg - h);
    EXPECT_NEAR(gain(0, 0), (p.cl - m.cl) / (2 * h), 1e-6 * std::max(1.0, std::abs(gain(0, 0)))) << deg;
    EXPECT_NEAR(gain(1, 0), (p.cd - m.cd) / (2 * h), 1e-6 * std::max(1.0, std::abs(gain(1, 0)))) << deg;
    EXPECT_NEAR(gain(2, 0), (p.cm - m.cm) / (2 * h), 1e-6 * std::max(1.0, std::abs(gain(2, 0)))) << deg;
    if (deg < 10) {
      EXPECT_NEAR(gain(0, 0), 2 * kPi, 1e-10);
      EXPECT_NEAR(lin.D(0, 0), 0.0, 1e-12);
    }
    // All four states decay (time constants c/(2U) times b_i⁻¹, T_p, T_f0).
    const Eigen::EigenSolver<Eigen::Matrix4d> es(lin.A);
    for (int k = 0; k < 4; ++k) EXPECT_LT(es.eigenvalues()(k).real(), 0.0);
  }
}

}  // namespace

namespace {

TEST(UnsteadyAirfoilOye, SeparationLagOnlyAndStaticSteadyState) {
  // UA_Mod 6 (AeroDyn's UA_OYE): x4 alone relaxes towards f_st(α34) with the time constant T_f0 c/(2U);
  // from the steady state at 12 deg, after a step to 16 deg, x4(t) = f16 + (f12 − f16) e^{−t/(T_f0 Tu)}
  // (one linear ODE: RK4 with h = 0.01 T_f0 Tu, global error ~1e-11 per 100 steps). The steady loads are the static
  // polar's at the knots; Cd and Cm are static at every state.
  const ThinAirfoil af;
  UaSection s = af.section(1.5);
  s.ua_mod = 6;
  const double u = 30.0, tu = 1.5 / 60.0, tf = af.ua.c.T_f0 * tu;
  for (double d : {-30.0, 0.0, 5.0, 12.0, 17.0, 60.0}) {
    const UaInput<double> in{d * kDeg, d * kDeg, u, 0.3};
    const HgmState<double> x = hgmSteady(s, in);
    EXPECT_NEAR(hgmDerivative(s, x, in).x4, 0.0, 1e-14);
    const auto l = hgmLoads(s, x, in);
    const auto st = evaluate(af.polar, d * kDeg);
    EXPECT_NEAR(l.cl, st.cl, 1e-12) << d;  // no π Tu ω term in UA_Mod 6
    EXPECT_NEAR(l.cd, st.cd, 1e-12) << d;
    EXPECT_NEAR(l.cm, st.cm, 1e-12) << d;
  }
  const UaInput<double> start{12 * kDeg, 12 * kDeg, u, 0.0}, step{16 * kDeg, 16 * kDeg, u, 0.0};
  HgmState<double> x = hgmSteady(s, start);
  const double f12 = x.x4, f16 = separationAt(af.ua, 16 * kDeg).f_st;
  ASSERT_GT(f12 - f16, 0.05);
  const double h = 0.01 * tf;
  for (int k = 1; k <= 300; ++k) {
    const auto k1 = hgmDerivative(s, x, step);
    const auto k2 = hgmDerivative(s, add(x, k1, h / 2), step);
    const auto k3 = hgmDerivative(s, add(x, k2, h / 2), step);
    const auto k4 = hgmDerivative(s, add(x, k3, h), step);
    EXPECT_EQ(k1.x1, 0.0);
    EXPECT_EQ(k1.x3, 0.0);
    x.x4 += h / 6 * (k1.x4 + 2 * k2.x4 + 2 * k3.x4 + k4.x4);
    if (k % 100 == 0) {
      EXPECT_NEAR(x.x4, f16 + (f12 - f16) * std::exp(-k * h / tf), 1e-10) << k;
    }
  }
  const UaElementLinear lin = uaElementLinear(s, x, step);
  EXPECT_NEAR(lin.A(3, 3), -1.0 / tf, 1e-9);
  EXPECT_EQ(lin.A.topRows<3>().norm(), 0.0);
}

}  // namespace
