// The blade-root moments summed from the loads (OutputKind::SubtreeLoadMoment; ElastoDyn's RootMFlp =
// RootMyb and RootMEdg = RootMxb, MomH0B in ElastoDyn.f90): checked through the pitch joint's generalized
// force (Kane's projection, a second path through the same loads), against the NREL 5MW blade's first
// mass moment and, on certification Test26's BeamDyn blade, against the FE elements' stress resultants at
// a static equilibrium.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "linearize/operating_point.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/residual.hpp"
#include "src/fem/blade6_moments.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/turbine/beamdyn_blade.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kCases = std::string(WHIRL_SOURCE_DIR) + "/cases/";
constexpr double kPi = std::numbers::pi;

int output(const Model& m, const std::string& name) {
  const std::optional<int> i = m.findOutput(name);
  if (!i) throw std::runtime_error("no output " + name);
  return *i;
}

VecX outputsAt(const Model& m, const VecX& q, const VecX& qd, const VecX& qdd, const VecX& u) {
  Workspace<double> ws(m);
  VecX y(m.noutput());
  evaluateOutputs(m, ws, q, qd, qdd, y, &u);
  return y;
}

// Adds an output: the moment of the loads of `body`'s subtree about its origin, along `axis` (body axes).
void addSubtreeOutput(Model& m, int body, const Vec3& axis) {
  Output o;
  o.name = "subtree moment";
  o.kind = OutputKind::SubtreeLoadMoment;
  o.body = body;
  o.frame_body = body;
  o.direction = axis;
  m.outputs.push_back(o);
}

// A state around op's: every coordinate but `fixed` moved by up to `dq`, rates by 2.5 dq, accelerations up to 15 dq.
struct State {
  VecX q, qd, qdd;
};
State randomState(const Model& m, const OperatingPoint& op, unsigned seed, double dq, int fixed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  State s{op.q, op.qd, op.qdd};
  for (int i = 0; i < m.ndof(); ++i) {
    if (i == fixed) continue;
    s.q(i) += dq * d(rng);
    s.qd(i) += 2.5 * dq * d(rng);
    s.qdd(i) = 15 * dq * d(rng);
  }
  return s;
}

// The moment of blade 1's loads about its pitch axis (−x of the blade body, the revolute joint's axis) is
// the pitch joint's generalized force: the residual's row, projected through the partial angular velocities,
// at a random state — moving frames, elastic rates and accelerations, wind — with aerodynamics.
TEST(SubtreeLoadMoment, PitchAxisComponentIsThePitchJointsGeneralizedForce) {
  for (const char* deck : {"nrel5mw/Main_Aero.fst", "nrel5mw_beamdyn/Test26.fst"}) {
    Model m = readElastoDynModel(kCases + deck);
    const int pitch = *m.findDof("blade 1 pitch");
    addSubtreeOutput(m, m.dofs[static_cast<std::size_t>(pitch)].body, -Vec3::UnitX());
    OperatingCondition c;
    c.rotor_speed = 11 * kPi / 30;
    c.wind_speed = 9;
    c.collective_pitch = 0.02;
    const OperatingPoint op = initialPoint(m, c);
    const auto [q, qd, qdd] = randomState(m, op, 7, 0.02, pitch);
    Workspace<double> ws(m);
    VecX e(m.ndof());
    residual(m, ws, q, qd, qdd, op.u, e);
    const double y = outputsAt(m, q, qd, qdd, op.u)(m.noutput() - 1);
    const double root_flap = std::abs(outputsAt(m, q, qd, qdd, op.u)(output(m, "RootMFlp1")));
    // Both sum the same loads in different orders: equal to round-off of the flap moment's size.
    EXPECT_NEAR(y, e(pitch), 1e-10 * root_flap) << deck;
    EXPECT_GT(std::abs(y), 1e3) << deck;  // a pitching moment that is not zero by chance
  }
}

