// The byte round trip of exported operating points (linearize/export_serialize.hpp) that lets MPI
// ranks send their results to rank 0: every field comes back bit for bit, and bytes that are not
// an encoded point give a ComputeError, never a crash.
#include <gtest/gtest.h>

#include <cmath>

#include "linearize/export_serialize.hpp"
#include "src/base/error.hpp"
#include "tests/support/bit_exact.hpp"

namespace whirl {
namespace {

using test::sameBits;
const auto tricky = test::trickyDouble;

StateSpaceVariable variable(int i) {
  return {"var " + std::to_string(i), i % 2 ? "rad" : "m", tricky(i + 3), i % 4 - 1, i % 3 ? i / 2 : -1, i == 0};
}

StateSpaceModel model(int nx, int nu, int ny, int seed, bool with_wind) {
  StateSpaceModel s;
  for (int i = 0; i < nx; ++i) s.x.push_back(variable(seed + i));
  for (int i = 0; i < nu; ++i) s.u.push_back(variable(seed + 10 + i));
  for (int i = 0; i < ny; ++i) s.y.push_back(variable(seed + 20 + i));
  s.xdot_op = VecX::NullaryExpr(nx, [&](Eigen::Index i) { return tricky(seed + static_cast<int>(i)); });
  auto fill = [&](int r, int c) {
    return MatX::NullaryExpr(r, c, [&](Eigen::Index i, Eigen::Index j) {
      return tricky(seed + static_cast<int>(3 * i + 5 * j));
    });
  };
  s.A = fill(nx, nx);
  s.B = fill(nx, nu);
  s.C = fill(ny, nx);
  s.D = fill(ny, nu);
  s.azimuth = tricky(seed + 1);
  s.rotor_speed = tricky(seed + 2);
  if (with_wind) s.wind_speed = tricky(seed + 5);
  s.multiblade = seed % 2 == 0;
  return s;
}

ExportPoint point(bool optionals) {
  ExportPoint p;
  p.rpm = 12.1;
  if (optionals) {
    p.wind_speed = -0.0;
    p.pitch_deg = tricky(3);  // the NaN with a payload
  }
  p.model = model(4, 2, 3, 0, optionals);
  if (optionals)
    for (int k = 0; k < 3; ++k) p.azimuths.push_back(model(4, 2, 3, k + 1, true));
  p.azimuths.push_back(model(0, 0, 0, 7, false));  // empty matrices and lists
  p.equilibrium.q = VecX::Constant(5, tricky(2));
  p.equilibrium.qd = VecX::Constant(5, tricky(3));
  p.equilibrium.qdd = VecX::Constant(5, -0.0);
  p.equilibrium.u = VecX::Constant(2, tricky(5));
  p.equilibrium.solved = {0, 2, 4};
  p.equilibrium.held = {1};
  p.equilibrium.held_load = VecX::Constant(1, tricky(4));
  p.equilibrium.iterations = 7;
  p.equilibrium.residual_norm = tricky(2);
  p.equilibrium.residual_max_active = 3e-9;
  p.equilibrium.residual_max_dof = "tower FA 1";
  return p;
}

template <class M>
void expectSameBits(const M& a, const M& b, const std::string& what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  ASSERT_EQ(a.cols(), b.cols()) << what;
  for (Eigen::Index i = 0; i < a.size(); ++i) EXPECT_TRUE(sameBits(a.data()[i], b.data()[i])) << what << " " << i;
}

void expectSame(const std::vector<StateSpaceVariable>& a, const std::vector<StateSpaceVariable>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].unit, b[i].unit);
    EXPECT_TRUE(sameBits(a[i].op, b[i].op)) << a[i].name;
    EXPECT_EQ(a[i].blade, b[i].blade);
    EXPECT_EQ(a[i].rate_of, b[i].rate_of);
    EXPECT_EQ(a[i].azimuth, b[i].azimuth);
  }
}

