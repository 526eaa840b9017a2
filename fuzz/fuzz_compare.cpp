// libFuzzer harness: the bytes are the reference table of `whirl compare RESULT.csv REF.csv`
// (columns mode, freq_hz[, whirl_mode]; `a|b` sets, `*`), compared in-process against a fixed
// modes table of the parked NREL 5MW (the result side goes through the same CSV reader).
#include "fuzz/fuzz_cli.hpp"
#include "src/cli/commands.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  static const std::string result = [] {
    const std::string text =
        "index,name,freq_hz,damped_freq_hz,damping_ratio\n"
        "1,tower SS 1,0.3139,0.3139,0.01\n2,tower FA 1,0.3244,0.3244,0.01\n3,drivetrain,0.6196,0.6196,0.0\n"
        "4,flap 1 BW,0.6664,0.6664,0.0\n5,flap 1 FW,0.6675,0.6675,0.0\n6,flap 1 collective,0.6993,0.6993,0.0\n"
        "7,edge 1 BW,1.0793,1.0793,0.0\n8,edge 1 FW,1.0898,1.0898,0.0\n9,tower SS 2,2.9537,2.9537,0.0\n";
    return whirl::fuzz::writeInput("result.csv", reinterpret_cast<const uint8_t*>(text.data()), text.size());
  }();
  const std::string ref = whirl::fuzz::writeInput("reference.csv", data, size);
  whirl::fuzz::runCommand(whirl::cli::addCompareCommand, {"compare", result, ref, "--tol-rel", "0.015"});
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_compare", fuzzOne);
