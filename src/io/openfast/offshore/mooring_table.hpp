#pragma once
/// \file
/// What the mooring readers (MAP++, MoorDyn) share: a file read row by row into blank-separated tokens,
/// numbers parsed as Fortran reads them, every error "file:line: key: reason".
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"

namespace whirl::io {

inline std::vector<std::string> mooringTokens(const std::string& s) {
  std::istringstream ss(s);
  std::vector<std::string> t;
  for (std::string w; ss >> w;) t.push_back(w);
  return t;
}

/// The place being read and the number parsers that name it.
struct MooringTableReader {
  std::string file;
  int line = 0;
  InputError fail(const std::string& key, const std::string& reason) const {
    return InputError(whirl::where(file, line, key, reason));
  }
  double number(const std::string& tok, const std::string& key) const {
    const std::optional<double> x = parseFortranDouble(tok);
    if (!x || !std::isfinite(*x)) throw fail(key, "'" + tok.substr(0, 40) + "' is not a finite number");
    return *x;
  }
  int integer(const std::string& tok, const std::string& key) const {
    const double x = number(tok, key);
    if (x != std::floor(x) || std::abs(x) > 1e9) throw fail(key, "'" + tok.substr(0, 40) + "' is not an integer");
    return static_cast<int>(x);
  }
};

}  // namespace whirl::io
