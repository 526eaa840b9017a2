// The unsteady-airfoil states in a turbine's linear model (linearize/unsteady_aero.hpp, issue 47 step 3), on
// the one-blade NREL 5MW rotor of OpenFAST's r-test Fake5MW_AeroLin_B1_UA4_DBEMT3 (UA_Mod 4, elements 2-4 with
// states; tests/data/openfast-lin/ua4-dbemt3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

#include "linearize/linearize.hpp"
#include "linearize/linearize_workspace.hpp"
#include "linearize/mbc.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "linearize/unsteady_aero.hpp"
#include "modal/rotor_modes.hpp"
#include "src/aero/polar.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace {

using namespace whirl;
constexpr double kDeg = std::numbers::pi / 180.0;

std::string uaDeck() {
  return (std::filesystem::path(WHIRL_SOURCE_DIR) /
          "tests/data/openfast-lin/ua4-dbemt3/case/Fake5MW_AeroLin_B1_UA4_DBEMT3.fst")
      .string();
}

// [e_UA; ż] (or e_QS without states) in double at (q, q̇, u, z).
struct Evaluation {
  VecX e, zdot;
};
Evaluation evaluate(const Model& m, const OperatingPoint& op, const VecX& q, const VecX& qd, const VecX& u,
                    const VecX* z) {
  Workspace<double> ws(m);
  forwardKinematics(m, ws, q, qd, op.qdd);
  Evaluation out{VecX::Zero(m.ndof()), VecX::Zero(aeroStateCount(m.aero))};
  addUnsteadyAeroLoads<double>(m, ws, q, qd, u, op.inflow, z, out.e, z ? &out.zdot : nullptr);
  return out;
}

OperatingPoint rTestPoint(const Model& m) { return solveOperatingPoint(m, initialPoint(m)); }

// The quasi-steady linearization of a deck with UA data (the states are in by default: issue 47 item 6).
LinearizeOptions quasiSteady() {
  LinearizeOptions o;
  o.unsteady_aero = false;
  return o;
}

TEST(UnsteadyAeroLinear, StatesOnTheElementsAeroDynGivesThem) {
  // OpenFAST's .lin of the deck lists UA states x1-x4 at nodes 2, 3, 4 of blade 1 (node 1: Cylinder1.dat).
  const Model m = readElastoDynModel(uaDeck());
  EXPECT_EQ(m.aero.ua_mod, 4);
  ASSERT_EQ(uaStateCount(m.aero), 12);
  std::vector<std::string> names, groups;
  uaStateNames(m.aero, names, groups);
  EXPECT_EQ(names.front(), "UA x1 blade 1 element 2");
  EXPECT_EQ(names.back(), "UA x4 blade 1 element 4");
  EXPECT_EQ(groups.back(), "UA x4 blade 1");
}

