// libFuzzer harness for the OpenFAST readers, compiled once per file kind (fuzz/CMakeLists.txt):
// the bytes replace WHIRL_FUZZ_TARGET in a copy of cases/nrel5mw and the model is read from
// WHIRL_FUZZ_ENTRY as `whirl modes FILE` does (readElastoDynModel: .fst → ElastoDyn → tower and
// blade files → ServoDyn → turbine model, finalized), then one equilibrium and one linearization.
//   fuzz_fst        the .fst main file           entry: itself
//   fuzz_elastodyn  the ElastoDyn main file      entry: itself (the CLI takes a .dat too)
//   fuzz_servodyn   the ServoDyn file            entry: Main_Onshore.fst
//   fuzz_ed_tower   the ElastoDyn tower file     entry: the ElastoDyn main file
//   fuzz_ed_blade   the ElastoDyn blade file     entry: the ElastoDyn main file (all 3 blades)
//   fuzz_aerodyn, fuzz_ad_blade, fuzz_airfoil, fuzz_inflowwind, fuzz_servodyn_aero: the AeroDyn main
//                   file, its blade file, the tip airfoil, InflowWind, the aero ServoDyn (VSContrl = 1)
//                   entry: Main_Aero.fst (the aeroelastic model; AeroDyn, InflowWind and ServoDyn)
#include "fuzz/fuzz_support.hpp"
#include "src/turbine/elastodyn_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  whirl::fuzz::writeInput(WHIRL_FUZZ_TARGET, data, size);
  const std::string entry = (whirl::fuzz::sandbox() / WHIRL_FUZZ_ENTRY).string();
  whirl::fuzz::expectOnlyInputErrors([&] {
    const whirl::Model m = whirl::readElastoDynModel(entry);
    whirl::fuzz::solveAndLinearize(m);
  });
  return 0;
}
