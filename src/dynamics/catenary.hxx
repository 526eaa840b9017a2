#pragma once
/// \file
/// Templates of catenary.hpp: the profile equations of the elastic catenary, free-hanging and with
/// seabed contact [Jonkman2007], and the Newton solve.
#include <cmath>
#include <string>
#include <type_traits>

#include "src/base/error.hpp"
#include "src/dynamics/catenary.hpp"

namespace whirl::detail {

inline double catValue(double x) { return x; }
template <class D>
double catValue(const Eigen::AutoDiffScalar<D>& x) {
  return x.value();
}

/// asinh written with log and sqrt (AD types have no asinh), odd by construction.
template <class S>
S catAsinh(const S& x) {
  using std::log;
  using std::sqrt;
  if (catValue(x) < 0) return -catAsinh<S>(-x);
  return log(x + sqrt(x * x + 1.0));
}

/// (x, z): horizontal and vertical extent of the line, fairlead relative to the anchor, at the
/// fairlead tensions (H, V) [Jonkman2007]. Without seabed contact the line hangs freely between its
/// ends; with contact (anchor on the seabed, V < w L) a length L_B = L − V/w rests on the bottom, and
/// friction CB w holds part of its tension, the first H/(CB w) of it from the touchdown point.
template <class S>
void catenaryProfile(const MooringLine& ln, const S& H, const S& V, S& x, S& z) {
  using std::sqrt;
  const double w = ln.weight, L = ln.length, EA = ln.EA;
  const S vh = V / H;
  const double LB = L - catValue(V) / w;
  if (!ln.seabed || LB <= 0.0) {
    const S vah = (V - w * L) / H;
    x = H / w * (catAsinh(vh) - catAsinh(vah)) + H * L / EA;
    z = H / w * (sqrt(1.0 + vh * vh) - sqrt(1.0 + vah * vah)) + (V * L - 0.5 * w * L * L) / EA;
    return;
  }
  const S lb = L - V / w;
  x = lb + H / w * catAsinh(vh) + H * L / EA;
  if (ln.CB > 0.0) {
    const S slack = lb - H / (ln.CB * w);
    x += ln.CB * w / (2.0 * EA) * (catValue(slack) > 0 ? S(-lb * lb + slack * slack) : S(-lb * lb));
  }
  z = H / w * (sqrt(1.0 + vh * vh) - 1.0) + V * V / (2.0 * EA * w);
}

/// The taut-line residual (q X(q² s, V) − 1, z(q² s, V) − h) of catenary.hpp's tautLineTension.
template <class S>
void tautLineResidual(const MooringLine& ln, const S& q, const S& V, const S& s, const S& h, S& r1, S& r2) {
  using std::log;
  using std::sqrt;
  const double w = ln.weight, L = ln.length, EA = ln.EA;
  const S H2 = q * q * s, Va = V - w * L;
  const S top = sqrt(V * V + H2), bottom = sqrt(Va * Va + H2);
  const S X = log((V + top) / (Va + bottom)) / w + L / EA;
  r1 = q * X - 1.0;
  r2 = (top - bottom) / w + (V * L - 0.5 * w * L * L) / EA - h;
}

/// Newton on (H, V) in double, Jacobian by AD of the profile; returns the converged tensions and J.
struct CatenaryNewton {
  double H = 0, V = 0;
  Eigen::Matrix2d J;
};
CatenaryNewton solveCatenaryNewton(const MooringLine& ln, double l, double h);
/// Newton on (q, V) in double for the taut line (returned as H = q, V) and the Jacobian.
CatenaryNewton solveTautLineNewton(const MooringLine& ln, double s, double h);

}  // namespace whirl::detail

namespace whirl {

template <class T>
CatenaryTension<T> catenaryTension(const MooringLine& ln, const T& l, const T& h) {
  const detail::CatenaryNewton s = detail::solveCatenaryNewton(ln, valueOf(l), valueOf(h));
  if constexpr (std::is_same_v<T, double>) {
    return {s.H, s.V};
  } else {
    // One Newton step in T from the converged point: the residual's value is round-off, its
    // derivatives −∂(l, h), so (H, V) carry J⁻¹ ∂(l, h) — the implicit-function derivative.
    double x, z;
    detail::catenaryProfile<double>(ln, s.H, s.V, x, z);
    const Eigen::Matrix2d Ji = s.J.inverse();
    const T rx = l - x, rz = h - z;
    return {T(s.H) + Ji(0, 0) * rx + Ji(0, 1) * rz, T(s.V) + Ji(1, 0) * rx + Ji(1, 1) * rz};
  }
}

template <class T>
CatenaryTension<T> tautLineTension(const MooringLine& ln, const T& s, const T& h) {
  const detail::CatenaryNewton n = detail::solveTautLineNewton(ln, valueOf(s), valueOf(h));
  if constexpr (std::is_same_v<T, double>) {
    return {n.H, n.V};
  } else {
    // One Newton step in T from the converged point: the implicit-function derivative (as above).
    T r1, r2;
    detail::tautLineResidual<T>(ln, T(n.H), T(n.V), s, h, r1, r2);
    const Eigen::Matrix2d Ji = n.J.inverse();
    return {T(n.H) - Ji(0, 0) * r1 - Ji(0, 1) * r2, T(n.V) - Ji(1, 0) * r1 - Ji(1, 1) * r2};
  }
}

template <class T>
Vec3T<T> mooringFairleadForce(const MooringLine& ln, const Vec3T<T>& d) {
  using std::sqrt;
  const T s = d(0) * d(0) + d(1) * d(1);
  Vec3T<T> F;
  if (valueOf(s) < 1e-6 * ln.length * ln.length) {
    const CatenaryTension<T> t = tautLineTension<T>(ln, s, d(2));  // t.H is q = H / l here
    F << -t.H * d(0), -t.H * d(1), -t.V;
  } else {
    const T l = sqrt(s);
    const CatenaryTension<T> t = catenaryTension<T>(ln, l, d(2));
    F << -t.H * d(0) / l, -t.H * d(1) / l, -t.V;
  }
  return F;
}

}  // namespace whirl
