#include "src/writers/timeseries_output.hpp"

#include <algorithm>

#include "src/base/error.hpp"
#include "src/io/text/csv.hpp"
#include "src/writers/gnuplot.hpp"
#include "src/writers/output_set.hpp"

namespace whirl {

std::vector<std::string> timeseriesColumns(const Model& m) {
  std::vector<std::string> c{"time_s"};
  for (const Dof& d : m.dofs) {
    c.push_back(d.name);
    c.push_back(d.name + " rate");
  }
  for (const Input& in : m.inputs) c.push_back("input: " + in.name);
  for (const Output& o : m.outputs) c.push_back(o.unit.empty() ? o.name : o.name + " [" + o.unit + "]");
  return c;
}

std::string timeseriesCsv(const Model& m, const Simulation& sim) {
  std::string s;
  const std::vector<std::string> names = timeseriesColumns(m);
  for (size_t k = 0; k < names.size(); ++k) {
    // A name with a comma or quote is quoted (RFC 4180) so the columns stay aligned.
    const std::string& n = names[k];
    const bool quote = n.find_first_of(",\"") != std::string::npos;
    std::string field = n;
    if (quote) {
      field = "\"";
      for (char ch : n) field += ch == '"' ? std::string("\"\"") : std::string(1, ch);
      field += "\"";
    }
    s += (k ? "," : "") + field;
  }
  s += "\n";
  for (size_t r = 0; r < sim.time.size(); ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    s += formatNumber(sim.time[r]);
    for (int d = 0; d < m.ndof(); ++d) s += "," + formatNumber(sim.q(i, d)) + "," + formatNumber(sim.qd(i, d));
    for (int u = 0; u < m.ninput(); ++u) s += "," + formatNumber(sim.u(i, u));
    for (int y = 0; y < m.noutput(); ++y) s += "," + formatNumber(sim.y(i, y));
    s += "\n";
  }
  return s;
}

std::string timeseriesGnuplotScript(const Model& m, const Simulation& sim, const TimeseriesPlotOptions& opt) {
  const std::vector<std::string> names = timeseriesColumns(m);
  std::vector<int> cols;  // 1-based Gnuplot columns
  if (opt.channels.empty()) {
    // The integrated coordinates; of a rotating one (an azimuth) its rate, the rotor speed.
    for (size_t k = 0; k < sim.states.size() && k < 6; ++k)
      cols.push_back(2 + 2 * sim.states[k] + (m.dofs[static_cast<size_t>(sim.states[k])].rotating ? 1 : 0));
  } else {
    for (const std::string& c : opt.channels) {
      const auto it = std::find(names.begin(), names.end(), c);
      if (it == names.end() || it == names.begin())
        throw InputError("--plot: '" + c +
                         "': no such column of timeseries.csv (a coordinate, 'NAME rate', "
                         "'input: NAME' or an output with its unit)");
      cols.push_back(static_cast<int>(it - names.begin()) + 1);
    }
  }
  const int n = std::max<int>(1, static_cast<int>(cols.size()));
  std::string g =
      "# Time series written by whirl: gnuplot timeseries.gp (from this folder)\n"
      "# " +
      gnuplotComment(opt.title) +
      "\n"
      "if (!exists('png_out')) png_out = 'timeseries.png'\n"
      "if (!exists('svg_out')) svg_out = 'timeseries.svg'\n"
      "set datafile separator ','\n"
      "set key noenhanced top right\nset grid\n"
      "height = " +
      std::to_string(200 + 220 * n) +
      "\n"
      "do for [out = 1:2] {\n"
      "  if (out == 1) { set terminal pngcairo size 1000,height noenhanced; set output png_out }\n"
      "  else { set terminal svg size 1000,height noenhanced; set output svg_out }\n"
      "  set multiplot layout " +
      std::to_string(n) + ",1 title " + gnuplotQuoted(opt.title) + "\n";
  for (size_t k = 0; k < cols.size(); ++k) {
    const bool last = k + 1 == cols.size();
    g += std::string("  set format x ") + (last ? "'%g'" : "''") + "\n";
    g += std::string("  ") + (last ? "set xlabel 'Time [s]'" : "unset xlabel") + "\n";
    g += "  set ylabel " + gnuplotQuoted(names[static_cast<size_t>(cols[k] - 1)]) + "\n";
    g += "  plot 'timeseries.csv' skip 1 using 1:" + std::to_string(cols[k]) + " with lines lw 2 notitle\n";
  }
  g += "  unset multiplot\n}\n";
  return g;
}

std::vector<std::string> writeTimeseries(const Model& m, const Simulation& sim, const std::string& dir,
                                         const TimeseriesPlotOptions& opt) {
  const std::string script = timeseriesGnuplotScript(m, sim, opt);  // channel errors before anything is staged
  OutputSet files(dir);
  files.write("timeseries.csv", timeseriesCsv(m, sim));
  files.write("timeseries.gp", script);
  if (opt.render) renderGnuplot(files.stagingFolder(), opt.gnuplot, "timeseries", dir);
  files.commit();
  return files.paths();
}

}  // namespace whirl
