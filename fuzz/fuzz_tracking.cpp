// libFuzzer harness: the bytes are a `whirl campbell --tracking FILE` overrides file, applied by
// trackModes to the synthetic 5 MW Campbell diagram of the tests (tests/support). Beyond the
// reader's errors, the lines it returns must index existing modes.
#include "fuzz/fuzz_support.hpp"
#include "modal/tracking.hpp"
#include "synthetic_campbell.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const whirl::CampbellDiagram d = whirl::test::syntheticTurbineCampbell(false);
  const std::string path = whirl::fuzz::writeInput("tracking.csv", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    whirl::TrackingOptions opt;
    opt.overrides_file = path;
    for (const whirl::CampbellLine& l : whirl::trackModes(d.points, opt)) {
      bool ok = l.mode.size() == d.points.size();
      for (size_t p = 0; ok && p < l.mode.size(); ++p)
        ok = l.mode[p] >= -1 && l.mode[p] < static_cast<int>(d.points[p].modes.size());
      if (!ok) {
        std::fprintf(stderr, "whirl fuzz: FINDING: line '%s' indexes a mode that does not exist\n", l.name.c_str());
        std::abort();
      }
    }
  });
  return 0;
}
