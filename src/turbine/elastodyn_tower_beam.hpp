#pragma once
/// \file
/// The ElastoDyn tower file as a whirl beam: distributed properties in SI units and the polynomial
/// mode shapes, in the tower body frame (x up from the base, y side-to-side = −Y, z fore-aft = X).
#include <vector>

#include "src/io/elastodyn_input.hpp"
#include "src/shapes/beam.hpp"

namespace whirl {

struct ElastoDynTowerBeam {
  BeamProperties props;          ///< L = TowerHt − base; m = TMassDen·AdjTwMa, EIy = TwSSStif·AdjSSSt, EIz = TwFAStif·AdjFASt
  std::vector<ShapePtr> shapes;  ///< tower FA 1, SS 1, FA 2, SS 2: Σ c_k (x/L)^k, k = 2..6 [m per unit]
  double base = 0;               ///< height of the tower base [m]
};

/// Throws InputError naming the file when the tower has no height or bad properties.
ElastoDynTowerBeam elastoDynTowerBeam(const io::ElastoDynInput& ed);

}  // namespace whirl
