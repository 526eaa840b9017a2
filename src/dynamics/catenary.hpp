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
#include "src/model/mooring.hpp"
#include "src/model/scalar.hpp"

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

/// The line profile residual r = (x(H, V) − l, z(H, V) − h) [m] in double, for tests.
Eigen::Vector2d catenaryResidual(const MooringLine& line, double H, double V, double l, double h);

/// Length of the line resting on the seabed at tension (H, V) [m] (0 when it hangs free).
double catenarySeabedLength(const MooringLine& line, double V);

}  // namespace whirl
