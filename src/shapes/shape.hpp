#pragma once
/// \file
/// Shape functions of a thin beam along its body x axis [Branlard2019, §4.1]: displacement of the mean
/// line along y and z, torsion about x, and their derivatives along x. One concept: a function of
/// the spanwise coordinate x ∈ [0, L] that can be evaluated anywhere.
#include <memory>
#include <string>
#include <vector>

#include "src/base/types.hpp"

namespace whirl {

/// Values of one shape at one station (per unit of its coordinate).
struct ShapeValue {
  double uy = 0, uz = 0, tx = 0;     ///< displacement [m], torsion [rad]
  double uy1 = 0, uz1 = 0, tx1 = 0;  ///< slopes d/dx [1/m]
  double uy2 = 0, uz2 = 0;           ///< curvatures d²/dx² [1/m²]
};

class Shape {
 public:
  virtual ~Shape() = default;
  virtual ShapeValue eval(double x) const = 0;
  std::string name;
};
using ShapePtr = std::shared_ptr<const Shape>;

/// u = Σ_k a_k ((x + x0)/L)^k along the unit direction (dy, dz) (ElastoDyn mode-shape polynomials use
/// k = 2..6 with Σ a_k = 1 and x0 = 0). powers[k] is the coefficient of the k-th power. x0 ≠ 0
/// evaluates the polynomial from another origin (YAMS evaluates blade shapes at r/TipRad, r measured
/// from the rotor centre, for a blade starting at the hub radius x0).
ShapePtr polynomialShape(std::string name, double length, std::vector<double> powers, double dy, double dz,
                         double x0 = 0.0);

/// u = 1 − cos(π x / 2L) along (dy, dz): the massless beam with top mass [Branlard2019, §5.1].
ShapePtr oneMinusCosShape(std::string name, double length, double dy, double dz);

/// Mode j (1-based) of a uniform clamped-free beam with tip mass ratio Mt/M [Branlard2019, eq. 32],
/// along (dy, dz), scaled to unit tip displacement.
ShapePtr clampedTopMassShape(std::string name, double length, int j, double tip_mass_ratio, double dy, double dz);

/// β_j of [Branlard2019, eq. 32]: root of 1 + cosh β cos β − β Mt/M (sin β cosh β − cos β sinh β) = 0
/// closest to (2j−1)π/2.
double clampedTopMassBeta(int j, double tip_mass_ratio);

/// Torsion mode j (1-based) of a uniform clamped-free shaft: t_x = sin(β_j x/L), β_j = π/2 + (j−1)π
/// [Branlard2019, §5.3].
ShapePtr torsionSineShape(std::string name, double length, int j);

/// Tabulated shape: columns at increasing stations x (m). Missing derivatives (empty vectors) are
/// computed from the table by finite differences. Linear interpolation between stations.
struct ShapeTable {
  VecX x, uy, uz, tx, uy1, uz1, tx1, uy2, uz2;
};
ShapePtr tableShape(std::string name, ShapeTable table);

}  // namespace whirl
