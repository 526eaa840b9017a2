// libFuzzer harness: the bytes are a YAML case file (`whirl modes CASE.yaml`): readCase builds and
// finalizes the model, then one equilibrium and one linearization for small models.
#include "fuzz/fuzz_support.hpp"
#include "src/io/case/case_file.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput("case.yaml", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::Model m = whirl::readCase(path);
    whirl::fuzz::solveAndLinearize(m);
  });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_case_yaml", fuzzOne);