// Every block of unsteadyAeroLinear at op against central differences of the loads and state rates,
// within `tol` relative.
void expectAdEqualsCentralDifferences(const Model& m, const OperatingPoint& op, double tol = 1e-6) {
  const std::vector<int> cols = m.activeDofs();
  const UnsteadyAeroLinear ua = unsteadyAeroLinear(m, op, cols, true);
  const int nz = static_cast<int>(ua.z.size());
  // The steady states are the equilibrium of ż.
  EXPECT_LT(evaluate(m, op, op.q, op.qd, op.u, &ua.z).zdot.cwiseAbs().maxCoeff(), 1e-10);
  // Central differences with steps h: truncation ~h² f''' ≲ 1e-7 relative; round-off ~1e-16/h.
  auto check = [&](const char* what, const MatX& ad, const std::function<VecX(double)>& f, double h, int col) {
    const VecX fd = (f(h) - f(-h)) / (2 * h);
    const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
    EXPECT_LT((ad.col(col) - fd).cwiseAbs().maxCoeff(), tol * scale) << what << " column " << col;
  };
  // x4 (the separation point) is clamped to [0, 1] where the loads and rates use it, as in AeroDyn; in
  // attached flow its steady value is f_st = 1 exactly, on the clamp, where AD takes the branch inside
  // (src/aero/unsteady_airfoil.hxx clampT) and central differences would average it with the clamped
  // side's zero: there second-order backward differences, (3 f(0) − 4 f(−h) + f(−2h)) / 2h.
  auto checkInside = [&](const char* what, const MatX& ad, const std::function<VecX(double)>& f, double h, int col) {
    const VecX fd = (3 * f(0) - 4 * f(-h) + f(-2 * h)) / (2 * h);
    const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
    EXPECT_LT((ad.col(col) - fd).cwiseAbs().maxCoeff(), tol * scale) << what << " column " << col << " (x4 = 1)";
  };
  const int per = uaStatesPerElement(m.aero), nua = uaStateCount(m.aero);
  for (int c = 0; c < static_cast<int>(cols.size()); ++c) {
    auto dq = [&](double h, bool rate, bool states) {
      VecX q = op.q, qd = op.qd;
      (rate ? qd : q)(cols[c]) += h;
      return states ? evaluate(m, op, q, qd, op.u, &ua.z) : evaluate(m, op, q, qd, op.u, nullptr);
    };
    // 1.6e-4: ΔK is the difference of two blade loads of ~1e6 N, whose round-off dominates the steps below
    // (on the BeamDyn blades, ΔK's second column: 2.0e-7 relative at 1.6e-4, 4.0e-7 at 8e-5, 2.0e-6 at 4e-5,
    // 9.0e-7 at 2e-5, 1.4e-5 at 2.5e-6 — not falling with h², so not truncation; measured).
    const double hq = 1.6e-4 * std::max(1.0, std::abs(op.q(cols[c])));
    check(
        "dK", -ua.dK, [&](double h) { return VecX(dq(h, false, true).e - dq(h, false, false).e); }, hq, c);
    check(
        "dC", -ua.dC, [&](double h) { return VecX(dq(h, true, true).e - dq(h, true, false).e); }, 1e-5, c);
    check(
        "Zq", ua.Zq, [&](double h) { return dq(h, false, true).zdot; }, hq, c);
    check(
        "Zqd", ua.Zqd, [&](double h) { return dq(h, true, true).zdot; }, 1e-5, c);
  }
  for (int k = 0; k < nz; ++k) {
    auto dz = [&](double h) {
      VecX z = ua.z;
      z(k) += h;
      return evaluate(m, op, op.q, op.qd, op.u, &z);
    };
    const bool on_clamp = k < nua && k % per == per - 1 && ua.z(k) == 1.0;
    const auto g = [&](double h) { return VecX(dz(h).e); };
    const auto a = [&](double h) { return VecX(dz(h).zdot); };
    if (on_clamp) {
      checkInside("G", ua.G, g, 1e-6, k);
      checkInside("Azz", ua.Azz, a, 1e-6, k);
    } else {
      check("G", ua.G, g, 1e-6, k);
      check("Azz", ua.Azz, a, 1e-6, k);
    }
  }
  const int wind = m.roles.wind_speed_input;
  auto du = [&](double h) {
    VecX u = op.u;
    u(wind) += h;
    return std::pair{evaluate(m, op, op.q, op.qd, u, &ua.z), evaluate(m, op, op.q, op.qd, u, nullptr)};
  };
  check(
      "dQ", ua.dQ,
      [&](double h) {
        auto [a, b] = du(h);
        return VecX(a.e - b.e);
      },
      1e-4, wind);
  check(
      "Zu", ua.Zu, [&](double h) { return du(h).first.zdot; }, 1e-4, wind);
}

// The r-test deck's UA states and its dynamic-inflow states (DBEMT_Mod 3, every element): the rows of v̇
// carry the quasi-steady BEM induction's derivatives (implicit-function theorem), the central differences
// re-solve BEM at each perturbed inflow.
TEST(UnsteadyAeroLinear, AdJacobianEqualsCentralDifferences) {
  const Model m = readElastoDynModel(uaDeck());
  ASSERT_EQ(inflowStateCount(m.aero), 16);
  expectAdEqualsCentralDifferences(m, rTestPoint(m));
}

