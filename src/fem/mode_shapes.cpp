#include "src/fem/mode_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/skew.hpp"
#include "src/fem/boundary.hpp"
#include "src/fem/reduction.hpp"
#include "src/shapes/interpolate.hpp"

namespace whirl::fem {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

bool hasTorsion(const BeamProperties& p) {
  return p.GKt.size() && p.jG.size() && p.GKt.maxCoeff() > 0 && p.jG.minCoeff() > 0;
}

// Nodes at every property station (so sections are exactly linear along each element), each station
// interval split into equal elements no longer than L/elements. Merging stations into an equal grid
// instead would leave elements of millimetres next to a station that falls near a grid node: their
// EI/ℓ³ makes K too ill-conditioned for the dense eigensolver.
std::vector<double> nodeStations(const VecX& x, double L, int elements) {
  const double h = L / std::max(1, elements);
  std::vector<double> nodes{x(0)};
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
    const int n = std::max(1, static_cast<int>(std::ceil((x(i + 1) - x(i)) / h - 1e-9)));
    for (int k = 1; k <= n; ++k) nodes.push_back(x(i) + (x(i + 1) - x(i)) * k / n);
  }
  return nodes;
}

// The cantilever on those nodes, principal axes turned by the mid-element twist.
BeamModel cantilever(const ModeShapeInput& in) {
  const BeamProperties& p = in.props;
  BeamStations s;
  s.x = p.x;
  s.m = p.m;
  s.EIy = p.EIy;
  s.EIz = p.EIz;
  // Axial DOFs are held (the axial load is prescribed, not solved): EA only has to pass validate().
  s.EA = VecX::Ones(p.x.size());
  const bool torsion = hasTorsion(p);
  if (torsion) {
    s.GJ = p.GKt;
    s.iy2 = 0.5 * p.jG;  // polar inertia split equally, as for fem_beam bodies (cases/README.md)
    s.iz2 = 0.5 * p.jG;
  }
  BeamModel m = straightBeam(s, nodeStations(p.x, p.length, in.elements), false);
  for (Element& e : m.elements) {
    const double xm = 0.5 * (m.nodes[e.n1](0) + m.nodes[e.n2](0)), tw = interpolateStations(p.x, p.twist, xm);
    e.y_axis = Vec3(0, std::cos(tw), std::sin(tw));
  }
  clamp(m, 0);
  keepOnly(m, {false, true, true, torsion, true, true});
  return m;
}

// Axial force of each element at its midpoint (tension > 0) [N]: centrifugal minus weight carried.
VecX axialLoads(const BeamModel& model, const ModeShapeInput& in) {
  const BeamProperties& p = in.props;
  const double W2 = in.rotor_speed * in.rotor_speed, g = in.axial_gravity, L = p.length;
  // Per unit mass at radius r: Ω² (r_h + r) outward (along +x), g inward (along −x).
  auto load = [&](double x) { return W2 * (in.hub_radius + x) - g; };
  const int ne = static_cast<int>(model.elements.size());
  VecX N(ne);
  double carried = in.tip.mass * (W2 * (in.hub_radius + L + in.tip.cm(0)) - g);  // at the tip
  for (int k = ne - 1; k >= 0; --k) {
    const double x1 = model.nodes[model.elements[k].n1](0), x2 = model.nodes[model.elements[k].n2](0);
    // ∫ m·load over [x, x2] by 4-point Gauss (m linear, load linear: exact).
    auto integral = [&](double a, double b) {
      double s = 0;
      for (int q = 0; q < 4; ++q) {
        const double x = a + (b - a) * Gauss4::x[q];
        s += Gauss4::w[q] * (b - a) * interpolateStations(p.x, p.m, x) * load(x);
      }
      return s;
    };
    const double xm = 0.5 * (x1 + x2);
    N(k) = carried + integral(xm, x2);
    carried += integral(x1, x2);
  }
  return N;
}

