#pragma once
/// \file
/// Multiblade coordinate (Coleman) transform of a linear time-periodic rotor model, after [Bir2008]:
/// "Multi-Blade Coordinate Transformation and its Application to Wind Turbine Analysis"
/// (NREL/CP-500-42553, 2008) and the MBC3 user's guide [Bir2010] (NREL/TP-500-44327).
///
/// Frames. Rotating-frame quantities q_b belong to blade b = 0 … N−1 (blade 1 is b = 0), whose
/// azimuth is ψ_b = ψ + 2πb/N, ψ being the azimuth of blade 1. Each set of N "same" rotating
/// quantities (one per blade) becomes N fixed-frame (multiblade) coordinates:
///   q_b = q_0 + Σ_{k=1}^{K} (q_kc cos kψ_b + q_ks sin kψ_b) [+ q_d (−1)^(b+1) for even N],
///   K = (N−1)/2 (integer division), i.e.
///   q_0 = (1/N) Σ_b q_b, q_kc = (2/N) Σ_b q_b cos kψ_b, q_ks = (2/N) Σ_b q_b sin kψ_b,
///   q_d = (1/N) Σ_b (−1)^(b+1) q_b ([Bir2008]; docs/dev/architecture.md, notation; blades numbered from 1).
/// In matrix form q = T1(ψ) q_NR. The transformed coordinates of a set take the slots of the set in
/// the original vector: blade 1's slot holds q_0, blade 2's q_1c, blade 3's q_1s, then q_2c, q_2s, …
/// and q_d last for even N (as MBC3 does for N = 3).
///
/// States. A state that is the time derivative q̇ of another state q (second-order DOF) is
/// marked in MbcLayout::velocity_of; with x = T x_NR, the transform of such a pair is
///   q = T1 q_NR,  q̇ = T1 q̇_NR + Ω T2 q_NR,  T2 = ∂T1/∂ψ,  T3 = ∂²T1/∂ψ²,
///   Ṫ: q-rows Ω T2 (on q_NR); q̇-rows (Ω² T3 + Ω̇ T2) (on q_NR) and Ω T2 (on q̇_NR),
/// other (first-order) rotating states use q = T1 q_NR only. Then
///   A_NR = T⁻¹ (A T − Ṫ),  B_NR = T⁻¹ B T1u,  C_NR = T1y⁻¹ C T,  D_NR = T1y⁻¹ D T1u,
/// where T1u, T1y are the T1 of the rotating inputs and outputs (no rate terms). This uses the
/// exact T⁻¹; when the q-rows of A are [0 I] (true for OpenFAST and whirl models) it equals the
/// MBC3 guide's eq. 29, blkdiag(T1⁻¹, T1⁻¹)(A T − R) with 2ΩT2 in the q̇-q̇ block of R.
/// Finally the matrices are averaged over the given azimuths (arithmetic mean, as MBC3: give
/// azimuths evenly spread over one revolution).
///
/// Blades. N ≥ 3 is required: with 2 blades the transformed equations stay periodic and
/// averaging them is not a valid approximation (use a Floquet analysis); N < 3 throws InputError.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace whirl {

/// Which entries of x, u, y are in the rotating frame, and of which blade.
/// Pairing rule: the j-th rotating entry of blade 0 (in the order of the vector, not counting
/// velocity states) forms a set with the j-th rotating entry of every other blade; all blades must
/// have the same number of rotating entries. Velocity states follow their displacement.
struct MbcLayout {
  int num_blades = 3;             ///< N (≥ 3)
  std::vector<int> state_blade;   ///< (dim nx) blade 0 … N−1 of each state, −1 = fixed frame
  std::vector<int> velocity_of;   ///< (dim nx, or empty = no second-order DOFs) for a state that
                                  ///< is q̇ of state i: i; otherwise −1
  std::vector<int> input_blade;   ///< (dim nu, or empty = all inputs fixed) blade of each input
  std::vector<int> output_blade;  ///< (dim ny, or empty = all outputs fixed) blade of each output
};

/// Layout for x = [q (dim n); q̇ (dim n); x1 (first-order states)], whirl's own ordering
/// (docs/dev/architecture.md, notation) and that of an OpenFAST model with ElastoDyn states only.
/// \param[in] dof_blade blade of each DOF q (dim n), −1 = fixed frame.
/// \param[in] first_order_blade blade of each first-order state (dim nx − 2n).
MbcLayout secondOrderLayout(int num_blades, const std::vector<int>& dof_blade,
                            const std::vector<int>& first_order_blade = {});

/// The linear model x' = A x + B u, y = C x + D u at one rotor azimuth. B, C, D may be empty.
struct MbcSample {
  double azimuth = 0.0;             ///< ψ, azimuth of blade 1 (rad)
  double rotor_speed = 0.0;         ///< Ω = dψ/dt (rad/s)
  double rotor_acceleration = 0.0;  ///< Ω̇ (rad/s²), usually 0 at a periodic operating point
  Eigen::MatrixXd A;                ///< (nx × nx)
  Eigen::MatrixXd B;                ///< (nx × nu) or empty
  Eigen::MatrixXd C;                ///< (ny × nx) or empty
  Eigen::MatrixXd D;                ///< (ny × nu) or empty
};

/// Meaning of one entry of a transformed vector.
enum class MbcKind { Fixed, Collective, Cosine, Sine, Differential };
struct MbcCoordinate {
  MbcKind kind = MbcKind::Fixed;
  int harmonic = 0;  ///< k of cos kψ / sin kψ (1 … (N−1)/2); 0 for the other kinds
};
/// "fixed", "collective", "cos", "sin", "cos 2", "sin 2", …, "differential".
std::string toString(MbcCoordinate c);

/// Transformed model of each sample and their azimuth average (the time-invariant approximation).
struct MbcResult {
  std::vector<MbcSample> samples;      ///< A_NR, B_NR, C_NR, D_NR at each given azimuth
  Eigen::MatrixXd A, B, C, D;          ///< averages over the samples (B, C, D empty if absent)
  std::vector<MbcCoordinate> states;   ///< (dim nx) meaning of each transformed state
  std::vector<MbcCoordinate> inputs;   ///< (dim nu)
  std::vector<MbcCoordinate> outputs;  ///< (dim ny)
};

/// Transforms one sample to multiblade coordinates.
/// \throws InputError if the layout is inconsistent (sizes, blade indices, sets, N < 3), or a
///         matrix has the wrong size or a non-finite entry.
MbcSample mbcTransform(const MbcLayout& layout, const MbcSample& sample);

/// Transforms every sample and averages them.
/// \param[in] samples the model at several azimuths of one operating point (same sizes).
MbcResult mbcAverage(const MbcLayout& layout, const std::vector<MbcSample>& samples);

}  // namespace whirl
