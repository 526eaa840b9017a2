#include "src/aero/rotor_performance.hpp"

namespace whirl::aero {
namespace {

/// NumPy's gradient along the rows (axis 0) with unit spacing and first-order edges.
MatX indexDifferences(const MatX& t) {
  const int n = static_cast<int>(t.rows());
  MatX d(t.rows(), t.cols());
  d.row(0) = t.row(1) - t.row(0);
  d.row(n - 1) = t.row(n - 1) - t.row(n - 2);
  for (int i = 1; i + 1 < n; ++i) d.row(i) = (t.row(i + 1) - t.row(i - 1)) / 2;
  return d;
}

}  // namespace

PerformanceSurface::PerformanceSurface(const std::vector<double>& pitch, const std::vector<double>& tsr, MatX table)
    : pitch_(pitch), tsr_(tsr), table_(std::move(table)) {
  d_tsr_ = indexDifferences(table_);
  d_pitch_ = indexDifferences(table_.transpose()).transpose();
  max_ = table_(0, 0);
  for (Eigen::Index i = 0; i < table_.rows(); ++i)
    for (Eigen::Index j = 0; j < table_.cols(); ++j)
      if (table_(i, j) >= max_) {
        max_ = table_(i, j);
        tsr_opt_ = tsr[i];
        pitch_opt_ = pitch[j];
      }
}

double PerformanceSurface::value(double pitch, double tsr) const {
  return tsr_.weights(tsr).dot(table_ * pitch_.weights(pitch));
}

VecX PerformanceSurface::valuesAtGridPitches(double tsr) const { return table_.transpose() * tsr_.weights(tsr); }

PerformanceSurface::Gradient PerformanceSurface::gradient(double pitch, double tsr) const {
  const VecX wp = pitch_.weights(pitch), wt = tsr_.weights(tsr);
  const std::vector<double>& p = pitch_.knots();
  const std::vector<double>& l = tsr_.knots();
  return {wt.dot(d_pitch_ * wp) / (p[1] - p[0]), wt.dot(d_tsr_ * wp) / (l[1] - l[0])};
}

}  // namespace whirl::aero
