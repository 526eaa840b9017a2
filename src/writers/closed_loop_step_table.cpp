#include "src/writers/closed_loop_step_table.hpp"

#include "src/io/text/csv.hpp"
#include "src/writers/gnuplot.hpp"

namespace whirl {
namespace {

/// A column name: the signal's name with spaces as underscores.
std::string column(const std::string& name) {
  std::string s = name;
  for (char& ch : s)
    if (ch == ' ' || ch == ',' || ch == '"') ch = '_';
  return s;
}

}  // namespace

std::string closedLoopStepCsv(const ClosedLoopStep& r, double wind_speed, const ClosedLoopStepOptions& opt) {
  std::string t = "time_s,wind_speed_m_s";
  for (const ClosedLoopStepSignal& s : r.signals)
    t += "," + column(s.name) + "_nonlinear," + column(s.name) + "_linear";
  t += "\n";
  for (size_t k = 0; k < r.time.size(); ++k) {
    t += formatNumber(r.time[k]) + "," + formatNumber(wind_speed + (r.time[k] >= opt.step_time ? opt.wind_step : 0));
    for (const ClosedLoopStepSignal& s : r.signals)
      t += "," + formatNumber(s.nonlinear[k]) + "," + formatNumber(s.linear[k]);
    t += "\n";
  }
  return t;
}

std::string closedLoopStepGnuplot(const ClosedLoopStep& r, double wind_speed, const ClosedLoopStepOptions& opt) {
  const int n = static_cast<int>(r.signals.size());
  std::string g = "# whirl verify --closed-loop: nonlinear (ROSCO's discrete laws) vs linear closed loop\n";
  g += "if (!exists('png_out')) png_out = 'closed_loop_step.png'\n";
  g += "if (!exists('svg_out')) svg_out = 'closed_loop_step.svg'\n";
  g += "set datafile separator ','\nset key top right noenhanced\nset grid\n";
  for (const char* term : {"png", "svg"}) {
    g += std::string(term == std::string("png") ? "set terminal pngcairo noenhanced size 900,"
                                                : "set terminal svg noenhanced size 900,") +
         std::to_string(250 * n) + "\n";
    g += std::string("set output ") + (term == std::string("png") ? "png_out" : "svg_out") + "\n";
    g += "set multiplot layout " + std::to_string(n) + ",1 title " +
         gnuplotQuoted("wind step " + formatNumber(opt.wind_step) + " m/s at " + formatNumber(opt.step_time) +
                       " s from " + formatNumber(wind_speed) + " m/s") +
         "\n";
    for (int j = 0; j < n; ++j) {
      const ClosedLoopStepSignal& s = r.signals[static_cast<size_t>(j)];
      g += "set ylabel " + gnuplotQuoted("d" + s.name + " [" + s.unit + "]") + "\n";
      g += j + 1 == n ? "set xlabel 'time [s]'\n" : "unset xlabel\n";
      g += "plot 'closed_loop_step.csv' using 1:" + std::to_string(3 + 2 * j) +
           " with lines lw 2 title 'nonlinear', '' using 1:" + std::to_string(4 + 2 * j) +
           " with lines dt 2 lw 2 title 'linear'\n";
    }
    g += "unset multiplot\n";
  }
  return g;
}

}  // namespace whirl
