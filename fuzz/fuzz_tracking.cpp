// libFuzzer harness: the bytes are a `whirl campbell --tracking FILE` overrides file. trackModes
// tracks the synthetic 5 MW Campbell diagram of the tests (tests/support) once, then applies the
// file with applyTrackingOverridesText, the function trackModes ends with (through
// applyTrackingOverrides, which only reads the file first) — re-tracking per input would make the
// harness 100x slower for no parser coverage. Beyond the reader's errors, the lines must still
// index existing modes.
#include "fuzz/fuzz_support.hpp"
#include "modal/tracking.hpp"
#include "modal/tracking_overrides.hpp"
#include "synthetic_campbell.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  static const whirl::CampbellDiagram d = whirl::test::syntheticTurbineCampbell(false);
  static const std::vector<whirl::CampbellLine> tracked = whirl::trackModes(d.points);
  const std::string text(reinterpret_cast<const char*>(data), size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    std::vector<whirl::CampbellLine> lines = tracked;
    whirl::applyTrackingOverridesText(text, "tracking.csv", d.points, lines);
    for (const whirl::CampbellLine& l : lines) {
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

static const whirl::fuzz::RegisterHarness kHarness("fuzz_tracking", fuzzOne);
