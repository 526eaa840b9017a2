#include "src/writers/bode_table.hpp"

#include <cmath>
#include <numbers>

#include "src/io/text/csv.hpp"
#include "src/writers/gnuplot.hpp"

namespace whirl {

std::vector<std::string> bodeColumns(const StateSpaceModel& s) {
  std::vector<std::string> c;
  for (const auto& y : s.y)
    for (const auto& u : s.u) {
      c.push_back(y.name + " / " + u.name + " dB");
      c.push_back(y.name + " / " + u.name + " deg");
    }
  return c;
}

MatX bodeValues(const std::vector<Eigen::MatrixXcd>& G) {
  const Eigen::Index pairs = G.empty() ? 0 : G.front().size();
  MatX v(static_cast<Eigen::Index>(G.size()), 2 * pairs);
  for (std::size_t k = 0; k < G.size(); ++k) {
    Eigen::Index c = 0;
    for (Eigen::Index i = 0; i < G[k].rows(); ++i)
      for (Eigen::Index j = 0; j < G[k].cols(); ++j) {
        v(static_cast<Eigen::Index>(k), c++) = 20 * std::log10(std::abs(G[k](i, j)));
        v(static_cast<Eigen::Index>(k), c++) = std::arg(G[k](i, j)) * 180 / std::numbers::pi;
      }
  }
  return v;
}

std::string bodeCsv(const StateSpaceModel& s, const std::vector<double>& f, const std::vector<Eigen::MatrixXcd>& G) {
  std::string csv = "freq_hz";
  for (const std::string& c : bodeColumns(s)) csv += "," + c;
  csv += "\n";
  const MatX v = bodeValues(G);
  for (std::size_t k = 0; k < f.size(); ++k) {
    csv += formatNumber(f[k]);
    for (Eigen::Index c = 0; c < v.cols(); ++c) csv += "," + formatNumber(v(static_cast<Eigen::Index>(k), c));
    csv += "\n";
  }
  return csv;
}

std::string bodeGnuplotScript(const std::string& title, int pairs) {
  return "# Bode diagram written by whirl: gnuplot bode.gp (from this folder)\n"
         "if (!exists('png_out')) png_out = 'bode.png'\n"
         "if (!exists('svg_out')) svg_out = 'bode.svg'\n"
         "set datafile separator ','\n"
         "set key noenhanced top right\n"
         "set logscale x\nset grid\n"
         "do for [out = 1:2] {\n"
         "  if (out == 1) { set terminal pngcairo size 1200,800 noenhanced; set output png_out }\n"
         "  else { set terminal svg size 1200,800 noenhanced; set output svg_out }\n"
         "  set multiplot layout 2,1 title " +
         gnuplotQuoted(title) +
         "\n"
         "  set ylabel 'Magnitude [dB of SI units]'\n  set format x ''\n  unset xlabel\n"
         "  plot for [k = 0:" +
         std::to_string(pairs - 1) +
         "] 'bode.csv' using 1:(column(2 + 2*k)) with lines lw 2 title columnhead(2 + 2*k)\n"
         "  set ylabel 'Phase [deg]'\n  set format x '%g'\n  set xlabel 'Frequency [Hz]'\n"
         "  plot for [k = 0:" +
         std::to_string(pairs - 1) +
         "] 'bode.csv' using 1:(column(3 + 2*k)) with lines lw 2 notitle\n"
         "  unset multiplot\n"
         "}\n";
}

}  // namespace whirl
