// Explicit instantiation of the residual and the input loads: the heavy templates compile once, for
// double and the AD chunk type (the kinematics: kinematics.cpp; the workspace: workspace.cpp).
#include "src/dynamics/residual.hxx"
#include "src/base/scalar.hpp"

namespace whirl {

template bool residual<double>(const Model&, Workspace<double>&, const VecX&, const VecX&, const VecX&, const VecX&,
                               VecX&, const AeroInflow*, AeroRecord*, const AdPass&);
template bool residual<ADChunk>(const Model&, Workspace<ADChunk>&, const VecXT<ADChunk>&, const VecXT<ADChunk>&,
                                const VecXT<ADChunk>&, const VecXT<ADChunk>&, VecXT<ADChunk>&, const AeroInflow*,
                                AeroRecord*, const AdPass&);
template void addInputLoads<double, double>(const Model&, const Workspace<double>&, const VecX&, const VecX&, VecX&);
template void addInputLoads<ADChunk, ADChunk>(const Model&, const Workspace<ADChunk>&, const VecXT<ADChunk>&,
                                              const VecXT<ADChunk>&, VecXT<ADChunk>&);
template void addInputLoads<double, ADChunk>(const Model&, const Workspace<double>&, const VecX&, const VecXT<ADChunk>&,
                                             VecXT<ADChunk>&);
template void addAeroLoads<double, ADChunk>(const Model&, Workspace<double>&, const VecX&, const VecXT<ADChunk>&,
                                            const AeroInflow*, AeroRecord*, VecXT<ADChunk>&, std::uint64_t,
                                            RotorTotals<ADChunk>*, AeroJets*);

}  // namespace whirl
