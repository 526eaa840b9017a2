#pragma once
/// \file
/// AeroDyn's skewed-wake correction of the axial induction (Pitt & Peters 1981, with the constant of
/// Glauert's form; AeroDyn v15 `SkewMod = 2`, v4 `Skew_Mod = 1` with `SkewRedistr_Mod = 1`, BEM_Mod 1): in
/// a wake skewed by χ0 from the rotor axis the induction is larger on the downwind side of the disk,
///   a ← a (1 + K tan(χ/2) (r / R_tip) sin ψ),   χ = (0.6 a + 1) χ0 (Burton et al. 2001),
/// K = `SkewModFactor` (15π/32 by default), applied after the BEM solution (and after DBEMT) and before the
/// low-TSR weight (BEMT.f90 ApplySkewedWakeCorrection_AllNodes, BEMTUncoupled.f90 ApplySkewedWakeCorrection);
/// elements with fixed inductions (a loss constant of 0) keep theirs.
///
/// The disk frame (AeroDyn SetInputsForBEMT): χ0 the angle between the rotor axis x̂ and the disk-averaged
/// relative wind V, ŷ_d along −V's in-plane part, ẑ_d = V × x̂ / |V's in-plane part|; a blade's azimuth
/// ψ = atan2(−ẑ_r·ŷ_d, ẑ_r·ẑ_d) from its root's span axis ẑ_r; R_tip the blade's largest distance from the
/// rotor axis. AeroDyn averages the wind less the structural velocity over every node of the rotor; here V is
/// the hub-height wind direction (as the low-TSR weight takes it): equal for a steady wind with shear and
/// upflow and a rotor whose nodes' velocities average out (any equilibrium), without the tower's potential
/// flow in the average and without V's derivatives in the structural velocities (second order: they move
/// χ0, which multiplies an induction already corrected by a few per cent).
#include <cmath>
#include <numbers>

#include "src/base/scalar.hpp"
#include "src/base/types.hpp"
#include "src/model/aero_model.hpp"
#include "src/model/model.hpp"

namespace whirl::detail {

/// The rotor's skew: χ0 and the disk axes ŷ_d, ẑ_d (ground components); inactive without the
/// correction, without wind, or with the wind along the rotor axis (χ0 = 0: no correction, nothing to
/// differentiate).
template <class TK>
struct RotorSkew {
  bool active = false;
  TK chi0 = TK(0.0);
  Vec3T<TK> y, z;
};

/// `disk`: the rotor axis (hub frame x, ground components); `wind_dir`: the steady wind's direction;
/// `speed`: the hub-height wind speed's value.
template <class TK>
RotorSkew<TK> rotorSkew(const AeroModel& am, const Vec3T<TK>& disk, const Vec3& wind_dir, double speed) {
  RotorSkew<TK> s;
  if (am.skew_factor == 0.0 || !am.induction || speed == 0.0) return s;
  const Vec3T<TK> v = (speed > 0 ? 1.0 : -1.0) * wind_dir.template cast<TK>();  // V / |V|
  const TK along = v.dot(disk);
  const Vec3T<TK> in_plane = along * disk - v;  // AeroDyn's tmp: −(V's in-plane part)
  using std::acos;
  using std::sqrt;
  const TK norm = sqrt(in_plane.dot(in_plane));
  // Below about 1e-7 rad of skew the correction is below 1e-8 of the induction.
  if (!(valueOf(norm) > 1e-7)) return s;
  s.active = true;
  s.chi0 = acos(valueOf(along) > 1.0 ? TK(1.0) : valueOf(along) < -1.0 ? TK(-1.0) : along);
  s.y = in_plane / norm;
  s.z = v.cross(disk) / norm;
  return s;
}

/// What one element's correction needs, in the loads' scalar: χ0 and (r / R_tip) sin ψ.
template <class T>
struct ElementSkew {
  T chi0 = T(0.0), radial_sin = T(0.0);
};

/// A blade's sin ψ and R_tip.
template <class TK>
struct BladeSkew {
  TK sin_psi = TK(0.0), tip_radius = TK(0.0);

  /// The element at distance r from the axis.
  template <class T>
  ElementSkew<T> at(const RotorSkew<TK>& rotor, const TK& r) const {
    return {T(rotor.chi0), T(TK(r / tip_radius * sin_psi))};
  }
};

/// A blade's sin ψ from the blade body's rotation R (the root's span axis ẑ_r, root to tip, is the body's x axis
/// as elementFrame takes AeroDyn's z_a; not the pitch axis, which ElastoDyn turns about −x), and
/// its R_tip (bladeTipRadius in aero_element.hxx).
template <class TK>
BladeSkew<TK> bladeSkew(const RotorSkew<TK>& rotor, const Mat3T<TK>& R, const TK& tip_radius) {
  using std::sqrt;
  BladeSkew<TK> b;
  b.tip_radius = tip_radius;
  const Vec3T<TK> span = R.col(0);
  const TK sy = -span.dot(rotor.y), sz = span.dot(rotor.z);
  const TK h = sqrt(sy * sy + sz * sz);
  if (valueOf(h) > 0) b.sin_psi = sy / h;  // ψ = atan2(sy, sz); 0 when both vanish (AeroDyn)
  return b;
}

/// The factor 1 + K tan(χ/2) (r / R_tip) sin ψ of an element with (uncorrected) axial induction a; |χ| beyond
/// π/2 takes tan(χ/2) = ±1 (AeroDyn limits it there, with a warning).
template <class T>
T skewFactor(const AeroModel& am, const ElementSkew<T>& e, const T& a) {
  T chi = (0.6 * a + 1.0) * e.chi0;
  // AeroDyn wraps χ into [−π, π] first (MPi2Pi): χ0 ∈ [0, π], so only a large induction leaves it.
  if (valueOf(chi) > std::numbers::pi) chi = chi - 2.0 * std::numbers::pi;
  using std::tan;
  const double cv = valueOf(chi);
  const T half_tan = std::abs(cv) > 0.5 * std::numbers::pi ? T(cv > 0 ? 1.0 : -1.0) : T(tan(chi / 2.0));
  return 1.0 + am.skew_factor * half_tan * e.radial_sin;
}

}  // namespace whirl::detail
