// openfast_toolbox's Campbell_OP.csv, Campbell_ModesID.csv, Campbell_PointNN.csv and Campbell_Summary.txt
// (src/writers/openfast_campbell_files.hpp).
#include "src/writers/openfast_campbell_files.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <regex>

#include <fmt/format.h>

#include "src/io/text/csv.hpp"
#include "src/writers/mode_shape_tables.hpp"

namespace whirl {
namespace {

bool byWind(const CampbellDiagram& d) {
  for (const auto& p : d.points)
    if (!p.wind_speed) return false;
  return !d.points.empty();
}

// A name as one unquoted field: the toolbox splits on every comma.
std::string field(std::string s) {
  std::replace(s.begin(), s.end(), ',', ' ');
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

// P empty fields after a row title: the toolbox's `','.join(['']*nOP)` plus the title's comma.
std::string titleRow(const std::string& title, std::size_t points) { return title + std::string(points, ',') + "\n"; }

std::string valueRow(const std::string& title, const std::vector<double>& v) {
  std::string s = title;
  for (double x : v) s += "," + formatNumber(x);
  return s + "\n";
}

std::string ordinal(int k) {
  const int mod100 = k % 100;
  const char* suffix = (mod100 >= 11 && mod100 <= 13) ? "th"
                       : k % 10 == 1                  ? "st"
                       : k % 10 == 2                  ? "nd"
                       : k % 10 == 3                  ? "rd"
                                                      : "th";
  return std::to_string(k) + suffix;
}

// Per coordinate, the mode of the point with the largest magnitude (shape scaled to unit 2-norm).
std::vector<int> modeWithMax(const CampbellPoint& pt) {
  const std::size_t n = pt.coordinates.size();
  std::vector<int> best(n, -1);
  std::vector<double> mag(n, -1);
  for (std::size_t m = 0; m < pt.modes.size(); ++m) {
    const Eigen::VectorXcd& s = pt.modes[m].shape;
    const double norm = s.norm();
    if (!(norm > 0) || static_cast<std::size_t>(s.size()) != n) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = std::abs(s(static_cast<Eigen::Index>(i))) / norm;
      if (a > mag[i]) mag[i] = a, best[i] = static_cast<int>(m);
    }
  }
  return best;
}

// One state row of a mode: description, has-max flag, signed magnitude, phase to the leading coordinate.
struct StateRow {
  std::string description;
  int has_max = 0;
  double magnitude = 0;
  double phase_deg = 0;
};

// campbell_diagram_data_oneOP: coordinates by magnitude (largest first, scaled to 1), the phase to the
// first folded into (−180, 180], then into (−90, 90] with the magnitude's sign flipped.
std::vector<StateRow> stateRows(const CampbellPoint& pt, std::size_t m, const std::vector<int>& with_max) {
  const std::size_t n = pt.coordinates.size();
  const Eigen::VectorXcd& s = pt.modes[m].shape;
  const bool has_shape = static_cast<std::size_t>(s.size()) == n;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto mag = [&](std::size_t i) { return has_shape ? std::abs(s(static_cast<Eigen::Index>(i))) : 0.0; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mag(a) > mag(b); });
  const double top = n > 0 ? mag(order[0]) : 0;
  const double phase0 = n > 0 && has_shape ? phaseDeg(s(static_cast<Eigen::Index>(order[0]))) : 0;
  std::vector<StateRow> rows;
  for (std::size_t i : order) {
    StateRow r;
    r.description = field(pt.coordinates[i]);
    r.has_max = with_max[i] == static_cast<int>(m) ? 1 : 0;
    r.magnitude = top > 0 ? mag(i) / top : 0;
    double d = has_shape && mag(i) > 0 ? std::fmod(phaseDeg(s(static_cast<Eigen::Index>(i))) - phase0 + 720, 360) : 0;
    if (d > 180) d -= 360;
    if (d > 90) r.magnitude = -r.magnitude, d -= 180;
    else if (d <= -90) r.magnitude = -r.magnitude, d += 180;
    r.phase_deg = d;
    rows.push_back(r);
  }
  return rows;
}

std::string summaryLine(const CampbellPoint& pt, std::size_t m, const std::vector<int>& with_max) {
  const Mode& md = pt.modes[m];
  std::string content = md.name + (md.ambiguous ? "?" : "");
  for (std::size_t i = 0; i < pt.coordinates.size(); ++i)
    if (with_max[i] == static_cast<int>(m)) content += " - " + pt.coordinates[i];
  return fmt::format("{:03d} ; {:8.3f} ; {:7.4f} ; {}\n", m + 1, md.freq_hz, md.damping_ratio, content);
}

}  // namespace

std::string campbellToolboxName(const std::string& whirl_name) {
  static const std::regex kRepeat(R"(^(.*?)( \(\d+\))$)");
  std::smatch rep;
  std::string base = whirl_name, suffix;
  if (std::regex_match(whirl_name, rep, kRepeat)) base = rep[1], suffix = rep[2];
  static const std::regex kTower(R"(^tower (FA|SS) (\d+)$)");
  static const std::regex kBlade(R"(^(flap|edge) (\d+) (BW|FW|collective)$)");
  std::smatch m;
  std::string name;
  if (std::regex_match(base, m, kTower)) {
    name = ordinal(std::stoi(m[2])) + " Tower " + m[1].str();
  } else if (std::regex_match(base, m, kBlade)) {
    const std::string kind = m[3] == "BW" ? "Regressive" : m[3] == "FW" ? "Progressive" : "Collective";
    name = ordinal(std::stoi(m[2])) + " Blade " + (m[1] == "flap" ? "Flap" : "Edge") + " (" + kind + ")";
  } else if (base == "drivetrain") {
    name = "1st Drivetrain Torsion";
  } else if (base == "yaw") {
    name = "Nacelle Yaw";
  } else if (base.rfind("platform ", 0) == 0 && base.size() > 9) {
    name = "Platform " + base.substr(9);
  } else {
    return field(whirl_name);
  }
  return field(name + suffix);
}

