// Aerodynamic loads in the equations: AD Jacobians against central differences (frozen wake and
// quasi-steady induction), the frozen-wake induction of a solved point, and the flap damping of
// blade elements in attached flow against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linearize/jacobian.hpp"
#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/aero_rotor_model.hpp"
#include "tests/support/residual_differences.hpp"

namespace whirl {
namespace {

using test::aeroRotorModel;
using test::AeroRotorOptions;

// A deflected, moving point near equilibrium: every coordinate and rate non-zero.
OperatingPoint perturbedPoint(const Model& m) {
  OperatingPoint op = initialPoint(m);
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[i].kind == DofKind::Elastic) {
      op.q(i) = 0.3 + 0.05 * i;
      op.qd(i) = 0.2 - 0.03 * i;
    }
  op.q(*m.findDof("azimuth")) = 0.4;
  return op;
}

using test::centralDifferences;

void expectJacobiansMatch(const Model& m, const OperatingPoint& op, const AeroInflow* frozen) {
  JacobianWorkspace jw(m);
  std::vector<int> all(m.ndof()), inputs(m.ninput());
  for (int i = 0; i < m.ndof(); ++i) all[i] = i;
  for (int i = 0; i < m.ninput(); ++i) inputs[i] = i;
  for (Wrt w : {Wrt::Q, Wrt::Qd, Wrt::U}) {
    const std::vector<int>& cols = w == Wrt::U ? inputs : all;
    const MatX ad = residualJacobian(m, jw, op.q, op.qd, op.qdd, op.u, w, cols, nullptr, frozen);
    const MatX fd = centralDifferences(m, op, w, cols, frozen);
    const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
    // Central differences with h = 1e-6 on loads of ~1e5: truncation and round-off ~1e-7 relative.
    Eigen::Index wr = 0, wc = 0;
    (ad - fd).cwiseAbs().maxCoeff(&wr, &wc);
    EXPECT_LT((ad - fd).cwiseAbs().maxCoeff(), 2e-6 * scale)
        << "wrt " << static_cast<int>(w) << ": row " << m.dofs[wr].name << ", column " << cols[wc] << ": AD "
        << ad(wr, wc) << ", central differences " << fd(wr, wc);
    EXPECT_GT(ad.cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(AeroLoads, FrozenWakeJacobiansEqualCentralDifferences) {
  const Model m = aeroRotorModel();
  const OperatingPoint op = perturbedPoint(m);
  // The induction of the point, then held fixed.
  Workspace<double> ws(m);
  VecX e(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
  const AeroInflow frozen = rec.inflow();
  ASSERT_EQ(frozen.axial.size(), 36);
  EXPECT_GT(frozen.axial.cwiseAbs().maxCoeff(), 0.5);  // real induction: ~a U
  expectJacobiansMatch(m, op, &frozen);
}

// AeroDyn's BlCrvAng tilts every element's annulus frame (aero_element.hxx): the frozen-wake blade
// jets (aero_blade_jet.hxx) and the quasi-steady evaluation differentiate the tilted frame as well.
TEST(AeroLoads, JacobiansOnCurvedSectionsEqualCentralDifferences) {
  AeroRotorOptions o;
  o.curve_deg = -9;
  const Model m = aeroRotorModel(o);
  const OperatingPoint op = perturbedPoint(m);
  Workspace<double> ws(m);
  VecX e(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
  const AeroInflow frozen = rec.inflow();
  expectJacobiansMatch(m, op, &frozen);
  expectJacobiansMatch(m, op, nullptr);
}

TEST(AeroLoads, QuasiSteadyJacobiansEqualCentralDifferences) {
  const Model m = aeroRotorModel();
  expectJacobiansMatch(m, perturbedPoint(m), nullptr);
}

// In a large yaw error the in-plane wind exceeds the rotation speed at the root at some azimuths, and
// BEM has no valid inflow angle there (AOC Test08, UAE VI Test09): those elements take the geometric
// angle without induction, as AeroDyn does, and the Jacobians stay those of the loads evaluated.
TEST(AeroLoads, ElementsWithoutABemRootTakeTheGeometricInflowWithConsistentJacobians) {
  Model m = aeroRotorModel(AeroRotorOptions{.rpm = 12, .wind = 8});
  m.aero.wind.direction = 60 * std::numbers::pi / 180;
  OperatingPoint op = perturbedPoint(m);
  Workspace<double> ws(m);
  VecX e(m.ndof());
  int invalid = 0;
  for (int k = 0; k < 36 && invalid == 0; ++k) {
    op.q(*m.findDof("azimuth")) = k * std::numbers::pi / 18;
    AeroRecord rec;
    residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
    for (const AeroElementState& el : rec.elements)
      if (!el.bem_valid) {
        ++invalid;
        EXPECT_EQ(el.a, 0.0);
        EXPECT_EQ(el.ap, 0.0);
        EXPECT_NEAR(el.phi, std::atan2(el.vx, el.vy), 1e-14);
      }
  }
  ASSERT_GT(invalid, 0) << "no element without a BEM root: the test does not reach the fallback";
  expectJacobiansMatch(m, op, nullptr);
}

TEST(AeroLoads, FrozenInductionReproducesTheSolvedPoint) {
  // At the point it was taken from, the frozen wake gives the same residual as the BEM solution.
  const Model m = aeroRotorModel();
  const OperatingPoint op = perturbedPoint(m);
  Workspace<double> ws(m);
  VecX e1(m.ndof()), e2(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e1, nullptr, &rec);
  const AeroInflow frozen = rec.inflow();
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e2, &frozen);
  EXPECT_LT((e1 - e2).cwiseAbs().maxCoeff(), 1e-9 * e1.cwiseAbs().maxCoeff());
}

TEST(AeroLoads, FlapDampingOfAttachedFlowEqualsClosedForm) {
  // Without induction, Cl = 2π α and Cd = 0: an element's normal force per span is
  //   Fx = ½ ρ c W² 2π (φ − θ) cos φ,  W² = Vx² + Vy², φ = atan2(Vx, Vy),
  // and a flap velocity ẇ (out of plane, downwind) lowers Vx by ẇ cos(slope). The damping of the
  // flap coordinate is Σ w_s φ_s² ∂Fx/∂Vx (Hansen 2004, quasi-steady aerodynamic damping), with
  //   ∂Fx/∂Vx = ½ ρ c 2π [2 Vx (φ − θ) cos φ + W² ∂φ/∂Vx (cos φ − (φ − θ) sin φ)],  ∂φ/∂Vx = Vy / W².
  AeroRotorOptions o;
  o.induction = false;
  o.cd = 0;
  o.precone_deg = 0;
  o.pitch_deg = 0;  // the flap shape (body y) then lies along the annulus x: no in-plane component
  const Model m = aeroRotorModel(o);
  OperatingPoint op = initialPoint(m);
  const LinearModel lin = linearize(m, op);
  const int flap = *m.findDof("blade 1 flap 1");
  int row = -1;
  for (size_t k = 0; k < lin.dofs.size(); ++k)
    if (lin.dofs[k] == flap) row = static_cast<int>(k);
  ASSERT_GE(row, 0);
  const double omega = o.rpm * std::numbers::pi / 30, rho = m.aero.air_density;
  double c = 0;
  const Body& blade = m.bodies[m.aero.blades[0].body];
  for (const AeroStation& st : m.aero.blades[0].stations) {
    const double r = st.z, vx = o.wind, vy = omega * r;
    const double phi = std::atan2(vx, vy), w2 = vx * vx + vy * vy;
    const double th = st.twist;
    const double dphi = vy / w2;
    const double dFx = 0.5 * rho * st.chord * 2 * std::numbers::pi *
                       (2 * vx * (phi - th) * std::cos(phi) + w2 * dphi * (std::cos(phi) - (phi - th) * std::sin(phi)));
    const double shape = blade.points[st.point].P(1, 1);  // flap shape value at the element (body y)
    c += st.weight * dFx * shape * shape;
  }
  // Exact up to the structural damping of the shapes (none here) and round-off.
  EXPECT_NEAR(lin.C(row, row), c, 1e-9 * c);
  EXPECT_GT(c, 1e3);
}

}  // namespace
}  // namespace whirl

namespace whirl {
namespace {

// The rotor outputs of the aeroelastic NREL 5MW deck: at the operating point the thrust and torque
// outputs equal the sums the equilibrium recorded (two paths: output evaluation vs residual record),
// and their derivatives with respect to the wind speed equal central differences with the wake
// frozen.
TEST(AeroLoads, RotorOutputsEqualTheRecordedSumsAndTheirDifferences) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst");
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const int fx = *m.findOutput("RtAeroFxh"), mx = *m.findOutput("RtAeroMxh");
  Workspace<double> ws(m);
  VecX y(m.noutput());
  evaluateOutputs(m, ws, op.q, op.qd, op.qdd, y, &op.u, &op.inflow);
  EXPECT_NEAR(y(fx), op.aero.thrust, 1e-9 * op.aero.thrust);
  EXPECT_NEAR(y(mx), op.aero.torque, 1e-9 * op.aero.torque);
  const int wind = m.roles.wind_speed_input;
  JacobianWorkspace jw(m);
  const MatX H = outputJacobian(m, jw, op.q, op.qd, op.qdd, op.u, Wrt::U, {wind}, &op.inflow);
  const double h = 1e-5;
  VecX up = op.u, um = op.u, yp(m.noutput()), ym(m.noutput());
  up(wind) += h;
  um(wind) -= h;
  evaluateOutputs(m, ws, op.q, op.qd, op.qdd, yp, &up, &op.inflow);
  evaluateOutputs(m, ws, op.q, op.qd, op.qdd, ym, &um, &op.inflow);
  for (int k : {fx, mx}) {
    const double fd = (yp(k) - ym(k)) / (2 * h);
    EXPECT_NEAR(H(k, 0), fd, 1e-6 * std::abs(fd)) << m.outputs[k].name;
  }
}

}  // namespace
}  // namespace whirl
