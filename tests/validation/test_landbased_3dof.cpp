// [BranlardGeisler2022, §4.5 and App. E2]: the three-DOF land-based turbine (tower
// fore-aft q1, side-side q2, azimuth ψ) built as a case of the general engine, checked against the
// closed-form mass matrix (E13–E21) and forcing (E22–E26) at several states. The closed form keeps
// the tilt θ_t to first order and the tower-top slopes ν to second order; the tolerances below
// follow from the terms it drops (stated next to each). The tower's axial shortening is off: the
// closed form has none.
#include <numbers>

#include "modal/modes.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr const char* kCase = "landbased_3dof";
constexpr double deg = std::numbers::pi / 180;

struct Params {
  double g = 9.80665, MN = 240000, xN = 1.9, zN = 1.75, JxN = 1.0e6, JyN = 1006490;
  double MR = 109582.3, xR = -5.0000008, zR = 2.4000034, JxR = 3.8462e7, JoR = 1.9231e7;
  double tilt = 0, nux = 0, nuy = 0, Me1 = 0, Me2 = 0, Ke1 = 0, Ke2 = 0, De1 = 0, De2 = 0;
};

struct State {
  double q1, q2, psi, qd1, qd2, psid, fa, ta;
};

// E13–E21.
Eigen::Matrix3d closedFormMass(const Params& p, const State& s) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  M(0, 0) = p.Me1 + p.MN + p.MR +
            (p.JyN + p.JoR + p.MN * (p.xN * p.xN - 2 * p.xN * s.q1 + p.zN * p.zN) +
             p.MR * (p.xR * p.xR - 2 * p.xR * s.q1 + p.zR * p.zR)) *
                p.nuy * p.nuy +
            2 * (p.MN * p.zN + p.MR * p.zR) * p.nuy;
  M(0, 2) = M(2, 0) = p.JxR * p.tilt * p.nux * p.nuy * s.q2;
  M(1, 1) = p.Me2 + p.MN + p.MR + (p.JxN + p.JxR + p.MN * p.zN * p.zN + p.MR * p.zR * p.zR) * p.nux * p.nux -
            2 * (p.MN * p.zN + p.MR * p.zR) * p.nux;
  M(1, 2) = M(2, 1) = p.JxR * p.nux;
  M(2, 2) = p.JxR;
  return M;
}

// E22–E26 (no distributed tower loads: f_e1 = f_e2 = 0).
Eigen::Vector3d closedFormForcing(const Params& p, const State& s) {
  const double t = p.tilt, nx = p.nux, ny = p.nuy;
  Eigen::Vector3d f;
  f(0) = -p.Ke1 * s.q1 - p.De1 * s.qd1 - p.JxR * t * nx * ny * s.psid * s.qd2 +
         (p.MN * p.xN + p.MR * p.xR) * ny * ny * s.qd1 * s.qd1 +
         p.g * (p.MN * (ny * ny * p.zN * s.q1 + ny * p.xN) + p.MR * (ny * ny * p.zR * s.q1 + ny * p.xR)) +
         s.fa * (t * ny * p.xR - t * ny * s.q1 + ny * p.zR + 1);
  f(1) = -p.Ke2 * s.q2 - p.De2 * s.qd2 + p.JxR * t * nx * ny * s.psid * s.qd1 +
         p.g * (p.MN * p.zN + p.MR * p.zR) * nx * nx * s.q2 + s.fa * t * nx * s.q2;
  f(2) = -p.JxR * t * nx * ny * s.qd1 * s.qd2 + s.ta;
  return f;
}

