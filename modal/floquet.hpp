#pragma once
/// \file
/// Floquet analysis of a linear time-periodic rotor model over one revolution, for rotors the
/// multiblade transform cannot make time-invariant (fewer than 3 blades, anisotropic rotors) and as
/// a check of the multiblade average where it can [Peters & Hohenemser 1971; Bauchau & Nikishkov
/// 2001; Skjoldan & Hansen 2009].
///
/// The state matrix A(ψ) known at N equally spaced azimuths is interpolated trigonometrically
/// (exact for harmonics below N/2) and the revolution T = 2π/|Ω| integrated with the fourth-order
/// Magnus scheme (exact for a constant A), in G groups of steps whose propagators give the
/// multipliers μ without forming their product (modal/floquet_multipliers.hpp: a slow rotor's
/// well-damped modes stay resolved); the characteristic exponents η = ln μ / T are known up to
/// multiples of iΩ. Each Floquet solution x(t) = e^{ηt} p(t) (p periodic) is seen in the fixed frame —
/// fixed coordinates as they are, each set of blade coordinates as its collective and first cosine and
/// sine components (for 2 blades the cyclic pair is (q1 − q2)(cos ψ, sin ψ)), a teeter β as the
/// differential pattern (β, −β) — and its frequency is Im η + kΩ with k the harmonic chosen from that
/// fixed-frame spectrum (kinetic-energy weights) by modal/floquet_harmonic.hpp: its centre, and a
/// 2-bladed rotor's cyclic (standing) mode at its backward whirl. Within a set of equal multipliers
/// (an isotropic rotor's collective, BW and FW modes share one) the solutions are first split into ones
/// of a single harmonic (generalized eigenvectors of the harmonic-index operator). For a rotor the
/// multiblade transform makes exactly time-invariant the modes equal those of the multiblade average.
#include <vector>

#include "linearize/mbc.hpp"
#include "modal/rotor_modes.hpp"

namespace whirl {

struct FloquetOptions {
  int steps_per_sample = 8;  ///< Magnus steps per azimuth interval
};

/// Modes of x' = A(ψ(t)) x, states [q (dim n); q̇ (dim n); first-order]; samples at N ≥ 2 equally
/// spaced azimuths, one rotor speed Ω ≠ 0. Mode shapes are in the fixed-frame coordinates
/// (RotorModes::coordinates: fixed DOFs, then "<shape> collective", "<shape> cos", "<shape> sin" per
/// blade set); RotorModes::A is empty.
/// \throws InputError for unequal spacing, Ω = 0, sizes that do not match or non-finite entries.
RotorModes floquetModes(const RotorCoordinates& coords, const std::vector<MbcSample>& samples,
                        const FloquetOptions& opt = {});

/// Modes of a parked rotor with fewer than 3 blades (or a teeter): the plain eigenanalysis of the one
/// model `sample.A`, shapes seen in the fixed frame at `sample.azimuth` as floquetModes sees them
/// (collective, cos and sin of each blade set; cos and sin of a teeter), so that a line of a Campbell
/// diagram has one name at 0 rpm and turning. Frequencies and damping are those of the model.
RotorModes parkedRotorModes(const RotorCoordinates& coords, const MbcSample& sample);

}  // namespace whirl
