#include "src/io/openfast/openfast_deck.hpp"

#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/io/openfast/offshore/wamit_input.hpp"
#include "src/io/openfast/offshore/wamit_state_space.hpp"
#include "src/io/openfast/openfast_input.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"

namespace whirl::io {

OpenFastDeck readOpenFastDeck(const std::filesystem::path& p, OverrideSet* overrides, const OpenFastDeckOptions& opt) {
  OpenFastDeck d;
  OpenFastTurbine& t = d.turbine;
  if (toLower(p.extension().string()) == ".fst") t = readOpenFastTurbine(p, overrides);
  else t.elastodyn = readElastoDyn(p, overrides);
  // A floating platform's potential flow: WAMIT's coefficients (PotMod = 1) and the state-space
  // radiation (RdtnMod = 2). On a SubDyn substructure potential flow is refused (requireSupported).
  if (t.hydrodyn && !t.subdyn && t.hydrodyn->PotMod == 1) {
    t.wamit = readWamitCoefficients(*t.hydrodyn);
    if (t.hydrodyn->RdtnMod == 2) t.radiation = readRadiationStateSpace(*t.hydrodyn);
  }
  bool servo_read = false;
  auto readServo = [&] {
    if (!servo_read) d.servodyn = readServoDynIfEnabled(t.fst, overrides), servo_read = true;
  };
  if (opt.servodyn_for_yaw && t.elastodyn.dof.YawDOF && t.fst.CompServo != 0) readServo();
  // Aerodynamics follows the deck: CompAero = 2 reads AeroDyn, its blades and airfoils and InflowWind
  // (`--set CompAero=0` gives the structural model of the same deck).
  if (t.fst.CompAero != 0) {
    d.aero = readAeroDeck(t.fst, overrides);
    requireSupported(d.aero->aerodyn);
    requireSupported(d.aero->inflow);
    readServo();
    // A ROSCO DISCON.IN, with the --set overrides of its keys: the model carries it to the commands.
    if (d.servodyn) d.controller = readServoDynController(*d.servodyn, overrides);
  }
  return d;
}

}  // namespace whirl::io
