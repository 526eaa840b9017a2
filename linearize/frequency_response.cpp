#include "linearize/frequency_response.hpp"

#include <cmath>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl {

std::vector<Eigen::MatrixXcd> frequencyResponse(const StateSpaceModel& s, const std::vector<double>& freq_hz) {
  const Eigen::Index n = s.A.rows();
  const Eigen::MatrixXcd A = s.A.cast<std::complex<double>>(), B = s.B.cast<std::complex<double>>();
  const Eigen::MatrixXcd C = s.C.cast<std::complex<double>>(), D = s.D.cast<std::complex<double>>();
  std::vector<Eigen::MatrixXcd> out;
  out.reserve(freq_hz.size());
  for (double f : freq_hz) {
    const std::complex<double> jw(0.0, 2 * std::numbers::pi * f);
    const Eigen::MatrixXcd S = jw * Eigen::MatrixXcd::Identity(n, n) - A;
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(S);
    if (!(lu.rcond() > 1e-15))
      throw ComputeError("frequency response: j·2π·" + std::to_string(f) + " Hz is an eigenvalue of A");
    out.push_back(C * lu.solve(B) + D);
  }
  return out;
}

std::vector<double> logFrequencies(double f0, double f1, int n) {
  if (!(f0 > 0) || !(f1 > f0) || n < 2 || !std::isfinite(f1))
    throw InputError("frequencies: need 0 < F0 < F1 and at least 2 points");
  std::vector<double> f(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) f[static_cast<std::size_t>(k)] = f0 * std::pow(f1 / f0, static_cast<double>(k) / (n - 1));
  return f;
}

}  // namespace whirl
