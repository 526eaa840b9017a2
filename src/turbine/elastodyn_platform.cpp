// The ElastoDyn platform: a rigid body on a free joint at the platform reference point, carrying the
// tower base [Jonkman2007] (ElastoDyn's platform DOFs).
#include <numbers>

#include "src/io/openfast_support.hpp"
#include "src/turbine/elastodyn_parts.hpp"
#include "src/model/error.hpp"

namespace whirl::elastodyn {

PlatformParts addPlatform(Builder& b) {
  const io::ElastoDynInput& ed = b.ed;
  PlatformParts out;
  if (!io::has_platform_dofs(ed)) return out;
  const io::ElastoDynConfiguration& c = ed.config;
  const io::ElastoDynMassInertia& m = ed.mass;
  // Reference point: PtfmRefzt (v1.00 files: PtfmRef, positive down), PtfmRefxt/yt from v5.
  out.reference = Vec3(c.PtfmRefxt.value_or(0.0), c.PtfmRefyt.value_or(0.0),
                       c.PtfmRefzt ? *c.PtfmRefzt : -c.PtfmRef.value_or(0.0));
  const Vec3 cm(c.PtfmCMxt.value_or(0.0), c.PtfmCMyt.value_or(0.0), c.PtfmCMzt.value_or(0.0));
  if (m.PtfmMass < 0) throw InputError(b.where("PtfmMass", "must not be negative"));
  // ElastoDyn's products of inertia are −∫xy dm etc., the off-diagonal entries of the tensor.
  Mat3 J;
  J << m.PtfmRIner, m.PtfmXYIner.value_or(0.0), m.PtfmXZIner.value_or(0.0),  //
      m.PtfmXYIner.value_or(0.0), m.PtfmPIner, m.PtfmYZIner.value_or(0.0),    //
      m.PtfmXZIner.value_or(0.0), m.PtfmYZIner.value_or(0.0), m.PtfmYIner;
  Body p;
  p.name = "platform";
  p.offset = out.reference;
  p.joint = JointType::Free;  // translations along ground x, y, z, then yaw, pitch, roll
  p.inertia = rigidBodyInertia(m.PtfmMass, cm - out.reference, J);
  out.body = b.addBody(std::move(p));
  const io::ElastoDynDofs& d = ed.dof;
  const io::ElastoDynInitialConditions& i = ed.init;
  constexpr double deg = std::numbers::pi / 180.0;
  const char* names[6] = {"platform surge", "platform sway", "platform heave",
                          "platform roll",  "platform pitch", "platform yaw"};
  const bool on[6] = {d.PtfmSgDOF, d.PtfmSwDOF, d.PtfmHvDOF, d.PtfmRDOF, d.PtfmPDOF, d.PtfmYDOF};
  const double value[6] = {i.PtfmSurge, i.PtfmSway, i.PtfmHeave, i.PtfmRoll * deg, i.PtfmPitch * deg, i.PtfmYaw * deg};
  for (int k = 0; k < 6; ++k) out.dofs[k] = b.addDof(names[k], out.body, DofKind::Joint, k, on[k], value[k]);
  return out;
}

}  // namespace whirl::elastodyn
