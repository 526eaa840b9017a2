#include "src/turbine/elastodyn_fem_shapes.hpp"

#include <cmath>
#include <numbers>

#include "src/shapes/interpolate.hpp"

namespace whirl {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// Rigid parts summed about one origin: mass, first moment, inertia about the origin.
struct RigidSum {
  double m = 0;
  Vec3 s = Vec3::Zero();
  Mat3 J = Mat3::Zero();
  // A part of mass m with centre of mass at p and inertia Jc about it.
  void add(double m_, const Vec3& p, const Mat3& Jc) {
    m += m_;
    s += m_ * p;
    J += Jc + m_ * (p.squaredNorm() * Mat3::Identity() - p * p.transpose());
  }
  Vec3 cm() const { return m > 0 ? Vec3(s / m) : Vec3::Zero(); }
  Mat3 aboutCm() const {
    const Vec3 c = cm();
    return J - m * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  }
};

// ∫ f(r) m(r) dr over the blade by the trapezoid rule on a fine grid [kg · unit of f].
template <class F>
double bladeIntegral(const BeamProperties& p, F&& f) {
  const int n = 2000;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const double r = p.length * i / n, w = (i == 0 || i == n) ? 0.5 : 1.0;
    s += w * f(r) * interpolateStations(p.x, p.m, r);
  }
  return s * p.length / n;
}

std::vector<ShapePtr> ordered(const std::vector<fem::BeamMode>& modes, const std::vector<std::pair<char, int>>& order,
                              const std::vector<std::string>& names, std::vector<double>* freq) {
  std::vector<ShapePtr> out;
  if (freq) freq->clear();
  for (std::size_t k = 0; k < order.size(); ++k)
    for (const fem::BeamMode& b : modes)
      if (b.direction == order[k].first && b.index == order[k].second) {
        out.push_back(tableShape(names[k], b.table));
        if (freq) freq->push_back(b.freq_hz);
      }
  return out;
}

}  // namespace

fem::ModeShapeInput elastoDynTowerModeInput(const io::ElastoDynInput& ed, const BeamProperties& props, double gravity,
                                            bool top_inertia) {
  const io::ElastoDynConfiguration& c = ed.config;
  const io::ElastoDynMassInertia& mi = ed.mass;
  // Ground axes at the tower top (X downwind, Y left, Z up), zero yaw; ElastoDyn's positions.
  RigidSum top;
  top.add(mi.YawBrMass, Vec3::Zero(), Mat3::Zero());
  const Vec3 nac(c.NacCMxn, c.NacCMyn, c.NacCMzn);
  const double Jyaw = std::max(0.0, mi.NacYIner - mi.NacMass * (nac(0) * nac(0) + nac(1) * nac(1)));
  top.add(mi.NacMass, nac, Mat3(Vec3(0, 0, Jyaw).asDiagonal()));
  const double tilt = c.ShftTilt * deg;
  const Vec3 c1(std::cos(tilt), 0, std::sin(tilt));  // shaft axis (elastodyn_nacelle.cpp)
  const Vec3 apex = Vec3(0, 0, c.Twr2Shft) + c.OverHang * c1;
  top.add(mi.HubMass, apex + c.HubCM * c1, mi.HubIner * c1 * c1.transpose());
  // Blades: the rotor averaged over the azimuth (N ≥ 3 equal blades are axisymmetric in inertia):
  // polar ∫ m ρ² about the shaft, ½ of it about any axis ⟂ the shaft, plus the coning offset along it.
  RigidSum rotor;  // about the apex, shaft axes (1 = along c1)
  for (std::size_t k = 0; k < ed.blades.size() && k < 3; ++k) {
    if (k >= static_cast<std::size_t>(c.NumBl)) break;
    const io::ElastoDynBlade& bf = ed.blades[k];
    BeamProperties p;
    p.length = c.TipRad - c.HubRad;
    p.x = VecX::Zero(static_cast<Eigen::Index>(bf.distributed.column("BlFract").size()));
    p.m = p.x;
    for (Eigen::Index i = 0; i < p.x.size(); ++i) {
      p.x(i) = bf.distributed.column("BlFract")[static_cast<std::size_t>(i)] * p.length;
      p.m(i) = bf.distributed.column("BMassDen")[static_cast<std::size_t>(i)] * bf.AdjBlMs;
    }
    const double beta = c.PreCone[k] * deg, cb = std::cos(beta), sb = std::sin(beta), tip = mi.TipMass[k];
    const double R = c.TipRad;
    const double mass = bladeIntegral(p, [](double) { return 1.0; }) + tip;
    const double along = bladeIntegral(p, [&](double r) { return (c.HubRad + r) * sb; }) + tip * R * sb;
    const double polar = bladeIntegral(p, [&](double r) { return std::pow((c.HubRad + r) * cb, 2); }) +
                         tip * R * R * cb * cb;
    const double axial2 = bladeIntegral(p, [&](double r) { return std::pow((c.HubRad + r) * sb, 2); }) +
                          tip * R * R * sb * sb;
    rotor.m += mass;
    rotor.s(0) += along;
    rotor.J(0, 0) += polar;
    rotor.J(1, 1) += 0.5 * polar + axial2;
    rotor.J(2, 2) += 0.5 * polar + axial2;
  }
  if (rotor.m > 0) {
    // Shaft axes → ground axes: columns c1, Y, c1 × Y.
    Mat3 R;
    R.col(0) = c1;
    R.col(1) = Vec3::UnitY();
    R.col(2) = c1.cross(Vec3::UnitY());
    top.add(rotor.m, apex + R * rotor.cm(), R * rotor.aboutCm() * R.transpose());
  }
  // Ground → tower body axes (x = Z, y = −Y, z = X).
  Mat3 G;
  G.col(0) = Vec3::UnitZ();
  G.col(1) = -Vec3::UnitY();
  G.col(2) = Vec3::UnitX();
  fem::ModeShapeInput in;
  in.props = props;
  in.tip.mass = top.m;
  in.tip.cm = G.transpose() * top.cm();
  if (top_inertia) in.tip.inertia = G.transpose() * top.aboutCm() * G;
  in.axial_gravity = gravity;
  return in;
}

fem::ModeShapeInput elastoDynBladeModeInput(const ElastoDynBladeBeam& blade, double hub_radius, double rotor_speed) {
  fem::ModeShapeInput in;
  in.props = blade.props;
  in.tip.mass = blade.tip_mass;
  in.rotor_speed = rotor_speed;
  in.hub_radius = hub_radius;
  in.rotation_axis = Vec3::UnitY();  // the shaft, out of plane (j1) at zero pitch and cone
  return in;
}

std::vector<ShapePtr> elastoDynTowerFemShapes(const fem::ModeShapeInput& in, std::vector<double>* freq) {
  return ordered(fem::beamModes(in, 2, 2), {{'z', 1}, {'y', 1}, {'z', 2}, {'y', 2}},
                 {"tower FA 1", "tower SS 1", "tower FA 2", "tower SS 2"}, freq);
}

std::vector<ShapePtr> elastoDynBladeFemShapes(const fem::ModeShapeInput& in, std::vector<double>* freq) {
  return ordered(fem::beamModes(in, 2, 1), {{'y', 1}, {'z', 1}, {'y', 2}}, {"flap 1", "edge 1", "flap 2"}, freq);
}

}  // namespace whirl
