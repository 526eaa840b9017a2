#include "src/fem/blade6_body.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "src/aero/not_a_knot_spline.hpp"
#include "src/base/error.hpp"
#include "src/base/limits.hpp"

namespace whirl::fem {
namespace {

// The reference axis x_r(z), y_r(z) and the initial twist(z) through the key points: a not-a-knot
// cubic spline in z_r (BeamDyn fits a spline per member; with 3 key points, a parabola through them).
class Axis {
 public:
  explicit Axis(const Blade6Input& in) {
    const Vec3 r0 = in.key_points.front().r;
    for (const Blade6KeyPoint& k : in.key_points) {
      z_.push_back(k.r.z() - r0.z());
      x_.push_back(k.r.x() - r0.x());
      y_.push_back(k.r.y() - r0.y());
      t_.push_back(k.twist);
    }
    if (z_.size() >= 4) spline_.emplace(z_);
  }
  double length() const { return z_.back(); }
  /// Position (x_r, y_r, z_r) and twist [rad] at z.
  Vec3 position(double z) const { return Vec3(eval(x_, z), eval(y_, z), z); }
  double twist(double z) const { return eval(t_, z); }
  Vec3 tangent(double z) const {
    const double h = 1e-6 * length();
    const double a = std::max(0.0, z - h), b = std::min(length(), z + h);
    return (position(b) - position(a)).normalized();
  }

 private:
  double eval(const std::vector<double>& v, double z) const {
    if (spline_) {
      const VecX w = spline_->weights(z);
      double s = 0;
      for (Eigen::Index i = 0; i < w.size(); ++i) s += w(i) * v[static_cast<std::size_t>(i)];
      return s;
    }
    // Three key points: the parabola through them (Lagrange).
    double s = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      double l = 1;
      for (std::size_t j = 0; j < 3; ++j)
        if (j != i) l *= (z - z_[j]) / (z_[i] - z_[j]);
      s += l * v[i];
    }
    return s;
  }
  std::vector<double> z_, x_, y_, t_;
  std::optional<aero::NotAKnotSpline> spline_;
};

// BeamDyn's section axes at the axis point with tangent e3 and twist θ (blade-root frame, columns e1,
// e2, e3): e1 ⟂ e3 with no y_r component, e2 = e3 × e1, then turned by −θ about e3
// (BeamDyn_Subs.f90, BD_ComputeIniNodalCrv; BeamDyn_IO.f90 stores −initial_twist).
Mat3 sectionAxes(const Vec3& e3, double twist) {
  Vec3 e1;
  e1.z() = -e3.x() / std::sqrt(e3.x() * e3.x() + e3.z() * e3.z());
  e1.x() = std::sqrt(1.0 - e1.z() * e1.z());
  e1.y() = 0;
  Mat3 R;
  R.col(0) = e1;
  R.col(1) = e3.cross(e1);
  R.col(2) = e3;
  return Eigen::AngleAxisd(-twist, e3).toRotationMatrix() * R;
}

// Blade-root frame → body frame: body (x, y, z) = (z_r, x_r, y_r).
Mat3 rootToBody() {
  Mat3 P;
  P << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  return P;
}

// The station matrices at η (linear between stations, as BeamDyn), section frame.
Section6 stationAt(const Blade6Input& b, double eta) {
  const auto& s = b.stations;
  std::size_t i = 1;
  while (i + 1 < s.size() && s[i].eta < eta) ++i;
  const double t = std::clamp((eta - s[i - 1].eta) / (s[i].eta - s[i - 1].eta), 0.0, 1.0);
  Section6 a, c;
  a.C = s[i - 1].K;
  a.M = s[i - 1].M;
  c.C = s[i].K;
  c.M = s[i].M;
  Section6 out = lerp6(a, c, t);
  // Stiffness-proportional damping: resultants diag(μ) C ε̇ (BeamDyn, BD_DissipativeForce).
  Eigen::Matrix<double, 6, 1> mu;
  for (int k = 0; k < 6; ++k) mu(k) = b.mu[static_cast<std::size_t>(k)];
  out.D = mu.asDiagonal() * out.C;
  return out;
}

const char* familyName(int f) {
  static const char* names[4] = {"axial", "torsion", "flap", "edge"};
  return names[f];
}

}  // namespace

Beam6Model blade6Model(const Blade6Input& in, int elements) {
  if (elements < 2 || elements > limits::kMaxFemElements)
    throw InputError("blade_elements: must be between 2 and " + std::to_string(limits::kMaxFemElements));
  const Axis axis(in);
  const double L = axis.length();
  // Arc length along the axis (fine chords), for η.
  const int fine = 20 * elements;
  std::vector<double> arc(static_cast<std::size_t>(fine) + 1, 0.0);
  for (int k = 1; k <= fine; ++k)
    arc[static_cast<std::size_t>(k)] = arc[static_cast<std::size_t>(k) - 1] +
                                       (axis.position(L * k / fine) - axis.position(L * (k - 1) / fine)).norm();
  const Mat3 P = rootToBody();
  Beam6Model m;
  std::vector<Section6> sections;
  for (int k = 0; k <= elements; ++k) {
    const double z = L * k / elements;
    m.nodes.push_back(P * axis.position(z));
    const double eta = arc[static_cast<std::size_t>(20 * k)] / arc.back();
    sections.push_back(rotated(stationAt(in, eta), P * sectionAxes(axis.tangent(z), axis.twist(z))));
  }
  for (int k = 0; k < elements; ++k)
    m.elements.push_back({k, k + 1, sections[static_cast<std::size_t>(k)], sections[static_cast<std::size_t>(k) + 1]});
  return m;
}

