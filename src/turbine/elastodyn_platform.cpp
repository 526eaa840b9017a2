// The ElastoDyn platform: a rigid body at the platform reference point carrying the tower base
// [Jonkman2007] (ElastoDyn's platform DOFs), on a free joint for a floating platform, or tied to a
// SubDyn substructure's transition piece (elastodyn_substructure.cpp).
#include <array>
#include <numbers>
#include <string>

#include "src/base/error.hpp"
#include "src/io/openfast/openfast_support.hpp"
#include "src/turbine/elastodyn_parts.hpp"

namespace whirl::elastodyn {

PlatformDescription describePlatform(const Builder& b) {
  const io::ElastoDynInput& ed = b.ed;
  const io::ElastoDynConfiguration& c = ed.config;
  const io::ElastoDynMassInertia& m = ed.mass;
  PlatformDescription p;
  // Reference point: PtfmRefzt (v1.00 files: PtfmRef, positive down), PtfmRefxt/yt from v5.
  p.reference = Vec3(c.PtfmRefxt.value_or(0.0), c.PtfmRefyt.value_or(0.0),
                     c.PtfmRefzt ? *c.PtfmRefzt : -c.PtfmRef.value_or(0.0));
  const Vec3 cm(c.PtfmCMxt.value_or(0.0), c.PtfmCMyt.value_or(0.0), c.PtfmCMzt.value_or(0.0));
  if (m.PtfmMass < 0) throw InputError(b.where("PtfmMass", "must not be negative"));
  // ElastoDyn's products of inertia are −∫xy dm etc., the off-diagonal entries of the tensor.
  Mat3 J;
  J << m.PtfmRIner, m.PtfmXYIner.value_or(0.0), m.PtfmXZIner.value_or(0.0),  //
      m.PtfmXYIner.value_or(0.0), m.PtfmPIner, m.PtfmYZIner.value_or(0.0),   //
      m.PtfmXZIner.value_or(0.0), m.PtfmYZIner.value_or(0.0), m.PtfmYIner;
  p.inertia = rigidBodyInertia(m.PtfmMass, cm - p.reference, J);
  const io::ElastoDynDofs& d = ed.dof;
  const io::ElastoDynInitialConditions& i = ed.init;
  constexpr double deg = std::numbers::pi / 180.0;
  p.on = {d.PtfmSgDOF, d.PtfmSwDOF, d.PtfmHvDOF, d.PtfmRDOF, d.PtfmPDOF, d.PtfmYDOF};
  p.value = {i.PtfmSurge, i.PtfmSway, i.PtfmHeave, i.PtfmRoll * deg, i.PtfmPitch * deg, i.PtfmYaw * deg};
  return p;
}

PlatformParts addPlatform(Builder& b) {
  PlatformParts out;
  if (!io::hasPlatformDofs(b.ed)) return out;
  const PlatformDescription d = describePlatform(b);
  out.reference = d.reference;
  Body p;
  p.name = "platform";
  p.offset = out.reference;
  p.joint = JointType::Free;  // translations along ground x, y, z, then yaw, pitch, roll
  p.inertia = d.inertia;
  out.body = b.addBody(std::move(p));
  for (int k = 0; k < 6; ++k)
    out.dofs[k] = b.addDof(kPlatformDofNames[k], out.body, DofKind::Joint, k, d.on[k], d.value[k]);
  return out;
}

void addPlatformOutputs(Builder& b, const PlatformParts& p) {
  if (p.body < 0) return;
  std::vector<Output>& y = b.model().outputs;
  constexpr std::array<const char*, 6> position = {"PtfmSurge", "PtfmSway",  "PtfmHeave",
                                                   "PtfmRoll",  "PtfmPitch", "PtfmYaw"};
  for (int k = 0; k < 6; ++k) y.push_back(dofOutput(position[k], k < 3 ? "m" : "rad", 0, {{p.dofs[k], 1.0}}));
  for (int order : {1, 2})
    for (int k = 0; k < 3; ++k)
      y.push_back(dofOutput(std::string(order == 1 ? "PtfmTV" : "PtfmTA") + "xyz"[k] + "i",
                            order == 1 ? "m/s" : "m/s^2", order, {{p.dofs[k], 1.0}}));
  // ElastoDyn's PtfmRVxi … are the platform's angular velocity (AngVelEX), not the rates of its
  // rotation coordinates: they differ once the platform is pitched (as under thrust).
  for (int order : {1, 2})
    for (int k = 0; k < 3; ++k) {
      Output o;
      o.name = std::string(order == 1 ? "PtfmRV" : "PtfmRA") + "xyz"[k] + "i";
      o.unit = order == 1 ? "rad/s" : "rad/s^2";
      o.kind = OutputKind::Angular;
      o.order = order;
      o.body = p.body;
      o.direction = Vec3::Unit(k);
      y.push_back(std::move(o));
    }
}

}  // namespace whirl::elastodyn
