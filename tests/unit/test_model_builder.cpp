// ModelBuilder (src/model/model_builder.hpp), the builder under the YAML case reader and the ElastoDyn
// turbine builder: repeated DOF names, lookups that fail listing the names there are, finish().
#include <gtest/gtest.h>

#include <string>

#include "src/base/error.hpp"
#include "src/model/model_builder.hpp"

namespace whirl {
namespace {

// The message of the InputError `f` throws, "" when it throws none.
template <class F>
std::string messageOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Dof dof(const std::string& name, int body) {
  Dof d;
  d.name = name;
  d.kind = DofKind::Joint;
  d.body = body;
  return d;
}

// A pendulum: a point mass on an arm, on a revolute joint about y, its point "tip" at the mass.
ModelBuilder pendulum() {
  ModelBuilder b;
  b.model().name = "pendulum";
  Body arm;
  arm.name = "arm";
  arm.joint = JointType::Revolute;
  arm.axis = Vec3::UnitY();
  arm.inertia = rigidBodyInertia(2.0, Vec3(0, 0, -1.5), Mat3::Zero());
  arm.points.push_back({"tip", Vec3(0, 0, -1.5), Mat3X::Zero(3, 0)});
  EXPECT_EQ(b.addBody(arm, Where{"case.yaml", 3, "bodies[0]", ""}), 0);
  EXPECT_EQ(b.addDof(dof("swing", 0), Where{"case.yaml", 7, "bodies[0].joint.dof", ""}), 0);
  return b;
}

TEST(ModelBuilder, RejectsARepeatedDofNameNamingBothPlaces) {
  ModelBuilder b = pendulum();
  EXPECT_EQ(messageOf([&] {
              b.addDof(dof("swing", 0), Where{"case.yaml", 12, "dofs.swing", ""});
            }),
            "case.yaml:12: dofs.swing: DOF name 'swing' is already used at line 7");
  EXPECT_EQ(messageOf([&] {
              b.addDof(dof("", 0), Where{"case.yaml", 13, "", ""});
            }),
            "case.yaml:13: a DOF name must not be empty");
  EXPECT_EQ(b.model().ndof(), 1);  // the refused DOFs were not added
  EXPECT_EQ(b.dofWhere(0).line, 7);
  EXPECT_EQ(b.bodyWhere(0).key, "bodies[0]");
}

TEST(ModelBuilder, LookupsFindByNameOrListTheNamesThereAre) {
  ModelBuilder b = pendulum();
  const Where at{"case.yaml", 20, "loads[0].dof", ""};
  EXPECT_EQ(b.dofIndex("swing", at), 0);
  EXPECT_EQ(b.bodyIndex("arm", at), 0);
  EXPECT_EQ(b.pointIndex(0, "tip", at), 0);
  EXPECT_EQ(messageOf([&] { b.dofIndex("swung", at); }),
            "case.yaml:20: loads[0].dof: no DOF named 'swung' (DOFs: swing)");
  EXPECT_EQ(messageOf([&] { b.bodyIndex("hub", at); }),
            "case.yaml:20: loads[0].dof: no body named 'hub' (bodies: arm)");
  EXPECT_EQ(messageOf([&] { b.inputIndex("thrust", at); }),
            "case.yaml:20: loads[0].dof: no input named 'thrust' (inputs: none)");
  EXPECT_EQ(messageOf([&] { b.pointIndex(0, "root", at); }),
            "case.yaml:20: loads[0].dof: body 'arm' has no point named 'root' (points: tip)");
}

TEST(ModelBuilder, FinishFinalizesTheModel) {
  const Model m = pendulum().finish();
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].joint_dof, 0);  // set by finalize(), −1 before
  EXPECT_FALSE(m.chains.empty());
}

TEST(ModelBuilder, FinishReportsWhatFinalizeRefuses) {
  ModelBuilder b = pendulum();
  b.model().bodies[0].parent = 5;  // no such body
  EXPECT_THROW(std::move(b).finish(), InputError);
}

}  // namespace
}  // namespace whirl
