#pragma once
// Test-only readers for the NREL 5MW aerodynamic data copied under tests/data/aero/ (see the headers of
// nrel5mw_polars.txt and nrel5mw_blade.txt for their origin).
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/aero/polar.hpp"

namespace whirl::test {

inline std::string aeroDataDir() { return std::string(WHIRL_SOURCE_DIR) + "/tests/data/aero/"; }

/// Reads every airfoil of nrel5mw_polars.txt, in file order (AeroDyn BlAFID 1..8).
inline std::vector<aero::Polar> readNrel5mwPolars(aero::PolarInterp interp = aero::PolarInterp::Linear) {
  const std::string path = aeroDataDir() + "nrel5mw_polars.txt";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<aero::Polar> polars;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream head(line);
    std::string word, name;
    int rows = 0;
    head >> word >> name >> rows;
    if (word != "airfoil") throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": expected 'airfoil'");
    const int first = lineNo + 1;
    std::vector<double> a, cl, cd, cm;
    for (int i = 0; i < rows && std::getline(in, line); ++i) {
      ++lineNo;
      std::istringstream row(line);
      double x[4];
      row >> x[0] >> x[1] >> x[2] >> x[3];
      a.push_back(x[0] * std::numbers::pi / 180.0);
      cl.push_back(x[1]);
      cd.push_back(x[2]);
      cm.push_back(x[3]);
    }
    polars.push_back(aero::makePolar(name, a, cl, cd, cm, interp, path + ":" + std::to_string(first)));
  }
  return polars;
}

struct BladeRow {
  double span, twist_deg, chord;
  int afid;
};

inline std::vector<BladeRow> readNrel5mwBlade() {
  const std::string path = aeroDataDir() + "nrel5mw_blade.txt";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<BladeRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    BladeRow r{};
    s >> r.span >> r.twist_deg >> r.chord >> r.afid;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace whirl::test
