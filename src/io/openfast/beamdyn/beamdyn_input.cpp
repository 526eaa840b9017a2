// The BeamDyn reader: scalars by key (overrides apply), the member, key-point and station tables
// positionally below their keys, as BeamDyn_IO.f90 reads them (BD_ReadPrimaryFile, BD_ReadBladeFile).
#include "src/io/openfast/beamdyn/beamdyn_input.hpp"

#include <cmath>
#include <optional>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/io/openfast/openfast_lines.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/refusals.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl::io {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

class Rows {
 public:
  Rows(const OpenFastFile& f, const OpenFastLines& lines) : f_(f), lines_(lines) {}

  std::string where(int line, const std::string& key, const std::string& reason) const {
    return whirl::where(f_.path().string(), line, key, reason);
  }

  const OpenFastEntry& entry(const char* key, const char* file_type) const {
    const OpenFastEntry* e = f_.find(key);
    if (!e) throw InputError(f_.where(key, std::string("key not found in this ") + file_type + " file"));
    return *e;
  }

  int count(const char* key, int lo, int hi, const char* file_type) const {
    entry(key, file_type);
    const int n = f_.getInt(key);
    if (n < lo || n > hi)
      throw InputError(f_.where(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                                         " (src/base/limits.hpp)"));
    return n;
  }

  // Exactly `n` numbers on line `ln` (words after them are a comment, as Fortran's list read skips them).
  std::vector<double> numbers(int ln, int n, const std::string& key, const std::string& what) const {
    if (ln > lines_.count()) throw InputError(where(ln, key, "the file ends before " + what + " (truncated file?)"));
    const std::vector<std::string> w = splitWords(lines_.line(ln));
    if (static_cast<int>(w.size()) < n)
      throw InputError(where(ln, key,
                             "expected " + std::to_string(n) + " numbers (" + what + "), found " +
                                 std::to_string(w.size()) + " words"));
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const std::optional<double> x = parseFortranDouble(w[static_cast<std::size_t>(k)]);
      if (!x)
        throw InputError(where(ln, key, "'" + w[static_cast<std::size_t>(k)] + "' is not a number (" + what + ")"));
      if (!std::isfinite(*x))
        throw InputError(where(ln, key, "'" + w[static_cast<std::size_t>(k)] + "' is not finite"));
      v[static_cast<std::size_t>(k)] = *x;
    }
    return v;
  }

  const OpenFastLines& lines() const { return lines_; }

 private:
  const OpenFastFile& f_;
  const OpenFastLines& lines_;
};

// Keys each file may hold once: a repeated line would shift BeamDyn's positional reading.
void checkOnce(const OpenFastFile& f, std::initializer_list<const char*> keys) {
  for (const char* key : keys) {
    const OpenFastEntry* first = f.find(key);
    if (!first) continue;
    for (const OpenFastEntry& e : f.entries())
      if (&e != first && !e.informal && canonicalKey(e.key) == canonicalKey(key))
        throw InputError(whirl::where(f.path().string(), e.line, e.key,
                                      "given twice (first on line " + std::to_string(first->line) +
                                          "): BeamDyn reads this file by position"));
  }
}

// A 6 × 6 matrix from six rows starting at line ln.
Mat6d matrix6(const Rows& rows, int ln, const std::string& key, int station) {
  Mat6d A;
  for (int i = 0; i < 6; ++i) {
    const std::vector<double> v = rows.numbers(ln + i, 6, key,
                                               "row " + std::to_string(i + 1) + " of station " +
                                                   std::to_string(station) + "'s " + key);
    for (int j = 0; j < 6; ++j) A(i, j) = v[static_cast<std::size_t>(j)];
  }
  return A;
}

// Symmetric to the file's printed precision (|a_ij − a_ji| ≤ 1e-5 max(|a_ij|, |a_ji|), or ≤ 1e-9 of the
// largest diagonal entry), then symmetrized.
Mat6d checkedSymmetric(const Rows& rows, const Mat6d& A, int ln, const std::string& key, int station) {
  const double scale = A.diagonal().cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const double a = A(i, j), b = A(j, i);
      if (std::abs(a - b) > std::max(1e-5 * std::max(std::abs(a), std::abs(b)), 1e-9 * scale))
        throw InputError(rows.where(ln, key,
                                    "station " + std::to_string(station) + ": not symmetric, entry (" +
                                        std::to_string(i + 1) + "," + std::to_string(j + 1) +
                                        ") = " + std::to_string(a) + " but (" + std::to_string(j + 1) + "," +
                                        std::to_string(i + 1) + ") = " + std::to_string(b)));
    }
  return 0.5 * (A + A.transpose());
}

