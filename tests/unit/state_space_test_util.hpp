#pragma once
// Shared by the state-space tests: the NREL 5MW model, accelerations from the equations of motion,
// frequency responses.
#include <complex>
#include <string>
#include <vector>

#include "linearize/export_point.hpp"
#include "src/dynamics/mass_matrix.hpp"
#include "src/dynamics/residual.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl::testing {

inline const std::string kNrel5mwFst = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Onshore.fst";

inline Model nrel5mw(const std::vector<std::string>& overrides = {}) {
  return readElastoDynModel(kNrel5mwFst, overrides);
}

/// q̈ of the active coordinates from M(q) q̈ = e(q, q̇, 0, u) (frozen coordinates: q̈ = 0).
inline VecX accelerations(const Model& m, const VecX& q, const VecX& qd, const VecX& u) {
  Workspace<double> ws(m);
  VecX e(m.ndof()), zero = VecX::Zero(m.ndof());
  residual(m, ws, q, qd, zero, u, e);
  MatX M;
  massMatrix(m, ws, q, M);
  const std::vector<int> a = m.activeDofs();
  MatX Ma(a.size(), a.size());
  VecX ea(a.size());
  for (size_t r = 0; r < a.size(); ++r) {
    ea(r) = e(a[r]);
    for (size_t c = 0; c < a.size(); ++c) Ma(r, c) = M(a[r], a[c]);
  }
  const VecX qdda = Ma.ldlt().solve(ea);
  VecX qdd = VecX::Zero(m.ndof());
  for (size_t r = 0; r < a.size(); ++r) qdd(a[r]) = qdda(r);
  return qdd;
}

/// G(jω) = C (jω I − A)⁻¹ B + D.
inline Eigen::MatrixXcd frequencyResponse(const StateSpaceModel& s, double omega) {
  const Eigen::Index n = s.A.rows();
  const Eigen::MatrixXcd sI = std::complex<double>(0, omega) * Eigen::MatrixXcd::Identity(n, n);
  const Eigen::MatrixXcd X =
      (sI - s.A.cast<std::complex<double>>()).partialPivLu().solve(s.B.cast<std::complex<double>>());
  return s.C.cast<std::complex<double>>() * X + s.D.cast<std::complex<double>>();
}

inline int indexOf(const std::vector<StateSpaceVariable>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace whirl::testing