// The yaw joint carries the nacelle, drivetrain and rotor: the moment of their loads about the yaw axis is
// the yaw coordinate's generalized force, less its spring and damper (ServoDyn YawSpr, YawDamp: a load on
// the subtree's own joint, not on its bodies). With the generator torque (law + input) and the rotor thrust
// and torque inputs, whose loads lie in the subtree.
TEST(SubtreeLoadMoment, YawAxisComponentIsTheYawCoordinatesGeneralizedForce) {
  Model m = readElastoDynModel(kCases + "nrel5mw/Main_Aero.fst");
  const int yaw = m.roles.yaw_dof;
  ASSERT_GE(yaw, 0);
  const int nacelle = m.dofs[static_cast<std::size_t>(yaw)].body;
  addSubtreeOutput(m, nacelle, m.bodies[static_cast<std::size_t>(nacelle)].axis);
  OperatingCondition c;
  c.rotor_speed = 11 * kPi / 30;
  c.wind_speed = 10;
  c.collective_pitch = 0.01;
  const OperatingPoint op = initialPoint(m, c);
  const auto [q, qd, qdd] = randomState(m, op, 11, 0.01, -1);
  VecX u = op.u;
  u(*m.findInput("generator torque")) = 2e4;
  u(*m.findInput("rotor thrust")) = 3e5;
  u(*m.findInput("rotor torque")) = 1e6;
  Workspace<double> ws(m);
  VecX e(m.ndof());
  residual(m, ws, q, qd, qdd, u, e);
  double spring = 0;
  for (const DofSpring& s : m.springs)
    if (s.dof == yaw) spring += s.k * (q(yaw) - s.q0) + s.c * qd(yaw);
  ASSERT_NE(spring, 0.0);
  const double y = outputsAt(m, q, qd, qdd, u)(m.noutput() - 1);
  EXPECT_NEAR(y, e(yaw) + spring, 1e-10 * std::abs(spring));
  EXPECT_GT(std::abs(y), 1e4);
}

// The tower at rest, undeflected: a tower-top force F adds F × the tower height (TowerHt 87.6 m above
// TowerBsHt 0, the deck's) to the base moment that bends the top its way; the weights' moment is the rest.
TEST(SubtreeLoadMoment, TowerTopForceAddsItsMomentAtTheBase) {
  const Model m = readElastoDynModel(kCases + "nrel5mw/Main_Onshore.fst");
  OperatingCondition c;
  c.rotor_speed = 0;
  const OperatingPoint op = initialPoint(m, c);
  VecX q = op.q;
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[static_cast<std::size_t>(i)].kind == DofKind::Elastic) q(i) = 0;
  const VecX zero = VecX::Zero(m.ndof());
  const VecX y0 = outputsAt(m, q, zero, zero, op.u);
  for (const auto& [input, channel] :
       {std::pair<std::string, std::string>{"tower-top force", "TwrBsMFA"}, {"tower-top side force", "TwrBsMSS"}}) {
    VecX u = op.u;
    u(*m.findInput(input)) = 1e5;
    const VecX y = outputsAt(m, q, zero, zero, u);
    const int k = output(m, channel);
    EXPECT_NEAR(y(k) - y0(k), 1e5 * 87.6, 1e-6) << channel;
  }
  // ElastoDyn's TwrBsMyt is the fore-aft one.
  EXPECT_EQ(y0(output(m, "TwrBsMyt")), y0(output(m, "TwrBsMFA")));
}

