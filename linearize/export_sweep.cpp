#include "linearize/export_sweep.hpp"

#include "linearize/export_serialize.hpp"

namespace whirl {

std::vector<ExportPoint> exportSweep(const Model& model, const std::vector<SweepPoint>& points,
                                     const ExportOptions& opt, const SweepOptions& sweep) {
  return sweepOperatingPoints<ExportPoint>(
      model, points,
      [&](const Model& m, const SweepPoint& sp, const OperatingPoint& start) {
        ExportOptions o = opt;
        if (sp.deflections.size() > 0) o.deflections = &sp.deflections;
        ExportPoint p = exportOperatingPoint(m, start, o);
        if (sweep.check_point) sweep.check_point(m, {p.equilibrium}, sp);
        p.rpm = sp.rpm;
        p.wind_speed = sp.wind_speed;
        p.pitch_deg = sp.pitch_deg;
        p.model.wind_speed = sp.wind_speed;
        for (auto& s : p.azimuths) s.wind_speed = sp.wind_speed;
        return p;
      },
      encodeExportPoint, decodeExportPoint, sweep);
}

}  // namespace whirl
