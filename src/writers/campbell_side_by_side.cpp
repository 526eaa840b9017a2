#include "src/writers/campbell_side_by_side.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "src/base/error.hpp"
#include "src/base/text.hpp"
#include "src/io/text/csv.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"

namespace whirl {
namespace {

// campbell.gp's colours and point types (src/writers/campbell_gnuplot.cpp), so a line looks the same in
// both figures when it has the same place in the key.
constexpr const char* kColours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00",
                                    "#56b4e9", "#000000", "#8b1a1a", "#6a3d9a", "#b8a000"};
constexpr int kPointTypes[] = {7, 5, 9, 13, 11, 6, 4, 8, 12};

// Screen fractions of the figure: the panels span [kLeft, kRight], the key is right of them; the top
// row is frequency, the bottom row damping.
constexpr double kLeft = 0.06, kRight = 0.82, kTop = 0.90, kMiddleHigh = 0.53, kMiddleLow = 0.47, kBottom = 0.09;

double xOf(const CampbellCsvPoint& p, bool versus_wind_speed) {
  return versus_wind_speed ? p.wind_speed.value_or(NAN) : p.rpm;
}

/// Whether `line` is drawn: it has a finite frequency, at or below max_freq_hz when that is set.
bool shown(const CampbellCsvLine& line, const SideBySideOptions& opt) {
  for (const auto& [p, v] : line.modes)
    if (std::isfinite(v.freq_hz) && (opt.max_freq_hz <= 0 || v.freq_hz <= opt.max_freq_hz)) return true;
  return false;
}

/// The names of the lines drawn, over every column in order of first appearance: line style k + 1 is
/// name k's, in every column.
struct LineStyles {
  std::vector<std::string> names;
  std::map<std::string, std::size_t> style;  ///< name → its line style (1-based)
};

LineStyles lineStyles(const std::vector<SideBySideColumn>& columns, const SideBySideOptions& opt) {
  LineStyles s;
  for (const SideBySideColumn& c : columns)
    for (const CampbellCsvLine& l : c.result.lines)
      if (shown(l, opt) && s.style.try_emplace(l.name, s.names.size() + 1).second) s.names.push_back(l.name);
  return s;
}

/// The axis end for the largest value v (v > 0 finite): v rounded up to a step of 1, 2 or 5 units of the
/// decade below v's leading digit, the smallest step that needs at most 20 of them (2.625 → 2.8, 84 → 85).
double roundUp(double v) {
  if (!(v > 0 && v < 1e300)) return 1;
  const int e = static_cast<int>(std::floor(std::log10(v))) - 1;
  const double scale = std::pow(10.0, std::abs(e));  // exact for the exponents met here
  const double units = e < 0 ? v * scale : v / scale;
  for (double step : {1.0, 2.0, 5.0, 10.0})
    if (units / step <= 20) {
      const double n = std::ceil(units / step - 1e-9) * step;
      return e < 0 ? n / scale : n * scale;
    }
  return v;
}

struct Ranges {
  double x0 = 0, x1 = 1, fmax = 1, dmin = 0, dmax = 1;
};

/// The axes of every column: x over all points, frequency and damping over the lines drawn.
Ranges ranges(const std::vector<SideBySideColumn>& columns, const SideBySideOptions& opt) {
  double x0 = INFINITY, x1 = -INFINITY, f1 = 0, z0 = 0, z1 = 0;
  for (const SideBySideColumn& c : columns) {
    for (const CampbellCsvPoint& p : c.result.points) {
      x0 = std::min(x0, xOf(p, opt.versus_wind_speed));
      x1 = std::max(x1, xOf(p, opt.versus_wind_speed));
    }
    for (const CampbellCsvLine& l : c.result.lines) {
      if (!shown(l, opt)) continue;
      for (const auto& [p, v] : l.modes) {
        if (std::isfinite(v.freq_hz) && (opt.max_freq_hz <= 0 || v.freq_hz <= opt.max_freq_hz))
          f1 = std::max(f1, v.freq_hz);
        if (std::isfinite(v.damping_ratio)) {
          z0 = std::min(z0, 100 * v.damping_ratio);
          z1 = std::max(z1, 100 * v.damping_ratio);
        }
      }
    }
  }
  Ranges r;
  if (x0 <= x1) {
    r.x0 = x0 < x1 ? x0 : x0 - 1;
    r.x1 = x0 < x1 ? x1 : x1 + 1;
  }
  r.fmax = opt.max_freq_hz > 0 ? opt.max_freq_hz : roundUp(1.05 * f1);
  r.dmax = opt.max_damping_percent > 0 ? opt.max_damping_percent : roundUp(1.05 * z1);
  r.dmin = z0 < 0 ? -roundUp(-1.05 * z0) : 0.0;
  return r;
}

std::string datName(std::size_t k) { return "campbell_side_by_side_" + std::to_string(k + 1) + ".dat"; }

/// The `plot` entries of column `k`'s panel (`using` column expression `y`); with `key`, titled, plus
/// an empty entry for every name drawn elsewhere only, so the one key lists every line.
std::string panelEntries(const std::vector<SideBySideColumn>& columns, std::size_t k, const std::string& y,
                         const LineStyles& styles, bool key, const SideBySideOptions& opt) {
  std::string s;
  auto add = [&](const std::string& e) { s += (s.empty() ? "" : ", \\\n       ") + e; };
  std::set<std::string> here;
  const std::vector<CampbellCsvLine>& lines = columns[k].result.lines;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!shown(lines[i], opt)) continue;
    here.insert(lines[i].name);
    add(gnuplotQuoted(datName(k)) + " index " + std::to_string(i) + " using xcol:" + y + " with linespoints ls " +
        std::to_string(styles.style.at(lines[i].name)) +
        (key ? " title " + gnuplotQuoted(lines[i].name) : std::string(" notitle")));
  }
  if (key)
    for (std::size_t n = 0; n < styles.names.size(); ++n)
      if (!here.count(styles.names[n]))
        add("NaN with linespoints ls " + std::to_string(n + 1) + " title " + gnuplotQuoted(styles.names[n]));
  return s.empty() ? "NaN notitle" : s;
}

