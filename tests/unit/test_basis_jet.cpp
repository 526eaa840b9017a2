// The preaccumulated derivatives of a body's stage-1 products (src/dynamics/basis_jet.hxx) against
// the AD evaluation of the same products (basisProducts in the AD scalar): a BeamDyn blade of
// Test26 (8 shapes, c = [1; q; q_i q_j], nc = 45) at deflected, moving and accelerating values, with
// arbitrary derivative directions on q_e, q̇_e and q̈_e, so that every term of the jet (S D(q),
// S D₂(q̇), the trace terms in q̈, 2 q̇ and q) carries weight.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "src/dynamics/basis_jet.hxx"
#include "src/dynamics/kinematics.hxx"
#include "src/dynamics/residual.hxx"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const Model& blades() {
  static const Model m = readElastoDynModel(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw_beamdyn/Test26.fst",
                                            {"CompAero=0", "CompInflow=0", "blade_elements=20", "blade_modes=8"});
  return m;
}

int bladeBody(const Model& m) {
  for (int i = 0; i < static_cast<int>(m.bodies.size()); ++i)
    if (m.bodies[i].inertia.ne == 8 && m.bodies[i].inertia.quadratic) return i;
  return -1;
}

// Values and derivatives agree to round-off relative to the largest value of the quantity.
void expectSame(const ADChunk& a, const ADChunk& b, double scale, const std::string& what) {
  EXPECT_NEAR(a.value(), b.value(), 1e-12 * scale) << what;
  EXPECT_LT((a.derivatives() - b.derivatives()).cwiseAbs().maxCoeff(), 1e-12 * scale) << what;
}

double scaleOf(const VecXT<ADChunk>& x, int n) {
  double s = 1;
  for (int r = 0; r < n; ++r) s = std::max({s, std::abs(x(r).value()), x(r).derivatives().cwiseAbs().maxCoeff()});
  return s;
}

template <class M>
double scaleOf(const M& x) {
  double s = 1;
  for (Eigen::Index c = 0; c < x.cols(); ++c)
    for (Eigen::Index r = 0; r < x.rows(); ++r)
      s = std::max({s, std::abs(x(r, c).value()), x(r, c).derivatives().cwiseAbs().maxCoeff()});
  return s;
}

struct Point {
  VecXT<ADChunk> q, qd, qdd;
};

// The blade's coordinates deflected (centimetres: shapes scaled to 1 m), moving and accelerating;
// derivative directions drawn at random on the sets asked for.
Point point(const Model& m, int body, bool seed_q, bool seed_rates) {
  const int n = m.ndof(), e0 = m.bodies[body].elastic_dof, ne = m.bodies[body].inertia.ne;
  Point p{VecXT<ADChunk>(n), VecXT<ADChunk>(n), VecXT<ADChunk>(n)};
  for (int i = 0; i < n; ++i) p.q(i) = p.qd(i) = p.qdd(i) = ADChunk(0.0);
  std::srand(7);
  for (int j = 0; j < ne; ++j) {
    p.q(e0 + j) = ADChunk(0.01 + 0.003 * j);
    p.qd(e0 + j) = ADChunk(0.02 - 0.007 * j);
    p.qdd(e0 + j) = ADChunk(0.5 - 0.13 * j);
    if (seed_q) p.q(e0 + j).derivatives() = ADChunk::DerType::Random();
    if (seed_rates) {
      p.qd(e0 + j).derivatives() = ADChunk::DerType::Random();
      p.qdd(e0 + j).derivatives() = ADChunk::DerType::Random();
    }
  }
  return p;
}

