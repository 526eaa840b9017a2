#pragma once
/// \file
/// A quasi-static mooring line: an elastic catenary from a fairlead on a body to an anchor fixed to
/// the ground, with seabed contact and friction [Jonkman2007], as MAP++ and FAST's quasi-static
/// mooring module describe it. Plain data; the tension comes from src/dynamics/catenary.hpp.
#include <string>

#include "src/base/types.hpp"

namespace whirl {

struct MooringLine {
  std::string name;              ///< for messages, e.g. "mooring line 2"
  int body = -1;                 ///< body the fairlead belongs to (a rigid body, e.g. the platform)
  Vec3 fairlead = Vec3::Zero();  ///< fairlead, body frame, from the body origin [m]
  Vec3 anchor = Vec3::Zero();    ///< anchor, ground frame [m]
  double length = 0.0;           ///< unstretched length L [m]
  double weight = 0.0;           ///< apparent weight in fluid per unit length w > 0 [N/m]
  double EA = 0.0;               ///< axial stiffness [N]
  double CB = 0.0;               ///< seabed static-friction coefficient [-] (0: no friction)
  bool seabed = false;           ///< the anchor lies on the seabed: the line may rest on it
};

}  // namespace whirl
