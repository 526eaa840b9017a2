#pragma once
// Reads a case's reference.csv (header with at least quantity, value, tolerance, source; quoted
// fields may hold commas) and checks computed values against it, naming the source on failure.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "linearize/linearize.hpp"
#include "modal/modes.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/text/csv.hpp"

namespace whirl::test {

inline std::string casePath(const std::string& name) {
  return std::string(WHIRL_SOURCE_DIR) + "/cases/" + name + "/" + name + ".yaml";
}

inline Model loadCase(const std::string& name, const std::vector<std::string>& sets = {}) {
  std::vector<CaseOverride> o;
  for (const auto& s : sets) o.push_back(parseOverride(s));
  return readCase(casePath(name), o);
}

struct ReferenceRow {
  double value = 0, tolerance = 0;
  std::string source;
};

inline std::map<std::string, ReferenceRow> loadReference(const std::string& case_name) {
  const std::string path = std::string(WHIRL_SOURCE_DIR) + "/cases/" + case_name + "/reference.csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(in, line);
  const auto header = splitCsvLine(line);
  auto col = [&](const std::string& n) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == n) return i;
    throw std::runtime_error(path + ": no column " + n);
  };
  const size_t q = col("quantity"), v = col("value"), t = col("tolerance"), s = col("source");
  std::map<std::string, ReferenceRow> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = splitCsvLine(line);
    rows[f.at(q)] = {std::stod(f.at(v)), std::stod(f.at(t)), f.at(s)};
  }
  return rows;
}

/// Checks every computed quantity that the reference lists; fails for computed names it lacks.
inline void expectMatchesReference(const std::string& case_name, const std::map<std::string, double>& computed) {
  const auto ref = loadReference(case_name);
  for (const auto& [name, value] : computed) {
    const auto it = ref.find(name);
    if (it == ref.end()) {
      ADD_FAILURE() << case_name << ": no reference row for " << name;
      continue;
    }
    EXPECT_NEAR(value, it->second.value, it->second.tolerance)
        << case_name << " " << name << " (reference: " << it->second.source << ")";
    if (std::getenv("WHIRL_PRINT_REFERENCE"))  // for reports: whirl's value next to the reference
      std::printf("%s,%s,%.10g,%.10g,%.3g\n", case_name.c_str(), name.c_str(), value, it->second.value,
                  it->second.tolerance);
  }
}

/// The linear model at a given state (no equilibrium solve): q̇ from the model's rates, q̈ = 0.
inline LinearModel linearizeAt(const Model& m, const VecX& q) {
  OperatingPoint op = initialPoint(m);
  op.q = q;
  return linearize(m, op);
}

inline LinearModel linearizeAtEquilibrium(const Model& m) {
  return linearize(m, solveOperatingPoint(m, initialPoint(m)));
}

/// The NREL 5MW's rated point on model m, solved: 11.4 m/s, 12.1 rpm, pitch 0 (Jonkman et al. 2009).
inline OperatingPoint nrel5mwRatedPoint(const Model& m) {
  OperatingCondition c;
  c.rotor_speed = 12.1 * std::numbers::pi / 30;
  c.wind_speed = 11.4;
  c.collective_pitch = 0;
  return solveOperatingPoint(m, initialPoint(m, c));
}

inline int dofIndex(const LinearModel& l, const std::string& name) {
  for (size_t i = 0; i < l.dof_names.size(); ++i)
    if (l.dof_names[i] == name) return static_cast<int>(i);
  throw std::runtime_error("no DOF " + name);
}

/// The frequency [Hz] of the mode in which coordinate `dof` has its largest participation.
inline double frequencyOf(const std::vector<Mode>& modes, const LinearModel& l, const std::string& dof) {
  const int i = dofIndex(l, dof);
  std::size_t best = 0;
  for (std::size_t k = 1; k < modes.size(); ++k)
    if (modes[k].participation(i) > modes[best].participation(i)) best = k;
  return modes[best].freq_hz;
}

}  // namespace whirl::test
