#include "src/fem/element.hpp"

namespace whirl::fem {
namespace {

// Shear-deformable cubic of one bending plane in its own variables (deflection d, rotation r = d'
// when Φ = 0) at nodes 1, 2: N (deflection), dN (d/dx), R (rotation field), each for
// (d1, r1, d2, r2).
struct PlaneFields {
  Eigen::Vector4d N, dN, R;
};

PlaneFields plane(double L, double phi, double xi) {
  const double a = 1.0 / (1.0 + phi), x2 = xi * xi, x3 = x2 * xi;
  PlaneFields f;
  f.N << a * (2 * x3 - 3 * x2 - phi * xi + 1 + phi), a * L * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi),
      a * (-2 * x3 + 3 * x2 + phi * xi), a * L * (x3 - (1 - phi / 2) * x2 - (phi / 2) * xi);
  f.dN << a * (6 * x2 - 6 * xi - phi) / L, a * (3 * x2 - (4 + phi) * xi + 1 + phi / 2),
      a * (-6 * x2 + 6 * xi + phi) / L, a * (3 * x2 - (2 - phi) * xi - phi / 2);
  f.R << 6 * a * (x2 - xi) / L, a * (3 * x2 - (4 + phi) * xi + 1 + phi), -6 * a * (x2 - xi) / L,
      a * (3 * x2 - (2 - phi) * xi);
  return f;
}

Eigen::Matrix4d planeStiffness(double L, double EI, double phi) {
  const double c = EI / ((1 + phi) * L * L * L), L2 = L * L;
  Eigen::Matrix4d k;
  k << 12, 6 * L, -12, 6 * L,                         //
      6 * L, (4 + phi) * L2, -6 * L, (2 - phi) * L2,  //
      -12, -6 * L, 12, -6 * L,                        //
      6 * L, (2 - phi) * L2, -6 * L, (4 + phi) * L2;
  return c * k;
}

// Element DOFs of the two bending planes and the sign of their rotation variable:
// plane y: (v1, θz1, v2, θz2) with r = θ_z; plane z: (w1, θy1, w2, θy2) with r = −θ_y.
constexpr int kPlaneY[4] = {1, 5, 7, 11};
constexpr int kPlaneZ[4] = {2, 4, 8, 10};
constexpr double kSignZ[4] = {1, -1, 1, -1};

}  // namespace

Section lerp(const Section& a, const Section& b, double xi) {
  auto l = [&](double Section::*f) { return (1 - xi) * a.*f + xi * b.*f; };
  Section s;
  s.m = l(&Section::m);
  s.EA = l(&Section::EA);
  s.EIy = l(&Section::EIy);
  s.EIz = l(&Section::EIz);
  s.GJ = l(&Section::GJ);
  s.iy2 = l(&Section::iy2);
  s.iz2 = l(&Section::iz2);
  s.kGAy = l(&Section::kGAy);
  s.kGAz = l(&Section::kGAz);
  return s;
}

ShearParameters shearParameters(double L, const Section& a, const Section& b, bool timoshenko) {
  ShearParameters p;
  if (!timoshenko) return p;
  const Section s = lerp(a, b, 0.5);
  if (s.kGAy > 0) p.y = 12 * s.EIy / (s.kGAy * L * L);
  if (s.kGAz > 0) p.z = 12 * s.EIz / (s.kGAz * L * L);
  return p;
}

ElementFields elementFields(double L, const ShearParameters& phi, double xi) {
  ElementFields f;
  f.u.setZero();
  f.du.setZero();
  f.th.setZero();
  f.u(0, 0) = 1 - xi;
  f.u(0, 6) = xi;
  f.du(0, 0) = -1 / L;
  f.du(0, 6) = 1 / L;
  f.th(0, 3) = 1 - xi;
  f.th(0, 9) = xi;
  const PlaneFields py = plane(L, phi.y, xi), pz = plane(L, phi.z, xi);
  for (int k = 0; k < 4; ++k) {
    f.u(1, kPlaneY[k]) = py.N(k);
    f.du(1, kPlaneY[k]) = py.dN(k);
    f.th(2, kPlaneY[k]) = py.R(k);
    f.u(2, kPlaneZ[k]) = kSignZ[k] * pz.N(k);
    f.du(2, kPlaneZ[k]) = kSignZ[k] * pz.dN(k);
    f.th(1, kPlaneZ[k]) = -kSignZ[k] * pz.R(k);  // θ_y = −r
  }
  return f;
}

Mat12 elementStiffness(double L, const Section& a, const Section& b, const ShearParameters& phi) {
  const Section s = lerp(a, b, 0.5);
  Mat12 K = Mat12::Zero();
  const double ka = s.EA / L, kt = s.GJ / L;
  K(0, 0) = K(6, 6) = ka;
  K(0, 6) = K(6, 0) = -ka;
  K(3, 3) = K(9, 9) = kt;
  K(3, 9) = K(9, 3) = -kt;
  const Eigen::Matrix4d ky = planeStiffness(L, s.EIy, phi.y), kz = planeStiffness(L, s.EIz, phi.z);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      K(kPlaneY[i], kPlaneY[j]) += ky(i, j);
      K(kPlaneZ[i], kPlaneZ[j]) += kSignZ[i] * kSignZ[j] * kz(i, j);
    }
  return K;
}

Mat12 elementGeometricStiffness(double L, const ShearParameters& phi) {
  Mat12 G = Mat12::Zero();
  for (int g = 0; g < 4; ++g) {
    const ElementFields f = elementFields(L, phi, Gauss4::x[g]);
    const double w = Gauss4::w[g] * L;
    G.noalias() += w * (f.du.row(1).transpose() * f.du.row(1) + f.du.row(2).transpose() * f.du.row(2));
  }
  return G;
}

Mat12 elementWinkler(double L, const ShearParameters& phi, const Vec3& k1, const Vec3& k2) {
  Mat12 K = Mat12::Zero();
  for (int g = 0; g < 4; ++g) {
    const double xi = Gauss4::x[g];
    const ElementFields f = elementFields(L, phi, xi);
    const Vec3 k = (1 - xi) * k1 + xi * k2;
    K.noalias() += (Gauss4::w[g] * L) * f.u.transpose() * k.asDiagonal() * f.u;
  }
  return K;
}

}  // namespace whirl::fem
