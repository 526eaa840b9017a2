#pragma once
/// \file
/// whirl's DOF names for OpenFAST state descriptions: "ED 1st flapwise bending-mode DOF of blade 2
/// (internal DOF index = DOF_BF(2,1)), m" → "blade 2 flap 1", "ED 1st tower fore-aft bending mode DOF"
/// → "tower FA 1", "ED Variable speed generator DOF" → "generator azimuth", … so that modes from
/// `.lin` files carry the same names as whirl's own models. BeamDyn nodes: "BD_2 finite element node 3
/// (…) rotational displacement in Y, rad" → "blade 2 BD node 3 rotation Y" (BeamDyn's own axes).
/// HydroDyn states: "HD RdtnPtfmSg3" → "HydroDyn radiation surge 3"; AeroDyn's unsteady-airfoil states:
/// "AD x1 blade 2, node 7, rad" → "UA x1 blade 2 element 7" (group "UA x1 blade 2"); its DBEMT states: "AD vind
/// (axial) at blade 1, node 2, m/s" → "DBEMT v axial blade 1 element 2", "AD First time derivative of vind
/// (axial) …" → "DBEMT v1 axial …" (Øye's intermediate state). Unknown states keep their
/// description (without the module prefix and the "(internal …)" part).
#include <string>

namespace whirl {

std::string dofNameFromLinDescription(const std::string& description);

/// What a first-order state is part of, for naming the modes it dominates: the name without its
/// trailing index ("HydroDyn radiation surge 3" → "HydroDyn radiation surge").
std::string firstOrderGroupFromLinDescription(const std::string& description);

/// True for the generator azimuth / rotor azimuth state (a rigid rotation of the rotor).
bool isAzimuthLinDescription(const std::string& description);

}  // namespace whirl
