// The closed loop of linearize/closed_loop.hpp against an independent assembly: the controller written
// as transfer functions (polynomials in s, realized in controllable canonical form here, one realization
// per command) and the loop closed with the textbook feedback formula on the plant's matrices. Same
// eigenvalues to 1e-8 relative (issue 43, item 3).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "linearize/closed_loop.hpp"
#include "src/base/error.hpp"

namespace whirl {
namespace {

using Poly = std::vector<double>;  // coefficients, highest power first

Poly mul(const Poly& a, const Poly& b) {
  Poly c(a.size() + b.size() - 1, 0.0);
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

/// Controllable canonical realization of num/den (deg num ≤ deg den, den monic after scaling).
struct Realization {
  MatX A, B, C;
  double D = 0;
};
Realization realize(Poly num, Poly den) {
  const double lead = den[0];
  for (double& x : den) x /= lead;
  for (double& x : num) x /= lead;
  const size_t n = den.size() - 1;
  while (num.size() < den.size()) num.insert(num.begin(), 0.0);
  Realization r;
  r.D = num[0];
  r.A = MatX::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  r.B = MatX::Zero(static_cast<Eigen::Index>(n), 1);
  r.C = MatX::Zero(1, static_cast<Eigen::Index>(n));
  for (size_t i = 0; i + 1 < n; ++i) r.A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i + 1)) = 1;
  for (size_t i = 0; i < n; ++i) {
    r.A(static_cast<Eigen::Index>(n - 1), static_cast<Eigen::Index>(i)) = -den[n - i];
    r.C(0, static_cast<Eigen::Index>(i)) = num[n - i] - num[0] * den[n - i];
  }
  r.B(static_cast<Eigen::Index>(n - 1), 0) = 1;
  return r;
}

/// A small plant: 3 masses on springs, the first a "rotor" whose speed is the generator speed
/// (gear 97), torque and pitch acting on it, the wind on all three.
StateSpaceModel plant() {
  StateSpaceModel p;
  const int n = 3;
  MatX K(n, n), Cd(n, n), Minv = MatX::Identity(n, n);
  K << 0, 0, 0, 0, 50, -20, 0, -20, 40;
  Cd << 0.3, -0.1, 0, -0.1, 0.4, -0.05, 0, -0.05, 0.2;
  p.A = MatX::Zero(2 * n, 2 * n);
  p.A.topRightCorner(n, n).setIdentity();
  p.A.bottomLeftCorner(n, n) = -K;
  p.A.bottomRightCorner(n, n) = -Cd;
  p.A(3, 1) = 2.0;  // aerodynamic coupling of the rotor to the second coordinate
  p.B = MatX::Zero(2 * n, 3);
  p.B(3, 0) = -97 * 2.3e-8;  // generator torque [N m] on the rotor speed
  p.B(3, 1) = -0.9;          // pitch
  p.B(4, 1) = 0.3;
  p.B(3, 2) = 0.05;  // wind
  p.B(4, 2) = 0.02;
  p.C = MatX::Zero(2, 2 * n);
  p.C(0, 3) = 97;  // GenSpeed
  p.C(1, 1) = 1;   // a displacement
  p.D = MatX::Zero(2, 3);
  p.D(1, 2) = 0.1;
  p.u = {{"generator torque", "N m"}, {"collective pitch", "rad"}, {"wind speed", "m/s"}};
  p.y = {{"GenSpeed", "rad/s"}, {"tower", "m"}};
  for (int i = 0; i < 2 * n; ++i) p.x.push_back({"x" + std::to_string(i), ""});
  return p;
}

std::vector<std::complex<double>> sortedEigenvalues(const MatX& A) {
  Eigen::EigenSolver<MatX> es(A, false);
  std::vector<std::complex<double>> v(es.eigenvalues().data(), es.eigenvalues().data() + es.eigenvalues().size());
  std::sort(v.begin(), v.end(),
            [](auto a, auto b) { return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag(); });
  return v;
}

/// The loop closed from transfer functions: θ = K_θ(s) ω_g, τ = K_τ(s) ω_g.
MatX independentClosedLoop(const StateSpaceModel& p, const Realization& kt, const Realization& kp) {
  const Eigen::Index n = p.A.rows(), mt = kt.A.rows(), mp = kp.A.rows();
  const VecX Cg = p.C.row(0).transpose();
  MatX A = MatX::Zero(n + mt + mp, n + mt + mp);
  // ẋ = A x + b_τ (C_τ ξ_τ + D_τ ω) + b_θ (C_θ ξ_θ + D_θ ω), ω = C_g x
  A.topLeftCorner(n, n) = p.A + (p.B.col(0) * kt.D + p.B.col(1) * kp.D) * Cg.transpose();
  A.block(0, n, n, mt) = p.B.col(0) * kt.C;
  A.block(0, n + mt, n, mp) = p.B.col(1) * kp.C;
  A.block(n, 0, mt, n) = kt.B * Cg.transpose();
  A.block(n, n, mt, mt) = kt.A;
  A.block(n + mt, 0, mp, n) = kp.B * Cg.transpose();
  A.block(n + mt, n + mt, mp, mp) = kp.A;
  return A;
}

/// Same eigenvalues; `extra` are poles the independent assembly has besides (a filter realized once per
/// command: the second copy is uncontrollable from the plant and keeps its open-loop poles).
void expectSameEigenvalues(const MatX& a, const MatX& b, const std::vector<std::complex<double>>& extra = {}) {
  const auto ea = sortedEigenvalues(a);
  auto eb = sortedEigenvalues(b);
  for (const auto& x : extra) {
    auto it = std::min_element(eb.begin(), eb.end(), [&](auto l, auto r) { return std::abs(l - x) < std::abs(r - x); });
    ASSERT_LE(std::abs(*it - x), 1e-8 * std::abs(x));
    eb.erase(it);
  }
  ASSERT_EQ(ea.size(), eb.size());
  for (size_t i = 0; i < ea.size(); ++i) EXPECT_LE(std::abs(ea[i] - eb[i]), 1e-8 * std::max(1.0, std::abs(eb[i]))) << i;
}

TEST(ClosedLoop, PitchLoopWithFilterAndActuatorEqualsTransferFunctions) {
  LinearController c;
  c.lpf_order = 1;
  c.lpf_freq = 1.5708;  // F_LPFCornerFreq, tests/data/rosco/DISCON.IN
  c.pitch_active = true;
  c.pitch_kp = -6.227e-3;  // PC_GS_KP, PC_GS_KI at 0.253 rad, DISCON.IN
  c.pitch_ki = -3.341e-3;
  c.actuator_order = 2;
  c.actuator_freq = 3.14;
  c.actuator_damping = 0.707;
  c.notches = {{4.2, 0.01, 0.25}};
  c.torque = LinearController::Torque::Static;
  c.torque_slope = -2.7;
  const StateSpaceModel p = plant();
  const StateSpaceModel cl = closeLoop(p, c);
  EXPECT_EQ(cl.x.size(), p.x.size() + 1 + 2 + 1 + 2);
  EXPECT_EQ(cl.x.back().name, "controller: pitch actuator rate");
  // K_θ = −(K_p s + K_i)/s · F(s) · Act(s), K_τ = slope · F(s), F = ω_c/(s + ω_c) · notch.
  const Poly lpf_n = {c.lpf_freq}, lpf_d = {1, c.lpf_freq};
  const SpeedNotch& nt = c.notches[0];
  const Poly notch_n = {1, 2 * nt.beta_num * nt.freq, nt.freq * nt.freq};
  const Poly notch_d = {1, 2 * nt.beta_den * nt.freq, nt.freq * nt.freq};
  const double wa = c.actuator_freq;
  const Poly act_n = {wa * wa}, act_d = {1, 2 * c.actuator_damping * wa, wa * wa};
  const Poly pi_n = {-c.pitch_kp, -c.pitch_ki}, pi_d = {1, 0};
  const Realization kp = realize(mul(mul(mul(pi_n, lpf_n), notch_n), act_n),
                                 mul(mul(mul(pi_d, lpf_d), notch_d), act_d));
  const Realization kt = realize(mul(Poly{c.torque_slope}, mul(lpf_n, notch_n)), mul(lpf_d, notch_d));
  const std::complex<double> notch_pole(-nt.beta_den * nt.freq, nt.freq * std::sqrt(1 - nt.beta_den * nt.beta_den));
  expectSameEigenvalues(cl.A, independentClosedLoop(p, kt, kp), {-c.lpf_freq, notch_pole, std::conj(notch_pole)});
}

TEST(ClosedLoop, FloatingFeedbackEqualsTransferFunctions) {
  // ROSCO's Fl_Mode 1 (Controllers.f90 FloatingFeedback): θ_c += −K_fl · LPF₂ · HPF · notch applied to
  // the tower-top velocity, here the rate of the plant's second coordinate.
  LinearController c;
  c.lpf_order = 1;
  c.lpf_freq = 1.5708;
  c.pitch_active = true;
  c.pitch_kp = -4.26e-3;  // cases/oc3_hywind/rosco/DISCON.IN, first point
  c.pitch_ki = -5.198e-4;
  c.floating_mode = 1;
  c.floating_kp = -0.032;  // Fl_Kp, same file
  c.floating_lpf_freq = 0.2115;
  c.floating_lpf_damping = 1.0;
  c.floating_hpf_freq = 0.01042;
  c.floating_notches = {{3.0, 0.0, 0.25}};
  StateSpaceModel p = plant();
  p.C.conservativeResize(3, p.C.cols());
  p.C.row(2).setZero();
  p.C(2, 4) = 1;
  p.D.conservativeResize(3, p.D.cols());
  p.D.row(2).setZero();
  p.y.push_back({"YawBrTVxp", "m/s"});
  const StateSpaceModel cl = closeLoop(p, c);
  EXPECT_EQ(cl.x.size(), p.x.size() + 1 + 1 + 2 + 1 + 2);
  // Independent: K_θ = −(K_p s + K_i)/s · ω_c/(s + ω_c) on ω_g; K_fl = −K_fl ω_l²/(s² + 2ζω_l s + ω_l²) ·
  // s/(s + ω_h) · notch on v; both added at the pitch input.
  const Realization kp = realize(mul(Poly{-c.pitch_kp, -c.pitch_ki}, Poly{c.lpf_freq}),
                                 mul(Poly{1, 0}, Poly{1, c.lpf_freq}));
  const double wl = c.floating_lpf_freq, wh = c.floating_hpf_freq;
  const SpeedNotch& nt = c.floating_notches[0];
  const Poly fl_n = mul(mul(Poly{-c.floating_kp * wl * wl}, Poly{1, 0}),
                        Poly{1, 2 * nt.beta_num * nt.freq, nt.freq * nt.freq});
  const Poly fl_d = mul(mul(Poly{1, 2 * c.floating_lpf_damping * wl, wl * wl}, Poly{1, wh}),
                        Poly{1, 2 * nt.beta_den * nt.freq, nt.freq * nt.freq});
  const Realization kf = realize(fl_n, fl_d);
  const Eigen::Index n = p.A.rows(), mp = kp.A.rows(), mf = kf.A.rows();
  const VecX Cg = p.C.row(0).transpose(), Cv = p.C.row(2).transpose(), bp = p.B.col(1);
  MatX A = MatX::Zero(n + mp + mf, n + mp + mf);
  A.topLeftCorner(n, n) = p.A + bp * (kp.D * Cg.transpose() + kf.D * Cv.transpose());
  A.block(0, n, n, mp) = bp * kp.C;
  A.block(0, n + mp, n, mf) = bp * kf.C;
  A.block(n, 0, mp, n) = kp.B * Cg.transpose();
  A.block(n, n, mp, mp) = kp.A;
  A.block(n + mp, 0, mf, n) = kf.B * Cv.transpose();
  A.block(n + mp, n + mp, mf, mf) = kf.A;
  expectSameEigenvalues(cl.A, A);
  // Without the plant's velocity output the loop cannot close: an InputError naming it.
  try {
    closeLoop(plant(), c);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("YawBrTVxp"), std::string::npos) << e.what();
  }
  // Fl_Mode 2 reads the nacelle's pitch rate instead: the same loop on the output of that name.
  LinearController c2 = c;
  c2.floating_mode = 2;
  StateSpaceModel p2 = p;
  p2.y.back().name = "NcIMURVys";
  expectSameEigenvalues(closeLoop(p2, c2).A, cl.A);
  EXPECT_EQ(floatingFeedbackOutput(c2), "NcIMURVys");
  EXPECT_THROW(closeLoop(p, c2), InputError);  // the plant has YawBrTVxp only
  // Without the pitch loop (below rated) the feedback has nothing to act through: no states, no output needed.
  LinearController below = c;
  below.pitch_active = false;
  EXPECT_EQ(floatingFeedbackOutput(below), "");
  EXPECT_EQ(closeLoop(plant(), below).x.size(), plant().x.size() + 1);  // the speed filter only
}

