// A user's program against the installed library: read a YAML case, solve its operating point,
// linearize, print the frequencies of the modes. Usage: whirl_consumer CASE.yaml
#include <cstdio>
#include <exception>

#include <whirl/linearize/linearize.hpp>
#include <whirl/linearize/operating_point.hpp>
#include <whirl/modal/modes.hpp>
#include <whirl/src/io/case/case_file.hpp>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: whirl_consumer CASE.yaml\n");
    return 2;
  }
  try {
    const whirl::Model model = whirl::readCase(argv[1]);
    const whirl::OperatingPoint op = whirl::solveOperatingPoint(model, whirl::initialPoint(model));
    const whirl::LinearModel lin = whirl::linearize(model, op);
    for (const whirl::Mode& m : whirl::computeModes(lin.M, lin.C, lin.K, lin.dof_names))
      std::printf("%s: %.4f Hz\n", m.name.c_str(), m.freq_hz);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "whirl_consumer: %s\n", e.what());
    return 1;
  }
  return 0;
}
