// The load outputs with the aerodynamic states (issues 46, 47): rotor thrust and torque and the subtree moments
// (RootMFlp, RootMEdg, TwrBsMyt, …) take the loads of the unsteady-airfoil and dynamic-inflow states
// (addUnsteadyAeroLoads), as the equations of motion do, and the state-space C and D carry their derivatives.
// Checked on the NREL 5MW (cases/nrel5mw/Main_Aero.fst with its airfoil files' UA data, UA_Mod 4; and with
// DBEMT_Mod 3 dynamic inflow, as scripts/main.sh runs it) through two independent paths: the pitch joint's
// generalized force of the unsteady residual, and central differences through the equations of motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/state_space.hpp"
#include "linearize/unsteady_aero.hpp"
#include "src/dynamics/aero_unsteady.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst";
const std::vector<std::string> kUa = {"AFAeroMod=2", "UAMod=4"};
const std::vector<std::string> kUaDbemt = {"AFAeroMod=2", "UAMod=4", "WakeMod=2", "DBEMT_Mod=3"};

VecX outputsAt(const Model& m, const OperatingPoint& op, const VecX& q, const VecX& qd, const VecX& qdd, const VecX& u,
               const VecX* z) {
  Workspace<double> ws(m);
  VecX y(m.noutput());
  evaluateOutputs(m, ws, q, qd, qdd, y, &u, &op.inflow, {}, z);
  return y;
}

// The residual of the equations of motion with the states (what the linear model linearizes,
// linearize/unsteady_aero.hpp): the frozen-wake residual with the elements' quasi-steady loads replaced by
// the states' loads, e_UA − e_QS from one pass over the elements.
VecX unsteadyResidual(const Model& m, const OperatingPoint& op, const VecX& q, const VecX& qd, const VecX& qdd,
                      const VecX& u, const VecX& z) {
  Workspace<double> ws(m);
  VecX e(m.ndof());
  residual(m, ws, q, qd, qdd, u, e, &op.inflow);
  forwardKinematics(m, ws, q, qd, qdd);
  addUnsteadyAeroLoads<double>(m, ws, q, qd, u, op.inflow, &z, e, nullptr, nullptr, nullptr, -1, true);
  return e;
}

// The states' steady values at op, each moved by up to `dz` (relative, at least absolute).
VecX perturbedStates(const Model& m, const OperatingPoint& op, unsigned seed, double dz) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  VecX z = unsteadyAeroSteadyStates(m, op);
  for (Eigen::Index k = 0; k < z.size(); ++k) z(k) += dz * d(rng) * std::max(1.0, std::abs(z(k)));
  return z;
}

