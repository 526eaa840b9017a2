// libFuzzer harness for the BeamDyn reader: the bytes are a BeamDyn blade file (stations with their
// 6 × 6 matrices), named by a fixed primary file (a straight axis of four key points), read as the
// turbine builder reads a deck's BDBldFile (io::readBeamDyn) and turned into the FE blade and its
// modes (beamDynBladeBody, 6 elements and 4 modes to keep each run short).
#include "fuzz/fuzz_support.hpp"
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"
#include "src/turbine/beamdyn_blade.hpp"

namespace {

constexpr const char* kPrimary =
    "--------- BEAMDYN with OpenFAST INPUT FILE ---------\nfuzz\n"
    "---------------------- SIMULATION CONTROL --------\n"
    "False         Echo            - Echo\n"
    " 2            quadrature      - 1=Gaussian; 2=Trapezoidal\n"
    " 2            refine          - refinement\n"
    "---------------------- GEOMETRY PARAMETER --------\n"
    "          1   member_total    - members\n"
    "          4   kp_total        - key points\n"
    "     1     4                 - Member number; Number of key points in this member\n"
    "  kp_xr kp_yr kp_zr initial_twist\n  (m) (m) (m) (deg)\n"
    "  0.0  0.0  0.0  10.0\n  0.0  0.0  10.0  5.0\n  -0.1  0.0  20.0  2.0\n  -0.3  0.0  30.0  0.0\n"
    "---------------------- MESH PARAMETER ------------\n"
    "          5   order_elem      - order\n"
    "---------------------- MATERIAL PARAMETER --------\n"
    "\"fuzz_BeamDyn_Blade.dat\"    BldFile         - blade file\n"
    "---------------------- PITCH ACTUATOR PARAMETERS -\n"
    "False         UsePitchAct     - actuator\n"
    "---------------------- OUTPUTS -------------------\n"
    "              OutList         - outputs\n"
    "END of input file\n";

}  // namespace

static int fuzzOne(const uint8_t* data, size_t size) {
  whirl::fuzz::writeInput("fuzz_BeamDyn_Blade.dat", data, size);
  const std::string primary = whirl::fuzz::writeInput("fuzz_BeamDyn.dat", reinterpret_cast<const uint8_t*>(kPrimary),
                                                      std::char_traits<char>::length(kPrimary));
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::io::BeamDynInput bd = whirl::io::readBeamDyn(primary);
    whirl::beamDynBladeBody(bd, {6, 4});
  });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_read_beamdyn", fuzzOne);