// −Ω² ∫ m (u·e)² dx for the in-plane unit direction e ⟂ x and ⟂ the rotation axis. Euler–Bernoulli
// Hermite fields are the same in every plane through x, so the body-frame DOFs interpolate directly.
SpMat inplaneSoftening(const BeamModel& model, const ModeShapeInput& in) {
  Vec3 a = in.rotation_axis;
  a(0) = 0;
  SpMat S(model.ndof(), model.ndof());
  if (in.rotor_speed == 0 || a.norm() == 0) return S;
  const Vec3 e = Vec3::UnitX().cross(a.normalized());
  const double W2 = in.rotor_speed * in.rotor_speed;
  Triplets t;
  for (const Element& el : model.elements) {
    const double L = (model.nodes[el.n2] - model.nodes[el.n1]).norm();
    Mat12 k = Mat12::Zero();
    for (int q = 0; q < 4; ++q) {
      const ElementFields f = elementFields(L, ShearParameters{}, Gauss4::x[q]);
      const double m = lerp(el.s1, el.s2, Gauss4::x[q]).m;
      const Eigen::Matrix<double, 1, 12> ue = e.transpose() * f.u;
      k.noalias() -= (Gauss4::w[q] * L * W2 * m) * ue.transpose() * ue;
    }
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        if (k(i, j) != 0.0)
          t.emplace_back(kNodeDofs * (i < 6 ? el.n1 : el.n2) + i % 6, kNodeDofs * (j < 6 ? el.n1 : el.n2) + j % 6,
                         k(i, j));
  }
  // The tip body's share of the same field.
  const int tip = kNodeDofs * (model.nnodes() - 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.emplace_back(tip + i, tip + j, -W2 * in.tip.mass * e(i) * e(j));
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

// Rigid tip body at the last node: u_cm = u + θ × d, so M = [[m I, −m D], [m D, J + m DᵀD]], D = skew(d).
SpMat tipMass(const BeamModel& model, const TipBody& b) {
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  const Mat3 D = skew(b.cm);
  M.topLeftCorner<3, 3>() = b.mass * Mat3::Identity();
  M.topRightCorner<3, 3>() = -b.mass * D;
  M.bottomLeftCorner<3, 3>() = b.mass * D;
  M.bottomRightCorner<3, 3>() = b.inertia + b.mass * D.transpose() * D;
  Triplets t;
  const int tip = kNodeDofs * (model.nnodes() - 1);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (M(i, j) != 0.0) t.emplace_back(tip + i, tip + j, M(i, j));
  SpMat S(model.ndof(), model.ndof());
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

// Hermite second derivative at ξ ∈ {0, 1} of one element from the nodal values and slopes.
double curvature(double L, double u1, double s1, double u2, double s2, double xi) {
  return (12 * xi - 6) / (L * L) * u1 + (6 * xi - 4) / L * s1 + (-12 * xi + 6) / (L * L) * u2 + (6 * xi - 2) / L * s2;
}

// A mode (full DOF vector) as a table at the nodes, unscaled. Curvatures are discontinuous between
// cubic elements: the mean of the two sides at interior nodes.
ShapeTable modeTable(const BeamModel& model, const VecX& u, bool torsion) {
  const int n = model.nnodes();
  ShapeTable t;
  t.x.resize(n);
  for (VecX* v : {&t.uy, &t.uz, &t.uy1, &t.uz1, &t.uy2, &t.uz2}) *v = VecX::Zero(n);
  if (torsion) t.tx = VecX::Zero(n);
  for (int i = 0; i < n; ++i) {
    const int d = kNodeDofs * i;
    t.x(i) = model.nodes[i](0);
    t.uy(i) = u(d + 1);
    t.uz(i) = u(d + 2);
    t.uy1(i) = u(d + 5);   // θ_z = v'
    t.uz1(i) = -u(d + 4);  // θ_y = −w'
    if (torsion) t.tx(i) = u(d + 3);
  }
  VecX count = VecX::Zero(n);
  for (int i = 0; i + 1 < n; ++i) {
    const double L = t.x(i + 1) - t.x(i);
    for (int end = 0; end < 2; ++end) {
      t.uy2(i + end) += curvature(L, t.uy(i), t.uy1(i), t.uy(i + 1), t.uy1(i + 1), end);
      t.uz2(i + end) += curvature(L, t.uz(i), t.uz1(i), t.uz(i + 1), t.uz1(i + 1), end);
      count(i + end) += 1;
    }
  }
  t.uy2 = t.uy2.cwiseQuotient(count);
  t.uz2 = t.uz2.cwiseQuotient(count);
  return t;
}

void scale(ShapeTable& t, double s) {
  for (VecX* v : {&t.uy, &t.uz, &t.tx, &t.uy1, &t.uz1, &t.uy2, &t.uz2}) *v *= s;
}

}  // namespace

std::vector<BeamMode> beamModes(const ModeShapeInput& in, int count_y, int count_z) {
  validateBeam(in.props, "mode shapes");
  if (count_y < 0 || count_z < 0) throw InputError("mode shapes: negative number of modes");
  if (!(in.tip.mass >= 0) || !in.tip.inertia.allFinite() || !in.tip.cm.allFinite())
    throw InputError("mode shapes: tip body: mass must be ≥ 0, inertia and centre of mass finite");
  const BeamModel model = cantilever(in);
  // Checked on the mesh, not only on `elements`: a property table with many stations adds nodes.
  if (model.elements.size() > static_cast<size_t>(limits::kMaxFemShapeMesh))
    throw InputError("mode shapes: the FE mesh has " + std::to_string(model.elements.size()) +
                     " elements (every property station is a node), more than the " +
                     std::to_string(limits::kMaxFemShapeMesh) +
                     " the dense eigensolver handles in seconds (src/base/limits.hpp)");
  validate(model, "mode shapes");
  const bool torsion = hasTorsion(in.props);
  const Assembly a = assemble(model, false);
  const DofMap map = freeDofs(model);
  const SpMat K = restrictTo(a.K + geometricStiffness(model, axialLoads(model, in)) + inplaneSoftening(model, in), map);
  const SpMat M = restrictTo(a.M + tipMass(model, in.tip), map);
  const GeneralizedModes modes = denseModes(K, M, map.nfree());

  std::vector<BeamMode> out;
  int found_y = 0, found_z = 0;
  // Weights m + mean(m): a massless beam (all mass at the tip) is still classified by its displacements.
  const VecX mass = in.props.m.array() + in.props.m.mean() + 1e-12;
  for (Eigen::Index k = 0; k < modes.omega2.size() && (found_y < count_y || found_z < count_z); ++k) {
    VecX u = VecX::Zero(map.nfull);
    for (int i = 0; i < map.nfree(); ++i) u(map.free[i]) = modes.vectors(i, k);
    // Kinetic-energy shares along y, along z and in torsion decide what the mode is.
    double ey = 0, ez = 0, et = 0;
    for (int i = 0; i < model.nnodes(); ++i) {
      const double x = model.nodes[i](0), mi = interpolateStations(in.props.x, mass, x);
      ey += mi * u(kNodeDofs * i + 1) * u(kNodeDofs * i + 1);
      ez += mi * u(kNodeDofs * i + 2) * u(kNodeDofs * i + 2);
      if (torsion) et += interpolateStations(in.props.x, in.props.jG, x) * std::pow(u(kNodeDofs * i + 3), 2);
    }
    if (et > ey + ez) continue;
    const char dir = ey >= ez ? 'y' : 'z';
    int& found = dir == 'y' ? found_y : found_z;
    if (found >= (dir == 'y' ? count_y : count_z)) continue;
    BeamMode bm;
    bm.direction = dir;
    bm.index = ++found;
    bm.freq_hz = std::sqrt(std::max(0.0, modes.omega2(k))) / (2 * std::numbers::pi);
    bm.table = modeTable(model, u, torsion);
    const double tipval = dir == 'y' ? bm.table.uy(bm.table.x.size() - 1) : bm.table.uz(bm.table.x.size() - 1);
    const double largest = std::max(bm.table.uy.cwiseAbs().maxCoeff(), bm.table.uz.cwiseAbs().maxCoeff());
    // A clamped-free mode moves its tip; only a near-infinite tip body holds it (then no unit-tip scaling).
    if (!(std::abs(tipval) > 1e-9 * largest))
      throw ComputeError("mode shapes: mode " + std::to_string(bm.index) + " along " + dir +
                         " has no tip displacement");
    scale(bm.table, 1.0 / tipval);
    out.push_back(std::move(bm));
  }
  if (found_y < count_y || found_z < count_z)
    throw ComputeError("mode shapes: the FE model has only " + std::to_string(found_y) + " bending modes along y and " +
                       std::to_string(found_z) + " along z");
  for (BeamMode& bm : out)
    bm.shape = tableShape(std::string("FE ") + bm.direction + " " + std::to_string(bm.index), bm.table);
  return out;
}

PolynomialFit fitElastoDynPolynomial(const VecX& xi, const VecX& u) {
  const Eigen::Index n = xi.size();
  if (n < 5 || u.size() != n) throw InputError("polynomial fit: needs at least 5 stations and one value per station");
  // Σ a_k = 1 eliminates a_6: u − ξ⁶ = Σ_{k=2..5} a_k (ξ^k − ξ⁶), an unconstrained least-squares problem.
  Eigen::MatrixXd A(n, 4);
  VecX b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x6 = std::pow(xi(i), 6);
    for (int k = 2; k <= 5; ++k) A(i, k - 2) = std::pow(xi(i), k) - x6;
    b(i) = u(i) - x6;
  }
  const VecX a = A.colPivHouseholderQr().solve(b);
  PolynomialFit f;
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += f.coeffs[k] = a(k);
  f.coeffs[4] = 1 - sum;
  const VecX r = A * a - b;
  f.rms = std::sqrt(r.squaredNorm() / static_cast<double>(n));
  f.max_deviation = r.cwiseAbs().maxCoeff();
  return f;
}

PolynomialFit fitElastoDynPolynomial(const Shape& shape, double L, char dir, int points) {
  VecX xi(points), u(points);
  for (int i = 0; i < points; ++i) {
    xi(i) = static_cast<double>(i) / (points - 1);
    const ShapeValue v = shape.eval(xi(i) * L);
    u(i) = dir == 'y' ? v.uy : v.uz;
  }
  return fitElastoDynPolynomial(xi, u);
}

namespace {
VecX sampled(const Shape& s, double L, int points) {
  VecX v(2 * points);
  for (int i = 0; i < points; ++i) {
    const ShapeValue e = s.eval(L * i / (points - 1));
    v(2 * i) = e.uy;
    v(2 * i + 1) = e.uz;
  }
  return v;
}
}  // namespace

double shapeMac(const Shape& a, const Shape& b, double L, int points) {
  const VecX u = sampled(a, L, points), v = sampled(b, L, points);
  const double d = u.squaredNorm() * v.squaredNorm();
  return d > 0 ? std::pow(u.dot(v), 2) / d : 0.0;
}

double shapeMaxDeviation(const Shape& a, const Shape& b, double L, int points, double b_scale) {
  return (sampled(a, L, points) - b_scale * sampled(b, L, points)).cwiseAbs().maxCoeff();
}

}  // namespace whirl::fem