BeamDynStation readStation(const Rows& rows, int ln, int index) {
  BeamDynStation s;
  s.line = ln;
  s.eta = rows.numbers(ln, 1, "station_eta", "η of station " + std::to_string(index))[0];
  const std::string st = std::to_string(index);
  s.K = checkedSymmetric(rows, matrix6(rows, ln + 1, "stiffness_matrix", index), ln + 1, "stiffness_matrix", index);
  s.M = checkedSymmetric(rows, matrix6(rows, ln + 8, "mass_matrix", index), ln + 8, "mass_matrix", index);
  if (Eigen::LLT<Mat6d>(s.K).info() != Eigen::Success || !(s.K.diagonal().array() > 0).all())
    throw InputError(rows.where(ln + 1, "stiffness_matrix",
                                "station " + st + " (η = " + std::to_string(s.eta) +
                                    "): not positive definite (every strain must take energy)"));
  if (!(s.M(0, 0) > 0) || s.M(1, 1) != s.M(0, 0) || s.M(2, 2) != s.M(0, 0))
    throw InputError(rows.where(ln + 8, "mass_matrix",
                                "station " + st +
                                    ": the first three diagonal entries must be the same positive mass "
                                    "per length"));
  const Eigen::SelfAdjointEigenSolver<Mat6d> eig(s.M, Eigen::EigenvaluesOnly);
  if (eig.eigenvalues().minCoeff() < -1e-9 * s.M.diagonal().maxCoeff())
    throw InputError(rows.where(ln + 8, "mass_matrix",
                                "station " + st + " (η = " + std::to_string(s.eta) +
                                    "): not positive semi-definite (negative kinetic energy)"));
  return s;
}

}  // namespace

std::string BeamDynInput::where(int line, const std::string& key, const std::string& reason) const {
  return whirl::where(source.path().string(), line, key, reason);
}

BeamDynBlade parseBeamDynBlade(std::string_view text, const std::filesystem::path& file) {
  BeamDynBlade b;
  b.source = OpenFastFile::parse(text, file);
  const OpenFastLines lines = OpenFastLines::fromText(text, file);
  const OpenFastFile& f = b.source;
  checkOnce(f, {"station_total", "damp_type", "n_modes"});
  const Rows rows(f, lines);
  const int n = rows.count("station_total", 2, limits::kMaxFemElements, "BeamDyn blade");
  const OpenFastEntry& damp = rows.entry("damp_type", "BeamDyn blade");
  b.damp_type = f.getInt("damp_type");
  if (b.damp_type < 0 || b.damp_type > 2) throw InputError(f.where("damp_type", "must be 0, 1 or 2"));
  if (b.damp_type == 2)
    throw InputError(f.where("damp_type", "2 not supported by whirl (modal damping of BeamDyn; use 1, mu)"));
  // A section line and the two rows of column names and units, then the six values (ReadCom × 3, ReadAry).
  b.mu_line = damp.line + 4;
  const std::vector<double> mu = rows.numbers(b.mu_line, 6, "mu", "mu1 … mu6");
  for (int k = 0; k < 6; ++k) {
    b.mu[static_cast<std::size_t>(k)] = b.damp_type == 1 ? mu[static_cast<std::size_t>(k)] : 0.0;
    if (mu[static_cast<std::size_t>(k)] < 0) throw InputError(rows.where(b.mu_line, "mu", "must not be negative"));
  }
  int ln = b.mu_line + 1;  // the Distributed Properties section line (after the modal block, if any)
  if (const OpenFastEntry* nm = f.find("n_modes")) {
    if (nm->line != ln + 1) throw InputError(f.where("n_modes", "expected on line " + std::to_string(ln + 1)));
    ln = nm->line + 2;
  }
  int at = ln + 1;
  for (int i = 1; i <= n; ++i) {
    if (i > 1) ++at;  // the blank line after the mass matrix
    b.stations.push_back(readStation(rows, at, i));
    at += 14;
  }
  for (std::size_t i = 0; i < b.stations.size(); ++i) {
    const BeamDynStation& s = b.stations[i];
    if (i == 0 && s.eta != 0.0) throw InputError(rows.where(s.line, "station_eta", "the first station must be at 0"));
    if (i > 0 && !(s.eta > b.stations[i - 1].eta))
      throw InputError(rows.where(s.line, "station_eta",
                                  "stations must increase: station " + std::to_string(i + 1) + " at η = " +
                                      std::to_string(s.eta) + " after " + std::to_string(b.stations[i - 1].eta)));
  }
  if (b.stations.back().eta != 1.0)
    throw InputError(rows.where(b.stations.back().line, "station_eta", "the last station must be at 1"));
  return b;
}

