// libFuzzer harness for the SubDyn reader: the bytes are a SubDyn input file, read as `whirl modes`
// reads a deck's SubFile (io::readSubDyn) and turned into the substructure body (SubDyn's
// discretization, the transition-piece tie, the Guyan or Craig–Bampton reduction) as the turbine
// builder does, with the transition piece at the OC3 monopile's platform reference point.
#include "fuzz/fuzz_support.hpp"
#include "src/io/openfast/offshore/subdyn_input.hpp"
#include "src/turbine/subdyn_fem.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput("fuzz_SubDyn.dat", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::io::SubDynInput sd = whirl::io::readSubDyn(path);
    whirl::buildSubDynBody(sd, whirl::Vec3(0, 0, 10));
  });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_subdyn", fuzzOne);
