// `.lin` writer (FAST_Lin layout) for whirl's state-space models.
#include <cstdio>
#include <ctime>
#include <map>
#include <regex>
#include <sstream>

#include "src/writers/state_space_files.hpp"
#include "src/model/text.hpp"

namespace whirl {
namespace {

std::string ordinal(int k) {
  const char* s = k == 1 ? "st" : k == 2 ? "nd" : k == 3 ? "rd" : "th";
  return std::to_string(k) + s;
}

// ElastoDyn's description of whirl's ElastoDyn-equivalent DOFs (without "ED " and the unit).
std::string elastoDynDescription(const std::string& name) {
  static const std::regex tower(R"(tower (FA|SS) (\d))"), blade(R"(blade (\d+) (flap|edge) (\d))");
  std::smatch m;
  if (std::regex_match(name, m, tower)) {
    const bool fa = m[1] == "FA";
    return ordinal(std::stoi(m[2])) + (fa ? " tower fore-aft" : " tower side-to-side") +
           " bending-mode DOF (internal DOF index = DOF_T" + (fa ? "FA" : "SS") + m[2].str() + ")";
  }
  if (std::regex_match(name, m, blade)) {
    const bool flap = m[2] == "flap";
    return ordinal(std::stoi(m[3])) + (flap ? " flapwise" : " edgewise") + " bending-mode DOF of blade " + m[1].str() +
           " (internal DOF index = DOF_B" + (flap ? "F(" : "E(") + m[1].str() + "," + m[3].str() + "))";
  }
  if (name == "generator azimuth") return "Variable speed generator DOF (internal DOF index = DOF_GeAz)";
  if (name == "drivetrain") return "Drivetrain rotational-flexibility DOF (internal DOF index = DOF_DrTr)";
  if (name == "yaw") return "Nacelle yaw DOF (internal DOF index = DOF_Yaw)";
  if (name == "teeter") return "Hub teetering DOF (internal DOF index = DOF_Teet)";
  return "";
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%24.16E", v);
  return buf;
}

std::string flag(int blade) { return blade >= 0 ? "T" : "F"; }

void table(std::ostringstream& o, const char* title, const std::vector<std::string>& desc,
           const std::vector<double>& op, const std::vector<int>& blade, const std::vector<int>& order) {
  o << title << "\n";
  o << "   Row/Column Operating Point          Rotating Frame? Derivative Order Description\n";
  o << "   ---------- ---------------          --------------- ---------------- -----------\n";
  for (size_t i = 0; i < desc.size(); ++i) {
    char head[96];
    std::snprintf(head, sizeof head, "%13zu %s %16s %16d         ", i + 1, number(op[i]).c_str(),
                  flag(blade[i]).c_str(), order[i]);
    o << head << withoutControlCharacters(desc[i]) << "\n";  // a newline would start a fake row
  }
  o << "\n";
}

void matrix(std::ostringstream& o, const char* name, const MatX& M) {
  o << name << ": " << M.rows() << " x " << M.cols() << "\n";
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    for (Eigen::Index c = 0; c < M.cols(); ++c) o << " " << number(M(r, c));
    o << "\n";
  }
  o << "\n";
}

std::string withUnit(const std::string& s, const std::string& unit, bool parens) {
  if (unit.empty()) return s;
  return s + ", " + (parens ? "(" + unit + ")" : unit);
}

}  // namespace

bool elastoDynStates(const std::vector<StateSpaceVariable>& all) {
  const std::vector<bool> first = firstOrderStates(all);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!first[i] && all[i].rate_of < 0 && elastoDynDescription(all[i].name).empty()) return false;
  return true;
}

