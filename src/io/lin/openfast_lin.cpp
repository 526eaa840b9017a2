#include "src/io/lin/openfast_lin.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <string_view>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl {
namespace {

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

/// Next whitespace-separated token of `s` from `pos` (pos is advanced past it); empty at the end.
std::string_view nextToken(std::string_view s, std::size_t& pos) {
  while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
  const std::size_t begin = pos;
  while (pos < s.size() && !std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
  return s.substr(begin, pos - begin);
}

bool fullParse(std::string_view t, double& v) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc() && end == t.data() + t.size();
}

/// Reads a whole file as lines and parses them; keeps the count of non-finite numbers.
class LinParser {
 public:
  explicit LinParser(const std::string& path) : path_(path) {
    std::istringstream in;
    if (!io::openInputFile(path, in)) throw InputError(where(path, 0, "", "cannot open file"));
    for (std::string l; std::getline(in, l);) {
      if (!l.empty() && l.back() == '\r') l.pop_back();
      lines_.push_back(std::move(l));
    }
  }

  OpenFastLin parse();

 private:
  [[noreturn]] void fail(std::size_t i, const std::string& key, const std::string& reason) const {
    throw InputError(where(path_, static_cast<int>(i + 1), key, reason));
  }

  /// Fails for a table or matrix that stops (end of file or blank line) at line `i`.
  [[noreturn]] void truncated(std::size_t i, const std::string& key, const std::string& reason) const {
    if (i >= lines_.size()) fail(lines_.empty() ? 0 : lines_.size() - 1, key, "truncated at end of file: " + reason);
    fail(i, key, "truncated: " + reason);
  }

  /// A number in Fortran E format; `****` (overflow) is NaN. Throws naming the line if not a number.
  double number(std::string_view t, std::size_t i, const std::string& key) {
    double v = 0.0;
    if (!t.empty() && t.find_first_not_of('*') == std::string_view::npos) {
      nonFinite(i, key);
      return std::numeric_limits<double>::quiet_NaN();
    }
    if (!fullParse(t, v)) {
      // Fortran drops the 'E' of a 3-digit exponent: "1.234567-100".
      const std::size_t e = t.find_last_of("+-");
      double mant = 0.0, expo = 0.0;
      if (e == 0 || e == std::string_view::npos || !fullParse(t.substr(0, e), mant) || !fullParse(t.substr(e), expo))
        fail(i, key, "'" + excerpt(t) + "' is not a number");
      v = mant * std::pow(10.0, expo);
    }
    if (!std::isfinite(v)) nonFinite(i, key);
    return v;
  }

  /// Counts a non-finite value and keeps "file:line: key" of the first one for messages.
  void nonFinite(std::size_t i, const std::string& key) {
    ++non_finite_;
    first_non_finite_.emplace(key, static_cast<int>(i + 1));  // keeps the first line of each key
  }

  int integer(std::string_view t, std::size_t i, const std::string& key) const {
    int v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec == std::errc::result_out_of_range && end == t.data() + t.size())
      fail(i, key, "'" + excerpt(t) + "' is out of the integer range");
    if (t.empty() || ec != std::errc() || end != t.data() + t.size())
      fail(i, key, "'" + excerpt(t) + "' is not an integer");
    return v;
  }

  /// A count or matrix dimension: an integer from 0 to limits::kMaxLinDimension.
  int dimension(std::string_view t, std::size_t i, const std::string& key) const {
    const int v = integer(t, i, key);
    if (v < 0) fail(i, key, "negative count");
    if (v > limits::kMaxLinDimension)
      fail(i, key,
           std::to_string(v) + " is above the limit of " + std::to_string(limits::kMaxLinDimension) +
               " (src/base/limits.hpp)");
    return v;
  }

  /// At most 40 characters of a token, for messages.
  static std::string excerpt(std::string_view t) {
    return t.size() <= 40 ? std::string(t) : std::string(t.substr(0, 40)) + "...";
  }

  void header(OpenFastLin& f, std::size_t& i);
  std::vector<LinVariable> table(std::size_t& i, int n, const std::string& key);
  Eigen::MatrixXd matrix(std::size_t& i, int rows, int cols, const std::string& key);

  std::string path_;
  std::vector<std::string> lines_;
  int non_finite_ = 0;
  std::map<std::string, int> first_non_finite_;  ///< key → line of its first non-finite value
};

