#pragma once
/// \file
/// Sparse K, M (and C) of small structures with known spectra, for the SLEPc tests and the sparse
/// benchmark: spring–mass chain, square spring grid, Euler–Bernoulli cantilever, 3D lattice
/// frame tower. Header-only, Eigen only.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <cmath>
#include <vector>

namespace whirl::test {

using Triplets = std::vector<Eigen::Triplet<double>>;

struct SparseModel {
  Eigen::SparseMatrix<double> K, M;
};

inline Eigen::SparseMatrix<double> fromTriplets(int n, const Triplets& t) {
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// n masses m in a line, n+1 springs k, both ends fixed: ω_j² = (4k/m) sin²(jπ / (2(n+1))).
inline SparseModel springChain(int n, double k, double m) {
  Triplets kt, mt;
  for (int i = 0; i < n; ++i) {
    kt.emplace_back(i, i, 2 * k);
    if (i + 1 < n) {
      kt.emplace_back(i, i + 1, -k);
      kt.emplace_back(i + 1, i, -k);
    }
    mt.emplace_back(i, i, m);
  }
  return {fromTriplets(n, kt), fromTriplets(n, mt)};
}

/// nx × ny masses m on a grid of springs k (out-of-plane motion, fixed border):
/// ω² = (4k/m) (sin²(iπ/(2(nx+1))) + sin²(jπ/(2(ny+1)))), i ≤ nx, j ≤ ny.
inline SparseModel springGrid(int nx, int ny, double k, double m) {
  const int n = nx * ny;
  Triplets kt, mt;
  auto id = [nx](int i, int j) { return j * nx + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int p = id(i, j);
      kt.emplace_back(p, p, 4 * k);
      mt.emplace_back(p, p, m);
      if (i + 1 < nx) {
        kt.emplace_back(p, id(i + 1, j), -k);
        kt.emplace_back(id(i + 1, j), p, -k);
      }
      if (j + 1 < ny) {
        kt.emplace_back(p, id(i, j + 1), -k);
        kt.emplace_back(id(i, j + 1), p, -k);
      }
    }
  return {fromTriplets(n, kt), fromTriplets(n, mt)};
}

/// Clamped–free Euler–Bernoulli beam, ne Hermite elements, consistent mass; DOFs (w, θ) of
/// nodes 1…ne (the clamped root removed), dim 2·ne.
inline SparseModel cantilever(int ne, double L, double EI, double rhoA) {
  const double h = L / ne;
  Eigen::Matrix4d ke, me;
  ke << 12, 6 * h, -12, 6 * h, 6 * h, 4 * h * h, -6 * h, 2 * h * h, -12, -6 * h, 12, -6 * h, 6 * h, 2 * h * h, -6 * h,
      4 * h * h;
  ke *= EI / (h * h * h);
  me << 156, 22 * h, 54, -13 * h, 22 * h, 4 * h * h, 13 * h, -3 * h * h, 54, 13 * h, 156, -22 * h, -13 * h, -3 * h * h,
      -22 * h, 4 * h * h;
  me *= rhoA * h / 420;
  Triplets kt, mt;
  for (int e = 0; e < ne; ++e)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int ia = 2 * e + a - 2, ib = 2 * e + b - 2;  // global DOF, root (−2, −1) dropped
        if (ia < 0 || ib < 0) continue;
        kt.emplace_back(ia, ib, ke(a, b));
        mt.emplace_back(ia, ib, me(a, b));
      }
  return {fromTriplets(2 * ne, kt), fromTriplets(2 * ne, mt)};
}

/// A lattice tower of 3D Euler–Bernoulli frame elements (6 DOF per node): `levels` storeys of a
/// side × side grid of nodes, spaced `dx` horizontally and `dz` vertically, joined by horizontal
/// and vertical members and one diagonal brace per vertical face panel; the ground level is
/// clamped. Steel tubes (E 210 GPa, ν 0.3, ρ 7850 kg/m³, D 0.5 m, t 20 mm); lumped mass (half of
/// each member to each node; rotary inertia ρI·L/2 about every axis). dim 6·side²·levels.
inline SparseModel latticeTower(int side, int levels, double dx = 2.0, double dz = 2.0) {
  const double E = 210e9, G = E / 2.6, rho = 7850, D = 0.5, t = 0.02;
  const double A = M_PI * (D * D - (D - 2 * t) * (D - 2 * t)) / 4;
  const double I = M_PI * (std::pow(D, 4) - std::pow(D - 2 * t, 4)) / 64, J = 2 * I;
  const int per_level = side * side, n_nodes = per_level * (levels + 1), ndof = 6 * per_level * levels;
  auto pos = [&](int node) {
    const int l = node / per_level, r = node % per_level;
    return Eigen::Vector3d((r % side) * dx, (r / side) * dx, l * dz);
  };
  auto dof = [&](int node, int k) { return node < per_level ? -1 : 6 * (node - per_level) + k; };  // level 0 clamped
  Triplets kt, mt;
  std::vector<double> lumped(static_cast<size_t>(6 * n_nodes), 0.0);
  auto member = [&](int a, int b) {
    const Eigen::Vector3d d = pos(b) - pos(a);
    const double L = d.norm();
    const Eigen::Vector3d e1 = d / L;
    const Eigen::Vector3d ref = std::abs(e1.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d e2 = ref.cross(e1).normalized(), e3 = e1.cross(e2);
    Eigen::Matrix3d R;
    R.row(0) = e1;
    R.row(1) = e2;
    R.row(2) = e3;
    Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero(), T = k;
    const double ea = E * A / L, gj = G * J / L, eil3 = E * I / (L * L * L);
    const std::array<int, 2> ax{0, 6}, tor{3, 9};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const double s = i == j ? 1 : -1;
        k(ax[i], ax[j]) = s * ea;
        k(tor[i], tor[j]) = s * gj;
      }
    // Bending in the local x-y plane (v, θz) and x-z plane (w, θy; opposite coupling sign).
    const double kb[4][4] = {{12, 6 * L, -12, 6 * L},
                             {6 * L, 4 * L * L, -6 * L, 2 * L * L},
                             {-12, -6 * L, 12, -6 * L},
                             {6 * L, 2 * L * L, -6 * L, 4 * L * L}};
    const std::array<int, 4> xy{1, 5, 7, 11}, xz{2, 4, 8, 10};
    const std::array<double, 4> sxz{1, -1, 1, -1};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        k(xy[i], xy[j]) = eil3 * kb[i][j];
        k(xz[i], xz[j]) = eil3 * kb[i][j] * sxz[i] * sxz[j];
      }
    for (int blk = 0; blk < 4; ++blk) T.block<3, 3>(3 * blk, 3 * blk) = R;
    const Eigen::Matrix<double, 12, 12> kg = T.transpose() * k * T;
    const int nodes[2] = {a, b};
    for (int i = 0; i < 12; ++i) {
      const int gi = dof(nodes[i / 6], i % 6);
      if (gi < 0) continue;
      for (int j = 0; j < 12; ++j) {
        const int gj2 = dof(nodes[j / 6], j % 6);
        if (gj2 >= 0 && kg(i, j) != 0.0) kt.emplace_back(gi, gj2, kg(i, j));
      }
    }
    const double half = rho * A * L / 2, rot = rho * I * L / 2;
    for (int nd : nodes)
      for (int c = 0; c < 6; ++c) lumped[static_cast<size_t>(6 * nd + c)] += c < 3 ? half : rot;
  };
  for (int l = 0; l <= levels; ++l)
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        const int p = l * per_level + y * side + x;
        if (x + 1 < side) member(p, p + 1);
        if (y + 1 < side) member(p, p + side);
        if (l < levels) {
          member(p, p + per_level);
          if (x + 1 < side) member(p, p + per_level + 1);     // brace in the x-z panel
          if (y + 1 < side) member(p, p + per_level + side);  // brace in the y-z panel
        }
      }
  for (int nd = per_level; nd < n_nodes; ++nd)
    for (int c = 0; c < 6; ++c) mt.emplace_back(dof(nd, c), dof(nd, c), lumped[static_cast<size_t>(6 * nd + c)]);
  return {fromTriplets(ndof, kt), fromTriplets(ndof, mt)};
}

}  // namespace whirl::test