// Rotor at rest, blade 1 horizontal, undeflected: the loads are the blade's weight, whose moment about the
// root is g × its first mass moment, at right angles to the span (flap and edge components only).
TEST(SubtreeLoadMoment, HorizontalBladeAtRestCarriesItsWeightsMoment) {
  const Model m = readElastoDynModel(kCases + "nrel5mw/Main_Onshore.fst");
  OperatingCondition c;
  c.rotor_speed = 0;
  c.azimuth = kPi / 2;
  c.collective_pitch = 0;
  const OperatingPoint op = initialPoint(m, c);
  VecX q = op.q;
  for (int i = 0; i < m.ndof(); ++i)
    if (m.dofs[static_cast<std::size_t>(i)].kind == DofKind::Elastic) q(i) = 0;
  const VecX zero = VecX::Zero(m.ndof());
  const VecX y = outputsAt(m, q, zero, zero, op.u);
  const double flap = y(output(m, "RootMFlp1")), edge = y(output(m, "RootMEdg1"));
  // The deck's first mass moment about the root: the midpoint rule over ElastoDyn's 17 nodes of BlMass,
  // linearly interpolated in BlFract, times AdjBlMs 1.04536 (NRELOffshrBsline5MW_Blade.dat; numpy, to
  // 1e-9): 362,132.6528 kg m. (Jonkman et al. 2009, Table 2-1, gives 363,231 kg m with AeroDyn v14's
  // nodes.) Its arm is horizontal but for sin δ = sin(PreCone) sin(ShftTilt): the cone leans the blade
  // towards the tilted shaft. Gravity 9.80665 m/s² (the deck's).
  const double delta = std::asin(std::sin(2.5 * kPi / 180) * std::sin(5 * kPi / 180));
  EXPECT_NEAR(std::hypot(flap, edge) / 9.80665, 362132.6528 * std::cos(delta), 0.01);
  // At zero pitch the weight of a horizontal blade bends it in its plane.
  EXPECT_GT(std::abs(edge), 10 * std::abs(flap));
}

// Test26 (BeamDyn blades), rotor at rest with blade 1 horizontal, static equilibrium under gravity: the
// moment of the loads (the weight) against the moment the FE elements carry at the root, Σ_j G_j q_j
// (fem::blade6MomentGains of the deflected modal coordinates). The resultant of a few modes misses the
// static deflection's higher modes (a stress converges more slowly than a displacement): with the deck's
// 8 modes it is 9 % (flap) and 6.5 % (edge) short, with 48 modes 1.1e-3 and 5.7e-4, with 96 modes
// 2.4e-4 and 1.3e-4 over. The loads' moment needs no modes beyond the motion's.
Eigen::Vector3d test26RootMoments(int modes) {
  const io::BeamDynInput bd = io::readBeamDyn(kCases + "nrel5mw_beamdyn/5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat");
  const Model m = readElastoDynModel(kCases + "nrel5mw_beamdyn/Test26.fst",
                                     {"CompAero=0", "CompInflow=0", "blade_modes=" + std::to_string(modes)});
  OperatingCondition c;
  c.rotor_speed = 0;
  c.azimuth = kPi / 2;
  c.collective_pitch = 0;
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m, c));
  const VecX y = outputsAt(m, op.q, op.qd, op.qdd, op.u);
  const fem::Blade6Body b = fem::blade6Body(blade6Input(bd), {60, modes});  // the deck's 60 elements
  const MatX G = fem::blade6MomentGains(b, 0.0);
  Eigen::Vector2d resultant = Eigen::Vector2d::Zero();
  for (std::size_t j = 0; j < b.shapes.size(); ++j)
    resultant += G.col(static_cast<Eigen::Index>(j)) * op.q(*m.findDof("blade 1 " + b.shapes[j]->name));
  // G's rows bend the blade towards +y and +z; RootMFlp is the loads' moment about +z (towards +y),
  // RootMEdg about +y (towards −z). Returned: relative errors of flap and edge, and the flap channel.
  const double flap = y(output(m, "RootMFlp1")), edge = y(output(m, "RootMEdg1"));
  return {resultant(0) / flap - 1, -resultant(1) / edge - 1, flap};
}

TEST(SubtreeLoadMomentSlow, Test26LoadsMomentIsTheElementsResultantAtEquilibrium) {
  const Eigen::Vector3d few = test26RootMoments(8), many = test26RootMoments(48);
  EXPECT_GT(many(2), 1e5);  // the cone and tilt give the weight a flapwise moment
  EXPECT_NEAR(many(0), 0, 1.5e-3);
  EXPECT_NEAR(many(1), 0, 1.5e-3);
  // Converging: the deck's 8 modes are far short, 48 modes twenty times closer.
  EXPECT_LT(few(0), -0.05);
  EXPECT_LT(few(1), -0.05);
  EXPECT_LT(std::abs(many(0)), std::abs(few(0)) / 20);
  EXPECT_LT(std::abs(many(1)), std::abs(few(1)) / 20);
}

}  // namespace
}  // namespace whirl