// BeamDyn (finite-element) blades: the elastic twist turns the section and its rate is the pitch rate ω
// the HGM model receives; the NREL 5MW BeamDyn deck (cases/nrel5mw_beamdyn/Main_Aero_BD.fst, a coarse
// blade: 20 elements, 6 modes) with UA_Mod 4, at its initial condition (12.1 rpm, 11.4 m/s).
TEST(UnsteadyAeroLinear, AdJacobianEqualsCentralDifferencesOnBeamDynBlades) {
  const Model m =
      readElastoDynModel((std::filesystem::path(WHIRL_SOURCE_DIR) / "cases/nrel5mw_beamdyn/Main_Aero_BD.fst").string(),
                         {"blade_elements=20", "blade_modes=6", "AFAeroMod=2", "UAMod=4"});
  ASSERT_EQ(m.aero.ua_mod, 4);
  ASSERT_GT(uaStateCount(m.aero), 0);
  // 2e-6 as the FE blades' quasi-steady loads against central differences (tests/unit/test_fe_blade_aero.cpp):
  // measured 2.0e-7 relative on ΔK's second column (steps 1.6e-4; with 4e-5 it read 1.2e-6 before the
  // skewed-wake correction moved the operating point and 2.0e-6 after: round-off of the difference of two
  // ~1e6 N blade loads), every other block within 1e-6.
  expectAdEqualsCentralDifferences(m, rTestPoint(m), 2e-6);
}

TEST(UnsteadyAeroLinear, LinearModelCarriesTheStatesAfterTheStructure) {
  const Model m = readElastoDynModel(uaDeck());
  const OperatingPoint op = rTestPoint(m);
  const LinearModel qs = linearize(m, op, quasiSteady()), ua = linearize(m, op);
  const int n = static_cast<int>(qs.dofs.size());
  // 12 UA states (elements 2-4), then 16 dynamic-inflow states (4 elements, DBEMT_Mod 3).
  ASSERT_EQ(ua.A.rows(), 2 * n + 28);
  ASSERT_EQ(ua.B.rows(), 2 * n + 28);
  ASSERT_EQ(ua.first_order_names.size(), 28u);
  EXPECT_EQ(ua.first_order_names[4], "UA x1 blade 1 element 3");
  EXPECT_EQ(ua.first_order_names[12], "DBEMT v axial blade 1 element 1");
  EXPECT_EQ(ua.first_order_names[27], "DBEMT v1 tangential blade 1 element 4");
  EXPECT_EQ(ua.first_order_groups[27], "DBEMT v1 tangential blade 1");
  const UnsteadyAeroLinear blocks = unsteadyAeroLinear(m, op, qs.dofs, true);
  EXPECT_EQ(ua.first_order_values, blocks.z);
  for (int r = 0; r < n; ++r) {
    EXPECT_NEAR(ua.K(r, r), qs.K(r, r) + blocks.dK(qs.dofs[r], r), 1e-9 * std::abs(qs.K(r, r)));
    EXPECT_NEAR(ua.C(r, r), qs.C(r, r) + blocks.dC(qs.dofs[r], r), 1e-9 * std::abs(qs.C(r, r)));
  }
  // The states' own rows: [Z_q, Z_q̇, A_zz] and Z_u.
  EXPECT_EQ(MatX(ua.A.bottomRightCorner(28, 28)), blocks.Azz);
  EXPECT_EQ(MatX(ua.A.block(2 * n, 0, 28, n)), MatX(blocks.Zq));
  EXPECT_EQ(MatX(ua.B.bottomRows(28)), blocks.Zu);
  // A model without its UA data and dynamic inflow (removeUnsteadyAirfoils, removeDynamicInflow:
  // --quasi-steady-aero) linearizes by default to the quasi-steady model, bit for bit.
  Model without = m;
  removeUnsteadyAirfoils(without.aero);
  removeDynamicInflow(without.aero);
  EXPECT_EQ(aeroStateCount(without.aero), 0);
  const LinearModel again = linearize(without, op);
  EXPECT_EQ(again.A, qs.A);
  EXPECT_EQ(again.B, qs.B);
}

