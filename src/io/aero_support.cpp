#include "src/io/aero_support.hpp"

#include "src/io/refusals.hpp"
#include "src/model/error.hpp"

namespace whirl::io {
namespace {

std::string wakeModelName(int m) {
  switch (m) {
    case 2: return "dynamic BEMT";
    case 3: return "OLAF free-vortex wake";
    default: return "unknown wake model";
  }
}

}  // namespace

std::vector<std::string> unsupportedAeroOptions(const FstInput& fst) {
  Refusals r(fst.source);
  const std::string aero = "CompAero = 2 (AeroDyn v15)";
  r.addIf(fst.CompAero == 0, "CompAero", "aerodynamics are off in this deck", aero);
  r.addIf(fst.CompAero == 1, "CompAero", "AeroDyn v14 (OpenFAST v3) or AeroDisk (v4+)", aero);
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
  const OpenFastFile& f = ad.source;
  const bool legacy_dbemt = ad.dbemt_key == "WakeMod";  // WakeMod = 2: reported on WakeMod itself
  r.addIf(ad.Wake_Mod != 0 && ad.Wake_Mod != 1, ad.wake_key, wakeModelName(ad.Wake_Mod),
          ad.wake_key + " = 0 (no induction) or 1 (BEMT)");
  r.addIf(legacy_dbemt, "WakeMod", "dynamic BEMT", "WakeMod = 0 (no induction) or 1 (BEMT)");
  r.addIf(!legacy_dbemt && ad.Wake_Mod == 1 && ad.DBEMT_Mod > 0, ad.dbemt_key, "dynamic BEMT",
          "DBEMT_Mod = 0 (quasi-steady BEMT) or -1 (frozen wake)");
  if (ad.ua_key == "AFAeroMod")
    r.addIf(ad.unsteadyAero(), "AFAeroMod", "Beddoes-Leishman unsteady airfoil aerodynamics",
            "AFAeroMod = 1 (steady airfoil tables)");
  else
    r.addIf(ad.unsteadyAero(), ad.ua_key, "unsteady airfoil aerodynamics",
            ad.ua_key + " = 0 (quasi-steady airfoil tables)");
  r.addIf(ad.TwrPotent != 0, "TwrPotent", "tower potential flow", "TwrPotent = 0 (no tower influence)");
  const OpenFastEntry* shadow = f.find("TwrShadow");
  const bool shadow_is_flag = shadow && !parseFortranDouble(shadow->raw);  // AeroDyn v15.0x: True/False
  r.addIf(ad.TwrShadow != 0, "TwrShadow", "tower shadow",
          shadow_is_flag ? "TwrShadow = False (no tower shadow)" : "TwrShadow = 0 (no tower shadow)");
  r.addIf(ad.TwrAero, "TwrAero", "tower drag loads", "TwrAero = False");
  r.addIf(ad.Buoyancy, "Buoyancy", "buoyancy", "Buoyancy = False");
  r.addIf(ad.CavitCheck, "CavitCheck", "cavitation check", "CavitCheck = False");
  r.addIf(ad.CompAA, "CompAA", "aeroacoustics", "CompAA = False");
  r.addIf(ad.NacelleDrag, "NacelleDrag", "nacelle drag", "NacelleDrag = False");
  r.addIf(ad.SectAvg, "SectAvg", "sector-averaged inflow", "SectAvg = False");
  r.addIf(ad.TFinAero, "TFinAero", "tail-fin aerodynamics", "TFinAero = False");
  r.addIf(ad.AFTabMod != 1, "AFTabMod", "interpolation between airfoil tables",
          "AFTabMod = 1 (the first table of each airfoil file)");
  r.addIf(ad.skew == SkewModel::Coupled, "SkewMod", "the coupled skewed-wake model (dropped in OpenFAST v4)",
          "SkewMod = 0, 1 or 2");
  return r.take();
}

std::vector<std::string> unsupportedOptions(const InflowWindInput& wind) {
  Refusals r(wind.source);
  static const char* names[] = {"", "steady", "uniform wind file", "TurbSim full field", "Bladed-style full field",
                                "HAWC full field", "user-defined wind", "native Bladed full field"};
  const bool known = wind.WindType >= 1 && wind.WindType <= 7;
  r.addIf(wind.WindType != 1, "WindType", known ? std::string(names[wind.WindType]) + " wind" : "unknown wind type",
          "WindType = 1 (steady wind)");
  return r.take();
}

void requireSupported(const AeroDynInput& ad) { throwIfAny(unsupportedOptions(ad)); }
void requireSupported(const InflowWindInput& wind) { throwIfAny(unsupportedOptions(wind)); }

}  // namespace whirl::io
