// Aerodynamics on BeamDyn (finite-element) blades, issue 46 item 3: the NREL 5MW deck with BeamDyn
// blades and AeroDyn (cases/nrel5mw_beamdyn/Main_Aero_BD.fst). The elastic twist enters the angle of
// attack, the airfoils' Cm loads the torsion modes, and AeroDyn's aerodynamic centres (BlCrvAC,
// BlSwpAC) sit off BeamDyn's reference axis on arms that turn with the section.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "linearize/jacobian.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "modal/floquet.hpp"
#include "modal/rotor_modes.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/residual_differences.hpp"

namespace whirl {
namespace {

// A coarse FE blade keeps the test fast: 20 elements, 6 modes (flap 1–2, edge 1–2, torsion 1, …).
Model deck(std::vector<std::string> extra = {}) {
  std::vector<std::string> o = {"blade_elements=20", "blade_modes=6"};
  o.insert(o.end(), extra.begin(), extra.end());
  return readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw_beamdyn/Main_Aero_BD.fst", o);
}

// Deflected and moving blades at rated speed: every elastic coordinate and rate non-zero (modes are
// scaled to a largest deflection of 1 m or twist of 1 rad, so these are centimetres and milliradians).
OperatingPoint deflected(const Model& m) {
  OperatingPoint op = initialPoint(m);
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].kind == DofKind::Elastic) {
      op.q(i) = 0.01 + 0.002 * (i % 7);
      op.qd(i) = 0.02 - 0.003 * (i % 5);
    }
  for (int a : m.roles.azimuth) op.q(a) += 0.4;  // off the blade-up azimuth
  return op;
}

using test::centralDifferences;

// The columns of the blade's elastic coordinates and the rows of every coordinate: AD against central
// differences (h = 1e-6 on loads up to ~1e6 N: truncation and round-off ~1e-7 relative; 2e-6 as in
// test_aero_loads.cpp).
void expectJacobiansMatch(const Model& m, const OperatingPoint& op, const AeroInflow* frozen) {
  JacobianWorkspace jw(m);
  std::vector<int> cols;
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].kind == DofKind::Elastic && m.dofs[i].blade == 0) cols.push_back(i);
  ASSERT_EQ(cols.size(), 6u);
  for (Wrt w : {Wrt::Q, Wrt::Qd}) {
    const MatX ad = residualJacobian(m, jw, op.q, op.qd, op.qdd, op.u, w, cols, nullptr, frozen);
    const MatX fd = centralDifferences(m, op, w, cols, frozen);
    const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
    Eigen::Index wr = 0, wc = 0;
    (ad - fd).cwiseAbs().maxCoeff(&wr, &wc);
    EXPECT_LT((ad - fd).cwiseAbs().maxCoeff(), 2e-6 * scale)
        << "wrt " << static_cast<int>(w) << ": row " << m.dofs[wr].name << ", column " << m.dofs[cols[wc]].name
        << ": AD " << ad(wr, wc) << ", central differences " << fd(wr, wc);
  }
}

