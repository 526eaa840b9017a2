#include "src/io/openfast/offshore/wamit_input.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "src/base/error.hpp"
#include "src/io/openfast/elastodyn_common.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {

std::filesystem::path wamitFile(const HydroDynInput& hd, const std::string& ext) {
  std::filesystem::path p = hd.PotFile;
  p += ext;
  std::error_code ec;
  if (std::filesystem::is_regular_file(p, ec)) return p;
  std::filesystem::path found;
  int matches = 0;
  const std::string want = toLower(p.filename().string());
  for (const auto& entry : std::filesystem::directory_iterator(p.parent_path(), ec))
    if (toLower(entry.path().filename().string()) == want) {
      found = entry.path();
      ++matches;
    }
  if (matches == 1 && std::filesystem::is_regular_file(found, ec)) return found;
  throw InputError(hd.source.where("PotFile", "WAMIT file not found: " + p.string()));
}

namespace {

// Number of rotational indices (4, 5, 6) among i, j (1-based).
int rotational(int i, int j) { return (i > 3) + (j > 3); }

struct Row {
  std::vector<double> v;
  int line = 0;
};

std::vector<Row> numericRows(const std::filesystem::path& file, std::size_t min_cols) {
  std::istringstream in;
  if (!openInputFile(file.string(), in)) throw InputError(whirl::where(file.string(), 0, "", "cannot open file"));
  std::vector<Row> rows;
  int n = 0;
  for (std::string s; std::getline(in, s);) {
    ++n;
    std::istringstream ss(s);
    Row r;
    r.line = n;
    for (std::string tok; ss >> tok;) {
      const std::optional<double> x = parseFortranDouble(tok);
      if (!x || !std::isfinite(*x))
        throw InputError(whirl::where(file.string(), n, "", "'" + tok + "' is not a finite number"));
      r.v.push_back(*x);
    }
    if (r.v.empty()) continue;
    if (r.v.size() < min_cols)
      throw InputError(
          whirl::where(file.string(), n, "", "expected at least " + std::to_string(min_cols) + " numbers"));
    rows.push_back(std::move(r));
  }
  return rows;
}

int index1to6(const std::filesystem::path& file, const Row& r, double x) {
  if (!(x >= 1 && x <= 6 && x == std::floor(x)))
    throw InputError(whirl::where(file.string(), r.line, "", "mode index " + numberText(x) + " is not 1 to 6"));
  return static_cast<int>(x) - 1;
}

}  // namespace

WamitCoefficients readWamitCoefficients(const HydroDynInput& hd) {
  WamitCoefficients c;
  c.L = hd.WAMITULEN;
  const std::filesystem::path hst = wamitFile(hd, ".hst");
  for (const Row& r : numericRows(hst, 3)) {
    const int i = index1to6(hst, r, r.v[0]), j = index1to6(hst, r, r.v[1]);
    c.hydrostatic(i, j) = r.v[2];
  }
  const std::filesystem::path one = wamitFile(hd, ".1");
  bool any = false;
  for (const Row& r : numericRows(one, 4)) {
    // WAMIT writes the zero-frequency limit as PER < 0 (infinite period) and the infinite-frequency
    // one as PER = 0 (zero period), as HydroDyn's WAMIT reader takes them; finite frequencies PER > 0.
    if (r.v[0] != 0) continue;
    const int i = index1to6(one, r, r.v[1]), j = index1to6(one, r, r.v[2]);
    c.added_mass(i, j) = r.v[3];
    any = true;
  }
  if (!any)
    throw InputError(whirl::where(one.string(), 0, "",
                                  "no infinite-frequency added mass (rows with PER = 0): "
                                  "HydroDyn needs the infinite-frequency limit"));
  return c;
}

WamitMatrices dimensional(const WamitCoefficients& c, double rho, double g) {
  WamitMatrices w;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const int k = rotational(i + 1, j + 1);
      w.hydrostatic(i, j) = c.hydrostatic(i, j) * rho * g * std::pow(c.L, 2 + k);
      w.added_mass(i, j) = c.added_mass(i, j) * rho * std::pow(c.L, 3 + k);
    }
  return w;
}

WamitMatrices readWamit(const HydroDynInput& hd, double rho, double g) {
  return dimensional(readWamitCoefficients(hd), rho, g);
}

}  // namespace whirl::io
