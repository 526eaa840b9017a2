#include "src/shapes/beam.hpp"

#include "src/shapes/gauss_legendre.hpp"
#include "src/shapes/interpolate.hpp"

#include <algorithm>
#include <cmath>

#include "src/base/error.hpp"
#include "src/base/skew.hpp"

namespace whirl {
namespace {

// Nodes and weights of the chosen quadrature on [0, L].
void quadrature(const BeamProperties& p, const BeamIntegration& q, VecX& x, VecX& w) {
  const double L = p.length;
  switch (q.method) {
    case BeamIntegration::Stations: {
      x = p.x;
      const int n = static_cast<int>(x.size());
      w = VecX::Zero(n);
      for (int i = 0; i + 1 < n; ++i) {
        const double h = x(i + 1) - x(i);
        w(i) += h / 2;
        w(i + 1) += h / 2;
      }
      return;
    }
    case BeamIntegration::Trapezoid: {
      x = VecX::LinSpaced(q.n + 1, 0, L);
      w = VecX::Constant(q.n + 1, L / q.n);
      w(0) /= 2;
      w(q.n) /= 2;
      return;
    }
    case BeamIntegration::Midpoint: {
      x.resize(q.n);
      w = VecX::Constant(q.n, L / q.n);
      for (int i = 0; i < q.n; ++i) x(i) = (i + 0.5) * L / q.n;
      return;
    }
    case BeamIntegration::Gauss: {
      gaussLegendre(q.n, x, w);
      x = (x.array() + 1.0) * (L / 2);
      w *= L / 2;
      return;
    }
  }
}

// The section inertia tensor at x: linear between stations, as the other properties.
Mat3 interpolateInertia(const VecX& x, const std::vector<Mat3>& J, double xi) {
  const Eigen::Index n = x.size();
  Eigen::Index i = 0;
  while (i < n - 2 && xi > x(i + 1)) ++i;
  const double w = std::clamp((xi - x(i)) / (x(i + 1) - x(i)), 0.0, 1.0);
  return (1 - w) * J[static_cast<std::size_t>(i)] + w * J[static_cast<std::size_t>(i) + 1];
}

// The section as a rigid lamina of inertia J about its COG (weight w of the quadrature point), turning
// with the mean line's small rotations θ_i = (t_x, −u_z', u_y') of each shape: a section point at ρ
// from the COG moves by θ_i × ρ. With Σ = ∫ ρ ρᵀ dm = ½ tr(J) 1 − J per length and ∫ ρ dm = 0, the basis
// columns a, b add (A_a Σ A_bᵀ)_jl to S_jl, A_0 = 1 (the rigid section), A_1+i = θ̃_i. The elastic
// mass block Σ_k S_kk then holds θ_iᵀ J θ_j, the section's rotary inertia, and the inertia about the
// body axes tr(S) 1 − S holds J: the gyroscopic and centrifugal terms of the turning sections follow
// from the multibody equations. The pair columns (axial shortening) carry none: second order.
void addSectionLamina(BodyInertia& in, double w, const Mat3& J, const std::vector<ShapeValue>& v) {
  const int ne = in.ne;
  const Mat3 Sigma = w * (0.5 * J.trace() * Mat3::Identity() - J);
  std::vector<Mat3> A(static_cast<std::size_t>(ne) + 1, Mat3::Identity());
  for (int i = 0; i < ne; ++i) A[static_cast<std::size_t>(i) + 1] = skew(Vec3(v[i].tx, -v[i].uz1, v[i].uy1));
  for (int a = 0; a <= ne; ++a)
    for (int b = 0; b <= ne; ++b) {
      const Mat3 B = A[static_cast<std::size_t>(a)] * Sigma * A[static_cast<std::size_t>(b)].transpose();
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l) in.S[3 * j + l](a, b) += B(j, l);
    }
}

int pairIndex(int ne, int i, int j) {  // position of q_i q_j (i <= j) in c
  int p = 1 + ne;
  for (int a = 0; a < ne; ++a)
    for (int b = a; b < ne; ++b, ++p)
      if (a == i && b == j) return p;
  return -1;
}

// Appends the axial-shortening columns −½ G_ii (i = j) and −G_ij (i < j) along x.
void shorteningColumns(Mat3X& P, const MatX& G) {
  const int ne = static_cast<int>(G.rows());
  for (int i = 0; i < ne; ++i)
    for (int j = i; j < ne; ++j) P(0, pairIndex(ne, i, j)) = (i == j ? -0.5 : -1.0) * G(i, j);
}

// The axial motion each shape gives a curved mean line (pre-sweep y0, pre-bend z0), to first order:
// −∫₀ˣ (y0' u_y,i' + z0' u_z,i') dx' (ne). An inextensible curved beam bent by u_i must move along x
// to keep its length; it is how a centrifugal or other axial load straightens a pre-bent blade
// ([Branlard2019, §5.4]: the spun-up pre-bent beam's tip from −0.5 m to about −0.13 m). y0, z0 are
// linear between stations, so each interval adds its slope times the shape's change over it: exact.
// Left out: the cross motion a twist gives the bent part (−∫ t_x z0', ∫ t_x y0'), whose centrifugal
// softening needs the second-order bending–torsion terms to stay consistent.
VecX meanLineAxialMotion(const BeamProperties& p, const std::vector<ShapePtr>& shapes, double x) {
  const int ne = static_cast<int>(shapes.size());
  VecX c = VecX::Zero(ne);
  if (p.y0.size() == 0 && p.z0.size() == 0) return c;
  for (Eigen::Index s = 0; s + 1 < p.x.size() && p.x(s) < x; ++s) {
    const double a = p.x(s), b = std::min(p.x(s + 1), x), h = p.x(s + 1) - p.x(s);
    const double dy = p.y0.size() ? (p.y0(s + 1) - p.y0(s)) / h : 0.0;
    const double dz = p.z0.size() ? (p.z0(s + 1) - p.z0(s)) / h : 0.0;
    if (dy == 0 && dz == 0) continue;
    for (int i = 0; i < ne; ++i) {
      const ShapeValue va = shapes[i]->eval(a), vb = shapes[i]->eval(b);
      c(i) -= dy * (vb.uy - va.uy) + dz * (vb.uz - va.uz);
    }
  }
  return c;
}

}  // namespace

