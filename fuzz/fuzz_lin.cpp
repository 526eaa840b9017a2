// libFuzzer harness: the bytes are an OpenFAST linearization file, run through `whirl lin FILE.lin
// --format csv` in-process: readOpenFastLin, the MBC layout from the state descriptions, the
// multiblade transform and the modes.
#include "fuzz/fuzz_cli.hpp"
#include "src/cli/commands.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput("fuzz.lin", data, size);
  whirl::fuzz::runCommand(whirl::cli::addLinCommand, {"lin", path, "--format", "csv"});
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_lin", fuzzOne);
