// `whirl modes` on the OC3-Hywind deck (cases/oc3_hywind, OpenFAST certification Test24): the six
// platform modes by name, the one-line note for the ignored waves, and the one-line refusal of the
// deck's radiation convolution.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

const std::string kDeck = "cases/oc3_hywind/Test24.fst";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(CliOffshore, Oc3HywindPlatformModes) {
  const auto r = test::whirl("modes " + kDeck + " --set CompAero=0 --set RdtnMod=0 --set RotSpeed=0 --set GenDOF=False");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"platform surge", "platform sway", "platform heave", "platform roll", "platform pitch",
                           "platform yaw"})
    EXPECT_THAT(r.out, HasSubstr(name));
  EXPECT_THAT(r.err, HasSubstr("HydroDyn.dat:9: WaveMod: incident waves ignored"));
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

TEST(CliOffshore, RadiationConvolutionRefusedOnOneLine) {
  const auto r = test::whirl("modes " + kDeck + " --set CompAero=0");
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("HydroDyn.dat:53: RdtnMod: 1 not supported by whirl"));
  EXPECT_THAT(r.err, HasSubstr("--set RdtnMod=0"));
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

}  // namespace
}  // namespace whirl
