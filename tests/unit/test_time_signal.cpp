// Input histories of `whirl simulate` (src/model/time_signal.hpp, src/io/text/time_signal_reader.hpp):
// the values and derivatives of each kind, their breakpoints, and the messages for bad forms.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "src/base/error.hpp"
#include "src/io/text/time_signal_reader.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;

std::string errorOf(const std::string& text) {
  try {
    parseTimeSignal(text, "--input thrust");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TimeSignal, StepRampSineAddToTheBase) {
  const TimeSignal step = parseTimeSignal("step(1.5, 2)", "k");
  EXPECT_EQ(evaluateSignal(step, 10, 1.4).value, 10);
  EXPECT_EQ(evaluateSignal(step, 10, 1.5).value, 12);
  EXPECT_EQ(signalBreakpoints(step), std::vector<double>{1.5});
  const TimeSignal ramp = parseTimeSignal("ramp(1,3,4)", "k");
  EXPECT_EQ(evaluateSignal(ramp, 1, 0.5).value, 1);
  EXPECT_DOUBLE_EQ(evaluateSignal(ramp, 1, 2).value, 3);
  EXPECT_DOUBLE_EQ(evaluateSignal(ramp, 1, 2).rate, 2);
  EXPECT_EQ(evaluateSignal(ramp, 1, 5).value, 5);
  EXPECT_EQ(evaluateSignal(ramp, 1, 5).rate, 0);
  const TimeSignal sine = parseTimeSignal("sin(2, 0.25)", "k");
  const double w = std::numbers::pi / 2, t = 0.3;
  const SignalValue s = evaluateSignal(sine, 1, t);
  EXPECT_DOUBLE_EQ(s.value, 1 + 2 * std::sin(w * t));
  EXPECT_DOUBLE_EQ(s.rate, 2 * w * std::cos(w * t));
  EXPECT_DOUBLE_EQ(s.acceleration, -2 * w * w * std::sin(w * t));
  EXPECT_TRUE(signalBreakpoints(sine).empty());
}

TEST(TimeSignal, SpinupIsKanesDriver) {
  // [Branlard2019, §5.2]: θ̈ = (2/5)(1 − cos(πt/7.5)) for 15 s, then 6 rad/s.
  const TimeSignal s = parseTimeSignal("spinup(15, 6)", "k");
  const double t = 4.2;
  EXPECT_NEAR(evaluateSignal(s, 0, t).acceleration, 0.4 * (1 - std::cos(std::numbers::pi * t / 7.5)), 1e-15);
  EXPECT_DOUBLE_EQ(evaluateSignal(s, 0, 15).rate, 6);
  EXPECT_DOUBLE_EQ(evaluateSignal(s, 0, 15).value, 45);  // ∫ θ̇ = w T/2
  EXPECT_NEAR(evaluateSignal(s, 0, 15 - 1e-9).value, 45, 1e-8);
  EXPECT_DOUBLE_EQ(evaluateSignal(s, 1, 17).value, 1 + 45 + 12);
  EXPECT_EQ(evaluateSignal(s, 0, 17).acceleration, 0);
  // θ̇ is the integral of θ̈ (midpoint rule over [0, t]).
  double v = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) v += evaluateSignal(s, 0, (k + 0.5) * t / n).acceleration * t / n;
  EXPECT_NEAR(evaluateSignal(s, 0, t).rate, v, 1e-6);
  EXPECT_THAT(errorOf("spinup(0,6)"), HasSubstr("spin-up time T must be > 0"));
}

TEST(TimeSignal, TableIsInterpolatedAndHeldAtItsEnds) {
  const auto path = std::filesystem::temp_directory_path() / "whirl_signal_table.csv";
  std::ofstream(path) << "time_s,pitch_rad\n0,0\n2,1\n4,1\n";
  const TimeSignal s = parseTimeSignal(path.string(), "k");
  EXPECT_EQ(evaluateSignal(s, 99, -1).value, 0);  // absolute: the base is not added
  EXPECT_DOUBLE_EQ(evaluateSignal(s, 99, 1).value, 0.5);
  EXPECT_DOUBLE_EQ(evaluateSignal(s, 99, 1).rate, 0.5);
  EXPECT_EQ(evaluateSignal(s, 99, 10).value, 1);
  EXPECT_EQ(signalBreakpoints(s), (std::vector<double>{0, 2, 4}));
}

TEST(TimeSignal, BadFormsNameTheOptionAndTheReason) {
  EXPECT_THAT(errorOf("step(1)"), HasSubstr("--input thrust: 'step(1)': step takes 2 numbers, got 1"));
  EXPECT_THAT(errorOf("ramp(2,1,3)"), HasSubstr("must end (t1) after it starts"));
  EXPECT_THAT(errorOf("sin(1,x)"), HasSubstr("'x' is not a finite number"));
  EXPECT_THAT(errorOf("square(1,2)"), HasSubstr("unknown signal"));
  EXPECT_THAT(errorOf(""), HasSubstr("empty signal"));
  const auto path = std::filesystem::temp_directory_path() / "whirl_signal_bad.csv";
  std::ofstream(path) << "time,value\n0,1\n1,2\n1,3\n";
  EXPECT_THAT(errorOf(path.string()), HasSubstr(":4: time: time not increasing (1 after 1)"));
  EXPECT_THAT(errorOf("/nonexistent/signal.csv"), HasSubstr("/nonexistent/signal.csv"));
}

TEST(TimeSignal, AssignmentSplitsAtTheFirstEquals) {
  EXPECT_EQ(splitAssignment(" tower FA 1 = 0.5 ", "--init"),
            (std::pair<std::string, std::string>{"tower FA 1", "0.5"}));
  EXPECT_THROW(splitAssignment("=1", "--init"), InputError);
  EXPECT_THROW(splitAssignment("abc", "--init"), InputError);
}

}  // namespace
}  // namespace whirl
