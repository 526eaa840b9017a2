#include "linearize/export_point.hpp"

#include <numbers>

#include "linearize/periodic.hpp"
#include "src/base/error.hpp"

namespace whirl {

ExportPoint exportOperatingPoint(const Model& m, const OperatingPoint& start, const ExportOptions& opt) {
  ExportPoint e;
  const int az = findAzimuthDof(m);
  e.rpm = az >= 0 ? start.qd(az) * 30 / std::numbers::pi : 0.0;
  if (az < 0) {
    const OperatingPoint op = solveOperatingPoint(m, start);
    e.equilibrium = op;
    LinearizeOptions lo;
    lo.frozen_wake = opt.frozen_wake;
    e.model = selectInputsOutputs(stateSpace(m, op, linearize(m, op, lo)), opt.inputs, opt.outputs);
  } else {
    PeriodicOptions popt;
    popt.azimuths = opt.azimuths;
    popt.deflections = opt.deflections;
    popt.linearize.frozen_wake = opt.frozen_wake;
    const PeriodicLinearization p = linearizePeriodic(m, start, popt);
    e.equilibrium = p.points.front();
    for (size_t k = 0; k < p.models.size(); ++k)
      e.azimuths.push_back(selectInputsOutputs(stateSpace(m, p.points[k], p.models[k]), opt.inputs, opt.outputs));
    if (bladeCount(e.azimuths.front()) >= 3) {
      try {
        e.model = multibladeAverage(e.azimuths);
      } catch (const InputError& err) {
        throw InputError(std::string("multiblade transform of the chosen inputs/outputs: ") + err.what() +
                         " (select the rotating-frame inputs/outputs of every blade)");
      }
    } else {
      e.model = e.azimuths.front();  // nothing in the rotating frame (or < 3 blades): the first azimuth
    }
  }
  if (opt.drop_azimuth) {
    e.model = dropAzimuth(e.model);
    for (auto& s : e.azimuths) s = dropAzimuth(s);
  }
  return e;
}

ExportPoint exportOperatingPoint(const Model& m, const OperatingCondition& c, const ExportOptions& opt) {
  return exportOperatingPoint(m, initialPoint(m, c), opt);
}

}  // namespace whirl