std::string openfastCampbellOp(const CampbellDiagram& d) {
  std::vector<double> ws, rpm;
  for (const auto& p : d.points) {
    ws.push_back(p.wind_speed ? *p.wind_speed : std::nan(""));
    rpm.push_back(p.rpm);
  }
  return titleRow("Operating Points", d.points.size()) + valueRow("Wind Speed (mps)", ws) +
         valueRow("Rotor Speed (rpm)", rpm);
}

std::string openfastCampbellModesId(const CampbellDiagram& d) {
  const bool wind = byWind(d);
  std::vector<double> op;
  for (const auto& p : d.points) op.push_back(wind ? *p.wind_speed : p.rpm);
  std::string s = titleRow("Mode Number Table", d.points.size()) +
                  valueRow(wind ? "Wind Speed (mps)" : "Rotor Speed (rpm)", op);
  for (const CampbellLine& line : d.lines) {
    s += campbellToolboxName(line.name);
    for (int k : line.mode) s += "," + std::to_string(k + 1);  // −1 (no mode) → 0, the toolbox's "not identified"
    s += "\n";
  }
  return s;
}

std::string openfastCampbellPointName(std::size_t p) { return fmt::format("Campbell_Point{:02d}.csv", p + 1); }

std::string openfastCampbellPoint(const CampbellDiagram& d, std::size_t p) {
  const CampbellPoint& pt = d.points.at(p);
  const std::size_t M = pt.modes.size();
  const std::vector<int> with_max = modeWithMax(pt);
  std::vector<std::vector<StateRow>> rows;
  for (std::size_t m = 0; m < M; ++m) rows.push_back(stateRows(pt, m, with_max));
  // Each group is 5 fields, the last one empty (the toolbox's trailing comma), groups joined by commas.
  const auto row = [&](auto group) {
    std::string s;
    for (std::size_t m = 0; m < M; ++m) s += (m ? "," : "") + group(m) + ",";
    return s + "\n";
  };
  std::string s;
  s += row([&](std::size_t m) { return fmt::format("Mode Number:,{},,", m + 1); });
  s += row(
      [&](std::size_t m) { return "Natural (undamped) frequency (Hz):," + formatNumber(pt.modes[m].freq_hz) + ",,"; });
  s += row([&](std::size_t m) { return "Damped frequency (Hz):," + formatNumber(pt.modes[m].damped_freq_hz) + ",,"; });
  s += row([&](std::size_t m) { return "Damping Ratio (-):," + formatNumber(pt.modes[m].damping_ratio) + ",,"; });
  s += row([&](std::size_t m) {
    return fmt::format(
        "Mode {0} state description,State has max at mode {0},Mode {0} signed magnitude,Mode {0} phase (deg)", m + 1);
  });
  for (std::size_t i = 0; i < pt.coordinates.size(); ++i)
    s += row([&](std::size_t m) {
      const StateRow& r = rows[m][i];
      return r.description + "," + std::to_string(r.has_max) + "," + formatNumber(r.magnitude) + "," +
             formatNumber(r.phase_deg);
    });
  return s;
}

std::string openfastCampbellSummary(const CampbellDiagram& d) {
  const std::string rule = "# -----------------------------------------------------------------------\n";
  std::string s;
  for (std::size_t p = 0; p < d.points.size(); ++p) {
    const CampbellPoint& pt = d.points[p];
    const std::vector<int> with_max = modeWithMax(pt);
    s += rule;
    s += fmt::format("# --- OP {} - WS {:.1f} - RPM {:.2f} \n", p + 1, pt.wind_speed ? *pt.wind_speed : std::nan(""),
                     pt.rpm);
    s += rule;
    s += "# --- \"Selected\" modes\n# ID; Freq [Hz]; Zeta [-]; Mode content\n";
    std::vector<std::size_t> rigid, skipped;
    for (std::size_t m = 0; m < pt.modes.size(); ++m) {
      const double zeta = pt.modes[m].damping_ratio;
      // The toolbox's default posDampRange [1e-5, 0.96]: undamped and overdamped roots aside.
      if (pt.modes[m].rigid_body) rigid.push_back(m);
      else if (zeta > 0.96 || std::abs(zeta) < 1e-5 || std::isnan(zeta)) skipped.push_back(m);
      else s += summaryLine(pt, m, with_max);
    }
    if (!rigid.empty()) {
      s += "# --- Skipped (rigid-body mode)\n";
      for (std::size_t m : rigid) s += summaryLine(pt, m, with_max);
    }
    if (!skipped.empty()) {
      s += "# --- Skipped (Damping outside of `posDampRange`=[1e-05, 0.96])\n";
      for (std::size_t m : skipped) s += summaryLine(pt, m, with_max);
    }
  }
  return s;
}

}  // namespace whirl