// A sweep's workspace carries nothing from one point to the next into the states' blocks (its BEM roots, frames
// and bases are keyed on the values they were formed at): after a linearization at another point (another wind
// speed and pitch), the same A, B as with fresh buffers.
TEST(UnsteadyAeroLinear, SweepWorkspaceGivesWhatFreshBuffersGive) {
  const Model m = readElastoDynModel(uaDeck());
  const OperatingPoint op = rTestPoint(m);
  OperatingCondition other;
  other.rotor_speed = 9.0 * std::numbers::pi / 30;
  other.wind_speed = 8.0;
  other.collective_pitch = 2 * kDeg;
  const OperatingPoint before = solveOperatingPoint(m, initialPoint(m, other));
  LinearizeWorkspace lw(m);
  const LinearModel first = linearize(m, before, lw);
  const LinearModel reused = linearize(m, op, lw), fresh = linearize(m, op);
  ASSERT_EQ(reused.A.rows(), fresh.A.rows());
  ASSERT_GT(reused.A.rows(), 2 * static_cast<Eigen::Index>(reused.dofs.size()));  // the states are in
  EXPECT_LT((reused.A - fresh.A).cwiseAbs().maxCoeff(), 1e-12 * fresh.A.cwiseAbs().maxCoeff());
  EXPECT_LT((reused.B - fresh.B).cwiseAbs().maxCoeff(), 1e-12 * fresh.B.cwiseAbs().maxCoeff());
  EXPECT_GT((first.A - fresh.A).cwiseAbs().maxCoeff(), 1e-6 * fresh.A.cwiseAbs().maxCoeff());  // another point
}

TEST(UnsteadyAeroLinear, FlapRateIsNoPitchRateOfTheSection) {
  // Issue 47: the NREL 5MW's flap modes move far with UA (docs/theory/unsteady-aero.md). Not from the
  // inputs: the pitch rate ω the HGM model receives is the section's rotation about its own span axis, so a
  // flap rate (a rotation about an axis across the span) must leave it unchanged, while it changes the
  // angle of attack by about −ḣ/U. Central differences of the UA inputs at the rated point (12 m/s,
  // 12.1 rpm, ElastoDyn's initial conditions) in each blade's flap rates, at every element with states.
  const Model m = readElastoDynModel((std::filesystem::path(WHIRL_SOURCE_DIR) / "cases/nrel5mw/Main_Aero.fst").string(),
                                     {"AFAeroMod=2", "UAMod=4"});
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const VecX z = unsteadyAeroSteadyStates(m, op);
  auto inputs = [&](const VecX& qd) {
    Workspace<double> ws(m);
    forwardKinematics(m, ws, op.q, qd, op.qdd);
    VecX e = VecX::Zero(m.ndof());
    std::vector<aero::UaInput<double>> in;
    addUnsteadyAeroLoads<double>(m, ws, op.q, qd, op.u, op.inflow, &z, e, nullptr, &in);
    return in;
  };
  int flap_dofs = 0;
  for (int d : m.activeDofs()) {
    if (m.dofs[d].name.find("flap") == std::string::npos) continue;
    ++flap_dofs;
    const double h = 1e-3;  // [m/s]; ω and α are smooth in q̇: truncation ~h², far below the tolerances
    VecX qp = op.qd, qm = op.qd;
    qp(d) += h;
    qm(d) -= h;
    const auto ip = inputs(qp), im = inputs(qm);
    ASSERT_EQ(ip.size(), static_cast<std::size_t>(uaStateCount(m.aero) / 4));
    double worst = 0, alpha_rate = 0;
    for (std::size_t k = 0; k < ip.size(); ++k) {
      const double dalpha = (ip[k].alpha_ac - im[k].alpha_ac) / (2 * h), domega = (ip[k].omega - im[k].omega) / (2 * h);
      // The pitch rate's share of α34 (ω c/(2U), c ≤ 4.7 m) against the flap rate's own change of α.
      worst = std::max(worst, std::abs(domega) * 4.7 / (2 * ip[k].u));
      alpha_rate = std::max(alpha_rate, std::abs(dalpha));
    }
    EXPECT_GT(alpha_rate, 1e-3) << m.dofs[d].name;  // the flap rate does move α (of order φ/U)
    // Measured: 1.2e-3 (flap 1), 7e-4 (flap 2) of the largest change of α; what is left is the section's
    // rotation about its deformed span axis at the point (slopes of order 1 %), as AeroDyn's node
    // orientation gives it. Were ω the flap slope's rate, the share would be of order c/r ≈ 0.08.
    EXPECT_LT(worst, 5e-3 * alpha_rate) << m.dofs[d].name;
  }
  EXPECT_EQ(flap_dofs, 6);  // two flap modes on each of three blades
}