Blade6Body blade6Body(const Blade6Input& in, const Blade6Options& opt) {
  if (opt.modes < 1 || opt.modes > 6 * opt.elements)
    throw InputError("blade_modes: must be between 1 and 6 × blade_elements");
  Blade6Body out;
  out.model = blade6Model(in, opt.elements);
  const Beam6Model& m = out.model;
  const Beam6Matrices mats = assemble6(m);
  // Axial modes are skipped: the blade body's shapes carry u_y, u_z and θ_x only (the span motion
  // comes from the axial shortening), so an axial mode would be a stiffness without inertia.
  const Modes6 modes = clampedModes6(mats, 0, std::min(opt.modes + 12, 6 * opt.elements));
  const int nn = static_cast<int>(m.nodes.size());
  out.length = m.nodes.back().x();

  // Spanwise properties at the nodes, body frame.
  BeamProperties& p = out.props;
  p.length = out.length;
  p.x.resize(nn);
  p.m = p.EIy = p.EIz = p.GKt = p.jG = p.y0 = p.z0 = p.cgy = p.cgz = VecX::Zero(nn);
  for (int i = 0; i < nn; ++i) {
    const Section6& s = i < nn - 1 ? m.elements[static_cast<std::size_t>(i)].s1 : m.elements.back().s2;
    const SectionMass sm = sectionMass(s.M);
    p.x(i) = m.nodes[static_cast<std::size_t>(i)].x();
    p.y0(i) = m.nodes[static_cast<std::size_t>(i)].y();
    p.z0(i) = m.nodes[static_cast<std::size_t>(i)].z();
    p.m(i) = sm.m;
    p.cgy(i) = sm.c.y();
    p.cgz(i) = sm.c.z();
    p.jG(i) = std::max(0.0, sm.J_cm(0, 0));
    p.J.push_back(sm.J_cm);  // the whole rotational block: flap and edge rotary inertia too
    p.EIy(i) = s.C(5, 5);    // deflection along y: curvature about z
    p.EIz(i) = s.C(4, 4);
    p.GKt(i) = s.C(3, 3);
  }
  p.x(0) = 0;
  p.x(nn - 1) = out.length;

  // Each mode: named after its family, scaled to a largest |u_y|, |u_z| [m] or |θ_x| [rad] of +1.
  const int ne = opt.modes;
  MatX Phi(m.ndof(), ne);
  int count[4] = {0, 0, 0, 0};
  int kept = 0;
  for (int k = 0; k < modes.omega2.size() && kept < ne; ++k) {
    VecX v = modes.vectors.col(k);
    const VecX Mv = mats.M * v;
    double fam[4] = {0, 0, 0, 0};
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      const int kind = static_cast<int>(i % 6);
      fam[kind == 0 ? 0 : kind == 3 ? 1 : (kind == 1 || kind == 5) ? 2 : 3] += v(i) * Mv(i);
    }
    int f = 0;
    for (int j = 1; j < 4; ++j)
      if (fam[j] > fam[f]) f = j;
    if (f == 0) continue;  // axial
    double big = 0;
    for (int i = 0; i < nn; ++i)
      for (int c : {1, 2, 3})
        if (std::abs(v(6 * i + c)) > std::abs(big)) big = v(6 * i + c);
    v /= big;
    Phi.col(kept++) = v;
    ShapeTable t;
    t.x = p.x;
    t.uy = t.uz = t.tx = VecX::Zero(nn);
    for (int i = 0; i < nn; ++i) {
      t.uy(i) = v(6 * i + 1);
      t.uz(i) = v(6 * i + 2);
      t.tx(i) = v(6 * i + 3);
    }
    out.shapes.push_back(tableShape(std::string(familyName(f)) + " " + std::to_string(++count[f]), t));
    out.freq_hz.push_back(std::sqrt(std::max(0.0, modes.omega2(k))) / (2 * std::numbers::pi));
  }
  if (kept < ne)
    throw InputError("blade_modes: " + std::to_string(ne) + " bending and torsion modes asked, the blade's " +
                     std::to_string(opt.elements) + " elements give " + std::to_string(kept) +
                     " among their lowest modes; use more blade_elements or fewer blade_modes");
  const MatX K = Phi.transpose() * (mats.K * Phi), D = Phi.transpose() * (mats.D * Phi);
  out.modes = Phi;
  out.K = 0.5 * (K + K.transpose());
  out.D = 0.5 * (D + D.transpose());
  return out;
}

}  // namespace whirl::fem