/// The margins of column `k` of `n` and one row (`top`: frequency).
std::string panelMargins(std::size_t k, std::size_t n, bool top) {
  const double w = (kRight - kLeft) / static_cast<double>(n);
  return "  set lmargin at screen " + formatNumber(kLeft + static_cast<double>(k) * w + (k ? 0.025 : 0.0)) +
         "; set rmargin at screen " + formatNumber(kLeft + static_cast<double>(k + 1) * w - 0.005) +
         "\n  set tmargin at screen " + formatNumber(top ? kTop : kMiddleLow) + "; set bmargin at screen " +
         formatNumber(top ? kMiddleHigh : kBottom) + "\n";
}

/// Column `k`'s two panels: frequency with its label as title, damping ratio with the x axis title.
std::string columnPanels(const std::vector<SideBySideColumn>& columns, std::size_t k, const LineStyles& styles,
                         const SideBySideOptions& opt) {
  const bool first = k == 0, last = k + 1 == columns.size();
  std::string g = "  # column " + std::to_string(k + 1) + ": " + gnuplotComment(columns[k].label) + "\n";
  g += panelMargins(k, columns.size(), true);
  g += "  set title " + gnuplotQuoted(columns[k].label) + "\n";
  g += first ? "  set ylabel 'Frequency [Hz]'\n" : "  unset ylabel\n";
  g += "  set yrange [0:fmax]; set format x ''; unset xlabel\n";
  g += last ? "  set key at screen " + formatNumber(kRight + 0.01) + ", " + formatNumber(kTop) + " top left\n"
            : "  set key off\n";
  g += "  plot " + panelEntries(columns, k, "3", styles, last, opt) + "\n";
  g += panelMargins(k, columns.size(), false);
  g += "  unset title; set key off\n";
  g += first ? "  set ylabel 'Damping ratio [%]'\n" : "  unset ylabel\n";
  g += "  set yrange [dmin:dmax]; set format x '%g'; set xlabel xtitle\n";
  g += "  plot " + panelEntries(columns, k, "(100*$4)", styles, false, opt) + "\n";
  return g;
}