// The moment of blade 1's loads about its pitch axis (−x of the blade body) is the pitch joint's generalized
// force (tests/unit/test_subtree_load_moment.cpp for the quasi-steady model), here of the unsteady residual, at
// a random state: coordinates, rates, accelerations and aerodynamic states all moved off the point.
void expectPitchAxisIdentity(const std::vector<std::string>& overrides) {
  Model m = readElastoDynModel(kDeck, overrides);
  ASSERT_GT(aeroStateCount(m.aero), 0);
  const int pitch = *m.findDof("blade 1 pitch");
  Output o;
  o.name = "pitch-axis moment";
  o.kind = OutputKind::SubtreeLoadMoment;
  o.body = m.dofs[static_cast<std::size_t>(pitch)].body;
  o.frame_body = o.body;
  o.direction = -Vec3::UnitX();
  m.outputs.push_back(o);
  const OperatingPoint op = test::nrel5mwRatedPoint(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  VecX q = op.q, qd = op.qd, qdd = op.qdd;
  for (int i = 0; i < m.ndof(); ++i) {
    if (i == pitch) continue;
    q(i) += 0.02 * d(rng);
    qd(i) += 0.05 * d(rng);
    qdd(i) = 0.3 * d(rng);
  }
  const VecX z = perturbedStates(m, op, 9, 0.01);
  const double e = unsteadyResidual(m, op, q, qd, qdd, op.u, z)(pitch);
  const VecX y = outputsAt(m, op, q, qd, qdd, op.u, &z);
  const double root_flap = std::abs(y(*m.findOutput("RootMFlp1")));
  // The same loads summed in two orders: equal to round-off of the flap moment's size.
  EXPECT_NEAR(y(m.noutput() - 1), e, 1e-10 * root_flap);
  // The quasi-steady loads' moment misses the states' part by far more than that (the test can fail).
  const double y_qs = outputsAt(m, op, q, qd, qdd, op.u, nullptr)(m.noutput() - 1);
  EXPECT_GT(std::abs(y_qs - e), 1e4 * 1e-10 * root_flap);
}

TEST(UnsteadyLoadOutputs, PitchAxisMomentIsThePitchJointsForceWithUa) { expectPitchAxisIdentity(kUa); }

TEST(UnsteadyLoadOutputs, PitchAxisMomentIsThePitchJointsForceWithUaAndDynamicInflow) {
  expectPitchAxisIdentity(kUaDbemt);
}

// The output function the state-space model linearizes, in double: y(x, u) = h(q, q̇, q̈(x, u), z, u), with
// q̈ on the active coordinates from the equations of motion with the states about op's mass matrix and
// accelerations, q̈ = q̈_op + M⁻¹ (e(q, q̇, q̈_op, u, z) − e_op): A's and B's rows of q̈ are its derivatives (e is
// linear in q̈). The states' residual at op, e_op, is not 0 (the UA loads at the states' steady values are not
// the quasi-steady equilibrium's, docs/theory/unsteady-aero.md): the state space keeps it in ẋ_op, not in C.
struct OutputFunction {
  const Model& m;
  const OperatingPoint& op;
  const LinearModel& lin;
  Eigen::LDLT<MatX> mass;
  VecX z0, e0;

  OutputFunction(const Model& model, const OperatingPoint& point, const LinearModel& l)
      : m(model),
        op(point),
        lin(l),
        mass(l.M),
        z0(l.first_order_values),
        e0(unsteadyResidual(model, point, point.q, point.qd, point.qdd, point.u, z0)) {}

  // x = [δq; δq̇; z] as the state space orders them (z: the aerodynamic states only, no body states here).
  VecX operator()(const VecX& x, const VecX& du) const {
    const int n = static_cast<int>(lin.dofs.size());
    VecX q = op.q, qd = op.qd, qdd = op.qdd, u = op.u + du;
    for (int k = 0; k < n; ++k) {
      q(lin.dofs[k]) += x(k);
      qd(lin.dofs[k]) += x(n + k);
    }
    for (int i = 0; i < m.ninput(); ++i)  // an input that drives frozen coordinates moves them (pitch)
      for (const InputDofTarget& t : m.inputs[i].dofs) q(t.dof) += t.gain * du(i);
    const VecX z = x.tail(z0.size());
    const VecX e = unsteadyResidual(m, op, q, qd, op.qdd, u, z) - e0;
    VecX e_active(n);
    for (int k = 0; k < n; ++k) e_active(k) = e(lin.dofs[k]);
    const VecX a = mass.solve(e_active);
    for (int k = 0; k < n; ++k) qdd(lin.dofs[k]) += a(k);
    return outputsAt(m, op, q, qd, qdd, u, &z);
  }
};

// C and D of a UA model's state space against central differences of the output function: every column of
// q, q̇ and the inputs, and the states' columns (the direct loads of the states and their inertial part).
void expectOutputMatricesAreDifferences(const std::vector<std::string>& overrides) {
  const Model m = readElastoDynModel(kDeck, overrides);
  ASSERT_TRUE(m.body_states.empty());
  const OperatingPoint op = test::nrel5mwRatedPoint(m);
  const LinearModel lin = linearize(m, op);
  const int n = static_cast<int>(lin.dofs.size()), nz = aeroStateCount(m.aero);
  ASSERT_EQ(static_cast<int>(lin.first_order_values.size()), nz);
  const StateSpaceModel s = stateSpace(m, op, lin);
  const OutputFunction y(m, op, lin);
  VecX x0(2 * n + nz);
  x0 << VecX::Zero(2 * n), lin.first_order_values;
  const VecX du0 = VecX::Zero(m.ninput());
  // The outputs at the point are those of the states' loads.
  EXPECT_LT((y(x0, du0) - outputsAt(m, op, op.q, op.qd, op.qdd, op.u, &lin.first_order_values)).cwiseAbs().maxCoeff(),
            1e-9 * std::max(1.0, y(x0, du0).cwiseAbs().maxCoeff()));
  // Central differences: truncation ~h² y''' and round-off ~1e-16 |y| / h; per output row, relative to the
  // row's largest entry (its scale), 1e-6 (measured: below 1e-8 but GenTq's D entry, 3.4e-7).
  MatX fdC(m.noutput(), 2 * n + nz), fdD(m.noutput(), m.ninput());
  for (int c = 0; c < 2 * n + nz; ++c) {
    const double h = 1e-6 * std::max(1.0, std::abs(x0(c)));
    VecX xp = x0, xm = x0;
    xp(c) += h;
    xm(c) -= h;
    fdC.col(c) = (y(xp, du0) - y(xm, du0)) / (2 * h);
  }
  for (int i = 0; i < m.ninput(); ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(op.u(i)));
    VecX dp = du0, dm = du0;
    dp(i) = h;
    dm(i) = -h;
    fdD.col(i) = (y(x0, dp) - y(x0, dm)) / (2 * h);
  }
  for (int r = 0; r < m.noutput(); ++r) {
    const double scale = std::max({1e-3, fdC.row(r).cwiseAbs().maxCoeff(), fdD.row(r).cwiseAbs().maxCoeff()});
    for (int c = 0; c < 2 * n + nz; ++c)
      EXPECT_NEAR(s.C(r, c), fdC(r, c), 1e-6 * scale) << s.y[r].name << " / " << s.x[c].name;
    for (int i = 0; i < m.ninput(); ++i)
      EXPECT_NEAR(s.D(r, i), fdD(r, i), 1e-6 * scale) << s.y[r].name << " / " << s.u[i].name;
  }
  // The states reach the blade-root flap moment directly, not only through q̈: a UA state of a blade-1
  // element near the tip moves RootMFlp1 (the columns are not those of the inertial part alone).
  const int flap = *m.findOutput("RootMFlp1");
  double largest = 0;
  for (int k = 0; k < nz; ++k) largest = std::max(largest, std::abs(s.C(flap, 2 * n + k)));
  EXPECT_GT(largest, 1e4);
}

TEST(UnsteadyLoadOutputs, OutputMatricesAreCentralDifferencesWithUa) { expectOutputMatricesAreDifferences(kUa); }

TEST(UnsteadyLoadOutputs, OutputMatricesAreCentralDifferencesWithUaAndDynamicInflow) {
  expectOutputMatricesAreDifferences(kUaDbemt);
}

}  // namespace
}  // namespace whirl
