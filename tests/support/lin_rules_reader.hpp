#pragma once
// A `.lin` reader written to the reading rules of the tools that read OpenFAST's files, independent of
// whirl's own reader (src/io/lin/openfast_lin.cpp), so that a whirl file these rules cannot read fails a
// test. The rules, from ROSCO's `getMats.readFASTMatrix` / `ReadFASTLinear` and openfast_toolbox's
// `fast_linearization_file.py` (read for their behaviour, nothing copied):
// - header values are found by their label ("Rotor Speed:", "Azimuth:", "Wind Speed:", "Number of
//   inputs:" …), the number after the colon;
// - a table ("Order of inputs:" …) is its title, two header lines, then exactly as many rows as the
//   header's count: index, operating point, T/F, derivative order, the description (rest of the line);
// - a matrix is "name: m x n" and exactly m rows of n numbers; an empty line ends the reading (the
//   tools stop there and leave the matrices after it zero), so an empty line between the first
//   matrix and the end of the file is an error here.
#include <Eigen/Dense>

#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace whirl::test {

struct RulesRow {
  double op = 0;
  bool rotating = false;
  int order = -1;
  std::string description;
};

struct RulesLin {
  std::vector<std::string> lines;        ///< the file, line by line
  std::map<std::string, double> header;  ///< "Rotor Speed" → value …
  std::vector<RulesRow> x, xdot, u, y;
  std::map<std::string, Eigen::MatrixXd> matrices;
};

inline double rulesHeader(const std::vector<std::string>& lines, const std::string& label) {
  for (const auto& l : lines) {
    const auto at = l.find(label + ":");
    if (at == std::string::npos || l.find_first_not_of(' ') != at) continue;
    return std::stod(l.substr(at + label.size() + 1));
  }
  throw std::runtime_error("no header line '" + label + ":'");
}

inline std::vector<RulesRow> rulesTable(const std::vector<std::string>& lines, const std::string& title, int n) {
  std::vector<RulesRow> rows;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i] != title) continue;
    if (i + 2 + n >= lines.size() + 1) throw std::runtime_error(title + " shorter than its count");
    for (int k = 0; k < n; ++k) {
      std::istringstream s(lines[i + 3 + k]);
      int index = 0;
      std::string flag;
      RulesRow r;
      if (!(s >> index >> r.op >> flag >> r.order) || index != k + 1 || (flag != "T" && flag != "F"))
        throw std::runtime_error(title + " row " + std::to_string(k + 1) + " unreadable: " + lines[i + 3 + k]);
      r.rotating = flag == "T";
      std::getline(s, r.description);
      r.description = r.description.substr(r.description.find_first_not_of(' '));
      rows.push_back(r);
    }
    return rows;
  }
  if (n == 0) return rows;
  throw std::runtime_error("no table '" + title + "'");
}

inline RulesLin readLinByOpenFastRules(const std::string& text) {
  RulesLin f;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) f.lines.push_back(l);
  const auto& L = f.lines;
  const int nx = static_cast<int>(rulesHeader(L, "Number of continuous states"));
  const int nu = static_cast<int>(rulesHeader(L, "Number of inputs"));
  const int ny = static_cast<int>(rulesHeader(L, "Number of outputs"));
  for (const char* key : {"Simulation time", "Rotor Speed", "Azimuth", "Wind Speed"})
    f.header[key] = rulesHeader(L, key);
  f.x = rulesTable(L, "Order of continuous states:", nx);
  f.xdot = rulesTable(L, "Order of continuous state derivatives:", nx);
  f.u = rulesTable(L, "Order of inputs:", nu);
  f.y = rulesTable(L, "Order of outputs:", ny);
  size_t i = 0;
  while (i < L.size() && L[i] != "Linearized state matrices:") ++i;
  if (i == L.size()) throw std::runtime_error("no 'Linearized state matrices:'");
  ++i;
  while (i < L.size() && L[i].empty()) ++i;  // blank lines before the first matrix are allowed
  while (i < L.size()) {
    if (L[i].empty()) {
      for (size_t j = i; j < L.size(); ++j)
        if (!L[j].empty()) throw std::runtime_error("empty line " + std::to_string(i + 1) + " before a matrix");
      break;  // trailing empty lines
    }
    const auto colon = L[i].find(':');
    if (colon == std::string::npos) throw std::runtime_error("line " + std::to_string(i + 1) + ": no matrix header");
    const std::string name = L[i].substr(0, colon);
    std::istringstream h(L[i].substr(colon + 1));
    int rows = 0, cols = 0;
    std::string times;
    if (!(h >> rows >> times >> cols) || times != "x") throw std::runtime_error("bad matrix header: " + L[i]);
    Eigen::MatrixXd M(rows, cols);
    for (int r = 0; r < rows; ++r) {
      if (i + 1 + r >= L.size()) throw std::runtime_error(name + ": file ends in its rows");
      std::istringstream s(L[i + 1 + r]);
      for (int c = 0; c < cols; ++c)
        if (!(s >> M(r, c))) throw std::runtime_error(name + ": row " + std::to_string(r + 1) + " too short");
      double extra;
      if (s >> extra) throw std::runtime_error(name + ": row " + std::to_string(r + 1) + " too long");
    }
    f.matrices[name] = M;
    i += 1 + static_cast<size_t>(rows);
  }
  return f;
}

}  // namespace whirl::test
