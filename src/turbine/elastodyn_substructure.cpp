// A SubDyn substructure under the ElastoDyn turbine: the FE body of subdyn_fem.hpp on the ground, its
// transition piece (TP) at ElastoDyn's platform reference point, and ElastoDyn's platform body tied
// to the TP. OpenFAST couples the two modules there: ElastoDyn's platform motion is SubDyn's TP input
// and SubDyn's TP reaction loads act on ElastoDyn's platform, so the platform coordinates are the TP's
// six DOFs [JonkmanJonkman2016]. Here both are one multibody model: the substructure is a Ritz body
// whose first six coordinates are the TP's translations and small rotations (ground axes)
// [Branlard2019, §3.4], the platform and everything above it ride on its TP point.
#include <utility>

#include "src/base/error.hpp"
#include "src/turbine/elastodyn_parts.hpp"
#include "src/turbine/hydrodyn_strip.hpp"
#include "src/turbine/subdyn_fem.hpp"

namespace whirl::elastodyn {

PlatformParts addSubstructurePlatform(Builder& b, const io::OpenFastTurbine& t) {
  const io::SubDynInput& sd = *t.subdyn;
  const PlatformDescription d = describePlatform(b);
  PlatformParts out;
  out.reference = d.reference;
  MatX added;
  if (t.hydrodyn)
    added = stripTheoryAddedMass(*t.hydrodyn, subDynFem(sd, d.reference).spec.model, waterDensity(t), waterDepth(t));
  SubDynBody sub = buildSubDynBody(sd, d.reference, added);
  Body s;
  s.name = "substructure";  // body frame = ground frame (SubDyn's SS coordinates)
  s.inertia = std::move(sub.fem.body.inertia);
  s.elastic.K = std::move(sub.fem.body.elastic.K);
  s.elastic.D = std::move(sub.damping);
  s.elastic.A = std::move(sub.added_mass);
  // HydroDyn's additional stiffness and damping act at the platform reference point, the TP, whose six
  // DOFs (ground axes, small rotations) are the body's first coordinates.
  if (t.hydrodyn) {
    s.elastic.K.topLeftCorner(6, 6) += t.hydrodyn->AddCLin;
    s.elastic.D.topLeftCorner(6, 6) += t.hydrodyn->AddBLin;
  }
  s.points = std::move(sub.fem.body.points);
  const int tp_point = static_cast<int>(s.points.size()) - 1;  // the TP (rigidInterfacePoint, last)
  if (tp_point < 0 || s.points[tp_point].name != "TP") throw ComputeError("substructure: the FE body has no TP point");
  const int ne = s.inertia.ne;
  const int body = b.addBody(std::move(s));
  // The TP coordinates are ElastoDyn's platform DOFs: switched and initialised as they are.
  for (int k = 0; k < 6; ++k)
    out.dofs[k] = b.addDof(kPlatformDofNames[k], body, DofKind::Elastic, k, d.on[k], d.value[k]);
  for (int j = 6; j < ne; ++j) b.addDof("substructure CB " + std::to_string(j - 5), body, DofKind::Elastic, j, true);
  if (t.hydrodyn)
    for (int k = 0; k < 6; ++k)
      if (t.hydrodyn->AddF0(k) != 0.0) b.model().dof_loads.push_back({out.dofs[k], t.hydrodyn->AddF0(k), -1});
  Body p;
  p.name = "platform";
  p.parent = body;
  p.parent_point = tp_point;
  p.inertia = d.inertia;
  out.body = b.addBody(std::move(p));
  return out;
}

}  // namespace whirl::elastodyn