void validateBeam(const BeamProperties& p, const std::string& body) {
  auto where = [&](const std::string& f, const std::string& why) { return "body '" + body + "': " + f + ": " + why; };
  if (!(p.length > 0) || !std::isfinite(p.length)) throw InputError(where("length", "must be positive"));
  const auto n = p.x.size();
  if (n < 2) throw InputError(where("stations", "need at least 2"));
  struct Col {
    const char* name;
    const VecX* v;
    bool required;
  };
  const Col cols[] = {{"m", &p.m, true},      {"EIy", &p.EIy, true},      {"EIz", &p.EIz, true}, {"GKt", &p.GKt, false},
                      {"jG", &p.jG, false},   {"twist", &p.twist, false}, {"y0", &p.y0, false},  {"z0", &p.z0, false},
                      {"cgy", &p.cgy, false}, {"cgz", &p.cgz, false},     {"x", &p.x, true}};
  for (const Col& c : cols) {
    if (c.v->size() == 0 && !c.required) continue;
    if (c.v->size() != n)
      throw InputError(
          where(c.name, "has " + std::to_string(c.v->size()) + " values, stations have " + std::to_string(n)));
    for (Eigen::Index i = 0; i < n; ++i)
      if (!std::isfinite((*c.v)(i)))
        throw InputError(where(c.name, "value " + std::to_string(i + 1) + " is not a finite number"));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (i > 0 && !(p.x(i) > p.x(i - 1))) throw InputError(where("x", "stations must increase"));
    if (p.m(i) < 0) throw InputError(where("m", "negative mass per length at station " + std::to_string(i + 1)));
    if (p.jG.size() && p.jG(i) < 0)
      throw InputError(where("jG", "negative inertia at station " + std::to_string(i + 1)));
    if (!(p.EIy(i) > 0) || !(p.EIz(i) > 0))
      throw InputError(where("EI", "bending stiffness must be positive at station " + std::to_string(i + 1)));
    if (p.GKt.size() && p.GKt(i) < 0) throw InputError(where("GKt", "negative torsional stiffness"));
  }
  if (std::abs(p.x(0)) > 1e-9 * p.length || std::abs(p.x(n - 1) - p.length) > 1e-9 * p.length)
    throw InputError(where("x", "stations must run from 0 to the length"));
  if (!p.J.empty() && static_cast<Eigen::Index>(p.J.size()) != n)
    throw InputError(where("J", "has " + std::to_string(p.J.size()) + " values, stations have " + std::to_string(n)));
  for (std::size_t i = 0; i < p.J.size(); ++i)
    if (!p.J[i].allFinite()) throw InputError(where("J", "value " + std::to_string(i + 1) + " is not finite"));
}

