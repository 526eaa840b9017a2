#pragma once
/// \file
/// The ElastoDyn tower file as a whirl beam: distributed properties in SI units and the polynomial
/// mode shapes, in the tower body frame (x up from the base, y side-to-side = −Y, z fore-aft = X).
#include <vector>

#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/shapes/beam.hpp"

namespace whirl {

struct ElastoDynTowerBeam {
  BeamProperties props;  ///< L = TowerHt − base; m = TMassDen·AdjTwMa, EIy = TwSSStif·AdjSSSt, EIz = TwFAStif·AdjFASt
  std::vector<ShapePtr> shapes;  ///< tower FA 1, SS 1, FA 2, SS 2: Σ c_k (x/L)^k, k = 2..6 [m per unit]
  double base = 0;               ///< height of the tower base [m]
};

/// Throws InputError naming the file when the tower has no height or bad properties.
ElastoDynTowerBeam elastoDynTowerBeam(const io::ElastoDynInput& ed);

/// ElastoDyn puts the tower top at the DOF values themselves (CalculatePositions: rZO = (q_FA1 + q_FA2)
/// a1 + (q_SS1 + q_SS2) a3 + axial shortening), not at the polynomials' tip values (the NREL 5MW SS
/// coefficients sum to 0.9999 and 0.999); its top rotation does use the polynomial slopes. Sets the
/// translation columns of `top` (a point of the tower beam with the shapes FA 1, SS 1, FA 2, SS 2)
/// to one unit along body z (FA) or y (SS).
void placeTowerTopAtDofValues(BodyPoint& top);

}  // namespace whirl
