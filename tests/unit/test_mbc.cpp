// Multiblade coordinate transform on systems with known answers: an isotropic rotor (whirl split
// ±Ω, ±2Ω, differential mode), a fixed-frame system seen from the rotating frame (recovered
// exactly), and the errors of linearize/mbc.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "linearize/mbc.hpp"
#include "modal/eigen.hpp"
#include "src/base/error.hpp"

namespace {

using cd = std::complex<double>;

std::vector<cd> sortedValues(std::vector<cd> v) {
  std::sort(v.begin(), v.end(), [](cd a, cd b) {
    return std::abs(a.imag() - b.imag()) > 1e-9 ? a.imag() < b.imag() : a.real() < b.real();
  });
  return v;
}

void expectSameEigenvalues(const Eigen::MatrixXd& A, std::vector<cd> expected) {
  const auto ev = whirl::eigenStandard(A).values;
  ASSERT_EQ(static_cast<std::size_t>(ev.size()), expected.size());
  const auto got = sortedValues({ev.data(), ev.data() + ev.size()});
  expected = sortedValues(expected);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_LT(std::abs(got[i] - expected[i]), 1e-9) << i << " " << got[i];
}

// N identical blades, each a damped oscillator q̈_b + 2ζω q̇_b + ω² q_b = g u_b (a flap mode with
// its pitch input) plus a first-order lag state ẋ_b = −x_b/τ; a tower DOF in the fixed frame; outputs
// tower displacement and root moments k q_b + d u_b. In the rotating frame A is constant; seen from
// the fixed frame the cyclic modes split by ±Ω (BW: ω_d − Ω, FW: ω_d + Ω), the k-th harmonic
// coordinates (N ≥ 5) by ±kΩ, while collective and differential modes keep λ [Bir2008, §3].
struct IsotropicRotor {
  int N;
  double w = 4.0, zeta = 0.05, tau = 0.5, wt = 2.0, zt = 0.01, g = 3.0, k = 7.0, d = 0.25, Omega = 1.2;
  int n() const { return 1 + N; }  // DOFs
  whirl::MbcLayout layout() const {
    std::vector<int> dofs = {-1}, lag;
    for (int b = 0; b < N; ++b) dofs.push_back(b), lag.push_back(b);
    auto L = whirl::secondOrderLayout(N, dofs, lag);
    L.input_blade = dofs;
    L.output_blade = dofs;
    return L;
  }
  whirl::MbcSample sample(double psi) const {
    const int nd = n(), nx = 2 * nd + N;
    whirl::MbcSample s;
    s.azimuth = psi;
    s.rotor_speed = Omega;
    s.A = Eigen::MatrixXd::Zero(nx, nx);
    s.A.block(0, nd, nd, nd).setIdentity();
    s.A(nd, 0) = -wt * wt, s.A(nd, nd) = -2 * zt * wt;
    s.B = Eigen::MatrixXd::Zero(nx, nd);
    s.C = Eigen::MatrixXd::Zero(nd, nx);
    s.D = Eigen::MatrixXd::Zero(nd, nd);
    s.B(nd, 0) = 1.0, s.C(0, 0) = 1.0;
    for (int b = 1; b <= N; ++b) {
      s.A(nd + b, b) = -w * w, s.A(nd + b, nd + b) = -2 * zeta * w;
      s.A(2 * nd + b - 1, 2 * nd + b - 1) = -1.0 / tau;
      s.B(nd + b, b) = g, s.C(b, b) = k, s.D(b, b) = d;
    }
    return s;
  }
  /// Eigenvalues seen from the fixed frame.
  std::vector<cd> expected() const {
    const double wd = w * std::sqrt(1 - zeta * zeta), wtd = wt * std::sqrt(1 - zt * zt);
    std::vector<cd> v = {{-zt * wt, wtd}, {-zt * wt, -wtd}, {-zeta * w, wd}, {-zeta * w, -wd}, {-1 / tau, 0}};
    for (int h = 1; h <= (N - 1) / 2; ++h)
      for (double s : {1.0, -1.0}) {
        v.push_back({-zeta * w, s * (wd + h * Omega)}), v.push_back({-zeta * w, s * (wd - h * Omega)});
        v.push_back({-1 / tau, s * h * Omega});
      }
    if (N % 2 == 0) v.insert(v.end(), {{-zeta * w, wd}, {-zeta * w, -wd}, {-1 / tau, 0}});
    return v;
  }
};

class IsotropicRotorTest : public ::testing::TestWithParam<int> {};

TEST_P(IsotropicRotorTest, WhirlSplitAndTimeInvariance) {
  const IsotropicRotor rotor{GetParam()};
  const int N = rotor.N, nd = rotor.n();
  std::vector<whirl::MbcSample> samples;
  for (double psi : {0.3, 2.4, 4.5, 5.9}) samples.push_back(rotor.sample(psi));
  const auto r = whirl::mbcAverage(rotor.layout(), samples);

  // Truly time-invariant in the fixed frame: every azimuth gives the same A_NR, B_NR, C_NR, D_NR.
  for (const auto& s : r.samples) {
    EXPECT_LT((s.A - r.A).norm(), 1e-12 * r.A.norm());
    EXPECT_LT((s.B - r.B).norm(), 1e-12);
    EXPECT_LT((s.C - r.C).norm(), 1e-12);
    EXPECT_LT((s.D - r.D).norm(), 1e-12);
  }
  expectSameEigenvalues(r.A, rotor.expected());
  if (N == 3) {  // the classic split, stated explicitly: 4 rad/s blade mode at 1.2 rad/s rotor speed
    const auto ev = whirl::eigenStandard(r.A).values;
    std::vector<double> fd;
    for (Eigen::Index j = 0; j < ev.size(); ++j)
      if (ev(j).imag() > 0 && std::abs(ev(j).real() + rotor.zeta * rotor.w) < 1e-9) fd.push_back(ev(j).imag());
    std::sort(fd.begin(), fd.end());
    const double wd = rotor.w * std::sqrt(1 - rotor.zeta * rotor.zeta);
    ASSERT_EQ(fd.size(), 3u);
    EXPECT_NEAR(fd[0], wd - rotor.Omega, 1e-10);  // backward whirl
    EXPECT_NEAR(fd[1], wd, 1e-10);                // collective
    EXPECT_NEAR(fd[2], wd + rotor.Omega, 1e-10);  // forward whirl
  }
  // Pitch inputs act on the multiblade coordinates one to one, and so do root-moment outputs.
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(N, N);
  EXPECT_LT((r.B.block(nd + 1, 1, N, N) - rotor.g * I).norm(), 1e-12);
  EXPECT_LT((r.C.block(1, 1, N, N) - rotor.k * I).norm(), 1e-12);
  EXPECT_LT((r.D.block(1, 1, N, N) - rotor.d * I).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(r.B(nd, 0), 1.0);

  std::vector<std::string> names;
  for (int b = 1; b <= N; ++b) names.push_back(whirl::toString(r.states[b]));
  const std::vector<std::vector<std::string>> expected_names = {{"collective", "cos", "sin"},
                                                                {"collective", "cos", "sin", "differential"},
                                                                {"collective", "cos", "sin", "cos 2", "sin 2"}};
  EXPECT_EQ(names, expected_names[N - 3]);
  EXPECT_EQ(whirl::toString(r.states[nd + 1]), "collective");  // rate of the collective DOF
  EXPECT_EQ(whirl::toString(r.inputs[0]), "fixed");
}

INSTANTIATE_TEST_SUITE_P(Blades, IsotropicRotorTest, ::testing::Values(3, 4, 5));

// Blade values from multiblade coordinates, row b of T1 for 4 blades: q_b = q0 + qc cos ψ_b +
// qs sin ψ_b + qd (−1)^b ([Bir2008]; docs/dev/architecture.md, notation; b = 1 … 4), read through
// C_NR = C T1 of a fixed output y = q_1.
TEST(Mbc, FourBladeBasisRows) {
  whirl::MbcLayout L;
  L.num_blades = 4;
  L.state_blade = {0, 1, 2, 3};  // first-order states only
  whirl::MbcSample s;
  s.azimuth = 0.7;
  s.A = -2.0 * Eigen::MatrixXd::Identity(4, 4);
  s.C = Eigen::MatrixXd::Zero(2, 4);
  s.C(0, 0) = 1.0, s.C(1, 1) = 1.0;  // y = (q_1, q_2), fixed-frame outputs
  const auto t = whirl::mbcTransform(L, s);
  const double p2 = 0.7 + std::numbers::pi / 2;
  EXPECT_LT((t.C.row(0) - Eigen::RowVector4d(1, std::cos(0.7), std::sin(0.7), -1)).norm(), 1e-15);
  EXPECT_LT((t.C.row(1) - Eigen::RowVector4d(1, std::cos(p2), std::sin(p2), 1)).norm(), 1e-15);
  EXPECT_LT((t.A + 2.0 * Eigen::MatrixXd::Identity(4, 4)).norm(), 1e-14);  // Ω = 0: no Ṫ
}

// An azimuth-independent system in the fixed frame, Ã (states z = [q_t, q0, qc, qs, their rates,
// x0, xc, xs, x_t]), inputs [u_t, u0, uc, us], outputs [y0, yc, ys, y_t], seen from the rotating
// frame with the 3-blade transform written out here (not the library's): x = T z gives
// A(ψ) = (T Ã + Ṫ) T⁻¹, B(ψ) = T B̃ Tu⁻¹, C(ψ) = Ty C̃ T⁻¹, D(ψ) = Ty D̃ Tu⁻¹. The MBC of A(ψ) must
// return Ã exactly at every azimuth, with a varying rotor speed too.
TEST(Mbc, FixedFrameSystemIsRecoveredExactly) {
  const int nx = 12;
  auto filled = [](int r, int c, double a) {
    Eigen::MatrixXd m(r, c);
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < c; ++j) m(i, j) = std::sin(a * (i + 1) + 0.37 * (j + 1) * (j + 2)) * (1 + 0.1 * i);
    return m;
  };
  Eigen::MatrixXd At = filled(nx, nx, 1.3), Bt = filled(nx, 4, 0.7), Ct = filled(4, nx, 2.1), Dt = filled(4, 4, 0.4);
  At.topRows(4).setZero();
  At.block(0, 4, 4, 4).setIdentity();  // kinematic rows of the DOFs
  Bt.topRows(4).setZero();
  const double W = 0.9, Wdot = 0.05;

  auto rotating = [&](double psi) {
    Eigen::Matrix3d T1, T2, T3;  // rows b: [1, cos ψ_b, sin ψ_b] and its ψ-derivatives
    for (int b = 0; b < 3; ++b) {
      const double p = psi + 2 * std::numbers::pi * b / 3;
      T1.row(b) << 1, std::cos(p), std::sin(p);
      T2.row(b) << 0, -std::sin(p), std::cos(p);
      T3.row(b) << 0, -std::cos(p), -std::sin(p);
    }
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(nx, nx), Td = Eigen::MatrixXd::Zero(nx, nx);
    T(0, 0) = T(4, 4) = T(11, 11) = 1;
    T.block(1, 1, 3, 3) = T1, T.block(5, 5, 3, 3) = T1, T.block(8, 8, 3, 3) = T1;
    T.block(5, 1, 3, 3) = W * T2;
    Td.block(1, 1, 3, 3) = W * T2, Td.block(5, 5, 3, 3) = W * T2, Td.block(8, 8, 3, 3) = W * T2;
    Td.block(5, 1, 3, 3) = W * W * T3 + Wdot * T2;
    Eigen::Matrix4d Tu = Eigen::Matrix4d::Identity(), Ty = Eigen::Matrix4d::Identity();
    Tu.block(1, 1, 3, 3) = T1, Ty.block(0, 0, 3, 3) = T1;
    const Eigen::MatrixXd Ti = T.inverse();
    whirl::MbcSample s;
    s.azimuth = psi, s.rotor_speed = W, s.rotor_acceleration = Wdot;
    s.A = (T * At + Td) * Ti;
    s.B = T * Bt * Tu.inverse();
    s.C = Ty * Ct * Ti;
    s.D = Ty * Dt * Tu.inverse();
    return s;
  };
  auto L = whirl::secondOrderLayout(3, {-1, 0, 1, 2}, {0, 1, 2, -1});
  L.input_blade = {-1, 0, 1, 2};
  L.output_blade = {0, 1, 2, -1};
  std::vector<whirl::MbcSample> samples;
  for (double psi : {0.1, 1.7, 3.3, 5.0}) samples.push_back(rotating(psi));
  // The rotating-frame model is strongly azimuth dependent, and keeps its kinematic rows.
  EXPECT_GT((samples[1].A - samples[0].A).norm(), 0.2 * samples[0].A.norm());
  EXPECT_LT((samples[1].A.block(0, 4, 4, 4) - Eigen::Matrix4d::Identity()).norm(), 1e-12);

  const auto r = whirl::mbcAverage(L, samples);
  for (const auto& s : r.samples) {
    EXPECT_LT((s.A - At).norm(), 1e-12 * At.norm());
    EXPECT_LT((s.B - Bt).norm(), 1e-12 * Bt.norm());
    EXPECT_LT((s.C - Ct).norm(), 1e-12 * Ct.norm());
    EXPECT_LT((s.D - Dt).norm(), 1e-12 * Dt.norm());
  }
  EXPECT_LT((r.A - At).norm(), 1e-12 * At.norm());
  EXPECT_LT((r.D - Dt).norm(), 1e-12 * Dt.norm());
}

std::string mbcError(const whirl::MbcLayout& L, const whirl::MbcSample& s) {
  try {
    whirl::mbcTransform(L, s);
  } catch (const whirl::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Mbc, FewerThanThreeBladesIsRefused) {
  const auto L = whirl::secondOrderLayout(2, {0, 1});
  whirl::MbcSample s;
  s.A = Eigen::MatrixXd::Identity(4, 4);
  const std::string msg = mbcError(L, s);
  EXPECT_NE(msg.find("num_blades: 2 blades: the multiblade transform needs at least 3"), std::string::npos) << msg;
}

TEST(Mbc, InconsistentLayoutOrDataIsRefused) {
  whirl::MbcSample s;
  s.A = Eigen::MatrixXd::Identity(8, 8);
  // Blade 1 has two rotating DOFs, blades 2 and 3 one.
  auto msg = mbcError(whirl::secondOrderLayout(3, {0, 1, 2, 0}), s);
  EXPECT_NE(msg.find("blade 2 has 1 rotating entries, blade 1 has 2"), std::string::npos) << msg;
  // Blade index out of range, layout of the wrong size.
  msg = mbcError(whirl::secondOrderLayout(3, {0, 1, 3, -1}), s);
  EXPECT_NE(msg.find("blade 3 not in -1"), std::string::npos) << msg;
  msg = mbcError(whirl::secondOrderLayout(3, {0, 1, 2}), s);
  EXPECT_NE(msg.find("state_blade: has 6 entries, A has 8 rows"), std::string::npos) << msg;
  // A rate on another blade than its displacement.
  auto L = whirl::secondOrderLayout(3, {-1, 0, 1, 2});
  std::swap(L.state_blade[5], L.state_blade[6]);
  msg = mbcError(L, s);
  EXPECT_NE(msg.find("is the rate of state"), std::string::npos) << msg;
  // Non-finite entries and wrong sizes of B.
  L = whirl::secondOrderLayout(3, {-1, 0, 1, 2});
  s.A(6, 2) = std::numeric_limits<double>::quiet_NaN();
  msg = mbcError(L, s);
  EXPECT_NE(msg.find("MBC A: entry (6,2) is not finite"), std::string::npos) << msg;
  s.A(6, 2) = 0.0;
  s.B = Eigen::MatrixXd::Zero(7, 2);
  s.D = Eigen::MatrixXd::Zero(1, 2);
  msg = mbcError(L, s);
  EXPECT_NE(msg.find("MBC B: is 7 x 2, expected 8 x 2"), std::string::npos) << msg;
  EXPECT_THROW(whirl::mbcAverage(L, {}), whirl::InputError);
}

}  // namespace