TEST(Landbased3Dof, MassAndForcingMatchAppendixE2) {
  const double tilt_deg = 0.5;
  const Model m = test::loadCase(kCase, {"bodies.tower.axial_shortening=false",
                                         "bodies.rotor.rotation.y_deg=" + std::to_string(tilt_deg)});
  const Body& tower = m.bodies[*m.findBody("tower")];
  Params p;
  p.tilt = tilt_deg * deg;
  p.nuy = -tower.points.at(0).theta(1, 0);  // rotation about body y (−ground y) is −u_z'
  p.nux = tower.points.at(0).theta(2, 1);   // rotation about body z (ground x) is u_y'
  for (int k = 0; k < 3; ++k) {
    p.Me1 += tower.inertia.S[4 * k](1, 1);
    p.Me2 += tower.inertia.S[4 * k](2, 2);
  }
  p.Ke1 = tower.elastic.K(0, 0);
  p.Ke2 = tower.elastic.K(1, 1);
  p.De1 = tower.elastic.D(0, 0);
  p.De2 = tower.elastic.D(1, 1);
  ASSERT_GT(p.nuy, 0);
  ASSERT_LT(p.nux, 0);  // YAMS sign: side-side deflection along +y rolls the nacelle about −x
  const int i1 = *m.findDof("tower FA 1"), i2 = *m.findDof("tower SS 1"), i3 = *m.findDof("azimuth");
  Workspace<double> ws(m);
  const std::vector<State> states = {{0, 0, 0, 0, 0, 1.2, 0, 0},
                                     {0.3, 0, 0.7, 0.2, 0, 1.2, 7e5, 3e6},
                                     {0, -0.3, 2.0, 0, 0.25, 1.2, 5e5, 0},
                                     {0.1, 0.1, 4.0, -0.3, 0.2, 1.0, 6e5, 2e6},
                                     {-0.2, 0.05, 5.5, 0.1, -0.2, 0.8, 0, 1e6}};
  // Dropped terms of the closed form (θ_t first order, ν second order), bounded per state:
  //  mass: θ_t² J_xR (|ν_x| + ν_x²) (cos θ_t of the shaft axis) + 4 ν² (ν(|q1|+|q2|))² I_RNA,
  //  forcing: θ_t² |f_a| + |f_a| (ν q)² + g Σ M|r| ν (ν q)² (cos/sin of the tower-top rotation).
  const double nu = std::max(std::abs(p.nux), std::abs(p.nuy));
  const double I_rna = p.JyN + p.JoR + p.MN * (p.xN * p.xN + p.zN * p.zN) + p.MR * (p.xR * p.xR + p.zR * p.zR);
  const double Mr = p.MN * std::hypot(p.xN, p.zN) + p.MR * std::hypot(p.xR, p.zR);
  for (const State& s : states) {
    VecX q = VecX::Zero(m.ndof()), qd = q, qdd = q, u(2), e(m.ndof()), e_torque(m.ndof());
    q(i1) = s.q1;
    q(i2) = s.q2;
    q(i3) = s.psi;
    qd(i1) = s.qd1;
    qd(i2) = s.qd2;
    qd(i3) = s.psid;
    MatX M;
    massMatrix(m, ws, q, M);
    u << s.fa, s.ta;
    residual(m, ws, q, qd, qdd, u, e);
    u << s.fa, 0.0;
    residual(m, ws, q, qd, qdd, u, e_torque);
    const Eigen::Matrix3d Mc = closedFormMass(p, s);
    const Eigen::Vector3d Fc = closedFormForcing(p, s);
    const double qq = nu * (std::abs(s.q1) + std::abs(s.q2));
    const double tol_m = p.tilt * p.tilt * p.JxR * (std::abs(p.nux) + p.nux * p.nux) + 4 * nu * nu * qq * qq * I_rna;
    const double tol_f = p.tilt * p.tilt * std::abs(s.fa) + std::abs(s.fa) * qq * qq + p.g * Mr * nu * qq * qq +
                         1e-9 * p.g * (p.MN + p.MR);  // round-off floor
    const int idx[3] = {i1, i2, i3};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(M(idx[r], idx[c]), Mc(r, c), tol_m) << "M" << r + 1 << c + 1 << " q1 " << s.q1;
      // E25 has no aerodynamic-torque term: the torque on the rotor about its tilted shaft projects
      // on the side-side roll ν_x (Kane's generalized force), which the closed form leaves out
      // (it holds for a torque acting between rotor and nacelle). Compare without it here and
      // check that projection separately.
      const double engine = r == 1 ? e_torque(idx[r]) : e(idx[r]);
      EXPECT_NEAR(engine, Fc(r), tol_f + 1e-9 * std::abs(Fc(r))) << "F" << r + 1 << " q1 " << s.q1;
    }
    EXPECT_NEAR(e(i2) - e_torque(i2), s.ta * p.nux * std::cos(p.tilt), tol_f + std::abs(s.ta * p.nux) * qq * qq)
        << "torque reaction on side-side";
  }
}

TEST(Landbased3Dof, ForeAftFrequency) {
  const Model m = test::loadCase(kCase);
  const LinearModel l = test::linearizeAtEquilibrium(m);
  double f = 0;
  for (const auto& mode : computeModes(l.M, l.C, l.K, l.dof_names))
    if (mode.name == "tower FA 1") f = mode.freq_hz;
  test::expectMatchesReference(kCase, {{"f_tower_fa", f}});
}

}  // namespace
}  // namespace whirl