TEST(ClosedLoop, TorquePiSecondOrderFilterEqualsTransferFunctions) {
  LinearController c;
  c.lpf_order = 2;
  c.lpf_freq = 2.0;
  c.lpf_damping = 0.7;
  c.torque = LinearController::Torque::PI;
  c.torque_kp = -697.771;  // VS_KP, VS_KI, DISCON.IN
  c.torque_ki = -104.507;
  c.reference_per_wind = 7.5 * 97 / 63;  // λ N / R
  const StateSpaceModel p = plant();
  const StateSpaceModel cl = closeLoop(p, c);
  // K_τ = −(K_p s + K_i)/s · F(s) (the reference's wind path does not change the poles); pitch held.
  const Poly f_n = {c.lpf_freq * c.lpf_freq}, f_d = {1, 2 * c.lpf_damping * c.lpf_freq, c.lpf_freq * c.lpf_freq};
  const Realization kt = realize(mul(Poly{-c.torque_kp, -c.torque_ki}, f_n), mul(Poly{1, 0}, f_d));
  Realization none;
  none.A = MatX::Zero(0, 0);
  none.B = MatX::Zero(0, 1);
  none.C = MatX::Zero(1, 0);
  expectSameEigenvalues(cl.A, independentClosedLoop(p, kt, none));
  // The wind reaches the torque through the reference: B of the integral state = K_i λ N / R.
  const int wind = 2;
  EXPECT_NEAR(cl.B(static_cast<Eigen::Index>(cl.x.size()) - 1, wind),
              c.torque_ki * (c.reference_per_wind + 0 * p.D(0, wind)), 1e-12);
}

TEST(ClosedLoop, MissingPortIsAnInputError) {
  StateSpaceModel p = plant();
  p.y[0].name = "RotSpeed";
  LinearController c;
  c.pitch_active = true;
  EXPECT_THROW(closeLoop(p, c), InputError);
}

}  // namespace
}  // namespace whirl
