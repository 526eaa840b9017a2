#pragma once
/// \file
/// A body as whirl integrates it: a mass distribution with a Ritz basis.
///
/// Every point P of body i sits, in the body frame, at s_P = P(x) c, where
///   c = [1; q_e; q_i q_j (i <= j)]   (dim nc)
/// collects the constant, the ne elastic coordinates q_e and, when axial shortening is on, their
/// pairwise products (the radial shortening of a bent beam, -1/2 ∫ ν·ν dx, as in ElastoDyn).
/// All inertia terms of Kane's equations [BranlardGeisler2022, eq. 12–21, App. A] are bilinear in c, so the
/// body carries only the shape integrals m1 = ∫ P dm and S_jl = ∫ P_jᵀ P_l dm ([Branlard2019, App. A]
/// with the quadratic terms appended). A rigid body is the case ne = 0, nc = 1, P = [ρ].
#include <array>
#include <string>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// The nonzero part of a shape integral S_jl as a dense block: the rows and columns of S that hold a
/// nonzero entry, and S on them, row by row (rows.size() × cols.size()).
struct ShapeIntegralBlock {
  std::vector<int> rows, cols;
  std::vector<double> values;
};

/// Shape integrals of one body (body frame, SI units).
struct BodyInertia {
  int ne = 0;              ///< number of elastic coordinates
  bool quadratic = false;  ///< c holds the q_i q_j products (axial shortening)
  double mass = 0.0;       ///< total mass [kg]
  Mat3X m1;                ///< ∫ P dm, 3 × nc [kg m]
  std::array<MatX, 9> S;   ///< S[3j+l] = ∫ P_jᵀ P_l dm, nc × nc [kg m²]
  /// Entries of P_j beyond len[j] are zero (the axial-shortening terms live in P_x only); set by
  /// finalize so that the hot loops skip the zero blocks of S.
  std::array<int, 3> len = {0, 0, 0};
  MatX Strace;  ///< Σ_k S_kk (nc × nc): the elastic mass block; set by finalize
  /// The nonzero blocks of S[3j+l] within len[j] × len[l] and of Strace; set by finalize. The
  /// ElastoDyn bodies' integrals are mostly zeros (NREL 5MW: 121 of the tower's 576 active entries,
  /// 169 of a blade's 324), but each P_j has a support — the basis entries it uses (the tower's P_x:
  /// the constant and the six same-plane products) — and S_jl is dense on support j × support l: the
  /// basis products of every residual are small dense products with a fixed number of terms per row.
  std::array<ShapeIntegralBlock, 9> S_block;
  ShapeIntegralBlock Strace_block;

  /// No mass and no inertia (m = 0, m1 = 0, S = 0: an ElastoDyn yaw bearing or low-speed shaft frame):
  /// no inertia forces, no mass matrix entries; set by finalize.
  bool massless = false;

  /// Length of c: 1 + ne (+ ne(ne+1)/2 when quadratic).
  int nc() const { return 1 + ne + (quadratic ? ne * (ne + 1) / 2 : 0); }
};

/// A material point of a body that children or loads attach to.
struct BodyPoint {
  std::string name;
  Mat3X P;      ///< position field, 3 × nc: s = P c (body frame)
  Mat3X theta;  ///< small rotation angles about body x, y, z per elastic coordinate, 3 × ne
};

/// Elastic stiffness and damping of the elastic coordinates (ne × ne).
struct ElasticProperties {
  MatX K;  ///< [N/m] (or N m/rad for torsion shapes)
  MatX D;  ///< [N s/m]
  /// Added mass on the elastic coordinates [kg, …]: inertia without weight, −A q̈_e (e.g. the water
  /// a submerged member carries along, HydroDyn's strip theory). Empty: none. Meant for a body whose
  /// frame does not move (a fixed-bottom substructure): it is not turned with the body.
  MatX A;
};

/// Rigid-body shape integrals: mass m, centre of gravity rho (body frame), inertia at the COG.
BodyInertia rigidBodyInertia(double mass, const Vec3& rho, const Mat3& inertia_cog);

/// Adds a point mass distribution (the whole of `other`) given in the same basis: used to merge
/// contributions (e.g. beam sections and their rotary inertia) before a body is frozen.
void addInertia(BodyInertia& into, const BodyInertia& other);

}  // namespace whirl
