#pragma once
/// \file
/// Eigen aliases used across whirl, for double and for a generic scalar T (double or AutoDiff).
#include <Eigen/Dense>

namespace whirl {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using Mat3X = Eigen::Matrix<double, 3, Eigen::Dynamic>;

template <class T>
using Vec3T = Eigen::Matrix<T, 3, 1>;
template <class T>
using Mat3T = Eigen::Matrix<T, 3, 3>;
template <class T>
using VecXT = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template <class T>
using MatXT = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template <class T>
using Mat3XT = Eigen::Matrix<T, 3, Eigen::Dynamic>;

}  // namespace whirl
