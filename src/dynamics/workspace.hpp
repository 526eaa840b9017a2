#pragma once
/// \file
/// Per-evaluation buffers (Pinocchio's Data): sized once from a Model, reused by every call so the
/// hot path does not allocate.
#include <array>
#include <utility>
#include <vector>

#include "src/base/scalar.hpp"
#include "src/dynamics/rotor_totals.hpp"
#include "src/model/model.hpp"

namespace whirl {

/// Pose and motion of one body frame, ground components.
/// Jv, Jw (3 × ndof): partial velocities ∂v/∂q̇ and ∂ω/∂q̇ (Kane); a and dw include q̈.
template <class T>
struct FrameState {
  Mat3T<T> R;   ///< body → ground rotation
  Vec3T<T> r;   ///< origin position [m]
  Vec3T<T> v;   ///< origin velocity [m/s]
  Vec3T<T> a;   ///< origin acceleration [m/s²]
  Vec3T<T> w;   ///< angular velocity [rad/s]
  Vec3T<T> dw;  ///< angular acceleration [rad/s²]
  Mat3XT<T> Jv, Jw;
};

/// Buffers of one body's Ritz basis: c(q_e) and its time derivatives, D = ∂c/∂q_e.
template <class T>
struct BasisState {
  VecXT<T> c, cd, cdd;  ///< nc
  MatXT<T> D;           ///< nc × ne
};

/// The shape integrals of one body contracted with its basis (body_forces.hxx, stage 1): TQ for the
/// terms in c only, TR for those with ċ or c̈. Buffers sized to the largest nc.
template <class TQ, class TR>
struct BasisProducts {
  explicit BasisProducts(int ncmax) {
    for (auto& v : y) v = VecXT<TQ>::Zero(ncmax);
    for (auto& v : z) v = VecXT<TR>::Zero(ncmax);
    scdd = VecXT<TR>::Zero(ncmax);
  }
  std::array<VecXT<TQ>, 9> y;  ///< y_kl = S_kl c
  std::array<VecXT<TR>, 9> z;  ///< z_kl = S_kl ċ (k ≠ l)
  VecXT<TR> scdd;              ///< Σ_k S_kk c̈
  Mat3T<TQ> Pc;                ///< Pc(l,j) = c·y_lj
  Mat3T<TR> Pcd, Pcdd;         ///< ċ·y_lj, c̈·y_lj
  Vec3T<TQ> m1c;               ///< m1 c
  Vec3T<TR> m1cd, m1cdd;       ///< m1 ċ, m1 c̈
};

/// The first derivatives of one body's stage-1 products (body_forces.hxx) with respect to its own
/// elastic coordinates at the values of a ConstantBasis, preaccumulated once per point for the AD
/// passes that seed them (Griewank & Walther 2008, §10; basis_jet.hxx). With D(x) the pattern of
/// ∂c/∂q_e with the values x in its quadratic rows (D(q) = ∂c/∂q_e, D₂(x) its quadratic rows only):
///   ∂y_kl = S_kl D(q) ∂q,  ∂z_kl = S_kl D(q) ∂q̇ + S_kl D₂(q̇) ∂q,
///   ∂s = Σ_k S_kk (D(q) ∂q̈ + 2 D₂(q̇) ∂q̇ + D₂(q̈) ∂q).
/// Each matrix holds the rows of its ShapeIntegralBlock (nr × ne): a pass then contracts ne
/// derivative rows instead of nc.
struct BasisJet {
  bool valid = false;
  bool rates = false;          ///< q̇_e ≠ 0 at the key (Sqd, Tqd formed)
  bool accelerations = false;  ///< q̈_e ≠ 0 at the key (Tqdd formed)
  std::array<MatX, 9> Sq;      ///< S_kl D(q)
  std::array<MatX, 9> Sqd;     ///< S_kl D₂(q̇), k ≠ l
  MatX Tq, Tqd, Tqdd;          ///< Σ_k S_kk D(q), D₂(q̇), D₂(q̈)
  /// Basis index → the pair (i, j) of its product q_i q_j (−1 for the constant and linear entries).
  std::vector<std::array<int, 2>> pair;
  MatX dq, dqd, dqdd;  ///< a pass's derivatives of q_e, q̇_e, q̈_e (directions × ne)
  MatX quadratic;      ///< forming's D₂(q̇) or D₂(q̈) (nc × ne)
  MatX rows;           ///< forming's rows of D at a block's columns (block columns × ne)
};

/// One body's basis state and basis products in double at given values of its elastic coordinates:
/// AD passes that seed none of them reuse these instead of recomputing them per chunk.
struct ConstantBasis {
  ConstantBasis(int nc, int ne) : prod(nc) {
    basis.c = VecX::Zero(nc);
    basis.cd = VecX::Zero(nc);
    basis.cdd = VecX::Zero(nc);
    basis.D = MatX::Zero(nc, ne);
    key = VecX::Zero(3 * ne);
  }
  bool valid = false;
  VecX key;  ///< [q_e; q̇_e; q̈_e] the products were formed at
  BasisState<double> basis;
  BasisProducts<double, double> prod;
  BasisJet jet;  ///< derivatives of prod in q_e, q̇_e, q̈_e at key (formed when a pass seeds them)
};

/// Buffers of the double mass-matrix assembly (mass_matrix.cpp), sized to the largest body.
struct MassScratch {
  std::array<VecX, 9> y;  ///< S_jl c (largest nc)
  MatX Mb;                ///< body mass matrix (6 + ne)²
  MatX Jb;                ///< [Rᵀ Jv; Rᵀ Jω] on the support, 6 × nsup
  MatX MJ;                ///< M_b,66 Jb
  VecX zero;              ///< ndof zeros (q̇ = q̈ = 0)
};

/// The BEM solution of one blade element at given values of its inputs (aero_section.hxx): AD passes
/// at one point see the same values chunk after chunk and reuse the root instead of solving again.
struct BemRoot {
  bool valid = false;
  double vx = 0, vy = 0, theta = 0, r = 0;  ///< the values it was solved at
  double phi = 0, a = 0, ap = 0;
  bool bem_valid = true;    ///< a BEM root; false: no bracket held one, φ geometric without induction (as AeroDyn)
  double slope = 0;         ///< ∂R/∂φ at phi for the AD passes (aero::inflowAngle), 0 until evaluated
  double search_slope = 0;  ///< the root search's last secant slope (BemSolution::slope): the next search's first step
  /// aero::InflowRoot::flow_at_root: the double loads take φ and the polar (cl, cd, cm at φ − θ) from
  /// the root's own evaluation (aero::loadsAtRoot)
  bool flow_at_root = false;
  double cl = 0, cd = 0, cm = 0;
  /// The double residual's root tolerance for this element (aero::BemOptions::tolerance), 0: the
  /// model's. A time simulation sets AeroDyn's own (linearize/simulate.hpp); the AD passes keep the model's.
  double tolerance = 0;
};

/// One blade element's frozen-wake loads at an inflow (vx, vy, θ) and their first derivatives in
/// those three, kept for the AD passes of one linearization: the section (polar, angles) is then
/// evaluated once per element instead of once per pass (aero_section.hxx).
struct SectionJet {
  bool valid = false;
  double vx = 0, vy = 0, theta = 0, r = 0, ax = 0, tn = 0;                   ///< the values it was evaluated at
  double phi = 0, alpha = 0, W = 0, cl = 0, cd = 0, cm = 0, cx = 0, cy = 0;  ///< values
  double f[3] = {0, 0, 0};                                                   ///< fx, fy, mz
  double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};                        ///< ∂(fx, fy, mz)/∂(vx, vy, θ)
};

