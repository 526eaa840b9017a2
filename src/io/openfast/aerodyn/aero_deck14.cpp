#include "src/io/openfast/aerodyn/aero_deck14.hpp"

#include "src/base/error.hpp"
#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/io/openfast/refusals.hpp"

namespace whirl::io {

AeroDynInput aerodynFromV14(const AeroDyn14Input& v14) {
  Refusals r(v14.source);
  r.addIf(v14.TLModel == "GTECH", "TLModel", "the Georgia Tech tip loss, which AeroDyn v15 does not have",
          "TLModel = PRANDtl or NONE");
  throwIfAny(r.take());
  AeroDynInput a;
  a.source = v14.source;
  a.Wake_Mod = v14.IndModel == "NONE" ? 0 : 1;
  a.wake_key = "IndModel";
  a.TanInd = v14.IndModel == "SWIRL";
  a.TipLoss = v14.TLModel == "PRANDTL";
  a.HubLoss = v14.HLModel == "PRANDTL";
  // Drag in the inductions only with EQUILDA/DT/DB; plain EQUIL and DYNIN (solved here as equilibrium)
  // have none, and so NREL set the v15 files it made from the certification tests' v14 files (AIDrag =
  // TIDrag = False).
  a.AIDrag = v14.InfModel == "EQUILDA" || v14.InfModel == "EQUILDB";
  a.TIDrag = v14.InfModel == "EQUILDT" || v14.InfModel == "EQUILDB";
  a.AirDens = v14.AirDens;
  a.KinVisc = v14.KinVisc;
  a.UseBlCm = v14.UseCm;
  a.AFNames = v14.FoilNm;
  a.AFNames_lines = v14.FoilNm_lines;
  return a;
}

std::vector<std::string> steadySubstitutes(const AeroDyn14Input& v14) {
  const OpenFastFile& f = v14.source;
  std::vector<std::string> notes;
  auto note = [&](bool on, const char* key, const std::string& what) {
    if (on) notes.push_back(f.where(key, f.find(key)->raw + ": " + what));
  };
  note(v14.IndModel != "NONE", "IndModel",
       "AeroDyn v14 file: whirl solves AeroDyn v15's BEMT on its elements (inflow-angle residual, Buhl's "
       "high-thrust correction), not AeroDyn v14's induction-factor iteration");
  note(v14.InfModel == "DYNIN", "InfModel",
       "dynamic inflow: whirl solves the equilibrium BEMT (InfModel = EQUIL), the steady state of the "
       "dynamic-inflow states, which are not in the linear model");
  note(v14.StallMod == "BEDDOES", "StallMod",
       "Beddoes dynamic stall: whirl uses the static airfoil tables, the steady state of the dynamic-stall "
       "model, whose states are not in the linear model");
  note(v14.TwrShad != 0, "TwrShad", "tower shadow left out: the blades see the undisturbed wind");
  return notes;
}

std::optional<std::string> multipleTables(const AeroDyn14Input& v14, const std::vector<AirfoilInput>& airfoils) {
  std::string several;
  for (const AirfoilInput& af : airfoils)
    if (af.tables.size() > 1) several += (several.empty() ? "" : ", ") + af.path.filename().string();
  if (several.empty() || v14.MultiTab == "SINGLE" || v14.MultiTab == "RENUM") return std::nullopt;
  const std::string file = v14.source.path().string();
  if (v14.MultiTab.empty())
    return whirl::where(file, 0, "MultiTab",
                        "absent at the end of the file: the first table of each airfoil file with several (" + several +
                            "), as AeroDyn v14 does");
  const std::string what = v14.MultiTab == "USER" ? "interpolation between airfoil tables on a user value"
                                                  : "not an option of AeroDyn v14 (USER, RENUM or SINGLE)";
  throw InputError(whirl::where(file, v14.MultiTab_line, "MultiTab",
                                v14.MultiTab + " not supported by whirl (" + what + ", for " + several +
                                    "; whirl supports SINGLE, the first table of each file, and RENUM)"));
}

AeroDynBladeInput bladeFromV14(const AeroDyn14Input& v14) {
  AeroDynBladeInput b;
  b.source = v14.source;
  b.NumBlNds = static_cast<int>(v14.RNodes.size());
  b.BlSpn = v14.RNodes;
  b.BlCrvAC.assign(b.NumBlNds, 0.0);
  b.BlSwpAC.assign(b.NumBlNds, 0.0);
  b.BlCrvAng.assign(b.NumBlNds, 0.0);
  b.BlTwist = v14.AeroTwst;
  b.BlChord = v14.Chord;
  b.BlAFID = v14.NFoil;
  b.row_lines = v14.row_lines;
  b.element_width = v14.DRNodes;
  return b;
}

}  // namespace whirl::io
