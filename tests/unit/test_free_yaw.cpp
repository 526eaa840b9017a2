// A coordinate without stiffness (a free yaw, YawDOF = True without a yaw spring) is held at its
// given value in the operating point and its mode reported as a rigid-body mode
// (linearize/unrestrained.hpp); a coordinate with a spring too weak for the loads on it gets a
// message that names it, the load and how to hold it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "linearize/unrestrained.hpp"
#include "modal/rotor_modes.hpp"
#include "src/base/error.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

// ws03: the NREL 5MW at 6.972 rpm (RotSpeed, GenDOF = False) with YawDOF = True and ServoDyn off
// (CompServo = 0): no yaw spring. Structural model (CompAero = 0).
const std::string kWs03 = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/ws03/ws03.0.fst";
// The toolbox deck: ServoDyn on, YawSpr = 9.02832E+09 N m/rad (its YawDOF is False).
const std::string kToolbox = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/aero/toolbox/Main.fst";

TEST(FreeYaw, RuleFindsTheYawWithoutSpringOnly) {
  const Model m = readElastoDynModel(kWs03, {"CompAero=0"});
  ASSERT_GE(m.roles.yaw_dof, 0);
  const OperatingPoint start = initialPoint(m);
  EXPECT_EQ(unrestrainedCoordinates(m, start.q, start.qd, start.u), std::vector<int>{m.roles.yaw_dof});
  // The same yaw with ServoDyn's yaw spring is restrained: solved for, not held.
  const Model s = readElastoDynModel(kToolbox, {"CompAero=0", "YawDOF=True"});
  const OperatingPoint ss = initialPoint(s);
  EXPECT_TRUE(unrestrainedCoordinates(s, ss.q, ss.qd, ss.u).empty());
}

TEST(FreeYaw, ParkedHoldsTheYaw) {
  Model m = readElastoDynModel(kWs03, {"CompAero=0", "NacYaw=10"});
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m, OperatingCondition{}));
  EXPECT_EQ(op.held, std::vector<int>{m.roles.yaw_dof});
  EXPECT_DOUBLE_EQ(op.q(m.roles.yaw_dof), 10 * std::numbers::pi / 180);
  EXPECT_LT(op.residual_norm, 1e-8 * op.load_scale);
}

// The case: before, "operating point did not converge … on DOF 'tower FA 2'" at any rotor speed.
TEST(FreeYaw, RotatingLinearizesWithRigidYawMode) {
  const Model m = readElastoDynModel(kWs03, {"CompAero=0"});
  PeriodicOptions opt;
  opt.azimuths = 4;
  const PeriodicLinearization p = linearizePeriodic(m, initialPoint(m), opt);
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_NEAR(p.rotor_speed, 6.972 * 2 * std::numbers::pi / 60, 1e-12);
  for (const OperatingPoint& op : p.points) {
    EXPECT_EQ(op.held, std::vector<int>{m.roles.yaw_dof});
    EXPECT_EQ(op.q(m.roles.yaw_dof), 0.0);  // NacYaw = 0: held there
    EXPECT_LT(op.residual_norm, 1e-8 * op.load_scale);
  }
  const RotorModes r = rotorModes(m, p);
  int yaw_modes = 0;
  for (const Mode& md : r.modes) {
    EXPECT_TRUE(std::isfinite(md.freq_hz) && std::isfinite(md.damping_ratio)) << md.name;
    if (md.name.find("yaw") != std::string::npos) {
      ++yaw_modes;
      EXPECT_TRUE(md.rigid_body) << md.name;
      EXPECT_EQ(md.name, "yaw (rigid body)");
      EXPECT_LT(md.freq_hz, 5e-3);
    }
  }
  EXPECT_EQ(yaw_modes, 1);
}

// A yaw spring of 1 N m/rad is no restraint against the loads of a turning rotor (with the tower
// DOFs on, yawing also tilts the overhang's weight moment into the tower): no equilibrium, and the
// message says which coordinate, what load and how to hold it. (With the tower rigid the same spring
// gives an "equilibrium" at −12698 rad, the yaw load 12698 N m over 1 N m/rad.)
TEST(FreeYaw, WeakSpringMessageNamesTheYaw) {
  const Model m = readElastoDynModel(kToolbox, {"CompAero=0", "YawDOF=True", "YawSpr=1", "TwFADOF1=True",
                                                "TwSSDOF1=True", "TwFADOF2=True", "TwSSDOF2=True"});
  try {
    PeriodicOptions opt;
    opt.azimuths = 4;
    linearizePeriodic(m, initialPoint(m), opt);
    FAIL() << "expected a ComputeError";
  } catch (const ComputeError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("operating point did not converge in 50 Newton iterations"), std::string::npos) << msg;
    // The load with the yaw held: the −12698 N m that the rigid tower's "equilibrium" divides by 1 N m/rad.
    EXPECT_NE(msg.find("DOF 'yaw' is nearly unrestrained (stiffness 1 N m/rad) and a load of -1.27e+04 N m"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("N m acts on it; hold it with --set YawDOF=False, or a yaw spring (ServoDyn YawSpr with "
                       "CompServo = 1)"),
              std::string::npos)
        << msg;
  }
}

// At 1 rpm in 3 m/s wind the stalled rotor's mean yaw moment turns a free yaw 0.821 rad in one
// revolution (60 s): no periodic operating point. (0.82 rad, 1.15e4 N m, without AeroDyn's skewed-wake
// correction of the tilted rotor's induction.) (At 6.972 rpm the same deck drifts 0.007 rad per
// revolution and linearizes: tests/validation/test_nrel5mw_aero_ws03.cpp.)
TEST(FreeYaw, MeanYawMomentTooLargeNamesTheYaw) {
  const std::string deck = std::string(WHIRL_SOURCE_DIR) + "/tests/data/openfast/aero/ws03/ws03.0.fst";
  const Model m = readElastoDynModel(deck);
  OperatingCondition c;
  c.rotor_speed = 1.0 * 2 * std::numbers::pi / 60;
  PeriodicOptions opt;
  opt.azimuths = 8;
  try {
    linearizePeriodic(m, c, opt);
    FAIL() << "expected a ComputeError";
  } catch (const ComputeError& e) {
    EXPECT_STREQ(e.what(),
                 "operating point: a mean load of 1.152e+04 N m acts along DOF 'yaw', which has no stiffness (a free "
                 "rigid-body motion): it would move 0.821 rad in one revolution (limit 0.1), no periodic operating "
                 "point; hold it with --set YawDOF=False, or a yaw spring (ServoDyn YawSpr with CompServo = 1)");
  }
}

// Nothing turning, a held coordinate must carry (almost) no load: ws03 parked at 10° yaw carries
// 19 N m (the weight moment about the yaw axis the deflected tower tilts), 4e-5 rad in 10 s — held;
// the same yaw under a 1e6 N m yaw moment has no equilibrium.
TEST(FreeYaw, ParkedSteadyYawLoadHasNoEquilibrium) {
  Model m = readElastoDynModel(kWs03, {"CompAero=0"});
  m.dof_loads.push_back({m.roles.yaw_dof, 1e6, -1});
  try {
    solveOperatingPoint(m, initialPoint(m, OperatingCondition{}));
    FAIL() << "expected a ComputeError";
  } catch (const ComputeError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("operating point: a load acts along DOF 'yaw' (1e+06 N m), which has no stiffness (a free "
                       "rigid-body motion): it would move "),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find(" rad in 10 s (limit 0.1), no equilibrium; hold it with --set YawDOF=False"), std::string::npos)
        << msg;
  }
}

}  // namespace
}  // namespace whirl
