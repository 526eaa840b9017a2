// campbell.dat and campbell.gp: the Gnuplot data and the standalone two-panel script.
#include <algorithm>
#include <cmath>
#include <optional>

#include "src/base/text.hpp"
#include "src/io/text/csv.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/gnuplot.hpp"

namespace whirl {

namespace {

// Colours (colour-blind friendly first, grey left for the excitation lines) and point types
// (filled circle, square, triangle, diamond, inverted triangle, then open ones); line l uses
// colour l mod 10 and point type l mod 9, so 90 lines are told apart.
constexpr const char* kColours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00",
                                    "#56b4e9", "#000000", "#8b1a1a", "#6a3d9a", "#b8a000"};
constexpr int kPointTypes[] = {7, 5, 9, 13, 11, 6, 4, 8, 12};

/// Smallest number with two significant digits ≥ v (v > 0). A v past 1e300 (1.05 × a frequency near
/// DBL_MAX is inf) is returned as is: its exponent cast to int was undefined (UBSan; fuzz_writers).
double niceCeil(double v) {
  if (!(v > 0 && v < 1e300)) return v;
  const int e = static_cast<int>(std::floor(std::log10(v))) - 1;
  const double scale = std::pow(10.0, std::abs(e));  // exact for the exponents met here
  return e < 0 ? std::ceil(v * scale - 1e-9) / scale : std::ceil(v / scale - 1e-9) * scale;
}

double xOf(const CampbellPoint& p, const CampbellPlotOptions& opt) {
  return opt.versus_wind_speed ? p.wind_speed.value_or(NAN) : p.rpm;
}

}  // namespace

// A line entirely above the frequency axis (--max-freq), or one whose every mode is a first-order
// state's root (HydroDyn's radiation fit; unless first_order_lines), is left out of both panels and the
// key; its data stay in campbell.dat and the tables.
bool campbellLineShown(const CampbellDiagram& d, const CampbellLine& line, const CampbellPlotOptions& opt) {
  bool structural = opt.first_order_lines, below = opt.max_freq_hz <= 0;
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    if (line.mode[p] < 0) continue;
    const Mode& m = d.points[p].modes[line.mode[p]];
    structural = structural || !m.first_order;
    below = below || m.freq_hz <= opt.max_freq_hz;
  }
  return structural && below;
}

