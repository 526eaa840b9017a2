#include "src/shapes/shape.hpp"

#include <cmath>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl {
namespace {

constexpr double pi = std::numbers::pi;

// A scalar profile f(x) with derivatives, placed along (dy, dz).
class DirectedShape : public Shape {
 public:
  DirectedShape(double dy, double dz) : dy_(dy), dz_(dz) {}
  ShapeValue eval(double x) const override {
    double f, f1, f2;
    profile(x, f, f1, f2);
    ShapeValue v;
    v.uy = dy_ * f;
    v.uy1 = dy_ * f1;
    v.uy2 = dy_ * f2;
    v.uz = dz_ * f;
    v.uz1 = dz_ * f1;
    v.uz2 = dz_ * f2;
    return v;
  }

 protected:
  virtual void profile(double x, double& f, double& f1, double& f2) const = 0;

 private:
  double dy_, dz_;
};

class Polynomial : public DirectedShape {
 public:
  Polynomial(double L, std::vector<double> a, double dy, double dz, double x0)
      : DirectedShape(dy, dz), L_(L), x0_(x0), a_(std::move(a)) {}

 protected:
  void profile(double x, double& f, double& f1, double& f2) const override {
    const double s = (x + x0_) / L_;
    f = f1 = f2 = 0;
    for (size_t k = 0; k < a_.size(); ++k) {
      const double kk = static_cast<double>(k);
      f += a_[k] * (k == 0 ? 1.0 : std::pow(s, kk));
      if (k >= 1) f1 += a_[k] * kk * (k == 1 ? 1.0 : std::pow(s, kk - 1)) / L_;
      if (k >= 2) f2 += a_[k] * kk * (kk - 1) * (k == 2 ? 1.0 : std::pow(s, kk - 2)) / (L_ * L_);
    }
  }

 private:
  double L_, x0_;
  std::vector<double> a_;
};

class OneMinusCos : public DirectedShape {
 public:
  OneMinusCos(double L, double dy, double dz) : DirectedShape(dy, dz), L_(L) {}

 protected:
  void profile(double x, double& f, double& f1, double& f2) const override {
    const double k = pi / (2 * L_);
    f = 1 - std::cos(k * x);
    f1 = k * std::sin(k * x);
    f2 = k * k * std::cos(k * x);
  }

 private:
  double L_;
};

class ClampedTopMass : public DirectedShape {
 public:
  ClampedTopMass(double L, double beta, double dy, double dz) : DirectedShape(dy, dz), L_(L), b_(beta) {
    S_ = std::sinh(b_) + std::sin(b_);
    C_ = std::cosh(b_) + std::cos(b_);
    double f, f1, f2;
    scale_ = 1.0;
    profile(L_, f, f1, f2);
    scale_ = 1.0 / f;
  }

 protected:
  void profile(double x, double& f, double& f1, double& f2) const override {
    const double k = b_ / L_, t = k * x;
    f = S_ * (std::cosh(t) - std::cos(t)) - C_ * (std::sinh(t) - std::sin(t));
    f1 = k * (S_ * (std::sinh(t) + std::sin(t)) - C_ * (std::cosh(t) - std::cos(t)));
    f2 = k * k * (S_ * (std::cosh(t) + std::cos(t)) - C_ * (std::sinh(t) + std::sin(t)));
    f *= scale_;
    f1 *= scale_;
    f2 *= scale_;
  }

 private:
  double L_, b_, S_ = 0, C_ = 0, scale_ = 1;
};

class TorsionSine : public Shape {
 public:
  TorsionSine(double L, int j) : L_(L), b_(pi / 2 + (j - 1) * pi) {}
  ShapeValue eval(double x) const override {
    ShapeValue v;
    v.tx = std::sin(b_ * x / L_);
    v.tx1 = b_ / L_ * std::cos(b_ * x / L_);
    return v;
  }

