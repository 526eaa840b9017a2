// libFuzzer harness for one reader alone, compiled once per reader (fuzz/CMakeLists.txt,
// WHIRL_FUZZ_READER): the bytes are the file and only that reader (and what turns its result into
// model data) runs: hundreds to thousands of inputs/s under ASan, where the harnesses of the model
// behind each file (fuzz_case_yaml, fuzz_elastodyn, fuzz_aerodyn & co.) solve and linearize it at
// 1–100 inputs/s — so that each parser gets its 10⁶ executions.
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

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
#if WHIRL_FUZZ_READER == 13
  const std::string path = whirl::fuzz::writeInput("fuzz_rad.ss", data, size);
#else
  const std::string path = whirl::fuzz::writeInput("fuzz_aero.dat", data, size);
#endif
  whirl::fuzz::expectOnlyInputErrors([&] {
    namespace io = whirl::io;
#if WHIRL_FUZZ_READER == 1
    (void)io::readAeroDyn(path);
#elif WHIRL_FUZZ_READER == 2
    (void)io::readAeroDynBlade(path);
#elif WHIRL_FUZZ_READER == 3
    const io::AirfoilInput af = io::readAirfoil(path);
    // Every table on the Reynolds number (AFTabMod = 2) first: it checks the tables beyond the first.
    whirl::fuzz::expectOnlyInputErrors([&] { (void)io::airfoilPolar(af, true, whirl::aero::ReynoldsInterp::Log); });
    (void)io::airfoilPolar(af, true);
#elif WHIRL_FUZZ_READER == 4
    (void)io::readInflowWind(path);
#elif WHIRL_FUZZ_READER == 5
    (void)io::generatorTorqueLaw(io::readServoDyn(path));
#elif WHIRL_FUZZ_READER == 6
    (void)whirl::readCase(path);
#elif WHIRL_FUZZ_READER == 7
    (void)io::readFst(path);
#elif WHIRL_FUZZ_READER == 8
    (void)io::readElastoDyn(path);
#elif WHIRL_FUZZ_READER == 9
    (void)io::readElastoDynTower(path);
#elif WHIRL_FUZZ_READER == 10
    (void)io::readElastoDynBlade(path);
#elif WHIRL_FUZZ_READER == 11
    const io::AeroDyn14Input v14 = io::readAeroDyn14(path);
    (void)io::aerodynFromV14(v14);
    (void)io::bladeFromV14(v14);
    (void)io::steadySubstitutes(v14);
#elif WHIRL_FUZZ_READER == 12
    for (bool cm : {false, true}) {
      const io::AirfoilInput af = io::readAirfoil14(path, cm);
      whirl::fuzz::expectOnlyInputErrors(
          [&] { (void)io::airfoilPolar(af, cm, whirl::aero::ReynoldsInterp::Linear); });  // MultiTab = RENUM
      (void)io::airfoilPolar(af, cm);
    }
#elif WHIRL_FUZZ_READER == 13
    io::HydroDynInput hd;
    hd.PotFile = std::filesystem::path(path).replace_extension();
    (void)io::readRadiationStateSpace(hd);
#elif WHIRL_FUZZ_READER == 14
    (void)io::mapMooringLines(io::readMap(path), 0, 320, 1025, 9.80665);
#elif WHIRL_FUZZ_READER == 15
    (void)io::mapMooringLines(io::readMoorDyn(path), 0, 320, 1025, 9.80665);
#elif WHIRL_FUZZ_READER == 16
    const io::HydroDynInput hd = io::readHydroDyn(path);
    (void)whirl::elastodyn::ballastOf(hd.geometry, hd.WtrDens.value_or(1025), 9.80665, whirl::Vec3::Zero());
#elif WHIRL_FUZZ_READER == 17
    (void)io::readSeaState(path);
#elif WHIRL_FUZZ_READER == 18
    const whirl::RoscoController c = io::readDiscon(path);
    (void)whirl::roscoMinimumPitch(c, 12.0);
    if (!c.PC_GS_angles.empty()) (void)whirl::roscoPitchGains(c, 0.1);
    (void)whirl::roscoTorqueLimit(c, c.VS_RefSpd);
#else
#error "WHIRL_FUZZ_READER must be 1 to 18"
#endif
  });
  return 0;
}
