// libFuzzer harness: the bytes are a ROSCO rotor performance file (`Cp_Ct_Cq.*.txt`, `whirl tune
// --cp-surface`): readRotorPerformance, then the Cp surface built and evaluated at its grid's middle.
#include "fuzz/fuzz_support.hpp"
#include "src/io/openfast/servodyn/rotor_performance_input.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput("Cp_Ct_Cq.txt", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::aero::RotorPerformance p = whirl::io::readRotorPerformance(path);
    const whirl::aero::PerformanceSurface cp(p.pitch, p.tsr, p.cp);
    (void)cp.value(p.pitch[p.pitch.size() / 2], p.tsr[p.tsr.size() / 2]);
  });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_rotor_performance", fuzzOne);
