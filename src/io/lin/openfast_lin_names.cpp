#include "src/io/lin/openfast_lin_names.hpp"

#include <cctype>
#include <regex>
#include <utility>

namespace whirl {
namespace {

std::string ordinal(const std::string& s) { return s.substr(0, 1); }  // "1st" → "1"

/// HydroDyn's platform states (its state-space models of the radiation memory, SS_Rad, and of the
/// wave excitation, SS_Exctn): "HD RdtnPtfmSg3" → "HydroDyn radiation surge 3".
std::string hydroDynName(const std::string& d) {
  static const std::regex re(R"(^HD (Rdtn|Exctn)Ptfm(Sg|Sw|Hv|R|P|Y)(\d*))");
  std::smatch m;
  if (!std::regex_search(d, m, re)) return "";
  static const std::pair<const char*, const char*> dirs[] = {{"Sg", "surge"}, {"Sw", "sway"}, {"Hv", "heave"},
                                                             {"R", "roll"},   {"P", "pitch"}, {"Y", "yaw"}};
  std::string dir;
  for (const auto& [key, word] : dirs)
    if (m[2] == key) dir = word;
  return std::string("HydroDyn ") + (m[1] == "Rdtn" ? "radiation " : "wave excitation ") + dir +
         (m[3].length() ? " " + m[3].str() : "");
}

}  // namespace

bool isAzimuthLinDescription(const std::string& d) {
  return d.find("Variable speed generator DOF") != std::string::npos || d.find("DOF_GeAz") != std::string::npos;
}

std::string dofNameFromLinDescription(const std::string& d) {
  static const std::regex tower(R"((\d)(?:st|nd|rd|th) tower (fore-aft|side-to-side))", std::regex::icase);
  static const std::regex blade(R"((\d)(?:st|nd|rd|th) (flapwise|edgewise) bending-mode DOF of blade (\d+))",
                                std::regex::icase);
  static const std::regex beamdyn(
      R"(^BD_(\d+) (?:First time derivative of )?finite element node (\d+).*(translational|rotational) displacement in ([XYZ]))");
  // AeroDyn's unsteady-airfoil states: "AD x1 blade 1, node 2, rad" (UnsteadyAero, UA_Mod 4 to 6).
  static const std::regex airfoil(R"(^AD (x[1-5]) blade (\d+), node (\d+))");
  std::smatch m;
  if (std::regex_search(d, m, beamdyn))
    return "blade " + m[1].str() + " BD node " + m[2].str() +
           (m[3] == "translational" ? " translation " : " rotation ") + m[4].str();
  if (const std::string hd = hydroDynName(d); !hd.empty()) return hd;
  if (std::regex_search(d, m, airfoil)) return "UA " + m[1].str() + " blade " + m[2].str() + " element " + m[3].str();
  // AeroDyn's DBEMT states: "AD vind (axial) at blade 1, node 2, m/s" (v) and "AD First time derivative of vind
  // (axial) at blade 1, node 2, m/s/s" (Øye's intermediate state v1, DBEMT_Mod 3).
  static const std::regex inflow(
      R"(^AD (First time derivative of )?vind \((axial|tangential)\) at blade (\d+), node (\d+))");
  if (std::regex_search(d, m, inflow))
    return std::string("DBEMT ") + (m[1].matched ? "v1 " : "v ") + m[2].str() + " blade " + m[3].str() + " element " +
           m[4].str();
  if (std::regex_search(d, m, tower))
    return std::string("tower ") + (m[2].str()[0] == 'f' || m[2].str()[0] == 'F' ? "FA " : "SS ") + ordinal(m[1]);
  if (std::regex_search(d, m, blade))
    return "blade " + m[3].str() + (m[2].str()[0] == 'f' || m[2].str()[0] == 'F' ? " flap " : " edge ") + ordinal(m[1]);
  struct Fixed {
    const char* key;
    const char* name;
  };
  static const Fixed fixed[] = {{"Variable speed generator DOF", "generator azimuth"},
                                {"Drivetrain rotational-flexibility DOF", "drivetrain"},
                                {"Nacelle yaw DOF", "yaw"},
                                {"Rotor-teeter DOF", "teeter"},
                                {"Hub teetering DOF", "teeter"},  // ElastoDyn's own wording
                                {"Platform horizontal surge", "platform surge"},
                                {"Platform horizontal sway", "platform sway"},
                                {"Platform vertical heave", "platform heave"},
                                {"Platform roll tilt", "platform roll"},
                                {"Platform pitch tilt", "platform pitch"},
                                {"Platform yaw rotation", "platform yaw"}};
  for (const Fixed& f : fixed)
    if (d.find(f.key) != std::string::npos) return f.name;
  // Unknown: drop the module prefix ("ED ", "BD_1 ", …) and the "(internal …)" tail.
  std::string s = d;
  const auto sp = s.find(' ');
  if (sp != std::string::npos && sp < 8) s = s.substr(sp + 1);
  const auto par = s.find(" (internal");
  if (par != std::string::npos) s = s.substr(0, par);
  const auto comma = s.rfind(", ");
  if (comma != std::string::npos && s.size() - comma < 10) s = s.substr(0, comma);  // ", m" / ", rad"
  return s;
}

std::string firstOrderGroupFromLinDescription(const std::string& d) {
  std::string s = dofNameFromLinDescription(d);
  // "UA x1 blade 2 element 7" → "UA x1 blade 2", the group whirl's own models give it (uaStateNames).
  if (const std::size_t at = s.find(" element ");
      (s.rfind("UA x", 0) == 0 || s.rfind("DBEMT v", 0) == 0) && at != std::string::npos)
    return s.substr(0, at);
  while (!s.empty() && (std::isdigit(static_cast<unsigned char>(s.back())) || s.back() == ' ')) s.pop_back();
  return s.empty() ? dofNameFromLinDescription(d) : s;
}

}  // namespace whirl
