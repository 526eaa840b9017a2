// Explicit instantiation of the kinematics (kinematics.hxx) for double and the AD chunk type.
#include "src/dynamics/kinematics.hxx"
#include "src/base/scalar.hpp"

namespace whirl {

template void forwardKinematics<double>(const Model&, Workspace<double>&, const VecX&, const VecX&, const VecX&,
                                        const AdPass&);
template void forwardKinematics<ADChunk>(const Model&, Workspace<ADChunk>&, const VecXT<ADChunk>&,
                                         const VecXT<ADChunk>&, const VecXT<ADChunk>&, const AdPass&);
template Mat3T<double> axisRotation<double>(const Vec3&, const double&);

}  // namespace whirl