namespace {

// Adds ∫ₐᵇ (u_y,i' u_y,j' + u_z,i' u_z,j') dx to G by composite 4-point Gauss on `panels` equal panels.
void addSlopeProducts(const std::vector<ShapePtr>& shapes, double a, double b, int panels, MatX& G) {
  static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  const int ne = static_cast<int>(shapes.size());
  const double h = (b - a) / panels;
  std::vector<ShapeValue> v(ne);
  for (int p = 0; p < panels; ++p)
    for (int k = 0; k < 4; ++k) {
      const double xi = a + (p + 0.5) * h + 0.5 * h * gx[k];
      for (int i = 0; i < ne; ++i) v[i] = shapes[i]->eval(xi);
      for (int i = 0; i < ne; ++i)
        for (int j = 0; j < ne; ++j) G(i, j) += 0.5 * h * gw[k] * (v[i].uy1 * v[j].uy1 + v[i].uz1 * v[j].uz1);
    }
}

// Panels of the slope-product integral from the root: exact for the polynomial shapes in use.
constexpr int kSlopePanels = 64;

// G(x_k) at every integration point (ascending x), accumulated interval by interval with panels no
// wider than L/64: one pass along the beam rather than an integral from the root per point, which made
// the cost of a beam grow with the square of its point count.
std::vector<MatX> slopeProductIntegrals(const std::vector<ShapePtr>& shapes, const VecX& xs, double L) {
  const int ne = static_cast<int>(shapes.size());
  std::vector<MatX> out;
  out.reserve(xs.size());
  MatX G = MatX::Zero(ne, ne);
  double a = 0;
  for (Eigen::Index k = 0; k < xs.size(); ++k) {
    const double b = std::max(a, xs(k));
    if (b > a) addSlopeProducts(shapes, a, b, std::max(1, static_cast<int>(std::ceil(kSlopePanels * (b - a) / L))), G);
    out.push_back(G);
    a = b;
  }
  return out;
}

}  // namespace

MatX slopeProductIntegral(const std::vector<ShapePtr>& shapes, double x) {
  const int ne = static_cast<int>(shapes.size());
  MatX G = MatX::Zero(ne, ne);
  if (x > 0) addSlopeProducts(shapes, 0, x, kSlopePanels, G);
  return G;
}

