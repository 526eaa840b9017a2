#include "src/io/openfast/aerodyn/airfoil14_input.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/openfast_lines.hpp"

namespace whirl::io {
namespace {

/// The first `n` words of line `line` as numbers (the description after them is free text).
std::vector<double> leadingNumbers(const OpenFastLines& lines, int line, int n, const char* what) {
  const std::string file = lines.path().string();
  if (line > lines.count()) throw InputError(where(file, line, what, "the file ends (truncated header?)"));
  const std::vector<std::string> words = splitWords(lines.line(line));
  std::vector<double> out;
  for (int k = 0; k < n; ++k) {
    const std::optional<double> v = k < static_cast<int>(words.size()) ? parseFortranDouble(words[k]) : std::nullopt;
    if (!v || !std::isfinite(*v))
      throw InputError(where(file, line, what,
                             "expected " + std::to_string(n) + " number" + (n > 1 ? "s (one per table)" : "") +
                                 ", word " + std::to_string(k + 1) + " is " +
                                 (k < static_cast<int>(words.size()) ? "'" + words[k] + "'" : std::string("missing"))));
    out.push_back(*v);
  }
  return out;
}

}  // namespace

AirfoilInput readAirfoil14(const std::filesystem::path& file, bool use_cm) {
  const OpenFastLines lines = OpenFastLines::read(file);
  const std::string path = file.string();
  const double tables = leadingNumbers(lines, 3, 1, "number of tables").front();
  if (tables < 1 || tables != std::floor(tables) || tables > 1000)
    throw InputError(
        where(path, 3, "number of tables", "must be a whole number from 1 to 1000 (is " + numberText(tables) + ")"));
  const int n = static_cast<int>(tables);
  const std::vector<double> id = leadingNumbers(lines, 4, n, "table ID");
  const std::vector<double> stall = leadingNumbers(lines, 5, n, "stall angle");
  for (int l = 6; l <= 8; ++l) leadingNumbers(lines, l, n, "unused");
  const std::vector<double> alpha0 = leadingNumbers(lines, 9, n, "zero-lift angle");
  const std::vector<double> slope = leadingNumbers(lines, 10, n, "Cn slope");
  const std::vector<double> cn_pos = leadingNumbers(lines, 11, n, "Cn at positive stall");
  const std::vector<double> cn_neg = leadingNumbers(lines, 12, n, "Cn at negative stall");
  leadingNumbers(lines, 13, n, "angle of minimum Cd");
  const std::vector<double> cd_min = leadingNumbers(lines, 14, n, "minimum Cd");

  AirfoilInput a;
  a.path = file;
  a.name = file.stem().string();
  a.interp_order = 1;
  a.tables.resize(n);
  for (int t = 0; t < n; ++t) {
    AirfoilTable& tab = a.tables[t];
    tab.re = id[t];
    tab.re_line = 4;
    tab.num_alf_line = 14;
    tab.ua.included = true;
    tab.ua.alpha0 = alpha0[t];
    tab.ua.alpha1 = stall[t];
    tab.ua.C_nalpha = slope[t];
    tab.ua.Cn1 = cn_pos[t];
    tab.ua.Cn2 = cn_neg[t];
    tab.ua.Cd0 = cd_min[t];
  }
  const int per_table = use_cm ? 3 : 2;
  const std::size_t needed = 1 + static_cast<std::size_t>(n * per_table);
  std::vector<double> last_row;  // the previous coefficient row (alpha first)
  for (int l = 15; l <= lines.count(); ++l) {
    if (isBlankLine(lines.line(l))) continue;
    // Like AeroDyn v14's list-directed reads: the numbers a row needs, then anything (often a description).
    std::vector<double> numbers;
    for (const std::string& w : splitWords(lines.line(l))) {
      const std::optional<double> v = parseFortranDouble(w);
      if (!v) break;
      numbers.push_back(*v);
    }
    const std::optional<std::vector<double>> row = numbers.empty()
                                                       ? std::nullopt
                                                       : std::optional<std::vector<double>>(std::move(numbers));
    if (!row)
      throw InputError(
          where(path, l, "",
                "not a row of numbers (alpha, then Cl, Cd" + std::string(use_cm ? ", Cm" : "") + " per table)"));
    if (row->size() < needed)
      throw InputError(where(path, l, "",
                             "row has " + std::to_string(row->size()) + " numbers, " + std::to_string(n) +
                                 " table(s) with" + (use_cm ? "" : "out") + " Cm (UseCm) need " +
                                 std::to_string(needed)));
    for (std::size_t c = 0; c < needed; ++c)
      if (!std::isfinite((*row)[c]))
        throw InputError(
            where(path, l, c == 0 ? "Alpha" : "", std::isnan((*row)[c]) ? "value is NaN" : "value is infinite"));
    const double alpha = row->front();
    // A row repeated exactly (the certification decks' DU25_A17 repeats -13 deg) adds nothing to a
    // piecewise-linear table: it is skipped. The same angle with other coefficients is an error below.
    if (!a.tables.front().alpha_deg.empty() && alpha == a.tables.front().alpha_deg.back() &&
        std::equal(row->begin(), row->begin() + static_cast<std::ptrdiff_t>(needed), last_row.begin()))
      continue;
    last_row.assign(row->begin(), row->begin() + static_cast<std::ptrdiff_t>(needed));
    for (int t = 0; t < n; ++t) {
      AirfoilTable& tab = a.tables[t];
      if (!tab.alpha_deg.empty() && !(alpha > tab.alpha_deg.back()))
        throw InputError(where(path, l, "Alpha",
                               "must increase from row to row (" + numberText(alpha) + " after " +
                                   numberText(tab.alpha_deg.back()) + ")"));
      const std::size_t c = 1 + static_cast<std::size_t>(t * per_table);
      tab.alpha_deg.push_back(alpha);
      tab.cl.push_back((*row)[c]);
      tab.cd.push_back((*row)[c + 1]);
      if (use_cm) tab.cm.push_back((*row)[c + 2]);
      tab.row_lines.push_back(l);
    }
  }
  if (a.tables.front().alpha_deg.empty())
    throw InputError(where(path, lines.count() + 1, "", "no coefficient rows after the 14 header lines"));
  for (AirfoilTable& tab : a.tables) tab.first_row_line = tab.row_lines.front();
  return a;
}

}  // namespace whirl::io