void expectSame(const StateSpaceModel& a, const StateSpaceModel& b) {
  expectSame(a.x, b.x);
  expectSame(a.u, b.u);
  expectSame(a.y, b.y);
  expectSameBits(a.xdot_op, b.xdot_op, "xdot_op");
  expectSameBits(a.A, b.A, "A");
  expectSameBits(a.B, b.B, "B");
  expectSameBits(a.C, b.C, "C");
  expectSameBits(a.D, b.D, "D");
  EXPECT_TRUE(sameBits(a.azimuth, b.azimuth));
  EXPECT_TRUE(sameBits(a.rotor_speed, b.rotor_speed));
  ASSERT_EQ(a.wind_speed.has_value(), b.wind_speed.has_value());
  if (a.wind_speed) {
    EXPECT_TRUE(sameBits(*a.wind_speed, *b.wind_speed));
  }
  EXPECT_EQ(a.multiblade, b.multiblade);
}

TEST(ExportSerialize, RoundTripIsBitExact) {
  for (bool optionals : {true, false}) {
    const ExportPoint p = point(optionals);
    const ExportPoint q = decodeExportPoint(encodeExportPoint(p));
    EXPECT_TRUE(sameBits(p.rpm, q.rpm));
    ASSERT_EQ(p.wind_speed.has_value(), q.wind_speed.has_value());
    ASSERT_EQ(p.pitch_deg.has_value(), q.pitch_deg.has_value());
    if (p.wind_speed) {
      EXPECT_TRUE(sameBits(*p.wind_speed, *q.wind_speed));
    }
    if (p.pitch_deg) {
      EXPECT_TRUE(sameBits(*p.pitch_deg, *q.pitch_deg));
    }
    expectSame(p.model, q.model);
    ASSERT_EQ(p.azimuths.size(), q.azimuths.size());
    for (size_t k = 0; k < p.azimuths.size(); ++k) expectSame(p.azimuths[k], q.azimuths[k]);
    const OperatingPoint &a = p.equilibrium, &b = q.equilibrium;
    expectSameBits(a.q, b.q, "q");
    expectSameBits(a.qd, b.qd, "qd");
    expectSameBits(a.qdd, b.qdd, "qdd");
    expectSameBits(a.u, b.u, "u");
    EXPECT_EQ(a.solved, b.solved);
    EXPECT_EQ(a.held, b.held);
    expectSameBits(a.held_load, b.held_load, "held_load");
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_TRUE(sameBits(a.residual_norm, b.residual_norm));
    EXPECT_TRUE(sameBits(a.residual_max_active, b.residual_max_active));
    EXPECT_EQ(a.residual_max_dof, b.residual_max_dof);
    EXPECT_EQ(encodeExportPoint(q), encodeExportPoint(p));  // deterministic: ranks send the same bytes
  }
}

// Every truncation, every byte altered and bytes of another kind: a decoded point or a
// ComputeError naming the corruption, nothing else.
TEST(ExportSerialize, CorruptBytesGiveAClearError) {
  const std::string bytes = encodeExportPoint(point(true));
  for (size_t n = 0; n < bytes.size(); ++n) {
    try {
      decodeExportPoint(bytes.substr(0, n));
      ADD_FAILURE() << "truncated to " << n << " bytes, yet decoded";
    } catch (const ComputeError& e) {
      EXPECT_NE(std::string(e.what()).find("export point: corrupt result bytes"), std::string::npos) << e.what();
    }
  }
  for (size_t i = 0; i < bytes.size(); ++i)
    for (unsigned char v : {0x00, 0x1b, 0xff}) {
      std::string b = bytes;
      b[i] = static_cast<char>(v);
      try {
        decodeExportPoint(b);
      } catch (const ComputeError&) {
      }
    }
  EXPECT_THROW(decodeExportPoint("not cbor at all"), ComputeError);
  EXPECT_THROW(decodeExportPoint(std::string("\x18\x2a", 2)), ComputeError);  // CBOR 42
}

}  // namespace
}  // namespace whirl