/// Header up to the first table or matrix. Keys are recognized at the start of a trimmed line only,
/// so the free-text description line cannot fake one.
void LinParser::header(OpenFastLin& f, std::size_t& i) {
  bool have_time = false, have_speed = false, have_azimuth = false, have_counts[5] = {};
  static const char* const count_keys[5] = {"Number of continuous states:", "Number of discrete states:",
                                            "Number of constraint states:", "Number of inputs:", "Number of outputs:"};
  int* const counts[5] = {&f.n_x, &f.n_xd, &f.n_z, &f.n_u, &f.n_y};
  auto value = [&](std::string_view line, std::string_view key) {
    std::size_t pos = key.size();
    return number(nextToken(line, pos), i, std::string(trimBlanks(key.substr(0, key.size() - 1))));
  };
  for (; i < lines_.size(); ++i) {
    const std::string_view l = trimBlanks(lines_[i]);
    if (startsWith(l, "Order of") || startsWith(l, "Linearized state matrices") || startsWith(l, "Jacobian matrices"))
      break;
    if (startsWith(l, "Linearized model:")) f.generator = std::string(trimBlanks(l.substr(17)));
    if (startsWith(l, "Simulation time:")) f.time = value(l, "Simulation time:"), have_time = true;
    if (startsWith(l, "Rotor Speed:")) f.rotor_speed = value(l, "Rotor Speed:"), have_speed = true;
    if (startsWith(l, "Azimuth:")) f.azimuth = value(l, "Azimuth:"), have_azimuth = true;
    if (startsWith(l, "Wind Speed:")) f.wind_speed = value(l, "Wind Speed:");
    for (int k = 0; k < 5; ++k) {
      if (!startsWith(l, count_keys[k])) continue;
      std::size_t pos = std::string_view(count_keys[k]).size();
      const std::string_view key(count_keys[k]);
      *counts[k] = dimension(nextToken(l, pos), i, std::string(key.substr(0, key.size() - 1)));
      have_counts[k] = true;
    }
    if (startsWith(l, "Jacobians included in this file?")) f.has_jacobians = l.find("Yes") != std::string_view::npos;
  }
  const std::size_t end_line = i == 0 ? 0 : i - 1;
  if (!have_time) fail(end_line, "Simulation time", "missing from the header");
  if (!have_speed) fail(end_line, "Rotor Speed", "missing from the header");
  if (!have_azimuth) fail(end_line, "Azimuth", "missing from the header");
  for (int k = 0; k < 5; ++k)
    if (!have_counts[k]) fail(end_line, count_keys[k], "missing from the header");
}

/// Table of `n` rows after its title line `i`: a column-title line, a dashed line, then rows
/// "index op[, op, op] T|F [order] description". On return `i` is the last row.
std::vector<LinVariable> LinParser::table(std::size_t& i, int n, const std::string& key) {
  if (i + 2 >= lines_.size()) truncated(lines_.size(), key, "table without column titles");
  const std::string_view columns = lines_[i + 1];
  if (columns.find("Operating Point") == std::string_view::npos)
    fail(i + 1, key, "expected the column titles (Row/Column, Operating Point, ...)");
  const bool has_order = columns.find("Derivative Order") != std::string_view::npos;
  i += 2;  // dashed line
  // Rows are added as they are read: the declared count alone must not size an allocation (a header
  // claiming 2e9 states is a truncated table, not 160 GB).
  std::vector<LinVariable> rows;
  rows.reserve(std::min(static_cast<std::size_t>(n), lines_.size() - i));
  for (int r = 0; r < n; ++r) {
    ++i;
    if (i >= lines_.size() || trimBlanks(lines_[i]).empty())
      truncated(i, key, std::to_string(r) + " rows where the header declares " + std::to_string(n));
    const std::string_view l = lines_[i];
    std::size_t pos = 0;
    if (integer(nextToken(l, pos), i, key) != r + 1) fail(i, key, "row " + std::to_string(r + 1) + " expected");
    LinVariable& v = rows.emplace_back();
    v.line = static_cast<int>(i + 1);
    for (std::string_view t = nextToken(l, pos);; t = nextToken(l, pos)) {  // "1.0E+00, 2.0E+00, 3.0E+00"
      if (t.empty()) fail(i, key, "operating point missing");
      const bool more = t.back() == ',';
      if (more) t.remove_suffix(1);
      v.op_values.push_back(number(t, i, key));
      if (!more) break;
    }
    v.op = v.op_values.front();
    if (v.op_values.size() == 1) v.op_values.clear();
    const std::string_view flag = nextToken(l, pos);
    if (flag == "T" || flag == "True" || flag == "TRUE") v.rotating = true;
    else if (!(flag == "F" || flag == "False" || flag == "FALSE"))
      fail(i, key, "rotating-frame flag '" + std::string(flag) + "' is not T or F");
    if (has_order) v.derivative_order = integer(nextToken(l, pos), i, key);
    // Descriptions become DOF and mode names: tabs are spacing, other control characters an error.
    v.description = tabsToSpaces(trimBlanks(l.substr(std::min(pos, l.size()))));
    requirePrintable(v.description, path_, static_cast<int>(i + 1), key + " description");
  }
  return rows;
}