 private:
  double L_, b_;
};

class Table : public Shape {
 public:
  explicit Table(ShapeTable t) : t_(std::move(t)) {
    const int n = static_cast<int>(t_.x.size());
    auto fill = [&](VecX& v) {
      if (v.size() == 0) v = VecX::Zero(n);
    };
    fill(t_.uy);
    fill(t_.uz);
    fill(t_.tx);
    auto deriv = [&](const VecX& f) {
      VecX d(n);
      for (int i = 0; i < n; ++i) {
        const int a = std::max(0, i - 1), b = std::min(n - 1, i + 1);
        d(i) = (f(b) - f(a)) / (t_.x(b) - t_.x(a));
      }
      return d;
    };
    if (t_.uy1.size() == 0) t_.uy1 = deriv(t_.uy);
    if (t_.uz1.size() == 0) t_.uz1 = deriv(t_.uz);
    if (t_.tx1.size() == 0) t_.tx1 = deriv(t_.tx);
    if (t_.uy2.size() == 0) t_.uy2 = deriv(t_.uy1);
    if (t_.uz2.size() == 0) t_.uz2 = deriv(t_.uz1);
  }
  ShapeValue eval(double x) const override {
    const VecX& X = t_.x;
    const int n = static_cast<int>(X.size());
    int i = 0;
    while (i < n - 2 && x > X(i + 1)) ++i;
    const double w = std::clamp((x - X(i)) / (X(i + 1) - X(i)), 0.0, 1.0);
    auto lerp = [&](const VecX& v) { return (1 - w) * v(i) + w * v(i + 1); };
    ShapeValue v;
    v.uy = lerp(t_.uy);
    v.uz = lerp(t_.uz);
    v.tx = lerp(t_.tx);
    v.uy1 = lerp(t_.uy1);
    v.uz1 = lerp(t_.uz1);
    v.tx1 = lerp(t_.tx1);
    v.uy2 = lerp(t_.uy2);
    v.uz2 = lerp(t_.uz2);
    return v;
  }

 private:
  ShapeTable t_;
};

template <class S, class... A>
ShapePtr make(std::string name, A&&... a) {
  auto s = std::make_shared<S>(std::forward<A>(a)...);
  s->name = std::move(name);
  return s;
}

void checkLength(const std::string& name, double L) {
  if (!(L > 0) || !std::isfinite(L)) throw InputError("shape '" + name + "': beam length must be positive");
}

}  // namespace

ShapePtr polynomialShape(std::string name, double L, std::vector<double> a, double dy, double dz, double x0) {
  checkLength(name, L);
  for (double c : a)
    if (!std::isfinite(c)) throw InputError("shape '" + name + "': polynomial coefficient is not finite");
  if (!std::isfinite(x0)) throw InputError("shape '" + name + "': polynomial offset is not finite");
  return make<Polynomial>(std::move(name), L, std::move(a), dy, dz, x0);
}

ShapePtr oneMinusCosShape(std::string name, double L, double dy, double dz) {
  checkLength(name, L);
  return make<OneMinusCos>(std::move(name), L, dy, dz);
}

double clampedTopMassBeta(int j, double r) {
  auto f = [r](double b) {
    return 1 + std::cosh(b) * std::cos(b) - b * r * (std::sin(b) * std::cosh(b) - std::cos(b) * std::sinh(b));
  };
  // The roots interlace with (2j−1)π/2; scan a bracket around it, then bisect.
  const double guess = (2 * j - 1) * pi / 2;
  double best = guess, bestd = 1e300;
  const int nscan = 4000;
  double a = std::max(1e-6, guess - pi), fa = f(a);
  for (int k = 1; k <= nscan; ++k) {
    const double b = std::max(1e-6, guess - pi) + 2 * pi * k / nscan, fb = f(b);
    if ((fa <= 0) != (fb <= 0)) {
      double lo = a, hi = b, flo = fa;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm <= 0) == (flo <= 0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      const double root = 0.5 * (lo + hi);
      if (std::abs(root - guess) < bestd) {
        bestd = std::abs(root - guess);
        best = root;
      }
    }
    a = b;
    fa = fb;
  }
  if (bestd > pi) throw InputError("clamped_topmass shape: no root found for mode " + std::to_string(j));
  return best;
}

ShapePtr clampedTopMassShape(std::string name, double L, int j, double r, double dy, double dz) {
  checkLength(name, L);
  if (j < 1) throw InputError("shape '" + name + "': mode number must be >= 1");
  if (!(r >= 0)) throw InputError("shape '" + name + "': tip mass ratio must be >= 0");
  return make<ClampedTopMass>(std::move(name), L, clampedTopMassBeta(j, r), dy, dz);
}

ShapePtr torsionSineShape(std::string name, double L, int j) {
  checkLength(name, L);
  if (j < 1) throw InputError("shape '" + name + "': mode number must be >= 1");
  return make<TorsionSine>(std::move(name), L, j);
}

ShapePtr tableShape(std::string name, ShapeTable t) {
  const auto n = t.x.size();
  if (n < 2) throw InputError("shape '" + name + "': a table needs at least 2 stations");
  for (const VecX* v : {&t.uy, &t.uz, &t.tx, &t.uy1, &t.uz1, &t.tx1, &t.uy2, &t.uz2})
    if (v->size() != 0 && v->size() != n) throw InputError("shape '" + name + "': table columns differ in length");
  for (Eigen::Index i = 1; i < n; ++i)
    if (!(t.x(i) > t.x(i - 1))) throw InputError("shape '" + name + "': stations must increase");
  return make<Table>(std::move(name), std::move(t));
}

}  // namespace whirl
