// libFuzzer harness: the bytes are a `--schedule FILE.csv` (wind speed → rotor speed, pitch) as
// `whirl campbell` and `whirl export` read it. Beyond the reader's errors, every point it returns
// must be usable: rotor speed finite and ≥ 0, wind speed and pitch finite.
#include <cmath>

#include "fuzz/fuzz_support.hpp"
#include "src/io/text/schedule.hpp"

static int fuzzOne(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput("schedule.csv", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    for (const whirl::SweepPoint& p : whirl::readSchedule(path)) {
      const bool ok = std::isfinite(p.rpm) && p.rpm >= 0 && (!p.wind_speed || std::isfinite(*p.wind_speed)) &&
                      (!p.pitch_deg || std::isfinite(*p.pitch_deg));
      if (!ok) {
        std::fprintf(stderr, "whirl fuzz: FINDING: readSchedule returned an unusable point (rpm %g)\n", p.rpm);
        std::abort();
      }
    }
  });
  return 0;
}

static const whirl::fuzz::RegisterHarness kHarness("fuzz_schedule", fuzzOne);