TEST(UnsteadyAeroLinear, SlowLimitIsTheQuasiSteadyFrozenWake) {
  // Eliminating the states of a slow motion (ż ≈ 0: z = −A_zz⁻¹(Z_q δq + Z_q̇ δq̇)) leaves
  // K + ΔK + G A_zz⁻¹ Z_q and C + ΔC + G A_zz⁻¹ Z_q̇, which are K and C of the quasi-steady frozen wake where
  // the HGM model's static gain is the polar's slope: attached flow on a straight-line lift (the thin-airfoil
  // table of test_unsteady_airfoil.cpp within ±10°, f_st = 1) and no pitch-rate terms (a parked rotor: ω = 0
  // and ∂ω/∂q = 0; flap shapes do not twist the section). The rotor is parked and pitched to 85° so that
  // every element's α lies within −8°..5°. The deck's dynamic inflow is taken out: its states, eliminated,
  // re-solve the induction (test_dynamic_inflow_linear.cpp), which the frozen wake does not.
  Model m = readElastoDynModel(uaDeck());
  removeDynamicInflow(m.aero);
  std::vector<double> a, cl, cd, cm;
  for (int d = -180; d <= 180; ++d) {
    const double x = d * kDeg;
    a.push_back(x);
    double l;
    if (std::abs(d) <= 10) l = 2 * std::numbers::pi * x;
    else if (std::abs(d) <= 20) l = std::copysign(2 * std::numbers::pi * 10 * kDeg - 0.06 * (std::abs(d) - 10), x);
    else l = std::sin(2 * x);
    cl.push_back(l);
    cd.push_back(0.01 + 1.2 * std::sin(x) * std::sin(x));
    cm.push_back(-0.05 * std::sin(x));
  }
  aero::UaGiven g;
  g.alpha0 = 0.0;
  g.c_lalpha = 2 * std::numbers::pi;
  g.c_nalpha = 2 * std::numbers::pi;
  m.aero.polars.push_back(aero::makePolar("thin", a, cl, cd, cm, aero::PolarInterp::Linear, "thin"));
  m.aero.ua_tables.push_back(aero::uaTable(g, a, cl, cd, cm, aero::PolarInterp::Linear, 4, "thin"));
  m.aero.ua_has_cm.push_back(true);
  for (AeroStation& st : m.aero.blades[0].stations)
    if (st.ua) st.polar = static_cast<int>(m.aero.polars.size()) - 1;
  OperatingCondition parked;
  parked.rotor_speed = 0;
  parked.collective_pitch = 85 * kDeg;
  parked.wind_speed = 13;
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m, parked));
  const std::vector<int> cols = m.activeDofs();
  const UnsteadyAeroLinear ua = unsteadyAeroLinear(m, op, cols, false);
  const MatX Ginv = ua.G * ua.Azz.inverse();
  const MatX dK = ua.dK + Ginv * ua.Zq, dC = ua.dC + Ginv * ua.Zqd;
  const LinearModel qs = linearize(m, op, quasiSteady());
  for (int c = 0; c < static_cast<int>(cols.size()); ++c) {
    const int r = cols[c];
    // No stiffness from the states here (the flap does not turn the section's flow at a parked rotor):
    // round-off of the structure's K.
    EXPECT_LT(std::abs(dK(r, c)), 1e-12 * std::abs(qs.K(c, c)));
    // The states carry the flap's aerodynamic damping, and eliminated they give the quasi-steady one back:
    // to 1e-4 because ω is not quite 0 here: the elastic rotation rates about the chord axes, projected on
    // the deflected span axis, give ∂ω/∂q̇ ≈ 4e-7…1.2e-6 (rad/s)/(m/s) at the three elements (measured from
    // the recorded UA inputs), and with the pitch-rate gain ∂Cl/∂ω ≈ 0.15…0.49 s against ∂Cl/∂α ∂α/∂q̇ ≈
    // 3.9e-3 s/m that is a relative 5e-5 at most.
    const double aero = std::abs((Ginv * ua.Zqd)(r, c));
    ASSERT_GT(aero, 1e-2 * std::abs(qs.C(c, c)));
    EXPECT_LT(std::abs(dC(r, c)), 1e-4 * aero);
  }
}

