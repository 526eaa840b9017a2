#pragma once
/// \file
/// Floquet analysis of a linear time-periodic rotor model over one revolution, for rotors the
/// multiblade transform cannot make time-invariant (fewer than 3 blades, anisotropic rotors) and as
/// a check of the multiblade average where it can [Peters & Hohenemser 1971; Bauchau & Nikishkov
/// 2001; Skjoldan & Hansen 2009].
///
/// The state matrix A(ψ) known at N equally spaced azimuths is interpolated trigonometrically
/// (exact for harmonics below N/2), the monodromy matrix Φ(T), T = 2π/|Ω|, is integrated with the
/// fourth-order Magnus scheme (exact for a constant A), and its eigenvalues μ give the characteristic
/// exponents η = ln μ / T, known up to multiples of iΩ. Each Floquet solution x(t) = e^{ηt} p(t)
/// (p periodic) is seen in the fixed frame — fixed coordinates as they are, each set of blade
/// coordinates as its collective and first cosine and sine components (for 2 blades the cyclic pair
/// is (q1 − q2)(cos ψ, sin ψ)) — and its frequency is Im η + kΩ with k the harmonic that carries most
/// of that fixed-frame response (kinetic-energy weights). Within a set of equal multipliers (an
/// isotropic rotor's collective, BW and FW modes share one) the solutions are first split into ones
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

}  // namespace whirl