void checkColumns(const std::vector<SideBySideColumn>& columns, const SideBySideOptions& opt) {
  if (columns.empty()) throw InputError(where("", 0, "side by side", "no Campbell result to draw"));
  std::set<std::string> labels;
  for (const SideBySideColumn& c : columns) {
    if (c.label.empty()) throw InputError(where("", 0, "--label", "empty: every column needs a title"));
    requirePrintable(c.label, "", 0, "--label");
    if (const std::string reason = invalidUtf8Reason(c.label); !reason.empty())
      throw InputError(where("", 0, "--label", reason));
    if (!labels.insert(c.label).second)
      throw InputError(where("", 0, "--label", "'" + c.label + "' given twice: the columns would not be told apart"));
    if (opt.versus_wind_speed)
      for (std::size_t p = 0; p < c.result.points.size(); ++p)
        if (!c.result.points[p].wind_speed)
          throw InputError(where(c.result.file, 0, "wind_speed",
                                 "point " + std::to_string(p + 1) + " has none: draw versus rpm (--versus rpm)"));
  }
}

}  // namespace

const std::vector<std::string>& sideBySideTabulatedModes() {
  static const std::vector<std::string> modes = {"tower FA 1",        "tower SS 1", "flap 1 BW", "flap 1 FW",
                                                 "flap 1 collective", "edge 1 BW",  "edge 1 FW", "edge 1 collective"};
  return modes;
}

std::string sideBySideData(const CampbellCsvResult& r) {
  std::string s = "# Campbell diagram read from " + gnuplotComment(r.file) +
                  ", one block per line (index 0, 1, ...)\n"
                  "# columns: rpm, wind speed [m/s] (nan: none), frequency [Hz], damping ratio [-]\n";
  for (std::size_t l = 0; l < r.lines.size(); ++l) {
    s += (l ? "\n\n" : "") + std::string("# index ") + std::to_string(l) + ": " + gnuplotComment(r.lines[l].name) +
         "\n";
    std::size_t next = 0;  // the point after the previous mode: a mode elsewhere follows a gap
    for (const auto& [p, v] : r.lines[l].modes) {
      if (p != next && next > 0) s += "\n";  // one blank line: Gnuplot does not join across it
      next = p + 1;
      s += formatNumber(r.points[p].rpm) + " " + formatNumber(r.points[p].wind_speed.value_or(NAN)) + " " +
           formatNumber(v.freq_hz) + " " + formatNumber(v.damping_ratio) + "\n";
    }
  }
  return s;
}

std::string sideBySideGnuplotScript(const std::vector<SideBySideColumn>& columns, const SideBySideOptions& opt) {
  const LineStyles styles = lineStyles(columns, opt);
  const Ranges r = ranges(columns, opt);
  const int width = 160 + 480 * static_cast<int>(std::max<std::size_t>(columns.size(), 1)) + 200;
  std::string g =
      "# Campbell diagrams side by side written by whirl: gnuplot campbell_side_by_side.gp (from this folder)\n"
      "# writes campbell_side_by_side.png and .svg. One column per result, frequency on top, damping ratio\n"
      "# in % below, the same axes in every column; the data are campbell_side_by_side_<column>.dat.\n";
  for (std::size_t k = 0; k < columns.size(); ++k)
    g += "# column " + std::to_string(k + 1) + ": " + gnuplotComment(columns[k].label) + " (" +
         gnuplotComment(columns[k].result.file) + ")\n";
  g += "if (!exists('png_out')) png_out = 'campbell_side_by_side.png'\n"
       "if (!exists('svg_out')) svg_out = 'campbell_side_by_side.svg'\n"
       "set datafile separator whitespace\n";
  g += "xcol = " + std::string(opt.versus_wind_speed ? "2" : "1") + "   # .dat column on x: 1 rpm, 2 wind speed\n";
  g += "xtitle = " + gnuplotQuoted(opt.versus_wind_speed ? "Wind speed [m/s]" : "Rotor speed [rpm]") + "\n";
  g += "xmin = " + formatNumber(r.x0) + "; xmax = " + formatNumber(r.x1) + "\n";
  g += "fmax = " + formatNumber(r.fmax) + "   # top of the frequency axis [Hz]\n";
  g += "dmin = " + formatNumber(r.dmin) + "; dmax = " + formatNumber(r.dmax) + "   # damping axis [%]\n";
  g += "# One style per line name, the same in every column.\n";
  for (std::size_t l = 0; l < styles.names.size(); ++l)
    g += "set style line " + std::to_string(l + 1) + " lc rgb '" + kColours[l % 10] + "' lw 2 pt " +
         std::to_string(kPointTypes[l % 9]) + " ps 0.8   # " + gnuplotComment(styles.names[l]) + "\n";
  g += "set grid\nset key noenhanced left top font ',9'\nset xrange [xmin:xmax]\n";
  g += "do for [out = 1:2] {\n"
       "  if (out == 1) { set terminal pngcairo size " +
       std::to_string(width) +
       ",900 noenhanced font 'Sans,11'; set output png_out }\n"
       "  else { set terminal svg size " +
       std::to_string(width) +
       ",900 noenhanced font 'Sans,11'; set output svg_out }\n"
       "  set multiplot title 'Campbell diagrams side by side'\n";
  for (std::size_t k = 0; k < columns.size(); ++k) g += columnPanels(columns, k, styles, opt);
  g += "  unset multiplot\n}\n";
  return g;
}

