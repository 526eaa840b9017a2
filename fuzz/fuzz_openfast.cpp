// libFuzzer harnesses for the OpenFAST readers, one per file kind (kSpecs): the bytes replace the
// harness's target file in a copy of cases/nrel5mw and the model is read from its entry file as `whirl modes FILE` does
// (readElastoDynModel: .fst → ElastoDyn → tower and blade files → ServoDyn → turbine model, finalized), then one
// equilibrium and one linearization.
//   fuzz_fst        the .fst main file           entry: itself
//   fuzz_elastodyn  the ElastoDyn main file      entry: itself (the CLI takes a .dat too)
//   fuzz_servodyn   the ServoDyn file            entry: Main_Onshore.fst
//   fuzz_ed_tower   the ElastoDyn tower file     entry: the ElastoDyn main file
//   fuzz_ed_blade   the ElastoDyn blade file     entry: the ElastoDyn main file (all 3 blades)
//   fuzz_aerodyn, fuzz_ad_blade, fuzz_airfoil, fuzz_inflowwind, fuzz_servodyn_aero: the AeroDyn main
//                   file, its blade file, the tip airfoil, InflowWind, the aero ServoDyn (VSContrl = 1)
//                   entry: Main_Aero.fst (the aeroelastic model; AeroDyn, InflowWind and ServoDyn)
#include <iterator>
#include <utility>

#include "fuzz/fuzz_support.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace {

struct Spec {
  const char* name;    ///< the harness
  const char* target;  ///< the file of the copy of cases/nrel5mw the bytes replace
  const char* entry;   ///< the file the model is read from
};

constexpr const char* kEd = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
constexpr Spec kSpecs[] = {
    {"fuzz_fst", "fuzz.fst", "fuzz.fst"},
    {"fuzz_elastodyn", "fuzz_ElastoDyn.dat", "fuzz_ElastoDyn.dat"},
    {"fuzz_servodyn", "NRELOffshrBsline5MW_Onshore_ServoDyn.dat", "Main_Onshore.fst"},
    {"fuzz_ed_tower", "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat", kEd},
    {"fuzz_ed_blade", "NRELOffshrBsline5MW_Blade.dat", kEd},
    // The aerodynamic deck of Main_Aero.fst (CompAero = 2, CompInflow = 1, CompServo = 1).
    {"fuzz_aerodyn", "aero/AeroDyn.dat", "Main_Aero.fst"},
    {"fuzz_ad_blade", "5MW_Baseline/NRELOffshrBsline5MW_AeroDyn_blade.dat", "Main_Aero.fst"},
    {"fuzz_airfoil", "5MW_Baseline/Airfoils/NACA64_A17.dat", "Main_Aero.fst"},
    {"fuzz_inflowwind", "aero/InflowWind.dat", "Main_Aero.fst"},
    {"fuzz_servodyn_aero", "aero/ServoDyn.dat", "Main_Aero.fst"},
};

template <std::size_t I>
int fuzzDeck(const uint8_t* data, size_t size) {
  whirl::fuzz::writeInput(kSpecs[I].target, data, size);
  const std::string entry = (whirl::fuzz::sandbox() / kSpecs[I].entry).string();
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::Model m = whirl::readElastoDynModel(entry);
    whirl::fuzz::solveAndLinearize(m);
  });
  return 0;
}

template <std::size_t... I>
bool registerDecks(std::index_sequence<I...>) {
  (whirl::fuzz::RegisterHarness(kSpecs[I].name, &fuzzDeck<I>), ...);
  return true;
}

[[maybe_unused]] const bool kRegistered = registerDecks(std::make_index_sequence<std::size(kSpecs)>{});

}  // namespace
