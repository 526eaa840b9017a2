// HAWCStab2 .cmb, .amp and .opt files of a Campbell diagram (src/writers/hawcstab2_files.hpp).
#include "src/writers/hawcstab2_files.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "src/writers/mode_shape_tables.hpp"

namespace whirl {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

bool byWind(const CampbellDiagram& d) {
  for (const auto& p : d.points)
    if (!p.wind_speed) return false;
  return !d.points.empty();
}

double operatingValue(const CampbellDiagram& d, const CampbellPoint& p) { return byWind(d) ? *p.wind_speed : p.rpm; }

std::string right(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

const BodyMotion* findRole(const ModeMotion& m, const std::string& role, int blade = -1) {
  for (const BodyMotion& b : m.bodies)
    if (b.role == role && (blade < 0 || b.blade == blade)) return &b;
  return nullptr;
}

}  // namespace

std::string fortranE(double x) {
  if (!std::isfinite(x)) return right(std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf"), 14);
  if (x == 0) return "  0.000000E+00";
  // 0.dddddd × 10^e with the mantissa in [0.1, 1): Fortran's E form.
  int e = static_cast<int>(std::floor(std::log10(std::abs(x)))) + 1;
  double mant = std::abs(x) / std::pow(10.0, e);
  long digits = std::lround(mant * 1e6);
  if (digits >= 1000000) digits /= 10, ++e;
  if (digits < 100000) digits *= 10, --e;
  char buf[64];  // room for any int exponent: no -Wformat-truncation
  std::snprintf(buf, sizeof buf, "%s0.%06ldE%c%02d", x < 0 ? "-" : "", digits, e < 0 ? '-' : '+', std::abs(e));
  return right(buf, 14);
}

std::string hawcstab2Cmb(const CampbellDiagram& d) {
  const std::size_t N = d.lines.size();
  std::string s = byWind(d) ? "  # Wind [m/s]" : "  # Rotor speed [rpm]";
  for (int rep = 0; rep < 3; ++rep)
    for (std::size_t k = 0; k < N; ++k) s += right(std::to_string(k + 1), 14);
  s += "\n";
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    const CampbellPoint& pt = d.points[p];
    std::string f, z, re;
    for (const CampbellLine& line : d.lines) {
      const Mode* m = line.mode[p] >= 0 ? &pt.modes[static_cast<std::size_t>(line.mode[p])] : nullptr;
      f += fortranE(m ? m->damped_freq_hz : kNan);
      z += fortranE(m ? 100 * m->damping_ratio : kNan);
      re += fortranE(m ? -m->damping_ratio * 2 * std::numbers::pi * m->freq_hz : kNan);
    }
    s += fortranE(operatingValue(d, pt)) + f + z + re + "\n";
  }
  return s;
}

Eigen::Matrix<std::complex<double>, 15, 1> hawcstab2Dofs(const ModeMotion& m) {
  Eigen::Matrix<std::complex<double>, 15, 1> v = Eigen::Matrix<std::complex<double>, 15, 1>::Zero();
  // Ground components of a node's translation (0..2) and rotation (3..5).
  const auto ground = [](const BodyMotion& b, Eigen::Index node) {
    Eigen::Matrix<std::complex<double>, 6, 1> g;
    g.head<3>() = b.R.cast<std::complex<double>>() * b.u.row(node).head<3>().transpose();
    g.tail<3>() = b.R.cast<std::complex<double>>() * b.u.row(node).tail<3>().transpose();
    return g;
  };
  if (const BodyMotion* t = findRole(m, "tower"); t && t->u.rows() > 0) {
    const auto g = ground(*t, t->u.rows() - 1);
    v(0) = g(1), v(1) = g(0), v(2) = g(5);  // side-side (ground Y), fore-aft (ground X), yaw (about Z)
  }
  if (const BodyMotion* h = findRole(m, "hub"); h && h->u.rows() > 0) {
    const auto g = ground(*h, 0);
    v(3) = g(1), v(4) = g(2), v(5) = h->u(0, 3);  // lateral, vertical; torsion about the shaft (hub x)
  }
  // Blade tip: edge = body z, flap = body y, torsion = body x rotation (modal/mode_motion.hpp).
  const int cols[3] = {2, 1, 3};
  if (m.collective.rows() > 0) {
    const Eigen::Index tip = m.collective.rows() - 1;
    for (int k = 0; k < 3; ++k) {
      v(6 + 3 * k) = m.collective(tip, cols[k]);
      v(7 + 3 * k) = m.backward(tip, cols[k]);
      v(8 + 3 * k) = m.forward(tip, cols[k]);
    }
  } else if (const BodyMotion* b = findRole(m, "blade", 0); b && b->u.rows() > 0) {
    for (int k = 0; k < 3; ++k) v(6 + 3 * k) = b->u(b->u.rows() - 1, cols[k]);
  }
  return v;
}

std::string hawcstab2Amp(const CampbellDiagram& d) {
  static const char* const kNames[15] = {"TWR x [m]",      "TWR y [m]",     "TWR yaw [rad]", "SFT x [m]",
                                         "SFT y [m]",      "SFT tor [rad]", "Sym edge [m]",  "BW edge [m]",
                                         "FW edge [m]",    "Sym flap [m]",  "BW flap [m]",   "FW flap [m]",
                                         "Sym tors [rad]", "BW tors [rad]", "FW tors [rad]"};
  const std::size_t N = d.lines.size();
  std::string mode_nr = "# Mode number:", col_nr = "# Column num.:",
              names = byWind(d) ? "# Wind speed" : "# Rotor speed";
  for (std::size_t k = 0; k < N; ++k)
    for (int j = 0; j < 30; ++j) {
      mode_nr += right(std::to_string(k + 1), 14);
      col_nr += right(std::to_string(2 + 30 * k + j), 14);
      names += right(j % 2 == 0 ? kNames[j / 2] : "phase [deg]", 14);
    }
  std::string s = "# Modal MAGNITUDE | PHASE of the following DOFs\n# Last node of: tower, shaft, blade1\n";
  s += mode_nr + "\n" + col_nr + "\n" + names + "\n";
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    const CampbellPoint& pt = d.points[p];
    s += fortranE(operatingValue(d, pt));
    for (const CampbellLine& line : d.lines) {
      const Mode* m = line.mode[p] >= 0 ? &pt.modes[static_cast<std::size_t>(line.mode[p])] : nullptr;
      if (!m || m->motion.empty()) {
        for (int j = 0; j < 30; ++j) s += fortranE(kNan);
        continue;
      }
      const auto v = hawcstab2Dofs(m->motion);
      const double largest = v.cwiseAbs().maxCoeff();
      for (int j = 0; j < 15; ++j)
        s += fortranE(largest > 0 ? std::abs(v(j)) / largest : 0.0) + fortranE(phaseDeg(v(j)));
    }
    s += "\n";
  }
  return s;
}

std::string hawcstab2Opt(const CampbellDiagram& d) {
  std::string s =
      right(std::to_string(d.points.size()), 4) +
      " wind speed [m/s]          pitch [deg]     rot. speed [rpm]      aero power [kw]     aero thrust [kn]\n";
  for (const CampbellPoint& p : d.points)
    s += fortranE(p.wind_speed.value_or(0)) + fortranE(p.pitch_deg.value_or(0)) + fortranE(p.rpm) + fortranE(kNan) +
         fortranE(kNan) + "\n";
  return s;
}

}  // namespace whirl