/// Matrix rows after its title line `i` ("A: 20 x 20"). On return `i` is the last row. The values
/// are collected as read and the matrix is sized at the end, so the title's dimensions alone never
/// size an allocation ("A: 20 x 2000000000" is a row with too few values, not 320 GB).
Eigen::MatrixXd LinParser::matrix(std::size_t& i, int rows, int cols, const std::string& key) {
  std::vector<double> values;  // grows with the rows read, not with the title's claim
  for (int r = 0; r < rows; ++r) {
    ++i;
    if (i >= lines_.size() || trimBlanks(lines_[i]).empty())
      truncated(i, key, std::to_string(r) + " of " + std::to_string(rows) + " rows");
    const std::string_view l = lines_[i];
    std::size_t pos = 0;
    int c = 0;
    for (std::string_view t = nextToken(l, pos); !t.empty(); t = nextToken(l, pos), ++c) {
      if (c == cols) fail(i, key, "more than " + std::to_string(cols) + " values in row " + std::to_string(r + 1));
      values.push_back(number(t, i, key));
    }
    if (c != cols)
      fail(i, key,
           std::to_string(c) + " values in row " + std::to_string(r + 1) + ", expected " + std::to_string(cols));
  }
  if (values.empty()) return Eigen::MatrixXd(rows, cols);  // a 0 x n or n x 0 block
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(values.data(), rows,
                                                                                                  cols);
}

OpenFastLin LinParser::parse() {
  OpenFastLin f;
  f.path = path_;
  std::size_t i = 0;
  header(f, i);
  static const std::regex mat_title(R"(^\s*([A-Za-z][A-Za-z0-9_]*)\s*:\s*(\d+)\s*x\s*(\d+)\s*$)");
  bool have_x = false, have_xdot = false, have_u = false, have_y = false, have_xd = false, have_z = false;
  for (; i < lines_.size(); ++i) {
    const std::string_view l = trimBlanks(lines_[i]);
    if (startsWith(l, "Order of continuous states:")) f.x = table(i, f.n_x, "continuous states"), have_x = true;
    else if (startsWith(l, "Order of continuous state derivatives:"))
      f.xdot = table(i, f.n_x, "continuous state derivatives"), have_xdot = true;
    else if (startsWith(l, "Order of discrete states:")) f.xd = table(i, f.n_xd, "discrete states"), have_xd = true;
    else if (startsWith(l, "Order of constraint states:")) f.z = table(i, f.n_z, "constraint states"), have_z = true;
    else if (startsWith(l, "Order of inputs:")) f.u = table(i, f.n_u, "inputs"), have_u = true;
    else if (startsWith(l, "Order of outputs:")) f.y = table(i, f.n_y, "outputs"), have_y = true;
    else if (std::smatch m; l.find(" x ") != std::string_view::npos && std::regex_match(lines_[i], m, mat_title)) {
      const std::string name = m[1];
      const int rows = dimension(m[2].str(), i, m[1].str() + " rows"),
                cols = dimension(m[3].str(), i, m[1].str() + " columns");
      const std::size_t title = i;
      Eigen::MatrixXd mat = matrix(i, rows, cols, name);
      auto expect = [&](int r, int c) {
        if (rows != r || cols != c)
          fail(title, name,
               "is " + std::to_string(rows) + " x " + std::to_string(cols) + ", the header implies " +
                   std::to_string(r) + " x " + std::to_string(c));
      };
      if (name == "A") expect(f.n_x, f.n_x), f.A = std::move(mat);
      else if (name == "B") expect(f.n_x, f.n_u), f.B = std::move(mat);
      else if (name == "C") expect(f.n_y, f.n_x), f.C = std::move(mat);
      else if (name == "D") expect(f.n_y, f.n_u), f.D = std::move(mat);
      // other blocks (dUdu, dUdy, StateRotation, ...) are read for consistency and dropped
    }
  }
  const std::size_t last = lines_.empty() ? 0 : lines_.size() - 1;
  auto require = [&](bool ok, const char* what) {
    if (!ok) fail(last, what, "missing (truncated file?)");
  };
  if (f.n_x > 0) require(have_x && have_xdot, "Order of continuous states");
  if (f.n_xd > 0) require(have_xd, "Order of discrete states");
  if (f.n_z > 0) require(have_z, "Order of constraint states");
  if (f.n_u > 0) require(have_u, "Order of inputs");
  if (f.n_y > 0) require(have_y, "Order of outputs");
  if (f.n_x > 0) require(f.A.size() > 0, "matrix A");
  if (f.n_x > 0 && f.n_u > 0) require(f.B.size() > 0, "matrix B");
  if (f.n_y > 0 && f.n_x > 0) require(f.C.size() > 0, "matrix C");
  if (f.n_y > 0 && f.n_u > 0) require(f.D.size() > 0, "matrix D");
  f.non_finite_values = non_finite_;
  f.first_non_finite = first_non_finite_;
  return f;
}

}  // namespace

OpenFastLin readOpenFastLin(const std::string& path) { return LinParser(path).parse(); }

}  // namespace whirl
