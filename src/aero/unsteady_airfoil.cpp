#include "src/aero/unsteady_airfoil.hxx"

namespace whirl::aero {

template double hgmTimeScale<double>(const double&, double);
template ADChunk hgmTimeScale<ADChunk>(const ADChunk&, double);
template HgmState<double> hgmDerivative<double>(const UaSection&, const HgmState<double>&, const UaInput<double>&);
template HgmState<ADChunk> hgmDerivative<ADChunk>(const UaSection&, const HgmState<ADChunk>&, const UaInput<ADChunk>&);
template HgmState<double> hgmSteady<double>(const UaSection&, const UaInput<double>&);
template HgmState<ADChunk> hgmSteady<ADChunk>(const UaSection&, const UaInput<ADChunk>&);
template Coefficients<double> hgmLoads<double>(const UaSection&, const HgmState<double>&, const UaInput<double>&);
template Coefficients<ADChunk> hgmLoads<ADChunk>(const UaSection&, const HgmState<ADChunk>&, const UaInput<ADChunk>&);

}  // namespace whirl::aero
