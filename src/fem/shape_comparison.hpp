#pragma once
/// \file
/// FE shapes against a model's current shapes (`whirl shapes`): for each bending shape of a flexible
/// beam body, the FE mode of the same direction and order, its frequency, its ElastoDyn polynomial
/// fit and how far the current shape is from it.
#include <string>
#include <vector>

#include "src/fem/mode_shapes.hpp"

namespace whirl::fem {

/// A Rayleigh–Ritz beam body of a model: its FE input and its shapes as the model has them.
struct FlexibleBeam {
  std::string body;
  ModeShapeInput input;
  std::vector<ShapePtr> shapes;
};

struct ShapeComparison {
  std::string body, shape;   ///< body and current shape names
  char direction = 'y';      ///< dominant direction of the current shape (its larger tip component)
  int index = 1;             ///< its order among the body's shapes of that direction (1-based)
  double freq_hz = 0;        ///< FE frequency of that mode [Hz]
  PolynomialFit fit;         ///< of the FE mode, in its direction
  double mac = 0;            ///< MAC of the FE mode and the current shape (both components)
  double max_deviation = 0;  ///< max |FE − current| over the span, both scaled to +1 tip [m per unit]
  BeamMode mode;             ///< the FE mode itself
};

/// One row per bending shape of `beam` (shapes with no tip displacement, e.g. torsion, are skipped);
/// the i-th shape of a direction is compared with the i-th FE mode of that direction.
std::vector<ShapeComparison> compareShapes(const FlexibleBeam& beam);

}  // namespace whirl::fem