namespace {

struct Ranges {
  double x0 = 0, x1 = 1, fmax = 1, dmin = 0, dmax = 1;
};

Ranges ranges(const CampbellDiagram& d, const CampbellPlotOptions& opt) {
  Ranges r;
  double x0 = INFINITY, x1 = -INFINITY, f1 = 0, z0 = 0, z1 = 0;
  for (const auto& p : d.points) {
    x0 = std::min(x0, xOf(p, opt));
    x1 = std::max(x1, xOf(p, opt));
  }
  for (const auto& line : d.lines)
    for (std::size_t p = 0; p < d.points.size(); ++p) {
      if (line.mode[p] < 0 || !campbellLineShown(d, line, opt)) continue;
      const Mode& m = d.points[p].modes[line.mode[p]];
      if (std::isfinite(m.freq_hz)) f1 = std::max(f1, m.freq_hz);
      if (std::isfinite(m.damping_ratio)) {
        z0 = std::min(z0, 100 * m.damping_ratio);
        z1 = std::max(z1, 100 * m.damping_ratio);
      }
    }
  if (x0 <= x1) {
    r.x0 = x0 < x1 ? x0 : x0 - 1;
    r.x1 = x0 < x1 ? x1 : x1 + 1;
  }
  r.fmax = opt.max_freq_hz > 0 ? opt.max_freq_hz : f1 > 0 ? niceCeil(1.05 * f1) : 1.0;
  r.dmax = opt.max_damping_percent > 0 ? opt.max_damping_percent : z1 > 0 ? niceCeil(1.05 * z1) : 1.0;
  r.dmin = z0 < 0 ? -niceCeil(-1.05 * z0) : 0.0;
  return r;
}

/// (x, rpm) along the x axis: the axis ends versus rpm (nP lines are straight lines through 0),
/// the operating points sorted by wind speed versus wind speed.
std::vector<std::pair<double, double>> sweep(const CampbellDiagram& d, const CampbellPlotOptions& opt,
                                             const Ranges& r) {
  if (!opt.versus_wind_speed) return {{r.x0, r.x0}, {r.x1, r.x1}};
  std::vector<std::pair<double, double>> s;
  for (const auto& p : d.points) s.emplace_back(xOf(p, opt), p.rpm);
  std::stable_sort(s.begin(), s.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return s;
}

/// Where the label of an nP line goes: above the frame where the line leaves it at the top, else
/// right of the frame at the line's end. `at` is the position along that edge as a graph fraction.
struct HarmonicLabel {
  int n = 0;
  bool top = false;
  double at = 0;
};

std::optional<HarmonicLabel> harmonicLabel(int n, const std::vector<std::pair<double, double>>& s, const Ranges& r) {
  const auto f = [&](std::size_t k) { return n * s[k].second / 60.0; };
  const double near_top = 0.97 * r.fmax;  // a line ending this close to the top is labelled there
  if (s.empty() || f(0) >= r.fmax) return std::nullopt;
  for (std::size_t k = 0; k + 1 < s.size(); ++k)
    if (f(k + 1) >= near_top && f(k) < near_top) {
      const double x = std::min(s[k].first + (r.fmax - f(k)) / (f(k + 1) - f(k)) * (s[k + 1].first - s[k].first), r.x1);
      return HarmonicLabel{n, true, (x - r.x0) / (r.x1 - r.x0)};
    }
  return HarmonicLabel{n, false, f(s.size() - 1) / r.fmax};
}

/// "set label" commands in data coordinates, labels on the same edge pushed apart (graph fraction).
std::string harmonicLabels(std::vector<HarmonicLabel> labels, const Ranges& r) {
  std::stable_sort(labels.begin(), labels.end(), [](const auto& a, const auto& b) { return a.at < b.at; });
  std::string g;
  double last_top = -1, last_right = -1;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    auto& l = labels[k];
    double& last = l.top ? last_top : last_right;
    l.at = std::max(l.at, last + (l.top ? 0.035 : 0.045));
    last = l.at;
    const std::string text = gnuplotQuoted(std::to_string(l.n) + "P");
    g += "  set label " + std::to_string(k + 1) + " " + text +
         (l.top ? " at first " + formatNumber(r.x0 + l.at * (r.x1 - r.x0)) + ", graph 1 center offset 0, char 0.7"
                : " at graph 1, first " + formatNumber(l.at * r.fmax) + " left offset char 0.5, 0") +
         " tc ls 100\n";
  }
  return g;
}

}  // namespace

std::string campbellGnuplotData(const CampbellDiagram& d) {
  std::string s =
      "# Campbell diagram written by whirl, read by campbell.gp: one block per line (index 0, 1, ...)\n"
      "# columns: rpm, wind speed [m/s] (nan: none), frequency [Hz], damping ratio [-]\n";
  for (std::size_t l = 0; l < d.lines.size(); ++l) {
    const auto& line = d.lines[l];
    s += (l ? "\n\n" : "") + std::string("# index ") + std::to_string(l) + ": " + gnuplotComment(line.name) + "\n";
    bool gap = false, any = false;
    for (std::size_t p = 0; p < d.points.size(); ++p) {
      if (line.mode[p] < 0) {
        gap = any;
        continue;
      }
      const auto& pt = d.points[p];
      const Mode& m = pt.modes[line.mode[p]];
      if (gap) s += "\n";  // one blank line: Gnuplot does not join across it
      gap = false;
      any = true;
      s += formatNumber(pt.rpm) + " " + formatNumber(pt.wind_speed.value_or(NAN)) + " " + formatNumber(m.freq_hz) +
           " " + formatNumber(m.damping_ratio) + "\n";
    }
  }
  return s;
}