/// One blade's aerodynamic load sums and their first derivatives with respect to the few variables
/// they depend on, at one point, for the frozen-wake AD passes of a linearization (Jacobian
/// preaccumulation, Griewank & Walther 2008, §10): each pass then chains these derivatives with its
/// own derivatives of the variables instead of evaluating the blade's elements in its AD scalar
/// (aero_blade_jet.hxx).
///
/// Sums S (dim ns = 6 + nc + ne; detail::BodyLoadSum in body components): the elements' force Fb (3)
/// and moment Mb about the body origin (3), fk_k = Σ P_kᵀ F (nc), gθ_j = Σ θ_jᵀ M (ne).
/// Variables z (dim nz = 12 + 2 ne), ground components: the small rotation δθ of the body frame
/// (R = (I + [δθ]×) R₀) (3), the height r_z of its origin (1), the body's elastic coordinates q_e (ne),
/// the pitch angle (1); the origin velocity v (3), the angular velocity ω (3), q̇_e (ne), the wind
/// speed U (1).
struct BladeJet {
  bool valid = false;
  VecX key;  ///< values it was formed at: R (9), r (3), v (3), ω (3), q_e, q̇_e, pitch, U, frozen inductions
  VecX S;    ///< ns
  MatX dS;   ///< ns × nz
  // Buffers (sized once): the pass's key, its derivatives of z (nz × kChunk) and of S; forming the
  // jet: the basis in AD and in double, the velocity-level derivatives (ns × (7 + ne), row-major).
  VecX pass_key;
  Eigen::Matrix<double, Eigen::Dynamic, kChunk> dz, dsum;
  VecXT<ADChunk> qe_ad, qed_ad, qdd_ad;
  BasisState<ADChunk> basis_ad;
  BasisState<double> basis;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> vel;
  VecX u1, u2, u3, r1, r2, r3;
};