template <class TQ>
void expectRatePartsSame(const BodyInertia& in, const BasisProducts<TQ, ADChunk>& jet,
                         const BasisProducts<ADChunk, ADChunk>& ref) {
  for (int kl = 0; kl < 9; ++kl) {
    if (kl % 4 == 0) continue;
    const int len = in.len[kl / 3];
    const double s = scaleOf(ref.z[kl], len);
    for (int r = 0; r < len; ++r) expectSame(jet.z[kl](r), ref.z[kl](r), s, "z " + std::to_string(kl));
  }
  const double s = scaleOf(ref.scdd, in.nc());
  for (int r = 0; r < in.nc(); ++r) expectSame(jet.scdd(r), ref.scdd(r), s, "s " + std::to_string(r));
  const double sd = scaleOf(ref.Pcd), sdd = scaleOf(ref.Pcdd);
  for (int k = 0; k < 9; ++k) {
    expectSame(jet.Pcd(k % 3, k / 3), ref.Pcd(k % 3, k / 3), sd, "Pcd");
    expectSame(jet.Pcdd(k % 3, k / 3), ref.Pcdd(k % 3, k / 3), sdd, "Pcdd");
  }
  for (int k = 0; k < 3; ++k) {
    expectSame(jet.m1cd(k), ref.m1cd(k), scaleOf(ref.m1cd), "m1cd");
    expectSame(jet.m1cdd(k), ref.m1cdd(k), scaleOf(ref.m1cdd), "m1cdd");
  }
}

// The blade at the point with the derivative directions asked for, and its products evaluated in the AD scalar.
class BasisJet : public testing::Test {
 protected:
  void prepare(bool seed_q) {
    body = bladeBody(m);
    ASSERT_GE(body, 0);
    ASSERT_EQ(in().Strace.rows(), in().nc());  // finalized: the jet's path
    p = point(m, body, seed_q, true);
    const int e0 = b().elastic_dof;
    detail::evalBasis(in(), p.q.data() + e0, p.qd.data() + e0, p.qdd.data() + e0, ws.basis[body]);
    ref = BasisProducts<ADChunk, ADChunk>(in().nc());
    basisProducts(in(), ws.basis[body].c, ws.basis[body].cd, ws.basis[body].cdd, ref);
  }
  const Body& b() const { return m.bodies[body]; }
  const BodyInertia& in() const { return b().inertia; }
  const ADChunk* at(const VecXT<ADChunk>& x) const { return x.data() + b().elastic_dof; }

  const Model& m = blades();
  int body = -1;
  Workspace<ADChunk> ws{m};
  Point p;
  BasisProducts<ADChunk, ADChunk> ref{1};
};

TEST_F(BasisJet, ProductsEqualTheirEvaluationInTheAdScalar) {
  ASSERT_NO_FATAL_FAILURE(prepare(true));
  ConstantBasis& cb = detail::constantBasisAt(b(), ws, body, p.q, p.qd, p.qdd);
  BasisProducts<ADChunk, ADChunk> jet(in().nc());
  jetBasisProducts(in(), cb, at(p.q), at(p.qd), at(p.qdd), true, true, true, ws.basis[body], jet);
  ASSERT_TRUE(cb.jet.rates && cb.jet.accelerations);
  for (int kl = 0; kl < 9; ++kl) {
    const int len = in().len[kl / 3];
    const double s = scaleOf(ref.y[kl], len);
    for (int r = 0; r < len; ++r) expectSame(jet.y[kl](r), ref.y[kl](r), s, "y " + std::to_string(kl));
  }
  const double sc = scaleOf(ref.Pc);
  for (int k = 0; k < 9; ++k) expectSame(jet.Pc(k % 3, k / 3), ref.Pc(k % 3, k / 3), sc, "Pc");
  for (int k = 0; k < 3; ++k) expectSame(jet.m1c(k), ref.m1c(k), scaleOf(ref.m1c), "m1c");
  expectRatePartsSame(in(), jet, ref);
}

// q̇ and q̈ seeded, q not: the rate part alone (y, Pc, m1c stay double).
TEST_F(BasisJet, RatePartEqualsItsEvaluationInTheAdScalar) {
  ASSERT_NO_FATAL_FAILURE(prepare(false));
  ConstantBasis& cb = detail::constantBasisAt(b(), ws, body, p.q, p.qd, p.qdd);
  BasisProducts<double, ADChunk> jet(in().nc());
  jetRateProducts(in(), cb, at(p.qd), at(p.qdd), true, true, ws.basis[body], jet);
  expectRatePartsSame(in(), jet, ref);
}

}  // namespace
}  // namespace whirl