BeamBody buildBeamBody(const BeamProperties& p, const std::vector<ShapePtr>& shapes, const BeamOptions& opt,
                       const std::string& body_name) {
  validateBeam(p, body_name);
  const int ne = static_cast<int>(shapes.size());
  BeamBody out;
  BodyInertia& in = out.inertia;
  in.ne = ne;
  in.quadratic = opt.axial_shortening && ne > 0;
  const int nc = in.nc();
  in.m1 = Mat3X::Zero(3, nc);
  for (auto& s : in.S) s = MatX::Zero(nc, nc);
  MatX K = MatX::Zero(ne, ne);

  VecX xs, ws;
  quadrature(p, opt.integration, xs, ws);
  const std::vector<MatX> G = in.quadratic ? slopeProductIntegrals(shapes, xs, p.length) : std::vector<MatX>{};
  std::vector<ShapeValue> v(ne);
  for (Eigen::Index k = 0; k < xs.size(); ++k) {
    const double x = xs(k), w = ws(k);
    const double m = interpolateStations(p.x, p.m, x), jG = interpolateStations(p.x, p.jG, x);
    const double cgy = interpolateStations(p.x, p.cgy, x), cgz = interpolateStations(p.x, p.cgz, x);
    for (int i = 0; i < ne; ++i) v[i] = shapes[i]->eval(x);
    // Position field of the COG line (eq. 30 for the torsion-induced COG motion).
    Mat3X P = Mat3X::Zero(3, nc);
    P.col(0) << x, interpolateStations(p.x, p.y0, x) + cgy, interpolateStations(p.x, p.z0, x) + cgz;
    for (int i = 0; i < ne; ++i) P.col(1 + i) << 0.0, v[i].uy - cgz * v[i].tx, v[i].uz + cgy * v[i].tx;
    if (in.quadratic) {
      P.block(0, 1, 1, ne) = meanLineAxialMotion(p, shapes, x).transpose();
      shorteningColumns(P, G[k]);
    }
    in.mass += w * m;
    in.m1 += w * m * P;
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l) in.S[3 * j + l].noalias() += (w * m) * P.row(j).transpose() * P.row(l);
    // The full section inertia, when given: a rigid lamina turning about all three axes. Otherwise
    // the polar inertia of the section turning with the torsion (eq. 31): section points at (y, z)
    // move by t_x (−z, y); with ∫y² = ∫z² = j_G/2 and ∫yz = 0 per unit length. Thin-beam
    // convention ([Branlard2019, eq. 31], ElastoDyn): sections have rotary inertia about the beam axis
    // only, so S_xx gets −j_G/2, which cancels the j_G/2 of S_yy, S_zz in J_yy and J_zz (the lamina
    // with J = diag(j_G, 0, 0) and the slopes left out).
    if (!p.J.empty()) {
      addSectionLamina(in, w, interpolateInertia(p.x, p.J, x), v);
    } else if (jG > 0) {
      const double h = 0.5 * w * jG;
      in.S[0](0, 0) -= h;
      MatX& Syy = in.S[4];
      MatX& Szz = in.S[8];
      MatX& Syz = in.S[5];
      MatX& Szy = in.S[7];
      Syy(0, 0) += h;
      Szz(0, 0) += h;
      for (int i = 0; i < ne; ++i) {
        Syz(0, 1 + i) += h * v[i].tx;
        Syz(1 + i, 0) -= h * v[i].tx;
        Szy(1 + i, 0) += h * v[i].tx;
        Szy(0, 1 + i) -= h * v[i].tx;
        for (int j = 0; j < ne; ++j) {
          Syy(1 + i, 1 + j) += h * v[i].tx * v[j].tx;
          Szz(1 + i, 1 + j) += h * v[i].tx * v[j].tx;
        }
      }
    }
    // Elastic stiffness (eq. 20): curvatures in the principal axes, rotated by the structural twist.
    const double th = interpolateStations(p.x, p.twist, x), ct = std::cos(th), st = std::sin(th);
    const double EIy = interpolateStations(p.x, p.EIy, x), EIz = interpolateStations(p.x, p.EIz, x),
                 GK = interpolateStations(p.x, p.GKt, x);
    for (int i = 0; i < ne; ++i) {
      const double kyi = ct * v[i].uy2 + st * v[i].uz2, kzi = -st * v[i].uy2 + ct * v[i].uz2;
      for (int j = 0; j < ne; ++j) {
        const double kyj = ct * v[j].uy2 + st * v[j].uz2, kzj = -st * v[j].uy2 + ct * v[j].uz2;
        K(i, j) += w * (EIy * kyi * kyj + EIz * kzi * kzj + GK * v[i].tx1 * v[j].tx1);
      }
    }
  }
  out.elastic.K = 0.5 * (K + K.transpose());
  MatX Mee = MatX::Zero(ne, ne);
  for (int k = 0; k < 3; ++k) Mee += in.S[4 * k].block(1, 1, ne, ne);
  MatX D = MatX::Zero(ne, ne);
  const BeamDamping& d = opt.damping;
  switch (d.kind) {
    case BeamDamping::None: break;
    case BeamDamping::ModalRatio:
      if (static_cast<int>(d.ratio.size()) != ne)
        throw InputError("body '" + body_name + "': damping: one ratio per shape needed (" + std::to_string(ne) + ")");
      for (int i = 0; i < ne; ++i) D(i, i) = 2 * d.ratio[i] * std::sqrt(out.elastic.K(i, i) * Mee(i, i));
      break;
    case BeamDamping::StiffnessProportional: D = d.beta * out.elastic.K; break;
    case BeamDamping::Rayleigh: D = d.alpha * Mee + d.beta * out.elastic.K; break;
  }
  out.elastic.D = D;
  return out;
}

BodyPoint beamPoint(const BeamProperties& p, const std::vector<ShapePtr>& shapes, bool axial_shortening, double x,
                    std::string name) {
  const int ne = static_cast<int>(shapes.size());
  BodyInertia tmp;
  tmp.ne = ne;
  tmp.quadratic = axial_shortening && ne > 0;
  BodyPoint pt;
  pt.name = std::move(name);
  pt.P = Mat3X::Zero(3, tmp.nc());
  pt.theta = Mat3X::Zero(3, ne);
  pt.P.col(0) << x, interpolateStations(p.x, p.y0, x), interpolateStations(p.x, p.z0, x);
  for (int i = 0; i < ne; ++i) {
    const ShapeValue v = shapes[i]->eval(x);
    pt.P.col(1 + i) << 0.0, v.uy, v.uz;
    pt.theta.col(i) << v.tx, -v.uz1, v.uy1;
  }
  if (tmp.quadratic) {
    pt.P.block(0, 1, 1, ne) = meanLineAxialMotion(p, shapes, x).transpose();
    shorteningColumns(pt.P, slopeProductIntegral(shapes, x));
  }
  return pt;
}

std::vector<BodyPoint> beamNodes(const BeamProperties& p, const std::vector<ShapePtr>& shapes, bool axial_shortening,
                                 double length, int count) {
  std::vector<BodyPoint> nodes;
  for (int k = 0; k < count; ++k)
    nodes.push_back(
        beamPoint(p, shapes, axial_shortening, length * k / std::max(count - 1, 1), "node " + std::to_string(k + 1)));
  return nodes;
}

}  // namespace whirl
