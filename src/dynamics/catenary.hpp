#pragma once
/// \file
/// Fairlead tension of a quasi-static elastic catenary mooring line with seabed contact and friction
/// [Jonkman2007] (the equations of FAST's quasi-static mooring module and of MAP++'s single
/// line): given the fairlead's horizontal distance l from the anchor and its height h above it, the
/// horizontal and vertical fairlead tensions H, V solve
///   l = x(H, V),  h = z(H, V)
/// (x, z in catenary.hxx). Newton solves them in double; the AD scalar takes one more Newton step in
/// its own type from the converged point, which gives exactly the implicit-function derivative
/// ∂(H, V)/∂(l, h) = J⁻¹ (no finite differences), so the mooring stiffness comes out of the
/// Jacobians like any other term.
#include "src/base/scalar.hpp"
#include "src/model/mooring.hpp"

namespace whirl {

/// Fairlead tension components.
template <class T>
struct CatenaryTension {
  T H;  ///< horizontal, towards the anchor [N]
  T V;  ///< vertical, downwards on the fairlead [N]
};

/// Solves the line for (l, h) [m]: l ≥ 0 horizontal fairlead-to-anchor distance, h fairlead height
/// above the anchor. Throws ComputeError("<line name>: …") when Newton does not converge, when the
/// fairlead tension would stretch the line by more than 20 % (it cannot reach its anchor), or l = 0.
template <class T>
CatenaryTension<T> catenaryTension(const MooringLine& line, const T& l, const T& h);

/// The force of the line on its fairlead, ground frame [N], from the anchor-to-fairlead vector d
/// (ground frame) [m]: (−H d_x/l, −H d_y/l, −V) with l the horizontal span. A line whose span is
/// below 1e-3 of its length (a tension-leg tendon, straight below its fairlead) is solved for the
/// ratio H/l instead of H (taut-line form below), so the force and its AD derivatives stay smooth
/// through l = 0, where the horizontal stiffness is the tendon's pendulum stiffness. Throws
/// ComputeError as catenaryTension, and for a near-vertical line that is slack.
template <class T>
Vec3T<T> mooringFairleadForce(const MooringLine& line, const Vec3T<T>& d);

/// The taut, fully suspended line in the variables (q, V), q = H/l, of the span squared s = l² [m²]
/// and the height h [m]: 1 = q X(q² s, V), h = z(q² s, V), with X = x/H written with logarithms
/// (asinh(V/H) − asinh(V_a/H) = ln((V + √(V² + H²)) / (V_a + √(V_a² + H²))), V_a = V − w L > 0, the
/// anchor's vertical tension), smooth in s through s = 0. Throws ComputeError when the line is slack
/// (V_a ≤ 0: it would hang below its anchor or rest on the seabed) or stretched beyond 20 %.
template <class T>
CatenaryTension<T> tautLineTension(const MooringLine& line, const T& s, const T& h);

/// The line profile residual r = (x(H, V) − l, z(H, V) − h) [m] in double, for tests.
Eigen::Vector2d catenaryResidual(const MooringLine& line, double H, double V, double l, double h);

/// Length of the line resting on the seabed at tension (H, V) [m] (0 when it hangs free).
double catenarySeabedLength(const MooringLine& line, double V);

}  // namespace whirl
