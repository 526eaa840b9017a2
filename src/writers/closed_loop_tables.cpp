#include "src/writers/closed_loop_tables.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <tuple>

#include "src/io/text/csv.hpp"
#include "src/writers/campbell_html.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"

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

namespace {

/// `plot` entries of one diagram's lines drawn from `dat` (columns rpm, wind, freq, damping).
std::string lineEntries(const CampbellDiagram& d, const std::string& dat, const std::string& column, bool open,
                        const CampbellPlotOptions& opt) {
  std::string s;
  for (size_t i = 0; i < d.lines.size(); ++i) {
    if (!campbellLineShown(d, d.lines[i], opt)) continue;
    s += s.empty() ? "" : ", \\\n       ";
    s += gnuplotQuoted(dat) + " index " + std::to_string(i) + " using 2:" + column;
    s += open ? " with lines dt 2 lc rgb 'gray' notitle"
              : " with linespoints pt 7 ps 0.5 title " + gnuplotQuoted(d.lines[i].name);
  }
  return s;
}

/// `plot` entries of the margin columns (Gnuplot `using` expressions on margins.csv) that have a finite value
/// somewhere: a loop that never acts (inf everywhere) would only make Gnuplot warn.
std::string marginEntries(
    const std::vector<ClosedLoopPoint>& points,
    const std::vector<std::tuple<std::string, std::string, std::function<double(const ClosedLoopPoint&)>>>& cols) {
  std::string s;
  for (const auto& [expr, title, value] : cols) {
    bool any = false;
    for (const ClosedLoopPoint& p : points) any = any || std::isfinite(value(p));
    if (!any) continue;
    s += (s.empty() ? "'margins.csv'" : ", ''") + std::string(" using 1:") + expr + " with linespoints title " +
         gnuplotQuoted(title);
  }
  return s.empty() ? "NaN notitle" : s;
}

}  // namespace

