#include "src/cli/mode_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "src/io/text/csv.hpp"
#include "src/writers/mode_shape_tables.hpp"

namespace whirl::cli {

std::string modesText(const std::vector<Mode>& modes, const std::vector<std::string>& coords, const std::string& format,
                      const nlohmann::json& header) {
  // An iterative (sparse) solve reports each pair's backward error; the dense path has none.
  bool residuals = !modes.empty();
  for (const auto& m : modes) residuals = residuals && m.residual.has_value();
  if (format == "csv") {
    std::string s = std::string("index,name,freq_hz,damped_freq_hz,damping_ratio") + (residuals ? ",residual" : "") +
                    "\n";
    for (size_t k = 0; k < modes.size(); ++k)
      s += std::to_string(k + 1) + "," + csvField(modes[k].name) + "," + formatNumber(modes[k].freq_hz) + "," +
           formatNumber(modes[k].damped_freq_hz) + "," + formatNumber(modes[k].damping_ratio) +
           (residuals ? "," + formatNumber(*modes[k].residual) : std::string()) + "\n";
    return s;
  } else if (format == "json") {
    nlohmann::json j = header;
    j["coordinates"] = coords;
    j["modes"] = nlohmann::json::array();
    for (size_t k = 0; k < modes.size(); ++k) {
      nlohmann::json mj;
      mj["index"] = k + 1;
      mj["name"] = modes[k].name;
      mj["name_evidence"] = {{"share", modes[k].name_share},
                             {"runner_up", modes[k].runner_up},
                             {"runner_up_share", modes[k].runner_up_share},
                             {"ambiguous", modes[k].ambiguous}};
      mj["freq_hz"] = modes[k].freq_hz;
      mj["damped_freq_hz"] = modes[k].damped_freq_hz;
      mj["damping_ratio"] = modes[k].damping_ratio;
      mj["rigid_body"] = modes[k].rigid_body;
      mj["first_order"] = modes[k].first_order;
      if (modes[k].residual) mj["residual"] = *modes[k].residual;
      mj["participation"] = nlohmann::json::object();
      for (size_t i = 0; i < coords.size(); ++i) mj["participation"][coords[i]] = modes[k].participation(i);
      if (!modes[k].motion.empty()) mj["motion"] = modeMotionJson(modes[k].motion);
      j["modes"].push_back(mj);
    }
    return j.dump(2) + "\n";
  }
  // fmt, not a fixed buffer: a mode's name (from a case file or a `.lin` description) has no length bound.
  std::string out = fmt::format("{:>5}  {:<40} {:>12} {:>14} {:>13}{}\n", "index", "name", "freq [Hz]", "damped [Hz]",
                                "damping [-]", residuals ? "   residual" : "");
  for (size_t k = 0; k < modes.size(); ++k) {
    const Mode& m = modes[k];
    out += fmt::format("{:>5}  {:<40} {:12.6f} {:14.6f} {:13.6f}{}{}\n", k + 1, m.name, m.freq_hz, m.damped_freq_hz,
                       std::abs(m.damping_ratio) < 5e-7 ? 0.0 : m.damping_ratio,  // no "-0.000000"
                       residuals ? fmt::format(" {:10.1e}", *m.residual) : std::string(),
                       m.rigid_body && m.name.find("rigid body") == std::string::npos ? "  (rigid body)" : "");
  }
  return out;
}

void printModes(const std::vector<Mode>& modes, const std::vector<std::string>& coords, const std::string& format,
                const nlohmann::json& header) {
  std::cout << modesText(modes, coords, format, header);
}

}  // namespace whirl::cli