/// One blade element's section outputs with aerodynamic states and their first derivatives in its
/// section inputs, at one point, for the AD passes of a linearization with those states that seed
/// none of the element's states (aero_unsteady.cpp): its airfoil and inflow equations are then
/// evaluated once per element instead of once per pass.
/// Inputs (8): vx, vy, θ, r, ω, the rotor's BEM weight, the skew's χ0 and (r / R_tip) sin ψ.
/// Outputs (kOutputs): the loads with the states fx, fy, mz, the quasi-steady frozen-wake ones, the
/// element's state rates (its UA states, then its dynamic-inflow states; up to 8).
struct UnsteadySectionJet {
  static constexpr int kInputs = 8, kStates = 8, kOutputs = 6 + kStates;
  bool valid = false;
  Eigen::Matrix<double, kInputs + kStates + 2, 1> key;  ///< inputs, states, frozen inductions
  Eigen::Matrix<double, kOutputs, 1> value;
  Eigen::Matrix<double, kOutputs, kInputs> d;  ///< ∂ outputs / ∂ inputs
};

/// The jets of the blade elements and of the blades (per element, per blade), kept across the AD
/// passes of one linearization.
struct AeroJets {
  std::vector<SectionJet> sections;          ///< per blade element (AeroModel::nstations())
  std::vector<BladeJet> blades;              ///< per AeroModel::blades
  std::vector<UnsteadySectionJet> unsteady;  ///< per blade element, with aerodynamic states
};

template <class T>
struct Workspace {
  explicit Workspace(const Model& m);
  std::vector<BemRoot> bem;  ///< per blade element (AeroModel::nstations())
  AeroJets jets;             ///< for AD passes with a frozen wake
  VecXT<T> scratch;          ///< ndof: generalized forces nobody keeps (rotor outputs)
  RotorTotals<T> totals;     ///< the load outputs' aerodynamic resultants (evaluateOutputs)
  /// The load outputs' moments per cut body (evaluateOutputs): body index and moment [N m], ground axes.
  std::vector<std::pair<int, Vec3T<T>>> cut_moments;
  std::vector<FrameState<T>> frames;  ///< per body
  std::vector<BasisState<T>> basis;   ///< per body
  // Scratch for the body inertia forces (sized to the largest nc). An AD pass uses the double
  // products for bodies whose own elastic coordinates are not seeded (body_forces.hxx).
  BasisProducts<T, T> prod;
  BasisProducts<double, T> prod_dt;  ///< c double, ċ and c̈ of type T (C columns)
  /// Double only (empty for AD types): per body, the stage-1 products of the last double residual.
  /// The mass matrix at that residual's kinematics reuses their position part (y = S c, c·y, m1 c);
  /// `body_products_current` says they belong to the current kinematics (forwardKinematics clears it).
  std::vector<BasisProducts<double, double>> body_products;
  bool body_products_current = false;
  std::vector<ConstantBasis> constant_basis;  ///< per body, for AD passes
  MassScratch mass;                           ///< mass-matrix assembly (double)
  VecXT<T> g;                                 ///< Σ_k ∫ P_kᵀ (a_P)_k dm
  VecXT<T> h;                                 ///< elastic generalized inertia forces of one body (largest ne)
};

/// What an AD Jacobian pass asks of forwardKinematics(), residual() and evaluateOutputs()
/// (linearize/jacobian.cpp). The default evaluates everything, values and derivatives.
struct AdPass {
  /// The double kinematics at the same (q, q̇, q̈), kept current by the caller. Given, the pass reads
  /// only derivatives: the frames of bodies whose support carries no seeded direction are copied from
  /// here instead of recomputed, and residual() leaves out the inertia forces of bodies and the loads
  /// that no seeded direction reaches (the values of e are then incomplete; residual() says so).
  const Workspace<double>* kinematics = nullptr;
  bool derivativesOnly() const { return kinematics != nullptr; }
};

}  // namespace whirl
