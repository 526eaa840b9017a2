// Explicit instantiation: the heavy templates compile once, for double and the AD chunk type.
#include "src/dynamics/residual.hxx"
#include "src/model/scalar.hpp"

namespace whirl {

template struct Workspace<double>;
template struct Workspace<ADChunk>;
template void forwardKinematics<double>(const Model&, Workspace<double>&, const VecX&, const VecX&, const VecX&);
template void forwardKinematics<ADChunk>(const Model&, Workspace<ADChunk>&, const VecXT<ADChunk>&,
                                         const VecXT<ADChunk>&, const VecXT<ADChunk>&);
template void residual<double>(const Model&, Workspace<double>&, const VecX&, const VecX&, const VecX&, const VecX&,
                               VecX&, const AeroInflow*, AeroRecord*);
template void residual<ADChunk>(const Model&, Workspace<ADChunk>&, const VecXT<ADChunk>&, const VecXT<ADChunk>&,
                                const VecXT<ADChunk>&, const VecXT<ADChunk>&, VecXT<ADChunk>&, const AeroInflow*,
                                AeroRecord*);
template void addInputLoads<double, double>(const Model&, const Workspace<double>&, const VecX&, const VecX&, VecX&);
template void addInputLoads<ADChunk, ADChunk>(const Model&, const Workspace<ADChunk>&, const VecXT<ADChunk>&,
                                              const VecXT<ADChunk>&, VecXT<ADChunk>&);
template void addInputLoads<double, ADChunk>(const Model&, const Workspace<double>&, const VecX&,
                                             const VecXT<ADChunk>&, VecXT<ADChunk>&);
template void addAeroLoads<double, ADChunk>(const Model&, Workspace<double>&, const VecX&,
                                            const VecXT<ADChunk>&, const AeroInflow*, AeroRecord*, VecXT<ADChunk>&,
                                            std::uint64_t, RotorTotals<ADChunk>*, AeroJets*);
template Mat3T<double> axisRotation<double>(const Vec3&, const double&);

}  // namespace whirl
