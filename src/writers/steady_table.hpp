#pragma once
/// \file
/// The table of `whirl steady` (steady.csv): one row per steady operating point with the rotor's
/// power, torque, thrust and coefficients. Shared by the command (src/cli/cmd_steady.cpp) and the
/// Python module's `Model.steady` (python/src/sweeps.cpp), which return the same numbers.
#include <string>
#include <vector>

#include "linearize/trim.hpp"

namespace whirl {

/// One row of steady.csv: the values of the numeric columns (steadyColumns() but the last) and the
/// region.
struct SteadyRow {
  std::vector<double> values;  ///< in the units of the column names (m/s, rpm, deg, kW, kN m, kN, -, m)
  std::string region;          ///< "below rated", "above rated", "given" (no generator torque law), or "ROSCO <branch>"
                               ///< (SteadyState::region)
  double cp = 0, ct = 0, tsr = 0;  ///< power and thrust coefficients, tip-speed ratio [-]
};

/// The column names of steady.csv, units in the name (wind_speed_m_s, …, region).
const std::vector<std::string>& steadyColumns();

/// The row of `s`: Cp = P_aero / (½ ρ A U³), Ct = T / (½ ρ A U²), TSR = Ω R / U with the model's
/// rotor radius R and air density ρ; generator power with the generator's efficiency.
SteadyRow steadyRow(const Model& model, const SteadyState& s);

/// steady.csv text (numbers at full precision, formatNumber).
std::string steadyCsv(const Model& model, const std::vector<SteadyState>& states);

}  // namespace whirl
