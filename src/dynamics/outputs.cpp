// Explicit instantiation of the outputs for double and the AD chunk type.
#include "src/dynamics/outputs.hxx"
#include "src/base/scalar.hpp"
#include "src/dynamics/aero_loads.hxx"

namespace whirl {

template void evaluateOutputs<double>(const Model&, Workspace<double>&, const VecX&, const VecX&, const VecX&, VecX&,
                                      const VecX*, const AeroInflow*, const AdPass&, const VecX*);
template void evaluateOutputs<ADChunk>(const Model&, Workspace<ADChunk>&, const VecXT<ADChunk>&, const VecXT<ADChunk>&,
                                       const VecXT<ADChunk>&, VecXT<ADChunk>&, const VecXT<ADChunk>*, const AeroInflow*,
                                       const AdPass&, const VecXT<ADChunk>*);

}  // namespace whirl
