// `.lin` writer (FAST_Lin layout) for whirl's state-space models.
#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

#include "src/base/text.hpp"
#include "src/writers/lin_channels.hpp"
#include "src/writers/state_space_files.hpp"

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
           " bending mode DOF (internal DOF index = DOF_T" + (fa ? "FA" : "SS") + m[2].str() + ")";
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
  // The platform's six DOFs as ElastoDyn names them (tests/data/openfast/decks/lin/StandstillSemi_ForID_EDHD.1.lin).
  static const std::map<std::string, std::string> platform = {
      {"platform surge", "Platform horizontal surge translation DOF (internal DOF index = DOF_Sg)"},
      {"platform sway", "Platform horizontal sway translation DOF (internal DOF index = DOF_Sw)"},
      {"platform heave", "Platform vertical heave translation DOF (internal DOF index = DOF_Hv)"},
      {"platform roll", "Platform roll tilt rotation DOF (internal DOF index = DOF_R)"},
      {"platform pitch", "Platform pitch tilt rotation DOF (internal DOF index = DOF_P)"},
      {"platform yaw", "Platform yaw rotation DOF (internal DOF index = DOF_Y)"}};
  if (const auto it = platform.find(name); it != platform.end()) return it->second;
  return "";
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%24.16E", v);
  return buf;
}

std::string flag(int blade) { return blade >= 0 ? "T" : "F"; }

// One row per variable: OpenFAST's columns (FAST_Lin.f90, WrLinFile_txt_Table): index, operating point,
// rotating-frame flag, derivative order, description. `head` is the first column's title, which
// OpenFAST writes as "Row/Column" for states, "Column" for inputs and "Row" for outputs.
void table(std::ostringstream& o, const char* title, const char* head, const std::vector<std::string>& desc,
           const std::vector<double>& op, const std::vector<int>& blade, const std::vector<int>& order) {
  o << title << "\n";
  o << head << " Operating Point          Rotating Frame? Derivative Order Description\n";
  o << "   ---------- ---------------          --------------- ---------------- -----------\n";
  for (size_t i = 0; i < desc.size(); ++i) {
    char row[96];
    std::snprintf(row, sizeof row, "%13zu %s %16s %16d         ", i + 1, number(op[i]).c_str(), flag(blade[i]).c_str(),
                  order[i]);
    o << row << withoutControlCharacters(desc[i]) << "\n";  // a newline would start a fake row
  }
  o << "\n";
}

// "name: rows x cols", then exactly `rows` lines and no empty line: the readers of the field read
// m rows after the size line and stop at an empty line (ROSCO's getMats.readFASTMatrix, OpenFAST's
// ReadFASTLinear), so an empty line inside or between blocks loses B, C and D.
void matrix(std::ostringstream& o, const char* name, const MatX& M) {
  o << name << ": " << M.rows() << " x " << M.cols() << "\n";
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    for (Eigen::Index c = 0; c < M.cols(); ++c) o << " " << number(M(r, c));
    o << "\n";
  }
}

std::string withUnit(const std::string& s, const std::string& unit) { return unit.empty() ? s : s + ", " + unit; }

// The modules OpenFAST would have linked for this model, from its channels: InflowWind and AeroDyn
// with a wind input, ServoDyn with a generator torque law (GenTq), HydroDyn with radiation states.
std::string moduleList(const StateSpaceModel& m) {
  auto has = [](const std::vector<StateSpaceVariable>& v, const std::string& prefix) {
    for (const auto& x : v)
      if (x.name.rfind(prefix, 0) == 0) return true;
    return false;
  };
  std::string s = "ElastoDyn";
  if (has(m.u, "wind speed")) s += "; InflowWind; AeroDyn";
  if (has(m.y, "GenTq")) s += "; ServoDyn";
  if (has(m.x, "HydroDyn")) s += "; HydroDyn";
  return s;
}

// Inputs in OpenFAST's order (InflowWind's wind speed first: ROSCO and ACDC take the first input's
// operating value as the wind speed), stable within a rank.
std::vector<size_t> inputOrder(const std::vector<StateSpaceVariable>& u) {
  std::vector<size_t> order(u.size());
  for (size_t i = 0; i < u.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return linInputChannel(u[a]).rank < linInputChannel(u[b]).rank; });
  return order;
}

// The model as the file writes it: inputs reordered, outputs in OpenFAST's units.
StateSpaceModel inFileUnits(const StateSpaceModel& m, std::vector<std::string>& ud, std::vector<std::string>& yd) {
  StateSpaceModel f = m;
  const std::vector<size_t> order = inputOrder(m.u);
  for (size_t j = 0; j < order.size(); ++j) {
    const auto c = static_cast<Eigen::Index>(j), from = static_cast<Eigen::Index>(order[j]);
    f.u[j] = m.u[order[j]];
    // Blocks of an empty matrix offset Eigen's null data pointer (UBSan; fuzz_writers): a model
    // without states has a 0 × nu B, one without outputs a 0 × nu D.
    if (f.B.rows() > 0) f.B.col(c) = m.B.col(from);
    if (f.D.rows() > 0) f.D.col(c) = m.D.col(from);
    ud.push_back(linInputDescription(f.u[j]));
  }
  for (size_t i = 0; i < m.y.size(); ++i) {
    const double scale = linOutputChannel(m.y[i]).scale;
    const auto r = static_cast<Eigen::Index>(i);
    f.y[i].op *= scale;
    if (f.C.cols() > 0) f.C.row(r) *= scale;
    if (f.D.cols() > 0) f.D.row(r) *= scale;
    yd.push_back(linOutputDescription(m.y[i]));
  }
  return f;
}

