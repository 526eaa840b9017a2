#include "src/io/openfast/aerodyn/aero_support.hpp"

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/io/openfast/refusals.hpp"

namespace whirl::io {
namespace {

std::string wakeModelName(int m) {
  switch (m) {
    case 3: return "OLAF free-vortex wake";
    default: return "unknown wake model";
  }
}

}  // namespace

std::vector<std::string> unsupportedAeroOptions(const FstInput& fst) {
  Refusals r(fst.source);
  const std::string aero = kAeroModules;
  r.addIf(fst.CompAero == 0, "CompAero", "aerodynamics are off in this deck", aero);
  r.addIf(fst.CompAero == 3, "CompAero", "external loads (ExtLoads)", aero);
  r.addIf(fst.CompAero < 0 || fst.CompAero > 3, "CompAero", "unknown aerodynamics module", aero);
  const std::string inflow = "CompInflow = 1 (InflowWind)";
  r.addIf(fst.CompInflow == 0, "CompInflow", "still air", inflow);
  r.addIf(fst.CompInflow == 2, "CompInflow", "inflow from an external code", inflow);
  r.addIf(fst.CompInflow < 0 || fst.CompInflow > 2, "CompInflow", "unknown inflow module", inflow);
  return r.take();
}

std::vector<std::string> unsupportedOptions(const AeroDynInput& ad) {
  Refusals r(ad.source);
  r.addIf(ad.Wake_Mod != 0 && ad.Wake_Mod != 1, ad.wake_key, wakeModelName(ad.Wake_Mod),
          ad.wake_key + " = 0 (no induction) or 1 (BEMT)");
  r.addIf(ad.Buoyancy, "Buoyancy", "buoyancy", "Buoyancy = False");
  r.addIf(ad.CavitCheck, "CavitCheck", "cavitation check", "CavitCheck = False");
  r.addIf(ad.CompAA, "CompAA", "aeroacoustics", "CompAA = False");
  r.addIf(ad.NacelleDrag, "NacelleDrag", "nacelle drag", "NacelleDrag = False");
  r.addIf(ad.SectAvg, "SectAvg", "sector-averaged inflow", "SectAvg = False");
  r.addIf(ad.TFinAero, "TFinAero", "tail-fin aerodynamics", "TFinAero = False");
  r.addIf(ad.AFTabMod < 1 || ad.AFTabMod > 3, "AFTabMod", "not an airfoil-table interpolation method",
          "AFTabMod = 1 (the first table of each airfoil file), 2 (tables on the Reynolds number) or 3 (tables on "
          "UserProp, taken at UserProp = 0)");
  r.addIf(ad.skew == SkewModel::Coupled, "SkewMod", "the coupled skewed-wake model (dropped in OpenFAST v4)",
          "SkewMod = 0, 1 or 2");
  return r.take();
}

namespace {

constexpr const char* kUnsteadyAirfoilReason =
    "unsteady airfoil aerodynamics: whirl uses the static airfoil tables, the steady state of the "
    "unsteady-airfoil model, whose states are not in the linear model";
constexpr const char* kDynamicInflowReason =
    "dynamic BEMT: whirl solves the quasi-steady BEMT, the steady state of DBEMT's "
    "inflow states, which are not in the linear model";

}  // namespace

bool isUnsteadyAirfoilNote(const std::string& note) { return note.find(kUnsteadyAirfoilReason) != std::string::npos; }

bool isDynamicInflowNote(const std::string& note) { return note.find(kDynamicInflowReason) != std::string::npos; }

std::vector<std::string> steadySubstitutes(const AeroDynInput& ad) {
  std::vector<std::string> notes;
  const OpenFastFile& f = ad.source;
  auto note = [&](bool on, const std::string& key, const std::string& what) {
    if (!on) return;
    const OpenFastEntry* e = f.find(key);
    notes.push_back(f.where(key, (e ? e->raw : std::string("?")) + ": " + what));
  };
  const bool legacy_dbemt = ad.dbemt_key == "WakeMod";  // WakeMod = 2: reported on WakeMod itself
  const std::string dbemt = kDynamicInflowReason;
  note(legacy_dbemt, "WakeMod", dbemt);
  note(!legacy_dbemt && ad.Wake_Mod == 1 && ad.DBEMT_Mod > 0, ad.dbemt_key, dbemt);
  note(ad.unsteadyAero(), ad.ua_key, kUnsteadyAirfoilReason);
  note(ad.TwrPotent != 0, "TwrPotent", "tower potential flow left out: the blades see the undisturbed wind");
  note(ad.TwrShadow != 0, "TwrShadow", "tower shadow left out: the blades see the undisturbed wind");
  note(ad.TwrAero, "TwrAero", "aerodynamic drag on the tower left out");
  return notes;
}

namespace {

const char* windTypeName(int type) {
  static const char* names[] = {"",
                                "steady",
                                "uniform wind file",
                                "TurbSim full field",
                                "Bladed-style full field",
                                "HAWC full field",
                                "user-defined wind",
                                "native Bladed full field"};
  return type >= 1 && type <= 7 ? names[type] : nullptr;
}

}  // namespace

std::vector<std::string> unsupportedOptions(const InflowWindInput& wind) {
  Refusals r(wind.source);
  r.addIf(!windTypeName(wind.WindType), "WindType", "unknown wind type", "WindType = 1 to 7");
  return r.take();
}

std::vector<std::string> steadySubstitutes(const InflowWindInput& wind) {
  if (wind.WindType == 1 || !windTypeName(wind.WindType)) return {};
  const OpenFastFile& f = wind.source;
  const std::string speed = fmt::format("{:g} m/s", wind.HWindSpeed);
  return {f.where("WindType", fmt::format("{}: {} wind: whirl linearizes in the steady wind of the file's "
                                          "steady-wind section, HWindSpeed = {}{} at RefHt = {:g} m with PLExp = "
                                          "{:g} (--wind or --set HWindSpeed=… for another speed)",
                                          wind.WindType, windTypeName(wind.WindType), speed,
                                          wind.HWindSpeed == 0 ? " (still air)" : "", wind.RefHt, wind.PLExp))};
}

void requireSupported(const AeroDynInput& ad) { throwIfAny(unsupportedOptions(ad)); }
void requireSupported(const InflowWindInput& wind) { throwIfAny(unsupportedOptions(wind)); }

}  // namespace whirl::io