// The NREL 5MW (cases/nrel5mw/Main_Aero.fst) with its airfoil files' UA data and UA_Mod 4 (AFAeroMod 2):
// HGM states on every element that AeroDyn gives them (UAStartRad 0.15; the cylinders have none).
// Made isotropic and symmetric: no gravity, no shaft tilt, no wind shear (no tower shadow, no yaw, as the
// deck has) and a tower without fore-aft bending (the thrust would tilt the rotor into a skewed flow), so
// that each blade sees the same flow at every azimuth.
Model isotropicUaRotor() {
  Model m = readElastoDynModel((std::filesystem::path(WHIRL_SOURCE_DIR) / "cases/nrel5mw/Main_Aero.fst").string(),
                               {"AFAeroMod=2", "UAMod=4", "ShftTilt=0", "TwFADOF1=False", "TwFADOF2=False"});
  m.gravity = Vec3::Zero();
  m.aero.wind.shear_exponent = 0;
  return m;
}

// Largest change of any entry of A between the samples, per row relative to the row's largest entry of
// the first sample.
double azimuthVariation(const std::vector<MbcSample>& s) {
  double worst = 0;
  for (std::size_t k = 1; k < s.size(); ++k)
    for (Eigen::Index r = 0; r < s[0].A.rows(); ++r) {
      const double scale = s[0].A.row(r).cwiseAbs().maxCoeff();
      if (scale > 0) worst = std::max(worst, (s[k].A.row(r) - s[0].A.row(r)).cwiseAbs().maxCoeff() / scale);
    }
  return worst;
}

TEST(UnsteadyAeroLinear, RotatingStatesGoThroughTheMultibladeTransform) {
  // For an isotropic rotor in uniform, untilted flow without gravity the multiblade equations are time
  // invariant (Bir 2008, NREL/CP-500-42553, sec. 3): the transformed A is the same at every azimuth, the
  // rotating unsteady-airfoil states included, once they are transformed with their blade like the blade
  // coordinates. Left in the fixed frame, their coupling with the transformed blade coordinates turns
  // with the rotor (1P), and the same check fails. 12.1 rpm, 11.4 m/s, pitch 0 (rated).
  const Model m = isotropicUaRotor();
  ASSERT_EQ(m.aero.ua_mod, 4);
  const int nz = uaStateCount(m.aero);
  ASSERT_GT(nz, 0);
  ASSERT_EQ(nz % 12, 0);  // 4 states per element, the same elements on the three blades
  OperatingCondition c;
  c.rotor_speed = 12.1 * std::numbers::pi / 30;
  c.wind_speed = 11.4;
  c.collective_pitch = 0;
  PeriodicOptions po;
  po.azimuths = 4;  // 0°, 90°, 180°, 270°: not a multiple of the blade spacing
  po.linearize.inputs = false;
  const PeriodicLinearization p = linearizePeriodic(m, c, po);
  const LinearModel& first = p.models.front();
  const int n = static_cast<int>(first.dofs.size());
  ASSERT_EQ(first.A.rows(), 2 * n + nz);
  ASSERT_EQ(first.first_order_blades.size(), static_cast<std::size_t>(nz));
  EXPECT_EQ(first.first_order_blades.front(), 0);
  EXPECT_EQ(first.first_order_blades.back(), 2);
  std::vector<int> dof_blade;
  for (int i : first.dofs) dof_blade.push_back(m.dofs[i].blade);
  std::vector<MbcSample> samples;
  for (std::size_t k = 0; k < p.models.size(); ++k) {
    MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    samples.push_back(std::move(s));
  }
  const MbcResult right = mbcAverage(secondOrderLayout(3, dof_blade, first.first_order_blades), samples);
  // Measured: 2.5e-14 (round-off); with the states left in the fixed frame 0.94.
  EXPECT_LT(azimuthVariation(right.samples), 1e-10);
  const MbcResult wrong = mbcAverage(secondOrderLayout(3, dof_blade, std::vector<int>(nz, -1)), samples);
  EXPECT_GT(azimuthVariation(wrong.samples), 1e-2);

  // The rotor modes take the same transform: multiblade UA coordinates, named without the blade.
  const RotorModes r = rotorModes(m, p);
  EXPECT_EQ(r.num_blades, 3);
  ASSERT_EQ(r.A.rows(), 2 * n + nz);
  EXPECT_LT((r.A - right.A).cwiseAbs().maxCoeff(), 1e-12 * right.A.cwiseAbs().maxCoeff());
  for (const char* name : {"UA x1 element 10 collective", "UA x4 element 10 cos", "UA x4 element 10 sin"})
    EXPECT_NE(std::find(r.coordinates.begin(), r.coordinates.end(), name), r.coordinates.end()) << name;
}

