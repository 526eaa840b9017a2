// The byte round trip of trimmed steady states (linearize/trim_serialize.hpp) that lets the ranks of a
// distributed trim schedule send their blocks to each other: every field that travels comes back bit
// for bit, the Newton matrices stay behind, and bytes that are not encoded states give a ComputeError.
#include <gtest/gtest.h>

#include "linearize/trim_serialize.hpp"
#include "src/base/error.hpp"
#include "tests/support/bit_exact.hpp"

namespace whirl {
namespace {

using test::sameBits;
const auto tricky = test::trickyDouble;

// Every field a distinct value; `seed` shifts them, `optionals` sets the condition's optional values.
SteadyState state(int seed, bool optionals) {
  SteadyState s;
  s.condition.rotor_speed = tricky(seed);
  if (optionals) {
    s.condition.azimuth = tricky(seed + 1);
    s.condition.collective_pitch = tricky(seed + 2);
    s.condition.blade_pitch_offsets = {tricky(seed + 3), tricky(seed + 4), tricky(seed + 5)};
    s.condition.wind_speed = tricky(seed + 6);
    s.condition.generator_torque = tricky(seed + 7);
    s.condition.yaw = -0.0;
  }
  s.above_rated = seed % 2 == 1;
  s.region = optionals ? "2.5 saturated + min pitch" : "";
  s.min_pitch = tricky(seed + 8);
  s.generator_efficiency = tricky(seed + 9);
  s.aero_torque = tricky(seed + 10);
  s.thrust = tricky(seed + 11);
  s.generator_torque = tricky(seed + 12);
  s.generator_speed = tricky(seed + 13);
  s.imbalance = tricky(seed + 14);
  s.tip_deflection = tricky(seed + 15);
  s.tower_top_fa = tricky(seed + 16);
  s.evaluations = 17 + seed;
  s.search_slope = tricky(seed + 17);
  for (int a = 0; a < 3; ++a) {
    s.azimuth_q.push_back(VecX::NullaryExpr(5, [&](Eigen::Index i) { return tricky(seed + a + static_cast<int>(i)); }));
    s.azimuth_stiffness.push_back(MatX::Constant(5, 5, tricky(a)));
  }
  if (optionals) s.azimuth_q.push_back(VecX());  // an empty vector travels as one
  return s;
}

void expectSameBits(const std::optional<double>& a, const std::optional<double>& b, const char* what) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what;
  if (a) {
    EXPECT_TRUE(sameBits(*a, *b)) << what;
  }
}

// `b` is `a` decoded: every field but the Newton matrices, bit for bit.
void expectSame(const SteadyState& a, const SteadyState& b) {
  EXPECT_TRUE(sameBits(a.condition.rotor_speed, b.condition.rotor_speed));
  expectSameBits(a.condition.azimuth, b.condition.azimuth, "azimuth");
  expectSameBits(a.condition.collective_pitch, b.condition.collective_pitch, "pitch");
  expectSameBits(a.condition.wind_speed, b.condition.wind_speed, "wind");
  expectSameBits(a.condition.generator_torque, b.condition.generator_torque, "generator torque");
  expectSameBits(a.condition.yaw, b.condition.yaw, "yaw");
  ASSERT_EQ(a.condition.blade_pitch_offsets.size(), b.condition.blade_pitch_offsets.size());
  for (size_t i = 0; i < a.condition.blade_pitch_offsets.size(); ++i)
    EXPECT_TRUE(sameBits(a.condition.blade_pitch_offsets[i], b.condition.blade_pitch_offsets[i]));
  EXPECT_EQ(a.above_rated, b.above_rated);
  EXPECT_EQ(a.region, b.region);
  EXPECT_EQ(a.evaluations, b.evaluations);
  const double SteadyState::*scalars[] = {&SteadyState::min_pitch,        &SteadyState::generator_efficiency,
                                          &SteadyState::aero_torque,      &SteadyState::thrust,
                                          &SteadyState::generator_torque, &SteadyState::generator_speed,
                                          &SteadyState::imbalance,        &SteadyState::tip_deflection,
                                          &SteadyState::tower_top_fa,     &SteadyState::search_slope};
  for (const auto field : scalars) EXPECT_TRUE(sameBits(a.*field, b.*field));
  ASSERT_EQ(a.azimuth_q.size(), b.azimuth_q.size());
  for (size_t k = 0; k < a.azimuth_q.size(); ++k) {
    ASSERT_EQ(a.azimuth_q[k].size(), b.azimuth_q[k].size());
    for (Eigen::Index i = 0; i < a.azimuth_q[k].size(); ++i)
      EXPECT_TRUE(sameBits(a.azimuth_q[k][i], b.azimuth_q[k][i])) << k << " " << i;
  }
  EXPECT_TRUE(b.azimuth_stiffness.empty());  // only the chain's next wind speed, on the same rank, uses them
}

TEST(TrimSerialize, EveryFieldBitForBit) {
  for (int seed = 0; seed < 8; ++seed)
    for (bool optionals : {false, true}) {
      const SteadyState s = state(seed, optionals);
      expectSame(s, decodeSteadyState(encodeSteadyState(s)));
    }
}

TEST(TrimSerialize, ListKeepsOrder) {
  const std::vector<SteadyState> states = {state(1, true), state(2, false), state(3, true)};
  const std::vector<SteadyState> back = decodeSteadyStates(encodeSteadyStates(states));
  ASSERT_EQ(back.size(), states.size());
  for (size_t k = 0; k < states.size(); ++k) expectSame(states[k], back[k]);
  EXPECT_TRUE(decodeSteadyStates(encodeSteadyStates({})).empty());
}

TEST(TrimSerialize, CorruptBytesAreComputeErrors) {
  const std::string good = encodeSteadyState(state(2, true));
  EXPECT_THROW(decodeSteadyState(good.substr(0, good.size() / 2)), ComputeError);
  EXPECT_THROW(decodeSteadyState(""), ComputeError);
  EXPECT_THROW(decodeSteadyState(encodeSteadyStates({state(1, false)})), ComputeError);  // a list, not a state
  EXPECT_THROW(decodeSteadyStates(good), ComputeError);                                  // a state, not a list
  try {
    decodeSteadyState("not cbor at all");
    FAIL() << "no exception";
  } catch (const ComputeError& e) {
    EXPECT_NE(std::string(e.what()).find("steady state: corrupt result bytes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace whirl