std::string aeroModelsCsv(const std::vector<SideBySideColumn>& columns, bool versus_wind_speed) {
  std::set<double> xs;
  for (const SideBySideColumn& c : columns)
    for (const CampbellCsvPoint& p : c.result.points)
      if (std::isfinite(xOf(p, versus_wind_speed))) xs.insert(xOf(p, versus_wind_speed));
  std::string t = versus_wind_speed ? "wind_speed_m_s,mode" : "rpm,mode";
  for (const SideBySideColumn& c : columns)
    t += "," + csvField("freq_hz " + c.label) + "," + csvField("damping_ratio " + c.label);
  t += "\n";
  // Per column the first point at each x and the line of each name: the table costs x values × modes × columns.
  std::vector<std::map<double, std::size_t>> point_at(columns.size());
  std::vector<std::map<std::string, const CampbellCsvLine*>> line_of(columns.size());
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const CampbellCsvResult& r = columns[k].result;
    for (std::size_t p = 0; p < r.points.size(); ++p) point_at[k].try_emplace(xOf(r.points[p], versus_wind_speed), p);
    for (const CampbellCsvLine& l : r.lines) line_of[k].try_emplace(l.name, &l);
  }
  auto value = [&](std::size_t k, const std::string& mode, double x) -> std::optional<CampbellCsvValue> {
    const auto p = point_at[k].find(x);
    const auto l = line_of[k].find(mode);
    if (p == point_at[k].end() || l == line_of[k].end()) return std::nullopt;
    return l->second->at(p->second);
  };
  for (double x : xs)
    for (const std::string& mode : sideBySideTabulatedModes()) {
      std::string row = formatNumber(x) + "," + csvField(mode);
      bool any = false;
      for (std::size_t k = 0; k < columns.size(); ++k) {
        const std::optional<CampbellCsvValue> v = value(k, mode, x);
        any = any || v.has_value();
        row += v ? "," + formatNumber(v->freq_hz) + "," + formatNumber(v->damping_ratio) : std::string(",,");
      }
      if (any) t += row + "\n";
    }
  return t;
}

std::vector<std::string> writeCampbellSideBySide(const std::vector<SideBySideColumn>& columns, const std::string& dir,
                                                 const SideBySideOptions& opt) {
  checkColumns(columns, opt);
  const std::string folder = dir.empty() ? "." : dir;
  prepareOutputFolder(folder);
  OutputSet files(folder);
  for (std::size_t k = 0; k < columns.size(); ++k) files.write(datName(k), sideBySideData(columns[k].result));
  files.write("campbell_side_by_side.gp", sideBySideGnuplotScript(columns, opt));
  files.write("aero_models.csv", aeroModelsCsv(columns, opt.versus_wind_speed));
  if (opt.render) renderGnuplot(files.stagingFolder(), opt.gnuplot, "campbell_side_by_side", folder);
  files.commit();
  return files.paths();
}

}  // namespace whirl
