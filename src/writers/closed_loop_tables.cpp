#include "src/writers/closed_loop_tables.hpp"

#include <cmath>
#include <numbers>

#include "src/io/csv.hpp"
#include "src/writers/gnuplot.hpp"

namespace whirl {
namespace {

constexpr double kPi = std::numbers::pi;

std::string pointColumns(const ClosedLoopPoint& p) {
  const OperatingCondition& c = p.steady.condition;
  return formatNumber(c.wind_speed.value_or(0)) + "," + formatNumber(c.rotor_speed * 30 / kPi) + "," +
         formatNumber(c.collective_pitch.value_or(0) * 180 / kPi);
}

std::string marginColumns(const LoopMargins& m) {
  std::string s;
  for (double v : {m.gain_margin, 20 * std::log10(m.gain_margin), m.gain_crossover, m.phase_margin, m.phase_crossover,
                   m.delay_margin, m.peak_sensitivity})
    s += formatNumber(v) + ",";
  return s;
}

}  // namespace

std::string closedLoopModesCsv(const std::vector<ClosedLoopPoint>& points) {
  std::string t =
      "wind_speed_m_s,rotor_speed_rpm,pitch_deg,loop,mode,freq_hz,damped_freq_hz,damping_ratio,real_1_s,imag_1_s,"
      "controller_share,unstable\n";
  for (const ClosedLoopPoint& p : points)
    for (int loop = 0; loop < 2; ++loop)
      for (const ClosedLoopMode& m : loop == 0 ? p.open_modes : p.closed_modes) {
        t += pointColumns(p) + (loop == 0 ? ",open," : ",closed,") + csvField(m.name) + ",";
        for (double v : {m.freq_hz, m.damped_freq_hz, m.damping_ratio, m.eigenvalue.real(), m.eigenvalue.imag(),
                         m.controller_share})
          t += formatNumber(v) + ",";
        t += m.eigenvalue.real() >= 0 ? "1\n" : "0\n";
      }
  return t;
}

std::string closedLoopMarginsCsv(const std::vector<ClosedLoopPoint>& points) {
  std::string t = "wind_speed_m_s,rotor_speed_rpm,pitch_deg";
  for (const char* loop : {"pitch", "torque"})
    for (const char* col : {"gain_margin", "gain_margin_db", "gain_margin_freq_rad_s", "phase_margin_deg",
                            "phase_margin_freq_rad_s", "delay_margin_s", "peak_sensitivity"})
      t += std::string(",") + loop + "_" + col;
  t += ",least_damping_ratio,stable\n";
  for (const ClosedLoopPoint& p : points)
    t += pointColumns(p) + "," + marginColumns(p.pitch) + marginColumns(p.torque) + formatNumber(p.least_damping) +
         (p.stable ? ",1\n" : ",0\n");
  return t;
}

std::string closedLoopGnuplotScript(const std::string& title) {
  return "# Closed-loop Campbell diagram and loop margins written by whirl: gnuplot closed_loop.gp (from this folder)\n"
         "if (!exists('png_out')) png_out = 'closed_loop.png'\n"
         "if (!exists('svg_out')) svg_out = 'closed_loop.svg'\n"
         "set datafile separator ','\n"
         "set key noenhanced outside right\n"
         "set grid\n"
         "set xlabel 'Wind speed [m/s]' noenhanced\n"
         "do for [out = 1:2] {\n"
         "  if (out == 1) { set terminal pngcairo size 1400,1000 noenhanced; set output png_out }\n"
         "  else { set terminal svg size 1400,1000 noenhanced; set output svg_out }\n"
         "  set multiplot layout 2,2 title " + gnuplotQuoted(title) + "\n"
         "  set ylabel 'Frequency [Hz]'\n"
         "  set yrange [0:3]\n"
         "  plot 'closed_loop_modes.csv' using 1:(strcol(4) eq 'open' ? $6 : NaN) with points pt 6 lc rgb 'gray' title 'open loop', \\\n"
         "       '' using 1:(strcol(4) eq 'closed' ? $6 : NaN) with points pt 7 ps 0.6 lc rgb 'blue' title 'closed loop', \\\n"
         "       '' using 1:(strcol(4) eq 'closed' && $12 == 1 ? $6 : NaN) with points pt 2 ps 2 lc rgb 'red' title 'unstable'\n"
         "  set ylabel 'Damping ratio [-]'\n"
         "  set yrange [-0.1:0.5]\n"
         "  plot 'closed_loop_modes.csv' using 1:(strcol(4) eq 'open' ? $8 : NaN) with points pt 6 lc rgb 'gray' title 'open loop', \\\n"
         "       '' using 1:(strcol(4) eq 'closed' ? $8 : NaN) with points pt 7 ps 0.6 lc rgb 'blue' title 'closed loop'\n"
         "  set autoscale y\n"
         "  set ylabel 'Gain margin [dB]'\n"
         "  plot 'margins.csv' using 1:5 with linespoints title 'pitch loop', '' using 1:12 with linespoints title 'torque loop'\n"
         "  set ylabel 'Phase margin [deg], Ms x 10'\n"
         "  plot 'margins.csv' using 1:7 with linespoints title 'pitch PM', '' using 1:($10*10) with linespoints title 'pitch Ms x 10'\n"
         "  unset multiplot\n"
         "}\n";
}

}  // namespace whirl