TEST(FeBladeAero, JacobiansEqualCentralDifferencesFrozenWakeAndQuasiSteady) {
  const Model m = deck();
  const OperatingPoint op = deflected(m);
  Workspace<double> ws(m);
  VecX e(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
  const AeroInflow frozen = rec.inflow();
  expectJacobiansMatch(m, op, &frozen);  // the blade-jet path (frozen wake)
  expectJacobiansMatch(m, op, nullptr);  // the element path, induction solved
}

// The aerodynamic centre turns with the section: a twist of the torsion mode moves the element points
// that sit off the reference axis, the rigid-arm columns θ_k × d of the shapes.
TEST(FeBladeAero, AerodynamicCentresTurnWithTheSection) {
  const Model m = deck();
  const int dof = *m.findDof("blade 1 torsion 1");
  const Body& body = m.bodies[m.dofs[dof].body];
  const int k = m.dofs[dof].local;
  const AeroStation& st = m.aero.blades[0].stations[10];
  const BodyPoint& pt = body.points[st.point];
  // Test26's AeroDyn blade: BlCrvAC = −0.0248 m, BlSwpAC = −0.1050 m at BlSpn = 4.1 m (node 3), off
  // BeamDyn's straight axis (kp_xr = kp_yr = 0); node 11 lies further out with its own offsets.
  const Vec3 d(0, pt.P(1, 0), pt.P(2, 0));
  ASSERT_GT(d.norm(), 1e-3);
  const Vec3 arm = Vec3(pt.theta.col(k)).cross(d);
  EXPECT_GT(std::abs(pt.theta(0, k)), 0.05);  // the torsion mode twists the section there
  EXPECT_NEAR(pt.P(1, 1 + k), arm(1), 1e-12 + 1e-9 * std::abs(arm(1)));
  EXPECT_NEAR(pt.P(2, 1 + k), arm(2), 1e-12 + 1e-9 * std::abs(arm(2)));
  EXPECT_GT(std::abs(arm(1)) + std::abs(arm(2)), 1e-3 * std::abs(pt.theta(0, k)));
}

// The pitching moment does work on the twist in the direction of its sign: the NREL 5MW airfoils'
// Cm is negative (nose down) at the angles of attack of the operating rotor, so the generalized force it
// adds to a torsion coordinate pushes that coordinate towards a lower angle of attack.
TEST(FeBladeAero, NoseDownPitchingMomentTwistsTheSectionTowardsLowerAngleOfAttack) {
  const Model with_cm = deck();
  Model without_cm = with_cm;
  for (aero::Polar& p : without_cm.aero.polars) {
    auto zero = [](aero::Polar& q) {
      std::fill(q.cm.begin(), q.cm.end(), 0.0);
      for (auto& c : q.ccm) c = {0, 0, 0, 0};
    };
    zero(p);
    for (aero::Polar& r : p.re_tables) zero(r);
  }
  const OperatingPoint op = initialPoint(with_cm);
  const int dof = *with_cm.findDof("blade 1 torsion 1");
  Workspace<double> ws(with_cm);
  VecX e1(with_cm.ndof()), e0(with_cm.ndof());
  AeroRecord rec, rec_up;
  residual(with_cm, ws, op.q, op.qd, op.qdd, op.u, e1, nullptr, &rec);
  residual(without_cm, ws, op.q, op.qd, op.qdd, op.u, e0, nullptr);
  const double force = e1(dof) - e0(dof);  // e = F − M q̈: the generalized force of the Cm loads
  // How the outer blade's angle of attack follows the torsion coordinate.
  OperatingPoint up = op;
  up.q(dof) += 1e-4;
  residual(with_cm, ws, up.q, up.qd, up.qdd, up.u, e1, nullptr, &rec_up);
  const std::size_t n = with_cm.aero.blades[0].stations.size();
  double dalpha = 0, cm = 0;
  for (std::size_t j = n / 2; j < n; ++j) {
    dalpha += rec_up.elements[j].alpha - rec.elements[j].alpha;
    cm += rec.elements[j].cm;
  }
  ASSERT_LT(cm, 0.0);                 // nose-down airfoils at these angles of attack
  ASSERT_GT(std::abs(dalpha), 1e-6);  // the elastic twist enters the angle of attack
  EXPECT_LT(force * dalpha, 0.0);
  EXPECT_GT(std::abs(force), 1.0);  // [N m per unit coordinate]: a real load, not round-off
}

// The multiblade average equals Floquet analysis for a symmetric rotor: Test26's structure with BeamDyn
// blades, no gravity and no shaft tilt (the only periodic terms of an isotropic rotor), at 12.1 rpm.
// Every Floquet mode is a multiblade mode: frequencies to 1e-6 relative and damping ratios to 1e-6
// (Magnus steps, 32 per sample; measured below 1e-8).
TEST(FeBladeRotor, MultibladeAverageEqualsFloquetForTheSymmetricRotor) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw_beamdyn/Test26.fst",
                                     {"CompAero=0", "CompInflow=0", "Gravity=0", "ShftTilt=0", "blade_elements=20",
                                      "blade_modes=4"});
  OperatingCondition c = modelCondition(m);
  c.rotor_speed = rpmToRadPerSec(12.1);
  PeriodicOptions po;
  po.azimuths = 12;
  const PeriodicLinearization p = linearizePeriodic(m, c, po);
  const RotorModes mbc = rotorModes(m, p);
  const LinearModel& first = p.models.front();
  RotorCoordinates rc;
  rc.names = first.dof_names;
  for (int d : first.dofs) {
    rc.blade.push_back(m.dofs[d].blade);
    rc.azimuth.push_back(m.dofs[d].rotating);
    rc.held.push_back(false);
    rc.teeter.push_back(false);
  }
  rc.weights = first.M;
  std::vector<MbcSample> samples;
  for (std::size_t k = 0; k < p.models.size(); ++k) {
    MbcSample s;
    s.azimuth = p.azimuths[k];
    s.rotor_speed = p.rotor_speed;
    s.A = p.models[k].A;
    samples.push_back(s);
  }
  FloquetOptions fo;
  fo.steps_per_sample = 32;
  const RotorModes fl = floquetModes(rc, samples, fo);
  int compared = 0;
  for (const Mode& f : fl.modes) {
    if (f.rigid_body || f.freq_hz < 0.1) continue;
    double best = 1e300;
    const Mode* near = nullptr;
    for (const Mode& g : mbc.modes) {
      const double d = std::abs(g.damped_freq_hz - f.damped_freq_hz);
      if (d < best) best = d, near = &g;
    }
    ASSERT_NE(near, nullptr);
    EXPECT_LT(best, 1e-6 * f.damped_freq_hz) << f.name << " " << f.damped_freq_hz << " Hz";
    EXPECT_NEAR(near->damping_ratio, f.damping_ratio, 1e-6) << f.name;
    ++compared;
  }
  EXPECT_GT(compared, 15);
}

}  // namespace
}  // namespace whirl
