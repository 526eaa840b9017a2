#pragma once
/// \file
/// Generalized forces of the quasi-static mooring lines (src/model/mooring.hpp): each line's fairlead
/// tension (catenary.hpp) at the fairlead's current position, applied to its body as a ground-frame
/// force at the fairlead. Nonlinear in the body pose, so the operating point carries the mean offset
/// under thrust and AD through the catenary solution gives the mooring stiffness with its geometric
/// (pretension) part.
#include "src/dynamics/catenary.hxx"
#include "src/dynamics/workspace.hpp"

namespace whirl::detail {

template <class T>
void addMooringLoads(const Model& m, const Workspace<T>& ws, VecXT<T>& e) {
  for (const MooringLine& ln : m.mooring) {
    const FrameState<T>& f = ws.frames[ln.body];
    const Vec3T<T> s = f.R * ln.fairlead.cast<T>();    // body origin → fairlead, ground frame
    const Vec3T<T> d = f.r + s - ln.anchor.cast<T>();  // anchor → fairlead
    const Vec3T<T> F = mooringFairleadForce<T>(ln, d);
    const Vec3T<T> M = s.cross(F);
    for (int sd : m.support[ln.body]) e(sd) += f.Jv.col(sd).dot(F) + f.Jw.col(sd).dot(M);
  }
}

}  // namespace whirl::detail
