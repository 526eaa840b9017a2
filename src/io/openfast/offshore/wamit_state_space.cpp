#include "src/io/openfast/offshore/wamit_state_space.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/openfast/offshore/wamit_input.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

struct Lines {
  std::filesystem::path file;
  std::vector<std::string> text;
  [[noreturn]] void fail(std::size_t index, const std::string& reason) const {
    throw InputError(whirl::where(file.string(), static_cast<int>(index) + 1, "", reason));
  }
};

// The first `count` numbers of line `index` (a comment may follow them on the header lines: `%Radiation
// states`); with `exact`, nothing else.
std::vector<double> numbers(const Lines& l, std::size_t index, int count, bool exact) {
  if (index >= l.text.size())
    l.fail(index, "the file ends early: expected " + std::to_string(count) + " numbers on this line");
  std::istringstream ss(l.text[index]);
  std::vector<double> v;
  for (std::string tok; static_cast<int>(v.size()) < count && ss >> tok;) {
    const std::optional<double> x = parseFortranDouble(tok);
    if (!x || !std::isfinite(*x)) l.fail(index, "'" + tok.substr(0, 40) + "' is not a finite number");
    v.push_back(*x);
  }
  std::string rest;
  if (static_cast<int>(v.size()) < count || (exact && ss >> rest))
    l.fail(index, "expected " + std::to_string(count) + " numbers");
  return v;
}

int wholeNumber(const Lines& l, std::size_t index, double x, const char* what) {
  if (!(x == std::floor(x) && x >= 0 && x <= limits::kMaxRadiationStates))
    l.fail(index, std::string(what) + " " + numberText(x) + " is not a whole number from 0 to " +
                      std::to_string(limits::kMaxRadiationStates));
  return static_cast<int>(x);
}

}  // namespace

RadiationStateSpace readRadiationStateSpace(const HydroDynInput& hd) {
  Lines l;
  l.file = wamitFile(hd, ".ss");
  std::istringstream in;
  if (!openInputFile(l.file.string(), in)) throw InputError(whirl::where(l.file.string(), 0, "", "cannot open file"));
  for (std::string s; std::getline(in, s);) l.text.push_back(s);
  const std::vector<double> flags = numbers(l, 1, 6, false);
  for (int k = 0; k < 6; ++k)
    if (flags[k] != 1)
      l.fail(1, "DOF " + std::to_string(k + 1) + " is not enabled (flag " + numberText(flags[k]) +
                    "): HydroDyn's radiation states need all six DOFs");
  const int n = wholeNumber(l, 2, numbers(l, 2, 1, false)[0], "the number of states");
  const std::vector<double> per = numbers(l, 3, 6, false);
  RadiationStateSpace r;
  int sum = 0;
  for (int k = 0; k < 6; ++k) sum += r.per_dof[k] = wholeNumber(l, 3, per[k], "a count of states");
  if (sum != n)
    l.fail(3,
           "the states per DOF sum to " + std::to_string(sum) + ", not the " + std::to_string(n) + " states of line 3");
  std::size_t line = 4;
  auto rows = [&](MatX& M, int nrows, int ncols) {
    M.resize(nrows, ncols);
    for (int i = 0; i < nrows; ++i, ++line) {
      const std::vector<double> v = numbers(l, line, ncols, true);
      for (int j = 0; j < ncols; ++j) M(i, j) = v[j];
    }
  };
  rows(r.A, n, n);
  rows(r.B, n, 6);
  rows(r.C, 6, n);
  for (; line < l.text.size(); ++line)
    if (l.text[line].find_first_not_of(" \t\r") != std::string::npos)
      l.fail(line, "text after the C matrix (" + std::to_string(n) + " states: A, B and C end on line " +
                       std::to_string(4 + 2 * n + 6) + ")");
  return r;
}

}  // namespace whirl::io