TEST(UnsteadyAeroLinear, DynamicInflowStatesGoThroughTheMultibladeTransform) {
  // The same check with the dynamic-inflow states (DBEMT_Mod 3: 4 per element, all 19 elements of each
  // blade, 228 states) beside the UA states: rotating-frame states of their blade, time invariant once
  // transformed with it, turning with the rotor when left in the fixed frame.
  Model m = readElastoDynModel((std::filesystem::path(WHIRL_SOURCE_DIR) / "cases/nrel5mw/Main_Aero.fst").string(),
                               {"AFAeroMod=2", "UAMod=4", "WakeMod=2", "DBEMT_Mod=3", "ShftTilt=0", "TwFADOF1=False",
                                "TwFADOF2=False"});
  m.gravity = Vec3::Zero();
  m.aero.wind.shear_exponent = 0;
  ASSERT_EQ(inflowStateCount(m.aero), 228);
  const int nz = aeroStateCount(m.aero);
  OperatingCondition c;
  c.rotor_speed = 12.1 * std::numbers::pi / 30;
  c.wind_speed = 11.4;
  c.collective_pitch = 0;
  PeriodicOptions po;
  po.azimuths = 4;
  po.linearize.inputs = false;
  const PeriodicLinearization p = linearizePeriodic(m, c, po);
  const LinearModel& first = p.models.front();
  ASSERT_EQ(first.first_order_blades.size(), static_cast<std::size_t>(nz));
  EXPECT_EQ(first.first_order_blades.back(), 2);
  std::vector<int> dof_blade;
  for (int i : first.dofs) dof_blade.push_back(m.dofs[i].blade);
  std::vector<MbcSample> samples;
  for (std::size_t k = 0; k < p.models.size(); ++k) {
    MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    samples.push_back(std::move(s));
  }
  // Measured: 1.6e-14; in the fixed frame 38 (the inflow states' rows turn with the rotor).
  EXPECT_LT(azimuthVariation(mbcAverage(secondOrderLayout(3, dof_blade, first.first_order_blades), samples).samples),
            1e-10);
  EXPECT_GT(azimuthVariation(mbcAverage(secondOrderLayout(3, dof_blade, std::vector<int>(nz, -1)), samples).samples),
            1e-2);
  const RotorModes r = rotorModes(m, p);
  for (const char* name : {"DBEMT v axial element 10 collective", "DBEMT v1 tangential element 19 sin"})
    EXPECT_NE(std::find(r.coordinates.begin(), r.coordinates.end(), name), r.coordinates.end()) << name;
}

}  // namespace
