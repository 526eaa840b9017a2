// The distribution layer (src/parallel/parallel_map.hpp) in one process, and the exact byte
// round trip of Campbell points that lets ranks send their results (modal/campbell_serialize.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "modal/campbell_serialize.hpp"
#include "src/base/error.hpp"
#include "src/parallel/parallel_map.hpp"
#include "src/parallel/session.hpp"

namespace whirl {
namespace {

TEST(ParallelMap, ResultsInTaskOrder) {
  int progress_calls = 0;
  parallel::MapOptions opt;
  opt.progress = [&](int done, int total) {
    ++progress_calls;
    EXPECT_EQ(total, 7);
    EXPECT_EQ(done, progress_calls);
  };
  const auto out = parallel::parallelMap<int>(
      7, [](int k) { return k * k; }, [](int v) { return std::to_string(v); },
      [](const std::string& b) { return std::stoi(b); }, opt);
  ASSERT_EQ(out.size(), 7u);
  for (int k = 0; k < 7; ++k) EXPECT_EQ(out[k], k * k);
  EXPECT_EQ(progress_calls, 7);
  EXPECT_TRUE(parallel::parallelMapBytes(0, [](int) { return std::string("x"); }).empty());
}

TEST(ParallelMap, LowestFailingTaskWinsWithItsType) {
  int ran = 0;
  auto task = [&](int k) -> std::string {
    ++ran;
    if (k == 3) throw InputError("cases/x.yaml:3: rpm: bad");
    if (k == 5) throw ComputeError("no convergence");
    return "ok";
  };
  try {
    parallel::parallelMapBytes(9, task);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cases/x.yaml:3: rpm: bad");
  }
  EXPECT_EQ(ran, 4);  // one process stops at its first failure, as the serial sweep did
  EXPECT_THROW(parallel::parallelMapBytes(9,
                                          [](int k) -> std::string {
                                            if (k == 2) throw ComputeError("x");
                                            return "";
                                          }),
               ComputeError);
}

// In one process the typed map keeps the tasks' results as they are (no byte round trip: an encoder that would
// fail is not called), stops at the first failing task with its type, and turns other errors into
// std::runtime_error with their text, as parallelMapBytes does.
TEST(ParallelMap, OneProcessKeepsTheResultsWithoutTheirBytes) {
  auto no_bytes = [](const std::vector<int>&) -> std::string { throw std::logic_error("encoded"); };
  auto no_result = [](const std::string&) -> std::vector<int> { throw std::logic_error("decoded"); };
  const auto out = parallel::parallelMap<std::vector<int>>(
      3, [](int k) { return std::vector<int>(k, k); }, no_bytes, no_result);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[2], (std::vector<int>{2, 2}));
  int ran = 0, progress = 0;
  parallel::MapOptions opt;
  opt.progress = [&](int done, int) { progress = done; };
  try {
    parallel::parallelMap<std::vector<int>>(
        9,
        [&](int k) {
          ++ran;
          if (k == 2) throw ComputeError("no convergence");
          return std::vector<int>{};
        },
        no_bytes, no_result, opt);
    FAIL() << "no exception";
  } catch (const ComputeError& e) {
    EXPECT_STREQ(e.what(), "no convergence");
  }
  EXPECT_EQ(ran, 3);
  EXPECT_EQ(progress, 3);  // the failing task counts as done, as in parallelMapBytes
  try {
    parallel::parallelMap<std::vector<int>>(
        2, [](int) -> std::vector<int> { throw std::length_error("vector::reserve"); }, no_bytes, no_result);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "vector::reserve");
    EXPECT_EQ(dynamic_cast<const std::length_error*>(&e), nullptr);
  }
}

