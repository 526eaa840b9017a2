#include "src/turbine/elastodyn_blade_shapes.hpp"

#include "src/shapes/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

VecX column(const io::DistributedTable& t, const char* name, double scale) {
  const std::vector<double>& c = t.column(name);
  VecX v(static_cast<Eigen::Index>(c.size()));
  for (std::size_t i = 0; i < c.size(); ++i) v(static_cast<Eigen::Index>(i)) = scale * c[i];
  return v;
}

// Linear interpolation in a property table (ElastoDyn's InterpStp), clamped at the ends.
// ElastoDyn's SHP: d-th derivative of Σ c_k (r/L)^k, k = 2..6, with respect to r.
double shp(double r, double L, const io::ModeShapeCoeffs& c, int d) {
  const double x = r / L;
  double s = 0;
  for (int i = 0; i < 5; ++i) {
    const int k = i + 2;
    if (d == 0) s += c[i] * std::pow(x, k);
    if (d == 1) s += c[i] * k * std::pow(x, k - 1) / L;
    if (d == 2) s += c[i] * k * (k - 1) * std::pow(x, k - 2) / (L * L);
  }
  return s;
}

// One twisted shape at the root, the n node centres and the tip (ElastoDyn `Coeff`, TwistedSF).
ShapePtr twistedShape(const std::string& name, const io::ModeShapeCoeffs& c, bool flap, const BeamProperties& p,
                      int n) {
  const double L = p.length, dr = L / n;
  ShapeTable t;
  t.x.resize(n + 2);
  for (VecX* v : {&t.uy, &t.uz, &t.uy1, &t.uz1, &t.uy2, &t.uz2}) *v = VecX::Zero(n + 2);
  t.x(0) = 0;
  for (int j = 1; j <= n; ++j) t.x(j) = (j - 0.5) * dr;
  t.x(n + 1) = L;
  // Curvatures: the polynomial curvature about the principal axis, rotated by the structural twist
  // θs = −twist into (j1, j2) = (y, z): flap (cos θs, −sin θs), edge (sin θs, cos θs).
  for (int j = 0; j <= n + 1; ++j) {
    const double ths = -interpolateStations(p.x, p.twist, t.x(j)), k = shp(t.x(j), L, c, 2);
    t.uy2(j) = k * (flap ? std::cos(ths) : std::sin(ths));
    t.uz2(j) = k * (flap ? -std::sin(ths) : std::cos(ths));
  }
  // ElastoDyn's node rule: half an element from the root to node 1, trapezoids between nodes, half an
  // element from node n to the tip; the same rule integrates the slopes into displacements.
  auto integrate = [&](const VecX& f, VecX& F) {
    F(0) = 0;
    F(1) = 0.5 * dr * f(1);
    for (int j = 2; j <= n; ++j) F(j) = F(j - 1) + 0.5 * dr * (f(j - 1) + f(j));
    F(n + 1) = F(n) + 0.5 * dr * f(n);
  };
  integrate(t.uy2, t.uy1);
  integrate(t.uz2, t.uz1);
  integrate(t.uy1, t.uy);
  integrate(t.uz1, t.uz);
  return tableShape(name, std::move(t));
}

}  // namespace

ElastoDynBladeBeam elastoDynBladeBeam(const io::ElastoDynBlade& f, double L, int nodes, double tip_mass) {
  const std::string file = f.source.path().string();
  if (nodes < 1) throw InputError(where(file, 0, "BldNodes", "must be at least 1 (is " + std::to_string(nodes) + ")"));
  if (!(L > 0) || !std::isfinite(L))
    throw InputError(where(file, 0, "TipRad", "blade length TipRad − HubRad must be positive"));
  const io::DistributedTable& d = f.distributed;
  ElastoDynBladeBeam b;
  b.nodes = nodes;
  b.tip_mass = tip_mass;
  BeamProperties& p = b.props;
  p.length = L;
  p.x = column(d, "BlFract", L);
  p.m = column(d, "BMassDen", f.AdjBlMs);
  p.EIy = column(d, "FlpStff", f.AdjFlSt);
  p.EIz = column(d, "EdgStff", f.AdjEdSt);
  p.twist = column(d, "StrcTwst", -deg);
  p.x(p.x.size() - 1) = L;  // BlFract ends at 1 exactly; keep the last station at L despite rounding
  try {
    validateBeam(p, "blade");
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }

  const io::ModeShapeCoeffs* coeffs[3] = {&f.BldFl1Sh, &f.BldEdgSh, &f.BldFl2Sh};
  const char* names[3] = {"flap 1", "edge 1", "flap 2"};
  for (int k = 0; k < 3; ++k) b.shapes.push_back(twistedShape(names[k], *coeffs[k], k != kEdge1, p, nodes));

  // ElastoDyn's printed generalized masses and stiffnesses, from the untwisted polynomials.
  const double dr = L / nodes;
  b.generalized_mass.setConstant(tip_mass);
  for (int j = 1; j <= nodes; ++j) {
    const double r = (j - 0.5) * dr, m = interpolateStations(p.x, p.m, r) * dr;
    const double EI[3] = {interpolateStations(p.x, p.EIy, r) * dr, interpolateStations(p.x, p.EIz, r) * dr,
                          interpolateStations(p.x, p.EIy, r) * dr};
    double k2[3];
    for (int a = 0; a < 3; ++a) {
      b.generalized_mass(a) += m * std::pow(shp(r, L, *coeffs[a], 0), 2);
      k2[a] = shp(r, L, *coeffs[a], 2);
    }
    b.generalized_stiffness(kFlap1, kFlap1) += EI[kFlap1] * k2[kFlap1] * k2[kFlap1];
    b.generalized_stiffness(kFlap1, kFlap2) += EI[kFlap1] * k2[kFlap1] * k2[kFlap2];
    b.generalized_stiffness(kFlap2, kFlap2) += EI[kFlap2] * k2[kFlap2] * k2[kFlap2];
    b.generalized_stiffness(kEdge1, kEdge1) += EI[kEdge1] * k2[kEdge1] * k2[kEdge1];
  }
  b.generalized_stiffness(kFlap2, kFlap1) = b.generalized_stiffness(kFlap1, kFlap2);
  b.stiffness_tuner << f.FlStTunr[0], 1.0, f.FlStTunr[1];
  b.generalized_stiffness = applyStiffnessTuners(b.generalized_stiffness, b.stiffness_tuner);
  b.damping_ratio << 0.01 * f.BldFlDmp[0], 0.01 * f.BldEdDmp, 0.01 * f.BldFlDmp[1];
  return b;
}

MatX applyStiffnessTuners(const MatX& K, const VecX& t) {
  MatX out = K;
  for (Eigen::Index i = 0; i < K.rows(); ++i)
    for (Eigen::Index j = 0; j < K.cols(); ++j) out(i, j) *= std::sqrt(t(i) * t(j));
  return out;
}

MatX elastoDynModalDamping(const MatX& K, const VecX& M, const VecX& zeta) {
  MatX D = MatX::Zero(K.rows(), K.cols());
  for (Eigen::Index l = 0; l < K.cols(); ++l) {
    if (!(K(l, l) > 0) || !(M(l) > 0)) continue;  // no stiffness or mass: ElastoDyn's frequency is undefined
    const double s = 2 * zeta(l) * std::sqrt(M(l) / K(l, l));
    for (Eigen::Index i = 0; i < K.rows(); ++i) D(i, l) = s * K(i, l);
  }
  return D;
}

}  // namespace whirl
