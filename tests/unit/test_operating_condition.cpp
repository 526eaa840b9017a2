// Operating conditions applied to a model through its roles (initialPoint(model, condition)): the
// roles the ElastoDyn and YAML builders give, what each field sets, and the fields a model cannot
// honour.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case_file_test_util.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/sweep.hpp"
#include "state_space_test_util.hpp"

namespace whirl {
namespace {

using testing::inputErrorOf;

TEST(OperatingCondition, ElastoDynModelNamesItsRoles) {
  const Model m = testing::nrel5mw();
  const ModelRoles& r = m.roles;
  ASSERT_EQ(r.azimuth.size(), 1u);
  EXPECT_EQ(m.dofs[r.azimuth[0]].name, "generator azimuth");
  ASSERT_EQ(r.blade_pitch.size(), 3u);
  ASSERT_EQ(r.blade_pitch_inputs.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(m.dofs[r.blade_pitch[k]].name, "blade " + std::to_string(k + 1) + " pitch");
    EXPECT_EQ(m.inputs[r.blade_pitch_inputs[k]].name, "blade " + std::to_string(k + 1) + " pitch");
  }
  EXPECT_EQ(m.inputs[r.collective_pitch_input].name, "collective pitch");
  EXPECT_EQ(m.inputs[r.generator_torque_input].name, "generator torque");
  EXPECT_EQ(m.dofs[r.yaw_dof].name, "yaw");
  EXPECT_EQ(r.wind_speed_input, -1);
}

TEST(OperatingCondition, TheModelsOwnConditionGivesItsInitialPoint) {
  const Model m = testing::nrel5mw();
  const OperatingPoint a = initialPoint(m), b = initialPoint(m, modelCondition(m));
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.qd, b.qd);
  EXPECT_EQ(a.u, b.u);
}

TEST(OperatingCondition, EachFieldSetsItsCoordinateOrInput) {
  const Model m = testing::nrel5mw();
  const Model before = m;
  OperatingCondition c;
  c.rotor_speed = 1.2;
  c.azimuth = 0.3;
  c.collective_pitch = 0.1;
  c.blade_pitch_offsets = {0.01, -0.02, 0.03};
  c.generator_torque = 4.0e4;
  c.yaw = 0.05;
  const OperatingPoint op = initialPoint(m, c);
  const ModelRoles& r = m.roles;
  EXPECT_EQ(op.qd(r.azimuth[0]), 1.2);
  EXPECT_EQ(op.q(r.azimuth[0]), 0.3);
  EXPECT_DOUBLE_EQ(op.q(r.blade_pitch[0]), 0.11);
  EXPECT_DOUBLE_EQ(op.q(r.blade_pitch[1]), 0.08);
  EXPECT_DOUBLE_EQ(op.q(r.blade_pitch[2]), 0.13);
  EXPECT_EQ(op.u(r.generator_torque_input), 4.0e4);
  EXPECT_EQ(op.q(r.yaw_dof), 0.05);
  // The model is not touched.
  for (int i = 0; i < m.ndof(); ++i) {
    EXPECT_EQ(m.dofs[i].value, before.dofs[i].value);
    EXPECT_EQ(m.dofs[i].rate, before.dofs[i].rate);
  }
  // Pitch from a schedule's degrees, as the old per-point model copy set it.
  const SweepPoint p = sweepPoint(9, 11.4, 6.5);
  EXPECT_EQ(initialPoint(m, sweepCondition(m, p)).q(r.blade_pitch[1]), 6.5 * std::numbers::pi / 180);
  EXPECT_EQ(p.condition.rotor_speed, 9 * 2 * std::numbers::pi / 60);
  EXPECT_FALSE(sweepCondition(m, p).wind_speed);  // no wind input: the wind speed only labels the point
}

TEST(OperatingCondition, FieldsTheModelCannotHonourAreNamed) {
  const Model m = testing::nrel5mw();
  OperatingCondition wind = modelCondition(m);
  wind.wind_speed = 11.4;
  EXPECT_NE(inputErrorOf([&] { initialPoint(m, wind); }).find("wind_speed"), std::string::npos);
  OperatingCondition offsets = modelCondition(m);
  offsets.blade_pitch_offsets = {0.1, 0.2};
  EXPECT_NE(inputErrorOf([&] { initialPoint(m, offsets); }).find("blade_pitch_offsets"), std::string::npos);
  OperatingCondition nan = modelCondition(m);
  nan.collective_pitch = std::nan("");
  EXPECT_NE(inputErrorOf([&] { initialPoint(m, nan); }).find("collective_pitch"), std::string::npos);

  testing::TempCaseDir dir;
  const Model tower = readCase(dir.write("turbine.yaml", testing::smallTurbineCase()));
  OperatingCondition pitch = modelCondition(tower);
  pitch.collective_pitch = 0.1;
  EXPECT_NE(inputErrorOf([&] { initialPoint(tower, pitch); }).find("collective_pitch"), std::string::npos);
  OperatingCondition yaw = modelCondition(tower);
  yaw.yaw = 0.1;
  EXPECT_NE(inputErrorOf([&] { initialPoint(tower, yaw); }).find("yaw"), std::string::npos);
  OperatingCondition torque = modelCondition(tower);
  torque.generator_torque = 1.0;
  EXPECT_NE(inputErrorOf([&] { initialPoint(tower, torque); }).find("generator_torque"), std::string::npos);

  const Model fixed = readCase(dir.write("fixed.yaml", testing::replaced(testing::smallTurbineCase(),
                                                                         "azimuth: {rotating: true, rate_rpm: 12.1}",
                                                                         "azimuth: {frozen: true}")));
  OperatingCondition spin;
  spin.rotor_speed = 1.0;
  EXPECT_NE(inputErrorOf([&] { initialPoint(fixed, spin); }).find("rotor_speed"), std::string::npos);
  EXPECT_EQ(initialPoint(fixed, OperatingCondition{}).qd, initialPoint(fixed).qd);

  // A schedule's pitch reaches a model only where it has pitch coordinates (as before conditions);
  // set explicitly, it is an error.
  SweepPoint scheduled = sweepPoint(12.1, 11.4, 6.5);
  EXPECT_FALSE(sweepCondition(tower, scheduled).collective_pitch);
  EXPECT_EQ(*sweepCondition(m, scheduled).collective_pitch, 6.5 * std::numbers::pi / 180);
  scheduled.condition.collective_pitch = 0.1;
  EXPECT_NE(inputErrorOf([&] { initialPoint(tower, sweepCondition(tower, scheduled)); }).find("collective_pitch"),
            std::string::npos);
}

// A wind beyond limits::kMaxWindSpeed (100 m/s, incompressible aerodynamics) is refused before the solve:
// at 1e6 m/s the loads (3e21 N) defeated the Newton matrix and were reported as a tower DOF "with no
// stiffness" (hardening issue, item 5).
TEST(OperatingCondition, WindBeyondTheLimitIsNamed) {
  const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Aero.fst");
  OperatingCondition c = modelCondition(m);
  c.rotor_speed = 1.0;
  c.wind_speed = 1e6;
  EXPECT_EQ(inputErrorOf([&] { solveOperatingPoint(m, c); }),
            "operating point: wind speed 1e+06 m/s is above the limit of 100 m/s (the aerodynamics are "
            "incompressible)");
  c.wind_speed = 100.0;  // at the limit: a point (blades stalled, far from trim)
  EXPECT_NO_THROW(solveOperatingPoint(m, c));
}

// A YAML rotor gives its pitch roles by structure: blade inputs that drive one frozen angle each,
// and the fixed-frame input that drives all of them.
TEST(OperatingCondition, CaseFilePitchRolesComeFromTheInputs) {
  std::string text = testing::smallTurbineCase();
  text = testing::replaced(text, "inputs:\n", R"(inputs:
  - {name: collective pitch, unit: rad, dofs: [pitch 1, pitch 2, pitch 3]}
  - {name: pitch input 1, unit: rad, dofs: pitch 1, blade: 1}
  - {name: pitch input 2, unit: rad, dofs: pitch 2, blade: 2}
  - {name: pitch input 3, unit: rad, dofs: pitch 3, blade: 3}
)");
  text = testing::replaced(
      text, "dofs:\n", R"(  - {name: blade 1, type: rigid, parent: rotor, mass: 1.0e4, inertia: [1.0e5, 1.0e5, 1.0e3],
     joint: {type: revolute, axis: [0, 0, 1], dof: pitch 1}}
  - {name: blade 2, type: rigid, parent: rotor, mass: 1.0e4, inertia: [1.0e5, 1.0e5, 1.0e3],
     joint: {type: revolute, axis: [0, 0, 1], dof: pitch 2}}
  - {name: blade 3, type: rigid, parent: rotor, mass: 1.0e4, inertia: [1.0e5, 1.0e5, 1.0e3],
     joint: {type: revolute, axis: [0, 0, 1], dof: pitch 3}}
dofs:
  pitch 1: {frozen: true, value_deg: 2}
  pitch 2: {frozen: true, value_deg: 2}
  pitch 3: {frozen: true, value_deg: 2}
)");
  testing::TempCaseDir dir;
  const Model m = readCase(dir.write("pitched.yaml", text));
  const ModelRoles& r = m.roles;
  ASSERT_EQ(r.blade_pitch.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(m.dofs[r.blade_pitch[k]].name, "pitch " + std::to_string(k + 1));
    EXPECT_EQ(m.inputs[r.blade_pitch_inputs[k]].name, "pitch input " + std::to_string(k + 1));
  }
  EXPECT_EQ(m.inputs[r.collective_pitch_input].name, "collective pitch");
  ASSERT_EQ(r.azimuth.size(), 1u);
  EXPECT_EQ(m.dofs[r.azimuth[0]].name, "azimuth");
  OperatingCondition c = modelCondition(m);
  c.collective_pitch = 0.25;
  const OperatingPoint op = initialPoint(m, c);
  for (int d : r.blade_pitch) EXPECT_EQ(op.q(d), 0.25);
  EXPECT_NEAR(initialPoint(m).q(r.blade_pitch[0]), 2 * std::numbers::pi / 180, 1e-15);
  EXPECT_DOUBLE_EQ(op.qd(r.azimuth[0]), 12.1 * std::numbers::pi / 30);
}

}  // namespace
}  // namespace whirl