TEST(ParallelMap, CommandLineSplitsPetscOptions) {
  const char* argv[] = {"whirl",
                        "modes",
                        "c.yaml",
                        "--petsc",
                        "-eps_nev 3  -st_type sinvert",
                        "--solver",
                        "sparse",
                        "--petsc=-eps_tol 1e-9",
                        "--",
                        "-pep_type",
                        "toar",
                        "--rpm"};
  std::vector<std::string> w, p;
  parallel::splitCommandLine(12, argv, w, p);
  EXPECT_EQ(w, (std::vector<std::string>{"whirl", "modes", "c.yaml", "--solver", "sparse"}));
  EXPECT_EQ(p, (std::vector<std::string>{"-eps_nev", "3", "-st_type", "sinvert", "-eps_tol", "1e-9", "-pep_type",
                                         "toar", "--rpm"}));
  const char* bad[] = {"whirl", "modes", "--petsc"};
  EXPECT_THROW(parallel::splitCommandLine(3, bad, w, p), InputError);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(CampbellSerialize, RoundTripIsBitExact) {
  CampbellPoint pt;
  pt.rpm = 12.1;
  pt.wind_speed = 11.4;
  pt.coordinates = {"tower FA 1", "flap 1 cos"};
  Mode m;
  m.freq_hz = 0.1 + 0.2;  // not representable in fewer digits
  m.damped_freq_hz = std::nextafter(0.3, 1.0);
  m.damping_ratio = -0.0;
  m.rigid_body = true;
  m.name = "flap 1 BW, \"quoted\"";
  m.shape = Eigen::VectorXcd(2);
  m.shape << std::complex<double>(1.0 / 3, -2.0 / 7), std::complex<double>(1e-300, 5e300);
  m.participation = Eigen::Vector2d(std::numeric_limits<double>::denorm_min(), 1 - 1e-16);
  m.residual = 3.3e-15;
  m.first_order = true;
  m.name_share = 0.625;
  m.runner_up = "edge 1 BW";
  m.runner_up_share = 0.5;
  m.ambiguous = true;
  // A node motion: every field of BodyMotion, the role too (the tower and blade tables of campbell.amp and
  // the report's drawing find bodies by it; the sweep's round trip once dropped it).
  BodyMotion bm;
  bm.body = "tower";
  bm.blade = -1;
  bm.role = "tower";
  bm.nodes = {"origin", "node 1"};
  bm.x = Eigen::Vector2d(0, 87.6);
  bm.position = Mat3X::Random(3, 2);
  bm.R = Mat3::Random();
  bm.u = Eigen::MatrixXcd::Random(2, 6);
  m.motion.bodies = {bm};
  m.motion.collective = Eigen::MatrixXcd::Random(2, 6);
  m.motion.backward = Eigen::MatrixXcd::Random(2, 6);
  m.motion.forward = Eigen::MatrixXcd::Random(2, 6);
  m.motion.blade_nodes = {"node 1", "node 2"};
  m.motion.blade_x = Eigen::Vector2d(1.5, 61.5);
  pt.modes = {m, m};
  pt.modes[1].residual.reset();
  const CampbellPoint back = decodeCampbellPoint(encodeCampbellPoint(pt));
  EXPECT_TRUE(sameBits(back.rpm, pt.rpm));
  EXPECT_TRUE(sameBits(*back.wind_speed, *pt.wind_speed));
  EXPECT_FALSE(back.pitch_deg.has_value());
  EXPECT_EQ(back.coordinates, pt.coordinates);
  ASSERT_EQ(back.modes.size(), 2u);
  const Mode& b = back.modes[0];
  EXPECT_TRUE(sameBits(b.freq_hz, m.freq_hz));
  EXPECT_TRUE(sameBits(b.damped_freq_hz, m.damped_freq_hz));
  EXPECT_TRUE(sameBits(b.damping_ratio, m.damping_ratio));  // the sign of −0 survives
  EXPECT_EQ(b.rigid_body, true);
  EXPECT_EQ(b.name, m.name);
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(sameBits(b.shape(i).real(), m.shape(i).real()));
    EXPECT_TRUE(sameBits(b.shape(i).imag(), m.shape(i).imag()));
    EXPECT_TRUE(sameBits(b.participation(i), m.participation(i)));
  }
  EXPECT_TRUE(sameBits(*b.residual, *m.residual));
  EXPECT_FALSE(back.modes[1].residual.has_value());
  EXPECT_TRUE(b.first_order);
  EXPECT_EQ(b.name_share, m.name_share);
  EXPECT_EQ(b.runner_up, m.runner_up);
  EXPECT_EQ(b.runner_up_share, m.runner_up_share);
  EXPECT_TRUE(b.ambiguous);
  ASSERT_EQ(b.motion.bodies.size(), 1u);
  const BodyMotion& bb = b.motion.bodies[0];
  EXPECT_EQ(bb.body, bm.body);
  EXPECT_EQ(bb.blade, bm.blade);
  EXPECT_EQ(bb.role, bm.role);
  EXPECT_EQ(bb.nodes, bm.nodes);
  EXPECT_EQ(bb.x, bm.x);
  EXPECT_EQ(bb.position, bm.position);
  EXPECT_EQ(bb.R, bm.R);
  EXPECT_EQ(bb.u, bm.u);
  EXPECT_EQ(b.motion.collective, m.motion.collective);
  EXPECT_EQ(b.motion.backward, m.motion.backward);
  EXPECT_EQ(b.motion.forward, m.motion.forward);
  EXPECT_EQ(b.motion.blade_nodes, m.motion.blade_nodes);
  EXPECT_EQ(b.motion.blade_x, m.motion.blade_x);
  EXPECT_THROW(decodeCampbellPoint("not cbor"), ComputeError);
}

}  // namespace
}  // namespace whirl
