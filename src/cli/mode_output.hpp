#pragma once
/// \file
/// Printing a list of modes as a table, CSV (index,name,freq_hz,damped_freq_hz,damping_ratio) or
/// JSON (with the energy share of every coordinate), shared by `modes` and `lin`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "modal/modes.hpp"

namespace whirl::cli {

/// The text of the modes in `format` (table, csv or json); `header` is merged into the JSON document
/// (case, operating point, …).
std::string modesText(const std::vector<Mode>& modes, const std::vector<std::string>& coordinates,
                      const std::string& format, const nlohmann::json& header);

/// modesText on stdout.
void printModes(const std::vector<Mode>& modes, const std::vector<std::string>& coordinates, const std::string& format,
                const nlohmann::json& header);

}  // namespace whirl::cli
