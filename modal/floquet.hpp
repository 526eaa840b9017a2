#pragma once
/// \file
/// Floquet analysis of a linear time-periodic rotor model ẋ = A(ψ) x over one revolution, ψ = ψ₀ + Ω t,
/// period T = 2π/Ω: what a rotor with fewer than 3 blades needs, whose equations stay periodic in
/// multiblade coordinates (linearize/mbc.hpp). After Bottasso & Cacciola 2015 ("Model-independent
/// periodic stability analysis of wind turbines", Wind Energy 18) and Skjoldan & Hansen 2009 ("On
/// the similarity of the Coleman and Lyapunov–Floquet transformations for modal analysis of bladed
/// rotor structures", J. Sound Vib. 327).
///
/// - A(ψ) between the N given azimuths: trigonometric (Dirichlet-kernel) interpolation of the
///   samples, exact for an A whose harmonics are below N/2 (an isotropic 3-bladed rotor's blade-frame
///   A holds harmonics 0 … 2).
/// - Monodromy Φ = X(T), Ẋ = A X, X(0) = I: classical Runge–Kutta, at least `steps` steps per sample
///   interval and more where the fastest root needs them (|λ| h / Ω ≤ 0.05).
/// - Characteristic multipliers μ_k = eig(Φ), exponents η_k = ln μ_k / T: damping from Re η exactly,
///   frequency Im η only modulo Ω.
/// - Ambiguity: the solution x_k(t) = e^{η_k t} p_k(t) with p_k periodic; p_k is expanded in harmonics
///   e^{i h ψ} and η_k moves to Im η_k + h* Ω with h* the harmonic that carries most of p_k, measured
///   in the coordinates an observer on the ground sees: the multiblade coordinates for 3 blades or
///   more (so that an isotropic rotor gives the multiblade eigenvalues), the fixed-frame states for
///   fewer (the blade states when a mode has no fixed-frame content).
/// - Limits: the solution is kept at about 512 points per revolution, so roots up to 255 Ω are
///   resolved; a model whose fastest root |λ| exceeds 255 Ω is refused (ComputeError).
/// Not yet used by the commands: the rotors with fewer than 3 blades whirl builds (YAML cases) are
/// analysed at their first azimuth (modal/rotor_modes.hpp), 2-bladed ElastoDyn decks are refused.
#include <complex>
#include <vector>

#include "linearize/mbc.hpp"

namespace whirl {

struct FloquetResult {
  Eigen::MatrixXd monodromy;             ///< Φ(T) (nx × nx)
  Eigen::VectorXcd multipliers;          ///< μ_k (dim nx)
  Eigen::VectorXcd exponents;            ///< η_k with the frequency resolved (rad/s)
  Eigen::MatrixXcd initial_vectors;      ///< eigenvectors of Φ: x_k(0) (nx × nx)
  std::vector<int> harmonic;             ///< h* added to each exponent's principal frequency
};

/// \param[in] layout which states are blade states (MbcLayout::state_blade) and rates; inputs and
///            outputs are not used.
/// \param[in] samples A at N ≥ 1 azimuths ψ₀ + 2πj/N (j = 0 … N−1, in that order), one rotor speed
///            Ω > 0 (rad/s); B, C, D not used.
/// \param[in] steps least number of Runge–Kutta steps per sample interval.
/// \throws InputError for Ω ≤ 0, unequal or unevenly spaced samples; ComputeError for a non-finite
///         monodromy or a root faster than 255 Ω.
FloquetResult floquetAnalysis(const MbcLayout& layout, const std::vector<MbcSample>& samples, int steps = 16);

}  // namespace whirl
