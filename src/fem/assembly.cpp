#include "src/fem/assembly.hpp"

#include <vector>

#include "src/base/skew.hpp"

namespace whirl::fem {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Element frame → body frame for the 12 element DOFs: u_body = T u_element.
Mat12 dofRotation(const Mat3& R) {
  Mat12 T = Mat12::Zero();
  for (int b = 0; b < 4; ++b) T.block<3, 3>(3 * b, 3 * b) = R;
  return T;
}

std::array<int, 12> elementDofs(const Element& e) {
  std::array<int, 12> d{};
  for (int k = 0; k < 6; ++k) {
    d[k] = kNodeDofs * e.n1 + k;
    d[6 + k] = kNodeDofs * e.n2 + k;
  }
  return d;
}

void scatter(Triplets& t, const Mat12& k, const std::array<int, 12>& dofs) {
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      if (k(i, j) != 0.0) t.emplace_back(dofs[i], dofs[j], k(i, j));
}

// Accumulates into the extended index space of c = [1; u]. P: 3 × nl position field, A: 3 × nl
// rotation field (column 0 = reference, zero rotation), index: extended index of each local column.
struct IntegralBuilder {
  std::array<Triplets, 9> S;
  Mat3X m1;
  double mass = 0;

  void add(const Eigen::Matrix<double, 3, Eigen::Dynamic>& P, const Eigen::Matrix<double, 3, Eigen::Dynamic>& A,
           const std::vector<int>& index, double dm, const Mat3& theta) {
    const int nl = static_cast<int>(index.size());
    mass += dm;
    for (int k = 0; k < nl; ++k) m1.col(index[k]) += dm * P.col(k);
    // Section points at r (∫ r dm = 0, ∫ r rᵀ dm = Θ) move by θ × r = skew(θ) r.
    std::vector<Mat3> E(nl);
    for (int k = 0; k < nl; ++k) E[k] = skew(Vec3(A.col(k)));
    for (int a = 0; a < nl; ++a)
      for (int b = 0; b < nl; ++b) {
        Mat3 s = dm * P.col(a) * P.col(b).transpose();  // s(j, l) = ∫ P_j(a) P_l(b)
        if (!theta.isZero(0)) {
          // Section part ρ_0 = r, ρ_k = θ_k × r = E_k r  ⇒  ∫ ρ_a ρ_bᵀ = L_a Θ L_bᵀ.
          const Mat3 La = a == 0 ? Mat3(Mat3::Identity()) : E[a];
          const Mat3 Lb = b == 0 ? Mat3(Mat3::Identity()) : E[b];
          s += La * theta * Lb.transpose();
        }
        for (int j = 0; j < 3; ++j)
          for (int l = 0; l < 3; ++l)
            if (s(j, l) != 0.0) S[3 * j + l].emplace_back(index[a], index[b], s(j, l));
      }
  }
};

}  // namespace

