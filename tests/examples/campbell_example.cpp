// A whirl-independent example: a synthetic 5 MW-like Campbell diagram tracked and written with
// writeCampbell (CSV, JSON, Gnuplot data and script, PNG and SVG when Gnuplot is installed).
//   campbell_example [folder] [--wind]     default folder: <tmp>/whirl_campbell_example
#include <filesystem>
#include <iostream>
#include <string>

#include "src/base/error.hpp"
#include "src/writers/campbell_output.hpp"
#include "tests/support/synthetic_campbell.hpp"

int main(int argc, char** argv) {
  std::string dir = (std::filesystem::temp_directory_path() / "whirl_campbell_example").string();
  bool wind = false;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--wind") wind = true;
    else dir = arg;
  }
  try {
    whirl::CampbellPlotOptions opt;
    opt.versus_wind_speed = wind;
    for (const auto& f : whirl::writeCampbell(whirl::test::syntheticTurbineCampbell(wind), dir, opt))
      std::cout << f << "\n";
  } catch (const std::exception& e) {
    std::cerr << "campbell_example: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