namespace {

/// The script's opening comments, the paths of its data and images, and its layout variables: page
/// size, x column and title, the axes' ranges (x in rpm or m/s, frequency [Hz], damping [%]).
std::string gnuplotScriptHeader(const CampbellDiagram& d, const CampbellPlotOptions& opt, const Ranges& r) {
  std::string g;
  g += "# Campbell diagram written by whirl. Run it from anywhere: gnuplot campbell.gp\n"
       "# It reads campbell.dat next to itself and writes campbell.png and campbell.svg there\n"
       "# (or elsewhere: gnuplot -e \"png_out='a.png'; svg_out='a.svg'\" campbell.gp).\n"
       "# campbell.dat: one block per Campbell line, columns rpm, wind speed [m/s], frequency [Hz],\n"
       "# damping ratio [-]; the damping panel shows it in percent.\n\n"
       "here = ''\n"
       "if (exists('ARG0')) { i = strlen(ARG0); while (i > 0 && ARG0[i:i] ne '/') { i = i - 1 }; "
       "if (i > 0) { here = ARG0[1:i] } }\n"
       "data = here.'campbell.dat'\n"
       "if (!exists('png_out')) { png_out = here.'campbell.png' }\n"
       "if (!exists('svg_out')) { svg_out = here.'campbell.svg' }\n\n"
       "# Layout: page size [px], font, axes; the plots end at 'right' (screen fraction), the key follows.\n"
       "width = 1280; height = 900; font = 'Sans,12'\n";
  g += "xcol = " + std::string(opt.versus_wind_speed ? "2" : "1") +
       "   # campbell.dat column on x: 1 rotor speed, 2 wind speed\n";
  g += "xtitle = " + gnuplotQuoted(opt.versus_wind_speed ? "Wind speed [m/s]" : "Rotor speed [rpm]") + "\n";
  g += "title = " + gnuplotQuoted(d.title.empty() ? "Campbell diagram" : d.title) + "\n";
  g += "# The nP labels below are placed for these ranges: move them when you change xmax or fmax.\n";
  g += "xmin = " + formatNumber(r.x0) + "; xmax = " + formatNumber(r.x1) + "\n";
  g += "fmax = " + formatNumber(r.fmax) + "   # top of the frequency axis [Hz]\n";
  g += "dmin = " + formatNumber(r.dmin) + "; dmax = " + formatNumber(r.dmax) + "   # damping axis [%]\n";
  g += "left = 0.08; right = 0.74\n\n";
  return g;
}

/// One line style per Campbell line (colour, point type), the excitation lines' style 100, and versus
/// wind speed the operating points (wind speed, rpm) `s` the nP lines are drawn through.
std::string gnuplotLineStyles(const CampbellDiagram& d, const CampbellPlotOptions& opt,
                              const std::vector<std::pair<double, double>>& s) {
  std::string g;
  g += "# One style per Campbell line (colour and point type); 100: excitation lines and labels.\n";
  for (std::size_t l = 0; l < d.lines.size(); ++l)
    g += "set style line " + std::to_string(l + 1) + " lc rgb '" + kColours[l % 10] + "' lw 2 pt " +
         std::to_string(kPointTypes[l % 9]) + " ps 1.1   # " + gnuplotComment(d.lines[l].name) + "\n";
  g += "set style line 100 lc rgb '#777777' lw 1.2 dt (20, 12)\n\n";
  if (opt.versus_wind_speed) {
    g += "# Operating points (wind speed, rpm) for the nP excitation lines.\n$points << EOD\n";
    for (const auto& [x, rpm] : s) g += formatNumber(x) + " " + formatNumber(rpm) + "\n";
    g += "EOD\n\n";
  }
  return g;
}

/// The items of the three plots (each ending in ", \" and a newline): the nP excitation lines with their labels, the
/// shown lines' frequencies and damping ratios, and their key entries.
struct PlotItems {
  std::string harmonics, freq, damp, key;
  std::vector<HarmonicLabel> labels;
};

/// The plot items of the harmonics opt.harmonics along `s` and of the lines campbellLineShown keeps.
PlotItems plotItems(const CampbellDiagram& d, const CampbellPlotOptions& opt,
                    const std::vector<std::pair<double, double>>& s, const Ranges& r) {
  PlotItems items;
  for (int n : opt.harmonics) {
    if (d.points.empty()) break;
    const std::string nP = std::to_string(n);
    items.harmonics += (opt.versus_wind_speed ? "  $points using 1:(" + nP + "*$2/60.0)" : "  " + nP + "*x/60.0") +
                       " with lines ls 100 notitle, \\\n";
    if (auto l = harmonicLabel(n, s, r)) items.labels.push_back(*l);
  }
  for (std::size_t l = 0; l < d.lines.size(); ++l) {
    if (!campbellLineShown(d, d.lines[l], opt)) continue;
    const std::string idx = "data index " + std::to_string(l) + " using xcol:";
    const std::string style = " with linespoints ls " + std::to_string(l + 1);
    items.freq += "  " + idx + "3" + style + " notitle, \\\n";
    items.damp += "  " + idx + "(100*$4)" + style + " notitle, \\\n";
    items.key += "  NaN" + style + " title " + gnuplotQuoted(d.lines[l].name) + ", \\\n";
  }
  return items;
}

/// A plot command's items without the last ", \" continuation, or a placeholder when there are none.
std::string plotItemList(const std::string& items) {
  if (items.empty()) return std::string("  NaN notitle\n");
  return items.substr(0, items.size() - 4) + "\n";  // drop the last ", \"
}

/// The loop over png and svg drawing the frequency panel (with the nP labels), the damping panel and
/// the key panel.
std::string gnuplotPanels(const PlotItems& items, const Ranges& r) {
  std::string g;
  g += "do for [out in 'png svg'] {\n"
       "  if (out eq 'png') {\n"
       "    set terminal pngcairo size width, height font font noenhanced\n"
       "    set output png_out\n"
       "  } else {\n"
       "    set terminal svg size width, height font font noenhanced dynamic background rgb 'white'\n"
       "    set output svg_out\n"
       "  }\n"
       "  set multiplot title title font ',15'\n"
       "  set lmargin at screen left; set rmargin at screen right\n"
       "  set xrange [xmin:xmax]\n"
       "  set grid back lt 1 lc rgb '#dddddd' lw 1\n"
       "  set border lw 1; set tics\n"
       "  set mxtics 2\n"
       "  # Top: natural frequencies with the nP lines, key to the right of the plots.\n"
       "  set tmargin at screen 0.91; set bmargin at screen 0.40\n"
       "  set format x ''; unset xlabel\n"
       "  set ylabel 'Frequency [Hz]'\n"
       "  set yrange [0:fmax]\n"
       "  unset key\n";
  g += harmonicLabels(items.labels, r);
  g += "  plot \\\n" + plotItemList(items.harmonics + items.freq);
  g += "  # Bottom: damping ratio in percent.\n"
       "  unset label; unset key\n"
       "  set tmargin at screen 0.37; set bmargin at screen 0.08\n"
       "  set format x '% g'; set xlabel xtitle\n"
       "  set ylabel 'Damping ratio [%]'\n"
       "  set yrange [dmin:dmax]\n"
       "  # Negative damping is an instability: that band is shaded and labelled.\n"
       "  if (dmin < 0) { set object 1 rect from graph 0, first dmin to graph 1, first 0 fc rgb '#ffd8d8' "
       "fs solid noborder behind; set label 1 'unstable (negative damping)' at graph 0.01, first dmin / 2 "
       "tc rgb '#a00000' front }\n";
  g += "  plot \\\n" + plotItemList(items.damp);
  // The key in a panel of its own right of both plots, as tall as both, so that some 40 lines fit in
  // one column (a key of the top panel alone wraps into columns past the page's edge).
  g += "  # Key: an empty panel right of the plots, as tall as both.\n"
       "  unset border; unset tics; unset xlabel; unset ylabel; unset grid; unset label; unset object 1\n"
       "  set lmargin at screen right; set rmargin at screen 0.995; set tmargin at screen 0.91; set bmargin at "
       "screen 0.08\n"
       "  set xrange [0:1]; set yrange [0:1]\n"
       "  set key at screen right + 0.045, screen 0.91 left top Left reverse samplen 3 spacing 1.15 "
       "title 'Mode'\n";
  g += "  plot \\\n" + plotItemList(items.key);
  g += "  unset multiplot\n"
       "  set output\n"
       "}\n";
  return g;
}

}  // namespace

std::string campbellGnuplotScript(const CampbellDiagram& d, const CampbellPlotOptions& opt) {
  const Ranges r = ranges(d, opt);
  const auto s = sweep(d, opt, r);
  return gnuplotScriptHeader(d, opt, r) + gnuplotLineStyles(d, opt, s) + gnuplotPanels(plotItems(d, opt, s, r), r);
}

}  // namespace whirl
