#include "src/io/openfast/aerodyn/airfoil_ua.hpp"

#include <numbers>
#include <string>
#include <vector>

#include "src/base/error.hpp"

namespace whirl::io {
namespace {

std::optional<double> radians(const std::optional<double>& deg) {
  if (!deg) return std::nullopt;
  return *deg * std::numbers::pi / 180.0;
}

/// AeroDyn's ConstData: fewer than 3 rows, or every row equal to the next in every column.
bool constantTable(const AirfoilTable& t) {
  if (t.alpha_deg.size() < 3) return true;
  for (std::size_t k = 0; k + 1 < t.alpha_deg.size(); ++k) {
    if (t.cl[k] != t.cl[k + 1] || t.cd[k] != t.cd[k + 1]) return false;
    if (!t.cm.empty() && t.cm[k] != t.cm[k + 1]) return false;
  }
  return true;
}

}  // namespace

aero::UaGiven uaGiven(const AirfoilUAData& ua) {
  aero::UaGiven g;
  g.alpha0 = radians(ua.alpha0);
  g.alpha1 = radians(ua.alpha1);
  g.alpha2 = radians(ua.alpha2);
  g.alpha_upper = radians(ua.alphaUpper);
  g.alpha_lower = radians(ua.alphaLower);
  g.eta_e = ua.eta_e;
  g.c_nalpha = ua.C_nalpha;
  g.c_lalpha = ua.C_lalpha;
  g.T_f0 = ua.T_f0;
  g.T_V0 = ua.T_V0;
  g.T_p = ua.T_p;
  g.T_VL = ua.T_VL;
  g.b1 = ua.b1;
  g.b2 = ua.b2;
  g.b5 = ua.b5;
  g.A1 = ua.A1;
  g.A2 = ua.A2;
  g.A5 = ua.A5;
  g.S1 = ua.S1;
  g.S2 = ua.S2;
  g.S3 = ua.S3;
  g.S4 = ua.S4;
  g.Cn1 = ua.Cn1;
  g.Cn2 = ua.Cn2;
  g.St_sh = ua.St_sh;
  g.Cd0 = ua.Cd0;
  g.Cm0 = ua.Cm0;
  g.k0 = ua.k0;
  g.k1 = ua.k1;
  g.k2 = ua.k2;
  g.k3 = ua.k3;
  g.k1_hat = ua.k1_hat;
  g.x_cp_bar = ua.x_cp_bar;
  g.ua_cutout = radians(ua.UACutout);
  g.ua_cutout_delta = radians(ua.UACutout_delta);
  g.filt_cutoff = ua.filtCutOff;
  return g;
}

aero::UaTable airfoilUa(const AirfoilInput& af, std::size_t table, int ua_mod) {
  if (table >= af.tables.size())
    throw InputError(whirl::where(af.path.string(), 0, "NumTabs",
                                  "table " + std::to_string(table + 1) + " asked for, the file has " +
                                      std::to_string(af.tables.size())));
  const AirfoilTable& t = af.tables[table];
  const std::string source = af.path.string() + ":" + std::to_string(t.re_line) + ": InclUAdata";
  aero::UaTable out;
  if (constantTable(t)) return out;  // included = false: AeroDyn runs no UA on a constant table
  if (!t.ua.invalid.empty()) throw InputError(t.ua.invalid);  // UA runs on it: AeroDyn's UA_ValidateAFI
  std::vector<double> alpha(t.alpha_deg.size());
  for (std::size_t k = 0; k < alpha.size(); ++k) alpha[k] = t.alpha_deg[k] * std::numbers::pi / 180.0;
  const aero::PolarInterp interp = af.interp_order == 3 ? aero::PolarInterp::CubicSpline : aero::PolarInterp::Linear;
  // InclUAdata false: AeroDyn computes every constant (ReadAFfile sets InclUAdata and all defaults).
  const aero::UaGiven given = t.ua.included ? uaGiven(t.ua) : aero::UaGiven{};
  return aero::uaTable(given, alpha, t.cl, t.cd, t.cm, interp, ua_mod, source);
}

}  // namespace whirl::io
