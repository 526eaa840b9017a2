#include "src/io/openfast/servodyn/rotor_performance_input.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/openfast/openfast_lines.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

struct Lines {
  std::string file;
  std::vector<std::string> text;

  std::vector<double> numbers(size_t i, const std::string& key) const {
    if (i >= text.size()) throw InputError(where(file, static_cast<int>(i), key, "file ends before the values"));
    auto row = parseNumberRow(text[i]);
    if (!row || row->empty()) throw InputError(where(file, static_cast<int>(i + 1), key, "expected a row of numbers"));
    for (double v : *row)
      if (!std::isfinite(v)) throw InputError(where(file, static_cast<int>(i + 1), key, "value is not finite"));
    return *row;
  }
  /// Index of the first comment line containing `word`, or throws.
  size_t find(const std::string& word, const std::string& key) const {
    for (size_t i = 0; i < text.size(); ++i)
      if (isCommentLine(text[i]) && text[i].find(word) != std::string::npos) return i;
    throw InputError(where(file, 0, key, "no '# ..." + word + "...' block"));
  }
};

/// Grid values per axis at most: ROSCO's surfaces have tens; the tables are allocated from these counts.
constexpr size_t kMaxGridValues = 1000;

void checkGrid(const Lines& f, size_t line, const std::string& key, const std::vector<double>& g) {
  if (g.size() > kMaxGridValues)
    throw InputError(where(f.file, static_cast<int>(line + 1), key, "more than 1000 values"));
  if (g.size() < 4) throw InputError(where(f.file, static_cast<int>(line + 1), key, "needs at least 4 values"));
  for (size_t i = 1; i < g.size(); ++i)
    if (!(g[i] > g[i - 1])) throw InputError(where(f.file, static_cast<int>(line + 1), key, "values must increase"));
}

MatX table(const Lines& f, const std::string& word, const std::string& key, size_t rows, size_t cols) {
  const size_t head = f.find(word, key);
  MatX t(rows, cols);
  for (size_t r = 0; r < rows; ++r) {
    const size_t i = head + 2 + r;
    const std::vector<double> row = f.numbers(i, key);
    if (row.size() != cols)
      throw InputError(
          where(f.file, static_cast<int>(i + 1), key,
                std::to_string(row.size()) + " values, expected one per pitch angle (" + std::to_string(cols) + ")"));
    for (size_t c = 0; c < cols; ++c) t(r, c) = row[c];
  }
  return t;
}

}  // namespace

aero::RotorPerformance readRotorPerformance(const std::string& path) {
  std::istringstream in;
  if (!openInputFile(path, in)) throw InputError(where(path, 0, "", "cannot open the rotor performance file"));
  Lines f{path, {}};
  for (std::string line; std::getline(in, line);) f.text.push_back(line);
  aero::RotorPerformance p;
  const size_t ip = f.find("Pitch angle", "pitch") + 1;
  const size_t it = f.find("TSR", "TSR") + 1;
  const std::vector<double> deg = f.numbers(ip, "pitch");
  p.tsr = f.numbers(it, "TSR");
  checkGrid(f, ip, "pitch", deg);
  checkGrid(f, it, "TSR", p.tsr);
  constexpr double kDegToRad = std::numbers::pi / 180;  // NumPy's deg2rad(1), as ROSCO converts
  for (double d : deg) p.pitch.push_back(d * kDegToRad);
  p.cp = table(f, "Power", "Cp", p.tsr.size(), deg.size());
  p.ct = table(f, "Thrust", "Ct", p.tsr.size(), deg.size());
  p.cq = table(f, "Torque", "Cq", p.tsr.size(), deg.size());
  return p;
}

}  // namespace whirl::io
