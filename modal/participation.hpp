#pragma once
/// \file
/// Modes of a first-order linear system ẋ = A x whose states carry no mass matrix (an OpenFAST
/// `.lin` file), named from participation factors [PerezArriaga1982] taken per coordinate: for
/// eigenvalue λ_k with right eigenvector v_k and left eigenvector u_k, coordinate c (its states i ∈ c)
/// takes the share
///   p_ck = (Σ_{i∈c} |u_ik|)(Σ_{i∈c} |v_ik|) / Σ_d (Σ_{i∈d} |u_ik|)(Σ_{i∈d} |v_ik|).
/// The shares do not change when a coordinate is rescaled (metres or radians, tip or tower-top
/// displacement), which is what a file without a mass matrix needs. For an undamped second-order
/// system with x = [q; q̇], u = [λ̄Mφ; Mφ] and v = [φ; λφ], so p_c = |φ_c (Mφ)_c| / Σ_d |φ_d (Mφ)_d|:
/// the kinetic-energy share that whirl's own modes use (modal/modes.hpp), with the full mass matrix,
/// although M is never known. Summing over a coordinate's states before the product, and normalizing
/// by the total rather than by uᴴv, keeps the shares defined at a defective root (the double zero
/// of a free azimuth: v is the angle, u its rate, uᴴv = 0).
///
/// Coordinates: a displacement and its rate form one coordinate; a first-order state (HydroDyn
/// radiation, an aerodynamic or controller state) is a coordinate of its own. A complex pair
/// (λ, λ̄) is one mode; each real root is a mode of its own, as MBC3 lists them [Bir2010]
/// (f = |λ|/2π, f_d = 0, ζ = −λ/|λ| = ±1), and a zero root is a rigid-body mode (a double zero
/// root, the angle and rate of a free azimuth, is one).
#include <string>
#include <vector>

#include "modal/eigen.hpp"
#include "modal/modes.hpp"

namespace whirl {

/// Modes of ẋ = A x from its eigendecomposition, sorted by frequency.
/// \param[in] ed eigenvalues, right and left eigenvectors of A (dim N): eigenStandard(A, true).
/// \param[in] coordinate_of (dim N) the coordinate 0 … n−1 each state belongs to.
/// \param[in] names (dim n) coordinate names, for Mode::name (refined by the caller).
/// Mode::shape (dim n) is the eigenvector at each coordinate's first state (the displacement, or the
/// first-order state), largest entry = 1; Mode::participation (dim n) sums the states' factors.
/// \throws ComputeError when ed has no left eigenvectors or the sizes disagree.
std::vector<Mode> participationModes(const EigenDecomposition& ed, const std::vector<int>& coordinate_of,
                                     const std::vector<std::string>& names);

}  // namespace whirl
