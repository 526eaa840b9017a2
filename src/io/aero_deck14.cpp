#include "src/io/aero_deck14.hpp"

#include "src/io/aero_support.hpp"
#include "src/io/refusals.hpp"

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
  // Drag out of both inductions: so NREL set the AeroDyn v15 files it made from these v14 files for the
  // FAST 8 certification tests (AWT-27, AOC, UAE VI, WindPACT, SWRT: AIDrag = TIDrag = False).
  a.AIDrag = false;
  a.TIDrag = false;
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
       "AeroDyn v14 file: whirl solves AeroDyn v15's BEMT on its elements (inflow-angle residual, no drag in the "
       "inductions, Buhl's high-thrust correction), not AeroDyn v14's induction-factor iteration");
  note(v14.InfModel == "DYNIN", "InfModel",
       "dynamic inflow: whirl solves the equilibrium BEMT (InfModel = EQUIL), the steady state of the "
       "dynamic-inflow states, which are not in the linear model");
  note(v14.StallMod == "BEDDOES", "StallMod",
       "Beddoes dynamic stall: whirl uses the static airfoil tables, the steady state of the dynamic-stall "
       "model, whose states are not in the linear model");
  note(v14.TwrShad != 0, "TwrShad", "tower shadow left out: the blades see the undisturbed wind");
  return notes;
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
