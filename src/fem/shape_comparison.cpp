#include "src/fem/shape_comparison.hpp"

#include <cmath>

namespace whirl::fem {

std::vector<ShapeComparison> compareShapes(const FlexibleBeam& beam) {
  const double L = beam.input.props.length;
  std::vector<ShapeComparison> rows;
  int ny = 0, nz = 0;
  for (const ShapePtr& s : beam.shapes) {
    const ShapeValue tip = s->eval(L);
    if (std::abs(tip.uy) == 0 && std::abs(tip.uz) == 0) continue;
    ShapeComparison r;
    r.body = beam.body;
    r.shape = s->name;
    r.direction = std::abs(tip.uy) >= std::abs(tip.uz) ? 'y' : 'z';
    r.index = r.direction == 'y' ? ++ny : ++nz;
    rows.push_back(r);
  }
  if (rows.empty()) return rows;
  const std::vector<BeamMode> modes = beamModes(beam.input, ny, nz);
  for (ShapeComparison& r : rows)
    for (const BeamMode& m : modes)
      if (m.direction == r.direction && m.index == r.index) {
        r.mode = m;
        r.freq_hz = m.freq_hz;
        r.fit = fitElastoDynPolynomial(*m.shape, L, m.direction);
        for (const ShapePtr& s : beam.shapes)
          if (s->name == r.shape) {
            r.mac = shapeMac(*m.shape, *s, L);
            // The current shape scaled to +1 at the tip in its direction, as the FE mode is.
            const ShapeValue tip = s->eval(L);
            r.max_deviation = shapeMaxDeviation(*m.shape, *s, L, 101, 1.0 / (r.direction == 'y' ? tip.uy : tip.uz));
          }
      }
  return rows;
}

}  // namespace whirl::fem