std::optional<double> windSpeed(const StateSpaceModel& m) {
  if (m.wind_speed) return m.wind_speed;
  for (const auto& u : m.u)
    if (u.name == "wind speed") return u.op;
  return std::nullopt;
}

}  // namespace

bool elastoDynStates(const std::vector<StateSpaceVariable>& all) {
  const std::vector<bool> first = firstOrderStates(all);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!first[i] && all[i].rate_of < 0 && elastoDynDescription(all[i].name).empty()) return false;
  return true;
}

std::string linStateDescription(const StateSpaceVariable& x, const std::vector<StateSpaceVariable>& all,
                                bool elastodyn) {
  // HydroDyn's radiation states as OpenFAST describes them ("HD RdtnPtfmSg3"), so that the file reads
  // back into the same names (src/io/lin/openfast_lin_names.hpp).
  static const std::regex radiation(R"(^HydroDyn radiation (surge|sway|heave|roll|pitch|yaw) (\d+)$)");
  std::smatch rm;
  if (x.rate_of < 0 && std::regex_match(x.name, rm, radiation)) {
    static const std::map<std::string, std::string> code = {{"surge", "Sg"}, {"sway", "Sw"}, {"heave", "Hv"},
                                                            {"roll", "R"},   {"pitch", "P"}, {"yaw", "Y"}};
    return "HD RdtnPtfm" + code.at(rm[1]) + rm[2].str();
  }
  // The unsteady-airfoil states of a blade element as AeroDyn describes them ("AD x1 blade 2, node 7, rad":
  // tests/data/openfast-lin/ua4-dbemt3/states_inputs.txt); in multiblade coordinates they keep whirl's name.
  static const std::regex airfoil(R"(^UA (x[1-4]) blade (\d+) element (\d+)$)");
  if (x.rate_of < 0 && std::regex_match(x.name, rm, airfoil))
    return withUnit("AD " + rm[1].str() + " blade " + rm[2].str() + ", node " + rm[3].str(), x.unit);
  // The dynamic-inflow states as AeroDyn's DBEMT describes them: v "AD vind (axial) at blade 1, node 2, m/s",
  // Øye's intermediate v1 "AD First time derivative of vind (axial) at blade 1, node 2, m/s/s" (OpenFAST's
  // label and unit, though v1 is a velocity and not v's rate; whirl writes both as first-order states).
  static const std::regex inflow(R"(^DBEMT (v1?) (axial|tangential) blade (\d+) element (\d+)$)");
  if (x.rate_of < 0 && std::regex_match(x.name, rm, inflow)) {
    const bool v1 = rm[1] == "v1";
    return std::string("AD ") + (v1 ? "First time derivative of " : "") + "vind (" + rm[2].str() + ") at blade " +
           rm[3].str() + ", node " + rm[4].str() + (v1 ? ", m/s/s" : ", m/s");
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
  return withUnit(d, x.unit);
}

std::string linFileText(const StateSpaceModel& model, const std::string& title) {
  std::vector<std::string> ud, yd;
  const StateSpaceModel m = inFileUnits(model, ud, yd);
  std::ostringstream o;
  // No time stamp: two runs write the same bytes (issue 48, item 6).
  o << "\nLinearized model: Predictions were generated using whirl " << WHIRL_VERSION
    << ", double precision (exact Jacobians by automatic differentiation)\n linked with  " << moduleList(m) << "\n\n";
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
  field("Wind Speed:", windSpeed(m).value_or(0.0), "m/s");  // OpenFAST writes 0 without InflowWind
  count("Number of continuous states:", m.x.size());
  count("Number of discrete states:", 0);
  count("Number of constraint states:", 0);
  count("Number of inputs:", m.u.size());
  count("Number of outputs:", m.y.size());
  o << "   Jacobians included in this file?    No\n\n";

  std::vector<std::string> xd, xdotd;
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
  for (const auto& v : m.u) uop.push_back(v.op), ub.push_back(v.blade);
  for (const auto& v : m.y) yop.push_back(v.op), yb.push_back(v.blade);
  const std::vector<bool> first = firstOrderStates(m.x);
  std::vector<int> xorder;
  for (bool f : first) xorder.push_back(f ? 1 : 2);
  table(o, "Order of continuous states:", "   Row/Column", xd, xop, xb, xorder);
  table(o, "Order of continuous state derivatives:", "   Row/Column", xdotd, xdotop, xb, xorder);
  if (!m.u.empty()) table(o, "Order of inputs:", "     Column  ", ud, uop, ub, std::vector<int>(m.u.size(), 0));
  if (!m.y.empty()) table(o, "Order of outputs:", "        Row  ", yd, yop, yb, std::vector<int>(m.y.size(), 0));
  o << "\nLinearized state matrices:\n\n";
  matrix(o, "A", m.A);
  if (!m.u.empty()) matrix(o, "B", m.B);
  if (!m.y.empty()) matrix(o, "C", m.C);
  if (!m.y.empty() && !m.u.empty()) matrix(o, "D", m.D);
  return o.str();
}

}  // namespace whirl