BeamDynBlade readBeamDynBlade(const std::filesystem::path& file) {
  std::string text;
  if (!readInputFile(file.string(), text)) throw InputError(file.string() + ": cannot open file");
  return parseBeamDynBlade(text, file);
}

BeamDynInput readBeamDyn(const std::filesystem::path& file, OverrideSet* overrides) {
  const OpenFastLines lines = OpenFastLines::read(file);  // the file opened once: keys and tables
  BeamDynInput in;
  in.source = OpenFastFile::parse(lines.text(), file);
  if (overrides) overrides->applyTo(in.source);
  const OpenFastFile& f = in.source;
  checkOnce(f, {"quadrature", "refine", "member_total", "kp_total", "order_elem", "BldFile", "UsePitchAct"});
  const Rows rows(f, lines);
  in.quadrature = f.getInt("quadrature");
  if (in.quadrature != 1 && in.quadrature != 2)
    throw InputError(f.where("quadrature", "must be 1 (Gauss) or 2 (trapezoidal)"));
  in.refine = f.findIntOr("refine", 1).value_or(1);
  if (in.refine < 1) throw InputError(f.where("refine", "must be at least 1"));
  const int members = rows.count("member_total", 1, limits::kMaxFemElements, "BeamDyn");
  const int kp = rows.count("kp_total", 3, limits::kMaxFemElements, "BeamDyn");
  const int kp_line = rows.entry("kp_total", "BeamDyn").line;
  int sum = 0;
  for (int m = 1; m <= members; ++m) {
    const std::vector<double> v = rows.numbers(kp_line + m, 2, "kp_member", "member number and its key points");
    if (v[0] != m)
      throw InputError(rows.where(kp_line + m, "kp_member", "members must be numbered 1, 2, … in order (BeamDyn)"));
    if (v[1] != std::floor(v[1]) || v[1] < 3 || v[1] > kp)
      throw InputError(
          rows.where(kp_line + m, "kp_member", "member " + std::to_string(m) + ": needs 3 to kp_total key points"));
    in.member_key_points.push_back(static_cast<int>(v[1]));
    sum += static_cast<int>(v[1]);
  }
  // Members share their end key points: Σ kp_member = kp_total + member_total − 1 (BeamDyn_IO.f90,
  // BD_ValidateInputData).
  if (sum != kp + members - 1)
    throw InputError(f.where("kp_total", std::to_string(kp) + " key points, but the members hold " +
                                             std::to_string(sum) +
                                             " (shared ends counted once: " + std::to_string(sum - members + 1) + ")"));
  const int first = kp_line + members + 3;  // after the column-name and unit rows
  for (int k = 0; k < kp; ++k) {
    const std::vector<double> v = rows.numbers(first + k, 4, "kp_xr", "kp_xr kp_yr kp_zr initial_twist");
    BeamDynKeyPoint p;
    p.r = Vec3(v[0], v[1], v[2]);
    p.twist = v[3] * kDeg;
    p.line = first + k;
    if (k > 0 && !(p.r.z() > in.key_points.back().r.z()))
      throw InputError(rows.where(p.line, "kp_zr",
                                  "key points must advance along z_r (towards the tip): " + std::to_string(p.r.z()) +
                                      " after " + std::to_string(in.key_points.back().r.z())));
    in.key_points.push_back(p);
  }
  // Nothing but the mesh section may follow the table: a longer table would shift BeamDyn's reading.
  const std::optional<int> next = lines.nextContentLine(first + kp - 1);
  const OpenFastEntry& order = rows.entry("order_elem", "BeamDyn");
  if (next && *next < order.line - 1)
    throw InputError(rows.where(*next, "kp_total",
                                "is " + std::to_string(kp) + " but line " + std::to_string(*next) +
                                    " is another row (expected the MESH PARAMETER section line)"));
  in.order_elem = f.getInt("order_elem");
  if (in.order_elem < 1) throw InputError(f.where("order_elem", "must be at least 1"));
  Refusals r(f);
  in.UsePitchAct = f.findBool("UsePitchAct").value_or(false);
  r.addIf(in.UsePitchAct, "UsePitchAct", "the pitch actuator of BeamDyn is not modelled");
  throwIfAny(r.take());
  in.blade = readBeamDynBlade(f.getExistingPath("BldFile"));
  return in;
}

}  // namespace whirl::io