Assembly assemble(const BeamModel& m, bool with_integrals) {
  const int n = m.ndof();
  Triplets tk, tm;
  IntegralBuilder ib;
  ib.m1 = Mat3X::Zero(3, n + 1);
  for (const Element& e : m.elements) {
    const Vec3 X1 = m.nodes[e.n1], X2 = m.nodes[e.n2];
    const double L = (X2 - X1).norm();
    const Mat3 R = elementFrame(m, e);
    const Mat12 T = dofRotation(R);
    const ShearParameters phi = shearParameters(L, e.s1, e.s2, m.timoshenko);
    const std::array<int, 12> dofs = elementDofs(e);
    scatter(tk, T * elementStiffness(L, e.s1, e.s2, phi) * T.transpose(), dofs);
    if (!e.k1.isZero(0) || !e.k2.isZero(0)) scatter(tk, T * elementWinkler(L, phi, e.k1, e.k2) * T.transpose(), dofs);
    Mat12 Me = Mat12::Zero();
    std::vector<int> index(13);
    index[0] = 0;
    for (int k = 0; k < 12; ++k) index[1 + k] = 1 + dofs[k];
    Eigen::Matrix<double, 3, Eigen::Dynamic> P(3, 13), A(3, 13);
    for (int g = 0; g < 4; ++g) {
      const double xi = Gauss4::x[g];
      const ElementFields f = elementFields(L, phi, xi);
      const Section s = lerp(e.s1, e.s2, xi);
      P.col(0) = (1 - xi) * X1 + xi * X2;
      A.col(0).setZero();
      P.rightCols(12) = R * f.u * T.transpose();
      A.rightCols(12) = R * f.th * T.transpose();
      const Mat3 theta = R * Vec3(0, s.iy2, s.iz2).asDiagonal() * R.transpose();
      const double w = Gauss4::w[g] * L;
      // Kinetic energy of the section: ½ m |u̇|² + ½ θ̇ᵀ J θ̇, J = tr(Θ) 1 − Θ.
      const Mat3 J = theta.trace() * Mat3::Identity() - theta;
      Me.noalias() += w * (s.m * P.rightCols(12).transpose() * P.rightCols(12) +
                           A.rightCols(12).transpose() * J * A.rightCols(12));
      if (with_integrals) ib.add(P, A, index, w * s.m, w * theta);
    }
    scatter(tm, Me, dofs);
  }
  for (const NodeMass& nm : m.masses) {
    std::vector<int> index(7);
    index[0] = 0;
    for (int k = 0; k < 6; ++k) index[1 + k] = 1 + kNodeDofs * nm.node + k;
    Eigen::Matrix<double, 3, Eigen::Dynamic> P = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, 7), A = P;
    P.col(0) = m.nodes[nm.node];
    P.block<3, 3>(0, 1).setIdentity();
    A.block<3, 3>(0, 4).setIdentity();
    // Second moment Θ from the inertia tensor: J = tr(Θ) 1 − Θ  ⇒  Θ = ½ tr(J) 1 − J.
    const Mat3 theta = 0.5 * nm.inertia.trace() * Mat3::Identity() - nm.inertia;
    if (with_integrals) ib.add(P, A, index, nm.mass, theta);
    for (int i = 0; i < 3; ++i) {
      tm.emplace_back(index[1 + i] - 1, index[1 + i] - 1, nm.mass);
      for (int j = 0; j < 3; ++j)
        if (nm.inertia(i, j) != 0.0) tm.emplace_back(index[4 + i] - 1, index[4 + j] - 1, nm.inertia(i, j));
    }
  }
  for (const NodeSpring& s : m.springs)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (s.K(i, j) != 0.0) tk.emplace_back(kNodeDofs * s.node + i, kNodeDofs * s.node + j, s.K(i, j));
  Assembly out;
  out.K.resize(n, n);
  out.K.setFromTriplets(tk.begin(), tk.end());
  out.M.resize(n, n);
  out.M.setFromTriplets(tm.begin(), tm.end());
  if (!with_integrals) return out;
  MassIntegrals& in = out.integrals;
  in.mass = ib.mass;
  in.m1 = ib.m1;
  for (int k = 0; k < 9; ++k) {
    in.S[k].resize(n + 1, n + 1);
    in.S[k].setFromTriplets(ib.S[k].begin(), ib.S[k].end());
  }
  return out;
}

SpMat geometricStiffness(const BeamModel& m, const VecX& N) {
  const int n = m.ndof();
  Triplets t;
  for (size_t k = 0; k < m.elements.size(); ++k) {
    if (N(k) == 0.0) continue;
    const Element& e = m.elements[k];
    const double L = (m.nodes[e.n2] - m.nodes[e.n1]).norm();
    const Mat12 T = dofRotation(elementFrame(m, e));
    const ShearParameters phi = shearParameters(L, e.s1, e.s2, m.timoshenko);
    scatter(t, N(k) * (T * elementGeometricStiffness(L, phi) * T.transpose()), elementDofs(e));
  }
  SpMat G(n, n);
  G.setFromTriplets(t.begin(), t.end());
  return G;
}

VecX axialForces(const BeamModel& m, const VecX& u) {
  VecX N(m.elements.size());
  for (size_t k = 0; k < m.elements.size(); ++k) {
    const Element& e = m.elements[k];
    const Vec3 d = m.nodes[e.n2] - m.nodes[e.n1];
    const double L = d.norm();
    const double EA = 0.5 * (e.s1.EA + e.s2.EA);
    N(k) = EA / L * (u.segment<3>(kNodeDofs * e.n2) - u.segment<3>(kNodeDofs * e.n1)).dot(d / L);
  }
  return N;
}

}  // namespace whirl::fem
