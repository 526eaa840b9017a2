// libFuzzer harnesses for one reader alone, one harness per reader (the name in the table): the bytes are the file and
// only that reader (and what turns its result into model data) runs: hundreds to thousands of inputs/s under ASan,
// where the harnesses of the model behind each file (fuzz_case_yaml, fuzz_elastodyn, fuzz_aerodyn & co.) solve and
// linearize it at 1–100 inputs/s — so that each parser gets its 10⁶ executions.
//   1 fuzz_read_aerodyn     readAeroDyn (AeroDyn v15 main file; named files are not opened)
//   2 fuzz_read_ad_blade    readAeroDynBlade
//   3 fuzz_read_airfoil     readAirfoil, then airfoilPolar (the polar AeroDyn uses; first table, and on Re)
//   4 fuzz_read_inflowwind  readInflowWind
//   5 fuzz_read_servodyn    readServoDyn, then generatorTorqueLaw
//   6 fuzz_read_case_yaml   readCase (the YAML case and the model it builds, no operating point)
//   7 fuzz_read_fst         readFst
//   8 fuzz_read_elastodyn   readElastoDyn (the tower and blade files it names do not exist: the keys
//                           before them are what is read)
//   9 fuzz_read_ed_tower    readElastoDynTower
//  10 fuzz_read_ed_blade    readElastoDynBlade
//  11 fuzz_read_aerodyn14   readAeroDyn14, then its AeroDyn v15 description and blade (FAST v8 CompAero = 1)
//  12 fuzz_read_airfoil14   readAirfoil14 with and without Cm columns, then airfoilPolar (first table, on Re)
//  13 fuzz_read_wamit_ss    readRadiationStateSpace (HydroDyn's state-space radiation, WAMIT `.ss`)
//  14 fuzz_read_map         readMap, then mapMooringLines (the catenary lines it describes)
//  15 fuzz_read_moordyn     readMoorDyn, then mapMooringLines
//  16 fuzz_read_hydrodyn    readHydroDyn (its member tables too), then ballastOf (the filled members' fluid)
//  17 fuzz_read_seastate    readSeaState (OpenFAST v4+ water properties)
//  18 fuzz_read_discon      readDiscon (ROSCO's DISCON.IN), then its minimum pitch, gains and torques
#include <iterator>
#include <utility>

#include "fuzz/fuzz_support.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/openfast/aerodyn/aero_deck14.hpp"
#include "src/io/openfast/aerodyn/aerodyn_blade_input.hpp"
#include "src/io/openfast/aerodyn/aerodyn_input.hpp"
#include "src/io/openfast/aerodyn/airfoil14_input.hpp"
#include "src/io/openfast/aerodyn/airfoil_input.hpp"
#include "src/io/openfast/aerodyn/inflowwind_input.hpp"
#include "src/io/openfast/elastodyn/elastodyn_blade.hpp"
#include "src/io/openfast/elastodyn/elastodyn_input.hpp"
#include "src/io/openfast/elastodyn/elastodyn_tower.hpp"
#include "src/io/openfast/fst_input.hpp"
#include "src/io/openfast/offshore/hydrodyn_input.hpp"
#include "src/io/openfast/offshore/map_input.hpp"
#include "src/io/openfast/offshore/moordyn_input.hpp"
#include "src/io/openfast/offshore/seastate_input.hpp"
#include "src/io/openfast/offshore/wamit_state_space.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/openfast/servodyn/servodyn_input.hpp"
#include "src/turbine/hydrodyn_ballast.hpp"

namespace {

namespace io = whirl::io;

// The reader numbered as in the table above.
void readAs(int reader, const std::string& path) {
  switch (reader) {
    case 1: (void)io::readAeroDyn(path); break;
    case 2: (void)io::readAeroDynBlade(path); break;
    case 3: {
      const io::AirfoilInput af = io::readAirfoil(path);
      // Every table on the Reynolds number (AFTabMod = 2) first: it checks the tables beyond the first.
      whirl::fuzz::expectOnlyInputErrors([&] { (void)io::airfoilPolar(af, true, whirl::aero::ReynoldsInterp::Log); });
      (void)io::airfoilPolar(af, true);
      break;
    }
    case 4: (void)io::readInflowWind(path); break;
    case 5: (void)io::generatorTorqueLaw(io::readServoDyn(path)); break;
    case 6: (void)whirl::readCase(path); break;
    case 7: (void)io::readFst(path); break;
    case 8: (void)io::readElastoDyn(path); break;
    case 9: (void)io::readElastoDynTower(path); break;
    case 10: (void)io::readElastoDynBlade(path); break;
    case 11: {
      const io::AeroDyn14Input v14 = io::readAeroDyn14(path);
      (void)io::aerodynFromV14(v14);
      (void)io::bladeFromV14(v14);
      (void)io::steadySubstitutes(v14);
      break;
    }
    case 12:
      for (bool cm : {false, true}) {
        const io::AirfoilInput af = io::readAirfoil14(path, cm);
        whirl::fuzz::expectOnlyInputErrors(
            [&] { (void)io::airfoilPolar(af, cm, whirl::aero::ReynoldsInterp::Linear); });  // MultiTab = RENUM
        (void)io::airfoilPolar(af, cm);
      }
      break;
    case 13: {
      io::HydroDynInput hd;
      hd.PotFile = std::filesystem::path(path).replace_extension();
      (void)io::readRadiationStateSpace(hd);
      break;
    }
    case 14: (void)io::mapMooringLines(io::readMap(path), 0, 320, 1025, 9.80665); break;
    case 15: (void)io::mapMooringLines(io::readMoorDyn(path), 0, 320, 1025, 9.80665); break;
    case 16: {
      const io::HydroDynInput hd = io::readHydroDyn(path);
      (void)whirl::elastodyn::ballastOf(hd.geometry, hd.WtrDens.value_or(1025), 9.80665, whirl::Vec3::Zero());
      break;
    }
    case 17: (void)io::readSeaState(path); break;
    case 18: {
      const whirl::RoscoController c = io::readDiscon(path);
      (void)whirl::roscoMinimumPitch(c, 12.0);
      if (!c.PC_GS_angles.empty()) (void)whirl::roscoPitchGains(c, 0.1);
      (void)whirl::roscoTorqueLimit(c, c.VS_RefSpd);
      break;
    }
  }
}

template <int Reader>
int fuzzReader(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput(Reader == 13 ? "fuzz_rad.ss" : "fuzz_aero.dat", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] { readAs(Reader, path); });
  return 0;
}

constexpr const char* kNames[] = {"fuzz_read_aerodyn",    "fuzz_read_ad_blade",  "fuzz_read_airfoil",
                                  "fuzz_read_inflowwind", "fuzz_read_servodyn",  "fuzz_read_case_yaml",
                                  "fuzz_read_fst",        "fuzz_read_elastodyn", "fuzz_read_ed_tower",
                                  "fuzz_read_ed_blade",   "fuzz_read_aerodyn14", "fuzz_read_airfoil14",
                                  "fuzz_read_wamit_ss",   "fuzz_read_map",       "fuzz_read_moordyn",
                                  "fuzz_read_hydrodyn",   "fuzz_read_seastate",  "fuzz_read_discon"};

template <std::size_t... I>
bool registerReaders(std::index_sequence<I...>) {
  (whirl::fuzz::RegisterHarness(kNames[I], &fuzzReader<static_cast<int>(I) + 1>), ...);
  return true;
}

[[maybe_unused]] const bool kRegistered = registerReaders(std::make_index_sequence<std::size(kNames)>{});

}  // namespace