std::string closedLoopGnuplotScript(const ClosedLoopCampbell& c, const CampbellPlotOptions& opt) {
  bool unstable = false;
  for (const ClosedLoopPoint& p : c.points) unstable = unstable || !p.stable;
  // The unstable roots as an inline data block (wind, frequency, damping %): the panels read
  // whitespace-separated .dat files, and Gnuplot has one separator at a time (the CSV's commas would
  // leave no valid point).
  std::string block = "$unstable << EOD\n";
  for (const ClosedLoopPoint& p : c.points)
    for (const ClosedLoopMode& m : p.closed_modes)
      if (m.eigenvalue.real() >= 0)
        block += formatNumber(p.steady.condition.wind_speed.value_or(0)) + " " + formatNumber(m.freq_hz) + " " +
                 formatNumber(100 * m.damping_ratio) + "\n";
  block += "EOD\n";
  const std::string unstable_f = "$unstable using 1:2 with points pt 2 ps 2 lw 2 lc rgb 'red' title 'unstable'";
  const std::string unstable_z = "$unstable using 1:3 with points pt 2 ps 2 lw 2 lc rgb 'red' notitle";
  auto panel = [&](const std::string& column, const std::string& red) {
    std::string entries = lineEntries(c.open, "open_loop_campbell.dat", column, true, opt);
    const std::string closed = lineEntries(c.closed, "campbell.dat", column, false, opt);
    for (const std::string& e : {closed, unstable ? red : std::string()})
      if (!e.empty()) entries += (entries.empty() ? "" : ", \\\n       ") + e;
    return "  plot " + (entries.empty() ? std::string("NaN notitle") : entries) + "\n";
  };
  using Col = std::tuple<std::string, std::string, std::function<double(const ClosedLoopPoint&)>>;
  const std::vector<Col> gain = {{"5", "pitch loop", [](const ClosedLoopPoint& p) { return p.pitch.gain_margin; }},
                                 {"12", "torque loop", [](const ClosedLoopPoint& p) { return p.torque.gain_margin; }}};
  const std::vector<Col> phase = {{"7", "pitch PM", [](const ClosedLoopPoint& p) { return p.pitch.phase_margin; }},
                                  {"($10*10)", "pitch Ms x 10",
                                   [](const ClosedLoopPoint& p) { return p.pitch.peak_sensitivity; }},
                                  {"14", "torque PM", [](const ClosedLoopPoint& p) { return p.torque.phase_margin; }},
                                  {"($17*10)", "torque Ms x 10",
                                   [](const ClosedLoopPoint& p) { return p.torque.peak_sensitivity; }}};
  const std::string top = opt.max_freq_hz > 0 ? formatNumber(opt.max_freq_hz) : "*";
  return "# Closed-loop Campbell diagram and loop margins written by whirl: gnuplot closed_loop.gp (from this folder)\n"
         "# Open loop grey dashed, closed loop in colour (lines tracked along the wind), unstable roots red.\n"
         "if (!exists('png_out')) png_out = 'closed_loop.png'\n"
         "if (!exists('svg_out')) svg_out = 'closed_loop.svg'\n" +
         (unstable ? block : std::string()) +
         "set datafile separator whitespace\n"
         "set key noenhanced outside right font ',8'\n"
         "set grid\n"
         "set xlabel 'Wind speed [m/s]' noenhanced\n"
         "do for [out = 1:2] {\n"
         "  if (out == 1) { set terminal pngcairo size 1600,1200 noenhanced; set output png_out }\n"
         "  else { set terminal svg size 1600,1200 noenhanced; set output svg_out }\n"
         "  set multiplot layout 2,2 title " +
         gnuplotQuoted(c.closed.title) +
         "\n"
         "  set datafile separator whitespace\n"
         "  set ylabel 'Frequency [Hz]'\n"
         "  set yrange [0:" +
         top + "]\n" + panel("3", unstable_f) +
         "  set ylabel 'Damping ratio [%]'\n"
         "  set yrange [-5:*]\n"
         "  set key off\n" +
         panel("(100*$4)", unstable_z) +
         "  set key on\n"
         "  set datafile separator ','\n"
         "  set autoscale y\n"
         "  set ylabel 'Gain margin [dB]'\n"
         "  plot " +
         marginEntries(c.points, gain) +
         "\n"
         "  set ylabel 'Phase margin [deg]; peak sensitivity Ms x 10'\n"
         "  plot " +
         marginEntries(c.points, phase) +
         "\n"
         "  unset multiplot\n"
         "}\n";
}

std::vector<std::string> writeClosedLoopCampbell(const ClosedLoopCampbell& c, const std::string& dir,
                                                 const CampbellPlotOptions& opt) {
  checkCampbell(c.closed, opt);
  checkCampbell(c.open, opt);
  const std::string folder = dir.empty() ? "." : dir;
  prepareOutputFolder(folder);
  OutputSet files(folder);
  files.write("campbell.csv", campbellCsv(c.closed));
  const std::string modes_json = campbellModesJson(c.closed);
  files.write("campbell_modes.json", modes_json);
  if (opt.html) {
    CampbellReportOptions r;
    r.harmonics = opt.harmonics;
    r.versus_wind_speed = opt.versus_wind_speed;
    r.max_freq_hz = opt.max_freq_hz;
    r.first_order_lines = true;
    r.summary = opt.summary;
    r.steady_csv = steadyCsvIn(folder);
    files.write("campbell.html", campbellHtml(modes_json, r));
  }
  files.write("campbell.dat", campbellGnuplotData(c.closed));
  files.write("campbell.gp", campbellGnuplotScript(c.closed, opt));
  files.write("open_loop_campbell.csv", campbellCsv(c.open));
  files.write("open_loop_campbell.dat", campbellGnuplotData(c.open));
  files.write("closed_loop_modes.csv", closedLoopModesCsv(c.points));
  files.write("margins.csv", closedLoopMarginsCsv(c.points));
  files.write("closed_loop.gp", closedLoopGnuplotScript(c, opt));
  if (opt.render) {
    renderGnuplot(files.stagingFolder(), opt.gnuplot, "campbell", folder);
    renderGnuplot(files.stagingFolder(), opt.gnuplot, "closed_loop", folder);
  }
  files.commit();
  return files.paths();
}

}  // namespace whirl
