// libFuzzer harness for one aerodynamic reader alone, compiled once per reader (fuzz/CMakeLists.txt,
// WHIRL_FUZZ_READER): the bytes are the file and only that reader (and what turns its result into
// model data) runs: 30–800 inputs/s under ASan against the 1–3 of fuzz_aerodyn & co.,
// which build and linearize the whole NREL 5MW aeroelastic model behind each input.
//   1 fuzz_read_aerodyn     readAeroDyn (AeroDyn v15 main file; named files are not opened)
//   2 fuzz_read_ad_blade    readAeroDynBlade
//   3 fuzz_read_airfoil     readAirfoil, then airfoilPolar (the polar AeroDyn uses)
//   4 fuzz_read_inflowwind  readInflowWind
//   5 fuzz_read_servodyn    readServoDyn, then generatorTorqueLaw
#include "fuzz/fuzz_support.hpp"
#include "src/io/aerodyn_blade_input.hpp"
#include "src/io/aerodyn_input.hpp"
#include "src/io/airfoil_input.hpp"
#include "src/io/inflowwind_input.hpp"
#include "src/io/servodyn_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = whirl::fuzz::writeInput("fuzz_aero.dat", data, size);
  whirl::fuzz::expectOnlyInputErrors([&] {
    namespace io = whirl::io;
#if WHIRL_FUZZ_READER == 1
    (void)io::readAeroDyn(path);
#elif WHIRL_FUZZ_READER == 2
    (void)io::readAeroDynBlade(path);
#elif WHIRL_FUZZ_READER == 3
    (void)io::airfoilPolar(io::readAirfoil(path), true);
#elif WHIRL_FUZZ_READER == 4
    (void)io::readInflowWind(path);
#elif WHIRL_FUZZ_READER == 5
    (void)io::generatorTorqueLaw(io::readServoDyn(path));
#else
#error "WHIRL_FUZZ_READER must be 1 to 5"
#endif
  });
  return 0;
}