std::string linStateDescription(const StateSpaceVariable& x, const std::vector<StateSpaceVariable>& all, bool elastodyn) {
  // HydroDyn's radiation states as OpenFAST describes them ("HD RdtnPtfmSg3"), so that the file reads
  // back into the same names (src/io/openfast_lin_names.hpp).
  static const std::regex radiation(R"(^HydroDyn radiation (surge|sway|heave|roll|pitch|yaw) (\d+)$)");
  std::smatch rm;
  if (x.rate_of < 0 && std::regex_match(x.name, rm, radiation)) {
    static const std::map<std::string, std::string> code = {{"surge", "Sg"}, {"sway", "Sw"}, {"heave", "Hv"},
                                                            {"roll", "R"},   {"pitch", "P"}, {"yaw", "Y"}};
    return "HD RdtnPtfm" + code.at(rm[1]) + rm[2].str();
  }
  const bool rate = x.rate_of >= 0;
  const StateSpaceVariable& base = rate ? all[x.rate_of] : x;
  std::string d = elastodyn ? elastoDynDescription(base.name) : "";
  if (d.empty()) {
    d = "whirl " + base.name;
    if (base.azimuth) d += " (internal DOF index = DOF_GeAz)";  // the rotor azimuth, as OpenFAST marks it
  } else {
    d = "ED " + d;
  }
  if (rate) {
    const std::size_t sp = d.find(' ');
    d = d.substr(0, sp) + " First time derivative of" + d.substr(sp);
  }
  return withUnit(d, x.unit, false);
}

std::string linFileText(const StateSpaceModel& m, const std::string& title) {
  std::ostringstream o;
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%d-%b-%Y at %H:%M:%S", std::localtime(&now));
  o << "\nLinearized model: Predictions were generated on " << date << " using whirl " << WHIRL_VERSION
    << ", double precision\n linked with whirl structural model (exact Jacobians by automatic differentiation; no "
       "aerodynamics)\n\n";
  // A newline in the title could fake a header line ("Rotor Speed: …") for the readers.
  o << "Description from the FAST input file: " << withoutControlCharacters(title) << "\n\n";
  char line[128];
  o << "Simulation information:\n";
  auto field = [&](const char* key, double v, const char* unit) {
    std::snprintf(line, sizeof line, "   %-30s %24.17g %s\n", key, v, unit);  // full precision
    o << line;
  };
  auto count = [&](const char* key, size_t n) {
    std::snprintf(line, sizeof line, "   %-30s %8zu\n", key, n);
    o << line;
  };
  field("Simulation time:", 0.0, "s");
  field("Rotor Speed:", m.rotor_speed, "rad/s");
  field("Azimuth:", m.azimuth, "rad");
  if (m.wind_speed) field("Wind Speed:", *m.wind_speed, "m/s");
  count("Number of continuous states:", m.x.size());
  count("Number of discrete states:", 0);
  count("Number of constraint states:", 0);
  count("Number of inputs:", m.u.size());
  count("Number of outputs:", m.y.size());
  o << "   Jacobians included in this file?    No\n\n";

  std::vector<std::string> xd, xdotd, ud, yd;
  std::vector<double> xop, xdotop, uop, yop;
  std::vector<int> xb, ub, yb;
  const bool ed = elastoDynStates(m.x);
  for (size_t i = 0; i < m.x.size(); ++i) {
    xd.push_back(linStateDescription(m.x[i], m.x, ed));
    xdotd.push_back("First time derivative of " + xd.back() + "/s");
    xop.push_back(m.x[i].op);
    xdotop.push_back(m.xdot_op(static_cast<Eigen::Index>(i)));
    xb.push_back(m.x[i].blade);
  }
  for (const auto& v : m.u) ud.push_back(withUnit("whirl " + v.name, v.unit, false)), uop.push_back(v.op), ub.push_back(v.blade);
  for (const auto& v : m.y) yd.push_back(withUnit("whirl " + v.name, v.unit, true)), yop.push_back(v.op), yb.push_back(v.blade);
  const std::vector<bool> first = firstOrderStates(m.x);
  std::vector<int> xorder;
  for (bool f : first) xorder.push_back(f ? 1 : 2);
  table(o, "Order of continuous states:", xd, xop, xb, xorder);
  table(o, "Order of continuous state derivatives:", xdotd, xdotop, xb, xorder);
  if (!m.u.empty()) table(o, "Order of inputs:", ud, uop, ub, std::vector<int>(m.u.size(), 0));
  if (!m.y.empty()) table(o, "Order of outputs:", yd, yop, yb, std::vector<int>(m.y.size(), 0));
  o << "\nLinearized state matrices:\n\n";
  matrix(o, "A", m.A);
  if (!m.u.empty()) matrix(o, "B", m.B);
  if (!m.y.empty()) matrix(o, "C", m.C);
  if (!m.y.empty() && !m.u.empty()) matrix(o, "D", m.D);
  return o.str();
}

}  // namespace whirl
