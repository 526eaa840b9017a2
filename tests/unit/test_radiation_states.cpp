// HydroDyn's state-space radiation memory (RdtnMod = 2) in the linear model of the ITI barge deck
// (cases/iti_barge, OpenFAST's certification Test22, parked, generator locked): the states x = [q; q̇; z],
// and every eigenvalue of the assembled A checked against the frequency-domain equation of motion
//   (λ² M + λ C + K − λ Pᵀ H(λ) P) q = 0,   H(s) = C_z (s I − A_z)⁻¹ B_z,
// built from the model's fit without the assembly (P picks the platform coordinates).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <complex>
#include <numbers>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

using Cplx = std::complex<double>;
using MatC = Eigen::MatrixXcd;

const std::string kDeck = std::string(WHIRL_SOURCE_DIR) + "/cases/iti_barge/Test22.fst";

struct Barge {
  Model m = readElastoDynModel(kDeck, {"CompAero=0", "RotSpeed=0", "GenDOF=False"});
  OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  LinearModel lin = linearize(m, op);
};

const Barge& barge() {
  static const Barge b;
  return b;
}

// Pᵀ H(s) P on the active coordinates.
MatC radiationLoad(const Barge& b, Cplx s) {
  const BodyStateSpace& bs = b.m.body_states.at(0);
  const int nz = static_cast<int>(bs.A.rows()), n = static_cast<int>(b.lin.dofs.size());
  const MatC H = bs.C.cast<Cplx>() *
                 (s * MatC::Identity(nz, nz) - bs.A.cast<Cplx>()).partialPivLu().solve(bs.B.cast<Cplx>());
  MatC P = MatC::Zero(6, n);
  const int d0 = b.m.bodies[bs.body].joint_dof;
  for (int c = 0; c < n; ++c)
    if (b.lin.dofs[c] >= d0 && b.lin.dofs[c] < d0 + 6) P(b.lin.dofs[c] - d0, c) = 1.0;
  return P.transpose() * H * P;
}

TEST(RadiationStates, AreStatesOfTheLinearModelAfterTheRates) {
  const Barge& b = barge();
  ASSERT_EQ(b.m.body_states.size(), 1u);
  const int n = static_cast<int>(b.lin.dofs.size()), nz = 30;  // barge.ss: 30 states
  ASSERT_EQ(b.lin.A.rows(), 2 * n + nz);
  ASSERT_EQ(b.lin.first_order_names.size(), 30u);
  EXPECT_EQ(b.lin.first_order_names[0], "HydroDyn radiation surge 1");
  EXPECT_EQ(b.lin.first_order_names[6], "HydroDyn radiation sway 1");
  EXPECT_EQ(b.lin.first_order_names[12], "HydroDyn radiation heave 1");
  EXPECT_EQ(b.lin.first_order_groups[29], "HydroDyn radiation yaw");
  EXPECT_EQ(b.lin.A.bottomRightCorner(nz, nz), b.m.body_states[0].A);
  EXPECT_EQ(b.lin.A.topRightCorner(n, nz), MatX::Zero(n, nz));  // q̇ rows: no z
}

TEST(RadiationStates, EigenvaluesSolveTheFrequencyDomainEquation) {
  const Barge& b = barge();
  const int n = static_cast<int>(b.lin.dofs.size());
  const Eigen::EigenSolver<MatX> es(b.lin.A);
  ASSERT_EQ(es.info(), Eigen::Success);
  int checked = 0, coupled = 0;
  for (int k = 0; k < es.eigenvalues().size(); ++k) {
    const Cplx s = es.eigenvalues()(k);
    const Eigen::VectorXcd q = es.eigenvectors().col(k).head(n);
    if (q.norm() < 1e-6 * es.eigenvectors().col(k).norm()) continue;  // a state of the fit alone
    const MatC Ms = s * s * b.lin.M.cast<Cplx>(), Cs = s * b.lin.C.cast<Cplx>(), Ks = b.lin.K.cast<Cplx>();
    const MatC Rs = s * radiationLoad(b, s);
    const double scale = (Ms * q).norm() + (Cs * q).norm() + (Ks * q).norm() + (Rs * q).norm();
    // LAPACK-quality eigenpairs of a nonsymmetric A whose entries span 1e-3 … 1e5 (M⁻¹K, M⁻¹ Pᵀ C_z)
    // leave relative residuals up to ~3e-8 here; a wrong sign or a missing coupling leaves O(1).
    EXPECT_LT(((Ms + Cs + Ks - Rs) * q).norm(), 1e-7 * scale) << "eigenvalue " << s;
    ++checked;
    coupled += (Rs * q).norm() > 1e-2 * scale;
  }
  EXPECT_GE(checked, 2 * n);  // every structural root and the coupled radiation roots
  EXPECT_GE(coupled, 8);      // the platform modes, where the radiation load counts
}

// The fit of barge.ss is not passive at low frequency: its surge radiation damping −Re H₁₁(iω) is
// negative below about 0.1 rad/s, where the surge mode lies (0.0067 Hz), so the surge mode of the
// linear model is slightly unstable, as OpenFAST's linearization of this deck would be. The sign of the
// mode's damping follows the sign of the fit's damping at its frequency.
TEST(RadiationStates, SurgeDampingHasTheSignOfTheFitsDampingAtItsFrequency) {
  const Barge& b = barge();
  const Eigen::EigenSolver<MatX> es(b.lin.A);
  const int surge = static_cast<int>(std::find(b.lin.dof_names.begin(), b.lin.dof_names.end(), "platform surge") -
                                     b.lin.dof_names.begin());
  // The slowest oscillating root: the surge (and sway) mode.
  Cplx slowest(0, 1e9);
  for (int k = 0; k < es.eigenvalues().size(); ++k) {
    const Cplx s = es.eigenvalues()(k);
    if (s.imag() > 1e-6 && s.imag() < slowest.imag()) slowest = s;
  }
  const double omega = std::abs(slowest);
  EXPECT_NEAR(omega / (2 * std::numbers::pi), 0.0067, 5e-4);
  const double fit_damping = -radiationLoad(b, Cplx(0, omega))(surge, surge).real();
  EXPECT_LT(fit_damping, 0.0);
  EXPECT_GT(slowest.real(), 0.0);  // negative damping ratio
}

}  // namespace
}  // namespace whirl
