#pragma once
/// \file
/// Which harmonic gives a Floquet solution its frequency. A characteristic exponent η is known only
/// up to multiples of iΩ; the solution x(t) = e^{ηt} p(t) has a spectrum of harmonics k (frequencies
/// Im η + kΩ), and the mode is reported at one of them [Skjoldan & Hansen 2009; Bottasso & Cacciola
/// 2015]. The rule, with E_k the kinetic-energy-weighted power of harmonic k:
/// - the *central* harmonics of a spectrum are those within 1.5 of its energy centroid Σ k E_k / Σ E_k
///   that carry at least a quarter of its largest harmonic's energy: the one dominant harmonic of a
///   fixed-frame or a whirling mode; the middle of a spread of harmonics when the mode shape changes
///   over the revolution faster than the mode oscillates (a slow rotor: the largest harmonic of such a
///   spread jumps from one rotor speed to the next, its centre moves by at most 2Ω); the two whirls at
///   ±Ω around a standing pattern's carrier, which itself carries nothing;
/// - the mode is reported at the central harmonic with the lowest |frequency| (of a standing
///   pattern's two whirls, the backward one, until one carries about three times the other);
/// - on a rotor with 2 blades (or a teeter) a mode carried mostly (> 50 % of its fixed-frame energy) by
///   the cyclic coordinates (blade cos/sin, teeter cos/sin) stands in the rotating frame: its carrier is
///   the largest central harmonic of the rotor's own coordinates (rotating-frame frequency ω), and it is
///   reported at its backward whirl ω − Ω in the fixed frame (|ω − Ω| when ω < Ω). The two whirls of
///   such a mode weigh nearly alike, and whichever is larger flips with small couplings (where a flap
///   mode's forward whirl meets an edge mode's backward one, for example): the rule keeps one line per
///   mode, continuous in rotor speed. Where two cyclic modes lock in a combination resonance (rotating
///   frequencies 2Ω apart, equal exponents modulo iΩ: UAE Phase VI flap and edge near 40 rpm) each
///   Floquet mode carries both, and which carrier it is reported at can change from point to point.
/// Every choice is symmetric under conjugation (a multiplier and its conjugate give one mode).
#include <vector>

namespace whirl {

/// Energies of one Floquet solution per harmonic: entry k mod M for harmonic k = −M/2 … M/2 − 1.
struct SolutionSpectrum {
  std::vector<double> fixed;     ///< the fixed-frame view, all rows (dim M)
  std::vector<double> cyclic;    ///< the cyclic rows of that view alone (dim M)
  std::vector<double> rotating;  ///< the rotor's own coordinates (blades, teeter) as they are (dim M, or empty)
};

/// Index (k mod M) of the harmonic that gives the mode its frequency |Im η + kΩ|, by the rule above.
/// \param[in] eta_imag Im η [rad/s]; \param[in] omega |Ω| [rad/s], > 0
/// \param[in] standing_rotor the rotor has at most 2 blades (or a teeter): its cyclic modes stand
int floquetHarmonic(const SolutionSpectrum& s, double eta_imag, double omega, bool standing_rotor);

/// True when `s` is a standing rotor's cyclic mode (the third rule above), reported at its backward
/// whirl: its name says BW whatever the phase of its shape at that harmonic (a slow rotor's spread
/// spectrum blurs it).
bool standingCyclicMode(const SolutionSpectrum& s, bool standing_rotor);

}  // namespace whirl
